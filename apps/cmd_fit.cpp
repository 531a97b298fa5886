// sphereset fit: fits N spheres that bound a mesh, writes them and reports the fit; exits with
// kUncovered when they fail eval's coverage check.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

struct FitCommandArgs {
  FitArgs fit;
  bool json = false;
};

// The summary printed by --json.
nlohmann::json fitJson(const FitArgs& a, const FitOptions& fo, const FitResult& r,
                       const EvalResult& ev, const RepairResult& rep) {
  nlohmann::json j = fieldsJson(fitResultFields(r, ev.mesh_volume));
  j["mesh"] = a.mesh.path;
  j["repair"] = repairJson(rep);
  j["output"] = a.out_path;
  j["spheres"] = r.spheres.size();
  j["seed"] = fo.seed;
  // The fit's own check (fitCheckEvalOptions): the union's E_r and the certificates.
  const nlohmann::json e = fieldsJson(evalResultFields(ev));
  for (const char* name : {"er_union", "er_union_stderr", "surface_covered", "interior_covered",
                           "original_covered", "walls_volume", "er_walls"})
    j[name] = e.at(name);
  return j;
}

// The summary on stderr unless --quiet.
void printFitSummary(const FitArgs& a, const FitResult& r, const EvalResult& ev,
                     const SolidInput& in) {
  const std::string rl = repairLine(in.repair);
  if (!rl.empty()) std::fprintf(stderr, "%s: %s\n", a.mesh.path.c_str(), rl.c_str());
  std::fprintf(stderr,
               "%s: %zu spheres -> %s\n"
               "  E_r summed %.4f (%.4f before bounding), E_r union %.4f +- %.4f\n"
               "  surface covered %s, interior covered %s, protrusion %.4g (certified; %.4g of "
               "the diagonal)\n"
               "  %lld points (%lld interior), %d rounds%s, %d teleports (%d kept), %lld SOV "
               "queries in assignment (%lld culled)\n"
               "  time %.2f s (sampling %.2f, assignment %.2f, update %.2f, teleport %.2f, "
               "bounding %.2f: bound %.2f, shrink %.2f, refine %.2f, radii %.2f)\n",
               a.mesh.path.c_str(), r.spheres.size(), a.out_path.c_str(), r.energy / ev.mesh_volume,
               r.energy_before_bounding / ev.mesh_volume, ev.er_union, ev.er_union_stderr,
               ev.surface_covered ? "yes" : "NO", ev.interior_covered ? "yes" : "NO", ev.protrusion,
               ev.protrusion / ev.bbox_diagonal, static_cast<long long>(r.points),
               static_cast<long long>(r.interior_points), r.iterations,
               r.converged ? " (converged)" : "", r.teleports, r.teleports_accepted,
               static_cast<long long>(r.sov_queries), static_cast<long long>(r.sov_queries_culled),
               r.seconds.total, r.seconds.sampling, r.seconds.assignment, r.seconds.update,
               r.seconds.teleport, r.seconds.bounding, r.seconds.bound, r.seconds.shrink,
               r.seconds.refine, r.seconds.radii);
  if (in.original())
    std::fprintf(stderr,
                 "  E_r relative to the repaired solid's volume; original triangles covered %s\n",
                 ev.original_covered ? "yes" : "NO");
  if (in.walls())
    std::fprintf(stderr,
                 "  the solid is the walls' envelope (openings narrower than %.4g closed): E_r "
                 "against the walls %.4f\n",
                 in.repair.fill_openings, ev.er_walls);
}

int runFit(const FitCommandArgs& c) {
  const FitArgs& a = c.fit;
  auto format = sphereFormatFromPath(a.out_path);
  if (!format) return fail(format.error());
  // Before any work: the output is not the input, and its folder accepts it.
  if (Status st = checkOutputPath(a.out_path, {a.mesh.path}); !st) return fail(st.error());
  auto options = fitOptions(a);  // bad options are refused before any loading
  if (!options) return fail(options.error());
  auto m = loadSolid(a.mesh);
  if (!m) return fail(m.error());
  FitOptions fo = std::move(options).value();
  fo.original = m->original();
  const SolidIndex index(m->repair.solid);
  auto r = fitSpheres(index, fo);
  if (!r) return fail(Error{r.error().code, a.mesh.path + ": " + r.error().message});
  SphereFileMeta meta;
  meta.name =
      a.link_name.empty() ? std::filesystem::path(a.mesh.path).stem().string() : a.link_name;
  meta.source_mesh = a.mesh.path;
  Status st = writeSpheres(a.out_path, r->spheres, meta);
  if (!st) return fail(st.error());
  auto checked =
      evaluateSpheres(index, r->spheres, fitCheckEvalOptions(fo.seed, m->original(), m->walls()));
  if (!checked) return fail(checked.error());
  const EvalResult& ev = *checked;
  if (c.json) std::cout << jsonText(fitJson(a, fo, *r, ev, m->repair)) << '\n';
  if (!a.quiet) printFitSummary(a, *r, ev, *m);
  // The summary's evaluation is eval's coverage check (same certificate depths).
  return coverageExit(a.mesh.path, "the fitted spheres", a.out_path, ev);
}

}  // namespace

Command registerFit(CLI::App& app) {
  auto c = std::make_shared<FitCommandArgs>();
  CLI::App* cmd = app.add_subcommand("fit", "Fit N spheres that bound the mesh");
  addFitArgs(cmd, &c->fit, true);
  cmd->add_option("--name", c->fit.link_name,
                  "Link name for .yaml output (default: the mesh's stem)");
  cmd->add_flag("--json", c->json, "Print the summary as one JSON object on stdout");
  return {cmd, [c] { return runFit(*c); }};
}

}  // namespace sphereset::cli

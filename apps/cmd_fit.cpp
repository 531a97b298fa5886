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
  TableArgs tolerance;  // the rows of toleranceOptionTable()
  std::string curve;    // --curve CSV
  bool best_effort = false;
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
                           "original_covered", "walls_volume", "er_walls", "protrusion"})
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

// fit with a tolerance: the fewest spheres that meet it (fitToTolerance), the curve on request,
// exit 10 when no count up to the cap meets it (the best set written only with --best-effort).
int runToleranceFit(const FitCommandArgs& c, const ToleranceOptions& tolerance) {
  const FitArgs& a = c.fit;
  auto request = fitRequest(a);
  if (!request) return fail(request.error());
  if (Status st = checkToleranceRequest(*request, tolerance); !st) return fail(st.error());
  auto m = loadSolid(a.mesh);
  if (!m) return fail(m.error());
  const SolidIndex index(m->repair.solid);
  ToleranceOptions to = tolerance;
  to.original = m->original();
  to.walls = m->walls();
  ProgressLine progress("fit");
  if (!a.quiet)
    to.progress = [&progress](const CurvePoint& p) {
      char what[128];
      std::snprintf(what, sizeof what, "n %d: protrusion %.4g, E_r %.4f%s", p.n, p.protrusion,
                    p.er_sum, p.meets ? ", meets it" : "");
      progress.show("tolerance search", p.n, p.n, what);
    };
  auto t = fitToTolerance(index, *request, to);
  if (!t) return fail(Error{t.error().code, a.mesh.path + ": " + t.error().message});
  if (!c.curve.empty())
    if (Status st = writeCurve(c.curve, t->curve); !st) return fail(st.error());
  if (t->met || c.best_effort) {
    SphereFileMeta meta;
    meta.name =
        a.link_name.empty() ? std::filesystem::path(a.mesh.path).stem().string() : a.link_name;
    meta.source_mesh = a.mesh.path;
    if (Status st = writeSpheres(a.out_path, t->fit.spheres, meta); !st) return fail(st.error());
  }
  FitOptions fo = fitOptionsFor(*request);
  if (c.json) {
    nlohmann::json j = fitJson(a, fo, t->fit, t->eval, m->repair);
    j["tolerance"] = {{"met", t->met},
                      {"n", t->n},
                      {"protrusion_limit", t->protrusion_limit},
                      {"max_er", tolerance.max_er},
                      {"seconds", t->seconds}};
    nlohmann::json curve = nlohmann::json::array();
    for (const CurvePoint& p : t->curve) curve.push_back(curvePointJson(p));
    j["tolerance"]["curve"] = curve;
    std::cout << jsonText(j) << '\n';
  }
  if (!a.quiet) {
    std::fprintf(stderr,
                 "%s: %d counts tried in %.2f s; %s n = %d: protrusion %.6g (certified), "
                 "E_r %.4f\n",
                 a.mesh.path.c_str(), static_cast<int>(t->curve.size()), t->seconds,
                 t->met ? "the fewest that meet the tolerance:" : "none meets it; the best,", t->n,
                 t->eval.protrusion, t->eval.er_sum);
  }
  if (!t->met) {
    std::fprintf(stderr,
                 "sphereset: %s: no count up to %d meets the tolerance (best: n = %d, protrusion "
                 "%.6g, E_r %.4f)%s\n",
                 a.mesh.path.c_str(), tolerance.max_spheres, t->n, t->eval.protrusion,
                 t->eval.er_sum,
                 c.best_effort ? "; its spheres are written (--best-effort)" : "; nothing written");
    return kToleranceNotMet;
  }
  return coverageExit(a.mesh.path, "the fitted spheres", a.out_path, t->eval);
}

int runFit(const FitCommandArgs& c) {
  const FitArgs& a = c.fit;
  auto format = sphereFormatFromPath(a.out_path);
  if (!format) return fail(format.error());
  // Before any work: the output is not the input, and its folder accepts it.
  if (Status st = checkOutputPath(a.out_path, {a.mesh.path}); !st) return fail(st.error());
  ToleranceOptions tolerance;
  for (const auto& [name, text] : c.tolerance.given())
    if (Status st = setToleranceOption(&tolerance, name, text); !st) return fail(st.error());
  if (!c.curve.empty() && !tolerance.active())
    return fail(Error{ErrorCode::kInvalidArgument,
                      "--curve goes with a tolerance (--max-protrusion, --max-er): it writes the "
                      "counts a tolerance search tries"});
  if (Status st = checkToleranceRequest(FitRequest{}, tolerance); !st) return fail(st.error());
  if (Status st = checkBestEffort(c.best_effort, tolerance); !st) return fail(st.error());
  if (!c.curve.empty())
    if (Status st = checkOutputPath(c.curve, {a.mesh.path, a.out_path}); !st)
      return fail(st.error());
  auto options = fitOptions(a);  // bad options are refused before any loading
  if (!options) return fail(options.error());
  if (tolerance.active()) return runToleranceFit(c, tolerance);
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
  addTableOptions(cmd, &c->tolerance, toleranceOptionTable());
  cmd->add_option("--curve", c->curve,
                  "With a tolerance: write every count tried as CSV (n, E_r, protrusion, "
                  "covered, meets, seconds)");
  cmd->add_flag("--best-effort", c->best_effort,
                "With a tolerance no count meets: write the best set anyway (exit 10 still)");
  return {cmd, [c] { return runFit(*c); }};
}

}  // namespace sphereset::cli

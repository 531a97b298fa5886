// sphereset tree: fits a sphere set and builds a sphere tree over it (Bradshaw .sph or JSON);
// exits with kUncovered when its leaves fail eval's coverage check.
#include <cstdio>
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
#include "sphereset/tree.hpp"

namespace sphereset::cli {
namespace {

struct TreeArgs {
  FitArgs fit;
  TableArgs tree;  // the rows of treeOptionTable() given
  bool json = false;
  int leaves = 0;  // -n: leaves to fit (0: B^D)
};

// The summary printed by --json.
nlohmann::json treeJson(const TreeArgs& a, const TreeOptions& to, const FitOptions& fo,
                        const TreeFitResult& r, double volume, const EvalResult& ev) {
  nlohmann::json lv = nlohmann::json::array();
  for (const TreeLevelStats& l : r.tree.levels)
    lv.push_back(fieldsJson(treeLevelFields(l, volume)));
  return {{"mesh", a.fit.mesh.path},
          {"output", a.fit.out_path},
          {"branching", to.branching},
          {"depth", to.depth},
          {"parents", treeParentsName(to.parents)},
          {"leaves", r.fit.spheres.size()},
          {"levels", lv},
          {"surface_covered", ev.surface_covered},
          {"interior_covered", ev.interior_covered},
          {"seconds", {{"fit", r.fit.seconds.total}, {"tree", r.tree.seconds}}},
          {"seed", fo.seed}};
}

// The summary on stderr unless --quiet.
void printTreeSummary(const TreeArgs& a, const TreeOptions& to, const TreeFitResult& r,
                      double volume, const EvalResult& ev) {
  std::fprintf(stderr, "%s: tree of branching %d, depth %d (%s parents) -> %s\n",
               a.fit.mesh.path.c_str(), to.branching, to.depth, treeParentsName(to.parents),
               a.fit.out_path.c_str());
  for (const TreeLevelStats& l : r.tree.levels)
    std::fprintf(stderr, "  level %d: %4lld spheres, E_r summed %.4f\n", l.level,
                 static_cast<long long>(l.nodes), l.outside_volume / volume);
  std::fprintf(stderr, "  leaves: surface covered %s, interior covered %s\n",
               ev.surface_covered ? "yes" : "NO", ev.interior_covered ? "yes" : "NO");
  std::fprintf(stderr, "  time %.2f s fit + %.2f s tree\n", r.fit.seconds.total, r.tree.seconds);
}

int runTree(TreeArgs a) {
  auto format = sphereFormatFromPath(a.fit.out_path);
  if (!format) return fail(format.error());
  if (*format != SphereFormat::kSph && *format != SphereFormat::kJson)
    return fail(Error{ErrorCode::kInvalidArgument,
                      a.fit.out_path + ": a sphere tree is written as .sph or .json"});
  if (Status st = checkOutputPath(a.fit.out_path, {a.fit.mesh.path}); !st) return fail(st.error());
  TreeOptions to;
  for (const auto& [name, text] : a.tree.given())
    if (Status st = setTreeOption(&to, name, text); !st) return fail(st.error());
  auto request = fitRequest(a.fit);
  if (!request) return fail(request.error());
  // The leaves replace the table's n (0: branching^depth); the preset's points follow them.
  request->num_spheres = a.leaves;
  auto leaves = treeFitRequest(*request, to);
  if (!leaves) return fail(leaves.error());
  FitOptions fo = fitOptions(*leaves, a.fit.quiet);
  auto m = loadSolid(a.fit.mesh);
  if (!m) return fail(m.error());
  fo.original = m->original();
  to.seed = fo.seed;
  const SolidIndex index(m->repair.solid);
  auto r = fitSphereTree(index, fo, to);
  if (!r) return fail(Error{r.error().code, a.fit.mesh.path + ": " + r.error().message});
  SphereFileMeta meta;
  meta.source_mesh = a.fit.mesh.path;
  Status st = writeSphereTree(a.fit.out_path, r->tree.tree, meta);
  if (!st) return fail(st.error());
  const double vol = signedVolume(m->repair.solid);
  // Eval's coverage check on the leaves as written; every parent encloses its children.
  EvalOptions eo;
  eo.seed = fo.seed;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = m->original();
  eo.walls = m->walls();
  auto checked = evaluateSpheres(index, r->tree.tree.leaves(), eo);
  if (!checked) return fail(checked.error());
  const EvalResult& ev = *checked;
  if (a.json) {
    nlohmann::json j = treeJson(a, to, fo, *r, vol, ev);
    j["repair"] = repairJson(m->repair);
    j["original_covered"] = ev.original_covered;
    std::cout << jsonText(j) << '\n';
  }
  if (!a.fit.quiet) {
    const std::string rl = repairLine(m->repair);
    if (!rl.empty()) std::fprintf(stderr, "%s: %s\n", a.fit.mesh.path.c_str(), rl.c_str());
    printTreeSummary(a, to, *r, vol, ev);
  }
  return coverageExit(a.fit.mesh.path, "the tree's leaves", a.fit.out_path, ev);
}

}  // namespace

Command registerTree(CLI::App& app) {
  auto a = std::make_shared<TreeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tree", "Fit a sphere set and build a sphere-tree over it (Bradshaw .sph or JSON)");
  addFitArgs(cmd, &a->fit, false);
  addTableOptions(cmd, &a->tree, treeOptionTable(), {"parents"});
  // Checked by the library's fit table once 0 became B^D (treeFitRequest).
  cmd->add_option("-n,--spheres", a->leaves, "Leaves to fit (default 0: B^D)");
  addTableOptions(cmd, &a->tree, treeOptionTable(), {"branching", "depth"});
  cmd->add_flag("--json", a->json, "Print the summary as one JSON object on stdout");
  return {cmd, [a] { return runTree(*a); }};
}

}  // namespace sphereset::cli

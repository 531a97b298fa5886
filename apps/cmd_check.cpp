// sphereset check: loads a mesh, diagnoses it as a solid (topology, self-intersections, shells)
// and says what fit will do about each problem.
#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/repair.hpp"

namespace sphereset::cli {
namespace {

struct CheckArgs {
  MeshArgs mesh;
  bool json = false;
};

// How many crossing pairs `check` lists.
constexpr size_t kListedPairs = 5;

nlohmann::json checkJson(const LoadedMesh& m, const MeshDiagnosis& d) {
  nlohmann::json j = fieldsJson(meshDiagnosisFields(d));
  j["file"] = m.report.path;
  j["format"] = m.report.format;
  j["load"] = fieldsJson(loadReportFields(m.report));
  return j;
}

// The first few crossing triangle pairs, to look at.
std::vector<std::array<int32_t, 2>> firstPairs(const ShellAnalysis& sa) {
  const auto& p = sa.intersections.pairs;
  return {p.begin(), p.begin() + static_cast<std::ptrdiff_t>(std::min(kListedPairs, p.size()))};
}

nlohmann::json shellsJson(const ShellAnalysis& sa) {
  nlohmann::json j = fieldsJson(shellCountFields(countShells(sa)));
  j["first_intersecting_pairs"] = firstPairs(sa);
  return j;
}

// Each problem found, with what the repair does about it (or that fit refuses the mesh).
std::vector<std::pair<std::string, std::string>> problemActions(const MeshDiagnosis& d,
                                                                const ShellCounts& c,
                                                                const Expected<RepairResult>& r) {
  std::vector<std::pair<std::string, std::string>> out;
  auto n = [](int64_t k, const char* one, const char* many) {
    return std::to_string(k) + " " + (k == 1 ? one : many);
  };
  const bool wrapped = r && r->kind == RepairKind::kWrapped;
  const bool welded = r && r->weld_tolerance > 0.0;
  // What happened to a problem the exact steps did not remove: the wrap, or the refusal.
  auto last = [&](const std::string& exact) -> std::string {
    if (!r) return "fit refuses the mesh (below)";
    return wrapped ? "wrapped" : exact;
  };
  if (d.boundary_edges > 0)
    out.emplace_back(n(d.boundary_edges, "boundary edge", "boundary edges"),
                     last(welded && r->holes_capped == 0 ? "welded shut" : "holes capped"));
  if (d.misoriented_edges > 0)
    out.emplace_back(
        n(d.misoriented_edges, "inconsistently oriented edge", "inconsistently oriented edges"),
        last("triangles flipped to agree"));
  if (d.nonmanifold_edges > 0 || d.nonmanifold_vertices > 0)
    out.emplace_back(n(d.nonmanifold_edges, "non-manifold edge", "non-manifold edges") + ", " +
                         n(d.nonmanifold_vertices, "non-manifold vertex", "non-manifold vertices"),
                     last("gone once the vertices are welded"));
  if (c.intersecting_pairs > 0)
    out.emplace_back(
        n(c.intersecting_pairs, "pair of crossing shells", "pairs of crossing shells"),
        last(r && r->kind == RepairKind::kUnion ? "united (corefinement)"
                                                : "gone once the vertices are welded"));
  if (c.triangle_pairs > 0)
    out.emplace_back(
        n(c.triangle_pairs, "crossing triangle pair", "crossing triangle pairs"),
        last(r && r->kind == RepairKind::kUnion ? "united (corefinement)"
                                                : "gone once the vertices are welded"));
  if (c.nested > 0)
    out.emplace_back(n(c.nested, "nested shell", "nested shells"),
                     !r ? "fit refuses the mesh (below)"
                        : (std::to_string(r->shells_dropped) + " dropped (same orientation), " +
                           std::to_string(r->cavities_filled) + " cavities filled, " +
                           std::to_string(r->cavities_kept) + " kept"));
  return out;
}

void printShells(const ShellCounts& c, const std::vector<std::array<int32_t, 2>>& first_pairs) {
  std::printf("  crossings   %s%lld intersecting triangle pairs", c.truncated ? "at least " : "",
              static_cast<long long>(c.triangle_pairs));
  for (size_t i = 0; i < first_pairs.size(); ++i)
    std::printf("%s%d/%d", i == 0 ? " (triangles " : ", ", first_pairs[i][0], first_pairs[i][1]);
  std::printf("%s\n", first_pairs.empty() ? "" : (c.triangle_pairs > 5 ? ", ...)" : ")"));
  std::printf(
      "  shells      %lld (%lld closed, %lld clean, %lld inward-facing, %lld nested in another, "
      "%lld intersecting pairs)\n",
      static_cast<long long>(c.shells), static_cast<long long>(c.closed),
      static_cast<long long>(c.clean), static_cast<long long>(c.inward),
      static_cast<long long>(c.nested), static_cast<long long>(c.intersecting_pairs));
}

void printCheck(const LoadedMesh& m, const MeshDiagnosis& d) {
  const LoadReport& r = m.report;
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::printf("%s (%s, %lld scene mesh%s)\n", r.path.c_str(), r.format.c_str(),
              static_cast<long long>(r.scene_meshes), r.scene_meshes == 1 ? "" : "es");
  std::printf("  loaded      %lld vertices, %lld triangles in the file\n",
              static_cast<long long>(r.file_vertices), static_cast<long long>(r.file_faces));
  std::printf(
      "  clean-up    %lld vertices welded, %lld unused removed, %lld degenerate and %lld "
      "duplicate triangles dropped%s\n",
      static_cast<long long>(r.welded_vertices), static_cast<long long>(r.unused_vertices),
      static_cast<long long>(r.degenerate_dropped), static_cast<long long>(r.duplicate_dropped),
      r.flipped ? ", orientation flipped outward" : "");
  std::printf("  mesh        %lld vertices, %lld triangles, %lld edges, %lld component%s\n",
              static_cast<long long>(d.vertices), static_cast<long long>(d.triangles),
              static_cast<long long>(d.edges), static_cast<long long>(d.components),
              d.components == 1 ? "" : "s");
  std::printf("  closed      %s (%lld boundary edges)\n", yes(d.closed),
              static_cast<long long>(d.boundary_edges));
  std::printf("  manifold    %s (%lld non-manifold edges, %lld non-manifold vertices)\n",
              yes(d.manifold), static_cast<long long>(d.nonmanifold_edges),
              static_cast<long long>(d.nonmanifold_vertices));
  std::printf("  oriented    %s (%lld inconsistent edges)\n", yes(d.oriented),
              static_cast<long long>(d.misoriented_edges));
  std::printf("  volume      %.9g\n  area        %.9g\n", d.volume, d.area);
  std::printf("  bbox        [%.6g %.6g %.6g] .. [%.6g %.6g %.6g], diagonal %.6g\n", d.bbox.min.x(),
              d.bbox.min.y(), d.bbox.min.z(), d.bbox.max.x(), d.bbox.max.y(), d.bbox.max.z(),
              d.bbox.diagonal());
  std::printf("  edges       %.6g .. %.6g\n", d.min_edge, d.max_edge);
  std::printf("  solid       %s\n",
              d.isSolid() ? "closed, oriented 2-manifold" : "no: not a closed oriented 2-manifold");
}

int runCheck(const CheckArgs& a) {
  // The diagnosis is of the mesh as fit sees it before repairing: exactly welded, or welded
  // with the tolerance given.
  auto ro = repairOptions(a.mesh);
  if (!ro) return fail(ro.error());
  auto m = loadMesh(a.mesh.path, loadOptions(*ro));
  if (!m) return fail(m.error());
  const MeshDiagnosis d = diagnoseMesh(m->mesh);
  const ShellAnalysis sa = analyzeShells(m->mesh);
  const ShellCounts sc = countShells(sa);
  // What fit would do with the same options.
  auto r = repairMesh(m->mesh, *ro, a.mesh.path);
  std::string plan;
  if (!r) {
    plan = "refuse it: " + r.error().message;
  } else if (r->kind == RepairKind::kNone && r->notes.empty()) {
    plan = "use it as it is";
  } else {
    plan = repairLine(*r);
  }
  const auto problems = problemActions(d, sc, r);
  if (a.json) {
    nlohmann::json j = checkJson(*m, d);
    j["self_intersections"] = shellsJson(sa);
    nlohmann::json pj = nlohmann::json::array();
    for (const auto& [problem, action] : problems)
      pj.push_back({{"problem", problem}, {"action", action}});
    j["problems"] = pj;
    if (r) j["repair"] = repairJson(*r);
    j["fit"] = plan;
    std::cout << jsonText(j) << '\n';
  } else {
    printCheck(*m, d);
    printShells(sc, firstPairs(sa));
    for (const auto& [problem, action] : problems)
      std::printf("  problem     %s: %s\n", problem.c_str(), action.c_str());
    std::printf("  fit will    %s\n", plan.c_str());
  }
  return r ? kOk : exitFor(r.error());
}

}  // namespace

Command registerCheck(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Load a mesh, diagnose it as a solid and say what fit will do about each problem (exit 0 "
      "when fit accepts it with the same options)");
  addMeshArgs(cmd, &a->mesh);
  cmd->add_flag("--json", a->json, "Print one JSON object");
  return {cmd, [a] { return runCheck(*a); }};
}

}  // namespace sphereset::cli

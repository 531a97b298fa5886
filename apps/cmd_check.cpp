// sphereset check: loads a mesh and diagnoses it as a solid.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/mesh.hpp"

namespace sphereset::cli {
namespace {

struct CheckArgs {
  MeshArgs mesh;
  bool json = false;
};

nlohmann::json checkJson(const LoadedMesh& m, const MeshDiagnosis& d) {
  const LoadReport& r = m.report;
  return {{"file", r.path},
          {"format", r.format},
          {"vertices", d.vertices},
          {"triangles", d.triangles},
          {"edges", d.edges},
          {"closed", d.closed},
          {"manifold", d.manifold},
          {"oriented", d.oriented},
          {"solid", d.isSolid()},
          {"components", d.components},
          {"boundary_edges", d.boundary_edges},
          {"nonmanifold_edges", d.nonmanifold_edges},
          {"nonmanifold_vertices", d.nonmanifold_vertices},
          {"misoriented_edges", d.misoriented_edges},
          {"volume", d.volume},
          {"area", d.area},
          {"bbox_min", vec(d.bbox.min)},
          {"bbox_max", vec(d.bbox.max)},
          {"bbox_diagonal", d.bbox.diagonal()},
          {"min_edge", d.min_edge},
          {"max_edge", d.max_edge},
          {"load",
           {{"scene_meshes", r.scene_meshes},
            {"file_vertices", r.file_vertices},
            {"file_triangles", r.file_faces},
            {"welded_vertices", r.welded_vertices},
            {"unused_vertices", r.unused_vertices},
            {"degenerate_dropped", r.degenerate_dropped},
            {"duplicate_dropped", r.duplicate_dropped},
            {"flipped", r.flipped}}}};
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
              d.isSolid() ? "yes: ready for fitting" : "no: fitting needs a closed manifold solid");
}

int runCheck(const CheckArgs& a) {
  LoadOptions lo;
  lo.weld_tolerance = a.mesh.weld;
  auto m = loadMesh(a.mesh.path, lo);
  if (!m) return fail(m.error());
  const MeshDiagnosis d = diagnoseMesh(m->mesh);
  const std::string hint = d.isSolid() ? std::string() : weldHint(a.mesh, d);
  if (a.json) {
    nlohmann::json j = checkJson(*m, d);
    if (!hint.empty()) j["hint"] = "closes with " + hint;
    std::cout << j.dump() << '\n';
  } else {
    printCheck(*m, d);
    if (!hint.empty()) std::printf("  hint        the mesh closes with %s\n", hint.c_str());
  }
  return d.isSolid() ? kOk : kNotSolid;
}

}  // namespace

Command registerCheck(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Load a mesh and diagnose it as a solid");
  addMeshArgs(cmd, &a->mesh);
  cmd->add_flag("--json", a->json, "Print one JSON object");
  return {cmd, [a] { return runCheck(*a); }};
}

}  // namespace sphereset::cli

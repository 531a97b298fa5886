// sphereset export: writes a sphere set (or a tree's leaves) as a triangle mesh.
#include <memory>
#include <string>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/export.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::cli {
namespace {

struct ExportArgs {
  std::string in, out;
  int subdivisions = 2;
};

int runExport(const ExportArgs& a) {
  if (Status st = checkOutputPath(a.out, {a.in}); !st) return fail(st.error());
  auto t = readSphereTree(a.in);
  if (!t) return fail(t.error());
  Status st = writeSphereSetMesh(a.out, t->leaves(), a.subdivisions);
  if (!st) return fail(st.error());
  return kOk;
}

}  // namespace

Command registerExport(CLI::App& app) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write a sphere set as a triangle mesh (.ply, .obj, .gltf, .glb), one colour "
      "per sphere");
  cmd->add_option("spheres", a->in, "Sphere set or tree (its leaves are written)")->required();
  cmd->add_option("-o,--output", a->out, "Mesh file: .ply, .obj, .gltf or .glb")->required();
  cmd->add_option("--subdivisions", a->subdivisions,
                  "Icosahedron subdivisions per sphere (20·4^s triangles, 0 to 6)")
      ->capture_default_str();
  return {cmd, [a] { return runExport(*a); }};
}

}  // namespace sphereset::cli

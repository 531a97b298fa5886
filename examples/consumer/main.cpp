// Fits N spheres to a mesh with an installed sphereset, as `sphereset fit MESH -n N --quality
// fast -o OUT` does, and writes them:  consumer MESH N OUT
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sphereset/fit.hpp>
#include <sphereset/repair.hpp>
#include <sphereset/solid_index.hpp>
#include <sphereset/sphere_io.hpp>
#include <string>
#ifdef SPHERESET_WITH_REPAIR
#include <sphereset/repair_cgal.hpp>
#endif

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: consumer MESH N OUT\n");
    return 2;
  }
  const std::string mesh = argv[1], out = argv[3];
  sphereset::RepairOptions repair;
#ifdef SPHERESET_WITH_REPAIR
  repair.operations = sphereset::cgalSolidOperations();
#endif
  auto solid = sphereset::loadSolid(mesh, repair);
  if (!solid) {
    std::fprintf(stderr, "consumer: %s\n", solid.error().message.c_str());
    return 3;
  }
  sphereset::FitRequest request;
  request.num_spheres = std::atoi(argv[2]);
  request.quality = sphereset::FitQuality::kFast;
  sphereset::FitOptions options = sphereset::fitOptionsFor(request);
  options.original = solid->original();
  const sphereset::SolidIndex index(solid->repair.solid);
  auto fit = sphereset::fitSpheres(index, options);
  if (!fit) {
    std::fprintf(stderr, "consumer: %s\n", fit.error().message.c_str());
    return 4;
  }
  sphereset::SphereFileMeta meta;
  meta.name = std::filesystem::path(mesh).stem().string();
  meta.source_mesh = mesh;
  if (auto st = sphereset::writeSpheres(out, fit->spheres, meta); !st) {
    std::fprintf(stderr, "consumer: %s\n", st.error().message.c_str());
    return 6;
  }
  std::printf("%zu spheres, outside volume %.6g -> %s\n", fit->spheres.size(), fit->energy,
              out.c_str());
  return 0;
}

// Fits N spheres to a closed triangle mesh in an OFF file with an installed sphereset, using
// only its core (sphereset::core: Eigen, TBB and NLopt; no file formats, no assimp), as
// `sphereset fit MESH -n N --quality fast` does, and writes them as "x y z r" lines:
//   consumer MESH.off N OUT
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sphereset/fit.hpp>
#include <sphereset/mesh.hpp>
#include <sphereset/solid_index.hpp>
#include <string>
#include <vector>

namespace {

// A triangle-only OFF file: "OFF", the counts, the vertices, then "3 a b c" per face.
bool readOff(const std::string& path, std::vector<sphereset::Vec3>* vertices,
             std::vector<sphereset::Triangle>* triangles) {
  std::ifstream in(path);
  std::string magic;
  long nv = 0, nf = 0, ne = 0;
  if (!(in >> magic >> nv >> nf >> ne) || magic != "OFF" || nv < 3 || nf < 1) return false;
  vertices->resize(nv);
  for (auto& v : *vertices)
    if (!(in >> v.x() >> v.y() >> v.z())) return false;
  triangles->resize(nf);
  for (auto& t : *triangles) {
    int corners = 0;
    if (!(in >> corners >> t[0] >> t[1] >> t[2]) || corners != 3) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: consumer MESH.off N OUT\n");
    return 2;
  }
  const std::string path = argv[1], out = argv[3];
  std::vector<sphereset::Vec3> vertices;
  std::vector<sphereset::Triangle> triangles;
  if (!readOff(path, &vertices, &triangles)) {
    std::fprintf(stderr, "consumer: %s: not a triangle OFF file\n", path.c_str());
    return 3;
  }
  auto mesh = sphereset::cleanMesh(std::move(vertices), std::move(triangles), {}, path);
  if (!mesh) {
    std::fprintf(stderr, "consumer: %s\n", mesh.error().message.c_str());
    return 4;
  }
  const sphereset::MeshDiagnosis d = sphereset::diagnoseMesh(mesh->mesh);
  if (!d.isSolid()) {
    std::fprintf(stderr, "consumer: %s\n", sphereset::notSolidError(path, d).message.c_str());
    return 4;
  }
  sphereset::FitRequest request;
  request.num_spheres = std::atoi(argv[2]);
  request.quality = sphereset::FitQuality::kFast;
  const sphereset::SolidIndex index(mesh->mesh);
  auto fit = sphereset::fitSpheres(index, sphereset::fitOptionsFor(request));
  if (!fit) {
    std::fprintf(stderr, "consumer: %s\n", fit.error().message.c_str());
    return 4;
  }
  std::FILE* f = std::fopen(out.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "consumer: %s: cannot be written\n", out.c_str());
    return 6;
  }
  for (const sphereset::Sphere& s : fit->spheres)
    std::fprintf(f, "%.17g %.17g %.17g %.17g\n", s.center.x(), s.center.y(), s.center.z(),
                 s.radius);
  std::fclose(f);
  std::printf("%zu spheres, outside volume %.6g -> %s\n", fit->spheres.size(), fit->energy,
              out.c_str());
  return 0;
}

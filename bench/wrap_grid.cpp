// The wrap's cost and tightness against its parameters, for choosing the automatic ones
// (src/repair/repair.cpp): for each alpha = diagonal / a (a from the list) and offset =
// alpha / 20, CGAL's 3D Alpha Wrapping of the mesh as loaded; prints one CSV line per alpha:
// mesh, input triangles, a, seconds, output triangles, output volume, and its ratio to a
// reference volume when given (e.g. from bench/winding_volume).
//   wrap_grid MESH [REFERENCE_VOLUME|-] [a ...]   (default a: 50 100 200)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "repair_cgal/cgal_ops.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"

int main(int argc, char** argv) {
  using namespace sphereset;
  if (argc < 2) {
    std::fprintf(stderr, "usage: wrap_grid MESH [REFERENCE_VOLUME|-] [a ...]\n");
    return 2;
  }
  auto m = loadMesh(argv[1]);
  if (!m) {
    std::fprintf(stderr, "%s\n", m.error().message.c_str());
    return 3;
  }
  const double ref = argc > 2 && std::string(argv[2]) != "-" ? std::atof(argv[2]) : 0.0;
  std::vector<double> as;
  for (int i = 3; i < argc; ++i) as.push_back(std::atof(argv[i]));
  if (as.empty()) as = {50, 100, 200};
  const double d = boundingBox(m->mesh).diagonal();
  for (double a : as) {
    const double alpha = d / a;
    const auto t0 = std::chrono::steady_clock::now();
    auto w = detail::alphaWrap(m->mesh, alpha, alpha / 20.0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!w) {
      std::fprintf(stderr, "%s\n", w.error().message.c_str());
      return 4;
    }
    const double v = signedVolume(*w);
    std::printf("%s,%zu,%g,%.2f,%zu,%.9g,%s\n", argv[1], m->mesh.triangles.size(), a, s,
                w->triangles.size(), v, ref > 0 ? std::to_string(v / ref).c_str() : "");
  }
  return 0;
}

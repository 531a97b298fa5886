// An independent check of the guarantee on a mesh's original triangles, for the benchmark
// tables: loads the mesh as the fit does (exact welding only, no repair), reads a sphere set,
// and tests `per_triangle` seeded random points on every triangle (and its corners) against
// every sphere by brute force. Prints one JSON line: points tested, points outside every
// sphere, the largest gap relative to the bounding box diagonal.
//   cover_check MESH SPHERES [per_triangle=10] [LINK]   (LINK: one link of a robot's YAML)
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/sphere_io.hpp"

int main(int argc, char** argv) {
  using namespace sphereset;
  if (argc < 3) {
    std::fprintf(stderr, "usage: cover_check MESH SPHERES [per_triangle]\n");
    return 2;
  }
  const int per = argc > 3 ? std::atoi(argv[3]) : 10;
  auto m = loadMesh(argv[1]);
  if (!m) {
    std::fprintf(stderr, "%s\n", m.error().message.c_str());
    return 3;
  }
  std::vector<Sphere> spheres;
  if (argc > 4) {
    auto links = readLinkSpheres(argv[2]);
    if (!links) {
      std::fprintf(stderr, "%s\n", links.error().message.c_str());
      return 3;
    }
    for (const LinkSpheres& l : *links)
      if (l.link == argv[4]) spheres = l.spheres;
  } else {
    auto sp = readSpheres(argv[2]);
    if (!sp) {
      std::fprintf(stderr, "%s\n", sp.error().message.c_str());
      return 3;
    }
    spheres = *sp;
  }
  const Mesh& mesh = m->mesh;
  const double diag = boundingBox(mesh).diagonal();
  const double tol = 1e-12 * diag;  // the coverage tolerance of the library's certificates
  const int64_t nt = static_cast<int64_t>(mesh.triangles.size());
  std::atomic<int64_t> missed{0};
  std::vector<double> worst(nt, 0.0);
  tbb::parallel_for(int64_t{0}, nt, [&](int64_t t) {
    std::mt19937_64 rng(static_cast<uint64_t>(t) * 0x9E3779B97F4A7C15ull + 1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    for (int k = -3; k < per; ++k) {
      double x = k == -2 ? 1.0 : 0.0, y = k == -1 ? 1.0 : 0.0;
      if (k >= 0) {
        x = u(rng);
        y = u(rng);
        if (x + y > 1.0) {
          x = 1.0 - x;
          y = 1.0 - y;
        }
      }
      const Vec3 p = a + x * (b - a) + y * (c - a);
      double gap = 1e300;
      for (const Sphere& s : spheres) gap = std::min(gap, (p - s.center).norm() - s.radius);
      if (gap > tol) {
        ++missed;
        worst[t] = std::max(worst[t], gap);
      }
    }
  });
  const double w = *std::max_element(worst.begin(), worst.end());
  std::printf("{\"points\": %lld, \"missed\": %lld, \"max_gap\": %.3g}\n",
              static_cast<long long>(nt * (per + 3)), static_cast<long long>(missed.load()),
              w / diag);
  return missed.load() == 0 ? 0 : 1;
}

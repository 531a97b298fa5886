// The volume a mesh encloses where its own volume is undefined (open, non-manifold,
// inconsistently oriented or self-intersecting), for the repair table's wrap volume ratio:
// the measure of the points whose generalised winding number (Jacobson, Kavan, Sorkine-Hornung
// 2013, "Robust inside-outside segmentation using generalized winding numbers") has magnitude
// at least 1/2, by seeded Monte Carlo over the bounding box. Brute-force winding numbers, so
// meant for meshes up to some 10^4 triangles. Prints one JSON line with the estimate and its
// standard error.
//   winding_volume MESH [samples=100000]
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "index/oracles.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/solid_index.hpp"

int main(int argc, char** argv) {
  using namespace sphereset;
  if (argc < 2) {
    std::fprintf(stderr, "usage: winding_volume MESH [samples]\n");
    return 2;
  }
  const int64_t samples = argc > 2 ? std::atoll(argv[2]) : 100000;
  auto m = loadMesh(argv[1]);
  if (!m) {
    std::fprintf(stderr, "%s\n", m.error().message.c_str());
    return 3;
  }
  const SolidIndex index(m->mesh);
  const Aabb box = boundingBox(m->mesh);
  const Vec3 ext = box.max - box.min;
  std::vector<char> inside(samples, 0);
  tbb::parallel_for(int64_t{0}, samples, [&](int64_t i) {
    std::mt19937_64 rng(static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ull + 7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Vec3 p = box.min + Vec3(u(rng) * ext.x(), u(rng) * ext.y(), u(rng) * ext.z());
    inside[i] = std::abs(windingNumber(index, p)) >= 0.5;
  });
  int64_t hits = 0;
  for (char c : inside) hits += c;
  const double f = static_cast<double>(hits) / static_cast<double>(samples);
  const double vbox = ext.x() * ext.y() * ext.z();
  std::printf("{\"volume\": %.9g, \"stderr\": %.3g}\n", f * vbox,
              vbox * std::sqrt(f * (1 - f) / static_cast<double>(samples)));
  return 0;
}

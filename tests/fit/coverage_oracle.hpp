// Test oracles of the fit's coverage: the energy summed sphere by sphere, and surface points
// tested against every sphere (independent of the sphere grid and of the bound's split).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset::test {

inline double totalSov(const SolidIndex& idx, const std::vector<Sphere>& sp) {
  double e = 0.0;
  for (const Sphere& s : sp) e += idx.outsideVolume(s).volume;
  return e;
}

// Every vertex and `per_triangle` uniform random points of every triangle, each tested against
// every sphere; returns how many lie in none.
inline int64_t uncoveredSurfacePoints(const Mesh& m, const std::vector<Sphere>& sp,
                                      int per_triangle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto covered = [&](const Vec3& p) {
    for (const Sphere& s : sp)
      if ((p - s.center).norm() <= s.radius * (1.0 + 1e-12)) return true;
    return false;
  };
  int64_t missed = 0;
  for (const Vec3& v : m.vertices) missed += covered(v) ? 0 : 1;
  for (const Triangle& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    for (int k = 0; k < per_triangle; ++k) {
      double s = u(rng), w = u(rng);
      if (s + w > 1.0) s = 1.0 - s, w = 1.0 - w;
      missed += covered(a + s * (b - a) + w * (c - a)) ? 0 : 1;
    }
  }
  return missed;
}

}  // namespace sphereset::test

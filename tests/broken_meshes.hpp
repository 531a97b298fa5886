// The broken meshes of the repair tests, built in code, and an independent coverage check:
// random points on every triangle, each tested against every sphere.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "test_meshes.hpp"

namespace sphereset::test {

// The unit box [0,1]^3 without its top face (z = 1): 10 triangles, 4 boundary edges.
inline Mesh openBox() {
  Mesh m = makeBox(Vec3::Zero(), Vec3::Ones());
  m.triangles.erase(m.triangles.begin() + 2, m.triangles.begin() + 4);  // face {4,5,7,6}
  return m;
}

// The unit box with one triangle's orientation reversed (closed, not oriented).
inline Mesh boxWithFlippedFace() {
  Mesh m = makeBox(Vec3::Zero(), Vec3::Ones());
  std::swap(m.triangles[5][1], m.triangles[5][2]);
  return m;
}

// Two unit cubes, the second moved by (0.5, 0.25, 0.25): they overlap in a box of
// 0.5 x 0.75 x 0.75, so the union has volume 2 - 0.28125 = 1.71875.
inline Mesh overlappingCubes() {
  return joined(makeBox(Vec3::Zero(), Vec3::Ones()),
                makeBox(Vec3(0.5, 0.25, 0.25), Vec3(1.5, 1.25, 1.25)));
}

// A cube of side 0.5 nested in the unit cube (outward, or inward as a cavity).
inline Mesh nestedCubes(bool inner_inward) {
  Mesh inner = makeBox(Vec3::Constant(0.25), Vec3::Constant(0.75));
  if (inner_inward)
    for (Triangle& t : inner.triangles) std::swap(t[1], t[2]);
  return joined(makeBox(Vec3::Zero(), Vec3::Ones()), inner);
}

// A prism over a self-crossing quadrilateral (a bow tie in the xy plane, height 1): closed,
// 2-manifold and oriented as a surface, but its side faces cross each other. The region it
// winds around is two triangular prisms of area 1/4 each, wound +1 and -1.
inline Mesh bowTiePrism() {
  Mesh m;
  const double xy[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  for (double z : {0.0, 1.0})
    for (const auto& p : xy) m.vertices.emplace_back(p[0], p[1], z);
  m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}};  // bottom, top (fans)
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    m.triangles.push_back({i, j, j + 4});
    m.triangles.push_back({i, j + 4, i + 4});
  }
  return m;
}

// Two unit cubes sharing one edge (x = y = 1), vertices welded: a closed mesh with a
// non-manifold edge (four triangles) and two non-manifold vertices.
inline Mesh cubesSharingAnEdge() {
  const Mesh m = joined(makeBox(Vec3::Zero(), Vec3::Ones()), makeBox(Vec3(1, 1, 0), Vec3(2, 2, 1)));
  auto w = cleanMesh(m.vertices, m.triangles);
  return w.ok() ? w->mesh : Mesh{};
}

// A single open square sheet, [0,1]^2 at z = 0, as 2 triangles.
inline Mesh openSheet() {
  Mesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// The unit cube with its first face stored twice (the loader drops the copy).
inline Mesh cubeWithDuplicatedFace() {
  Mesh m = makeBox(Vec3::Zero(), Vec3::Ones());
  m.triangles.push_back(m.triangles[0]);
  return m;
}

// Independent of the library's certificates: `per_triangle` random points on each triangle
// (and its corners) each lie in some sphere, within `tol`. Brute force over all spheres.
inline void expectPointsCovered(const Mesh& mesh, const std::vector<Sphere>& spheres,
                                int per_triangle = 200, double tol = 1e-9) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int64_t missed = 0;
  double worst = 0.0;
  auto check = [&](const Vec3& p) {
    double gap = std::numeric_limits<double>::infinity();
    for (const Sphere& s : spheres) gap = std::min(gap, (p - s.center).norm() - s.radius);
    if (gap > tol) {
      ++missed;
      worst = std::max(worst, gap);
    }
  };
  for (const Triangle& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    check(a);
    check(b);
    check(c);
    for (int k = 0; k < per_triangle; ++k) {
      double x = u(rng), y = u(rng);
      if (x + y > 1.0) {
        x = 1.0 - x;
        y = 1.0 - y;
      }
      check(a + x * (b - a) + y * (c - a));
    }
  }
  EXPECT_EQ(missed, 0) << "largest gap " << worst;
}

}  // namespace sphereset::test

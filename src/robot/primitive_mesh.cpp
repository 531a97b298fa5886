// Robot primitives as triangle meshes that contain them (primitive_mesh.hpp). Outward,
// counter-clockwise seen from outside. Reference for the containment: a convex polyhedron
// holds the ball of radius r about a point when every face plane is at least r from it; affine
// maps and Minkowski sums with a segment keep containment (tests/robot/test_primitive_mesh.cpp
// checks each shape by points on its surface and the polyhedra's convexity).
#include "robot/primitive_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace sphereset::detail {
namespace {

// A ring of a round shape: its height and radius, before the circumscribing scale.
struct Ring {
  double z, rho;
};

// The shape of rings `rings` (south to north, `segments` vertices each) closed by two poles at
// `south` and `north`; ring vertices at angles 2πi / segments.
Mesh ringMesh(const std::vector<Ring>& rings, double south, double north, int segments) {
  Mesh m;
  m.vertices.emplace_back(0.0, 0.0, south);
  for (const Ring& r : rings) {
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * std::numbers::pi * i / segments;
      m.vertices.emplace_back(r.rho * std::cos(a), r.rho * std::sin(a), r.z);
    }
  }
  const auto top = static_cast<int32_t>(m.vertices.size());
  m.vertices.emplace_back(0.0, 0.0, north);
  const int n = static_cast<int>(rings.size());
  auto at = [&](int ring, int i) {
    return static_cast<int32_t>(1 + ring * segments + (i % segments));
  };
  for (int i = 0; i < segments; ++i) {
    m.triangles.push_back({0, at(0, i + 1), at(0, i)});
    m.triangles.push_back({top, at(n - 1, i), at(n - 1, i + 1)});
    for (int r = 0; r + 1 < n; ++r) {
      m.triangles.push_back({at(r, i), at(r, i + 1), at(r + 1, i + 1)});
      m.triangles.push_back({at(r, i), at(r + 1, i + 1), at(r + 1, i)});
    }
  }
  return m;
}

// The unit sphere's rings through points of the sphere: an even count (one ring is the
// equator, z = 0 exactly), at least segments / 2 bands.
std::vector<Ring> unitRings(int segments) {
  int bands = std::max(2, segments / 2);
  bands += bands % 2;
  std::vector<Ring> rings;
  for (int r = 1; r < bands; ++r) {
    const double polar = std::numbers::pi * r / bands;  // from the south pole
    rings.push_back({2 * r == bands ? 0.0 : -std::cos(polar), std::sin(polar)});
  }
  return rings;
}

// The scale that moves every face plane of the unit polyhedron to distance 1 or more from the
// centre: 1 / the least distance, rounded up by a few ulps so that rounding cannot leave a
// plane short of 1.
double circumscribingScale(const Mesh& unit) {
  double least = std::numeric_limits<double>::infinity();
  for (const Triangle& t : unit.triangles) {
    const Vec3& a = unit.vertices[t[0]];
    const Vec3 n = (unit.vertices[t[1]] - a).cross(unit.vertices[t[2]] - a).normalized();
    least = std::min(least, std::fabs(n.dot(a)));
  }
  constexpr double kRoundUp = 1.0 + 8.0 * std::numeric_limits<double>::epsilon();
  return kRoundUp / least;
}

}  // namespace

Mesh boxMesh(const Vec3& size) {
  Mesh m;
  const Vec3 h = 0.5 * size;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                            (i & 4) ? h.z() : -h.z());
  }
  // Two triangles per face, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3},   // z = -h
                 {4, 5, 6}, {5, 7, 6},   // z = +h
                 {0, 1, 4}, {1, 5, 4},   // y = -h
                 {2, 6, 3}, {3, 6, 7},   // y = +h
                 {0, 4, 2}, {2, 4, 6},   // x = -h
                 {1, 3, 5}, {3, 7, 5}};  // x = +h
  return m;
}

Mesh cylinderMesh(double radius, double length, int segments) {
  // The circumscribed polygon: its vertices at radius / cos(π / segments).
  const double rho = radius / std::cos(std::numbers::pi / segments);
  const double h = 0.5 * length;
  Mesh m = ringMesh({{-h, rho}, {h, rho}}, -h, h, segments);
  return m;
}

Mesh sphereMesh(double radius, int segments) {
  Mesh m = ringMesh(unitRings(segments), -1.0, 1.0, segments);
  const double s = radius * circumscribingScale(m);
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

Mesh capsuleMesh(double radius, double length, int segments) {
  const std::vector<Ring> unit = unitRings(segments);
  const double s = radius * circumscribingScale(ringMesh(unit, -1.0, 1.0, segments));
  const double h = 0.5 * length;
  std::vector<Ring> rings;
  for (const Ring& r : unit) {
    if (r.z <= 0.0) rings.push_back({s * r.z - h, s * r.rho});  // the equator too, at -h
    if (r.z >= 0.0) rings.push_back({s * r.z + h, s * r.rho});  // and again at +h
  }
  return ringMesh(rings, -s - h, s + h, segments);
}

Mesh ellipsoidMesh(const Vec3& radii, int segments) {
  Mesh m = sphereMesh(1.0, segments);
  for (Vec3& v : m.vertices) v = v.cwiseProduct(radii);
  return m;
}

}  // namespace sphereset::detail

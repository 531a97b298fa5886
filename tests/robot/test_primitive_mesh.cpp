// The round primitives' meshes contain their primitives (primitive_mesh.hpp): each polyhedron is
// convex, and points drawn on the primitive's surface lie on the inner side of every face plane,
// so whatever covers the polyhedron covers the primitive. Closed forms where there is one.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "robot/primitive_mesh.hpp"
#include "sphereset/mesh.hpp"

namespace sphereset {
namespace {

// Rounding allowance of the plane tests (length units, shapes of size about 1).
constexpr double kPlaneTol = 1e-12;
constexpr int kSurfacePoints = 4000;

struct Plane {
  Vec3 n;
  double d;  // n · x <= d inside
};

std::vector<Plane> facePlanes(const Mesh& m) {
  std::vector<Plane> out;
  for (const Triangle& t : m.triangles) {
    const Vec3& a = m.vertices[t[0]];
    const Vec3 n = (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a);
    if (n.norm() == 0.0) continue;
    out.push_back({n.normalized(), n.normalized().dot(a)});
  }
  return out;
}

// Convex and outward: every vertex on the inner side of every face plane.
void expectConvex(const Mesh& m) {
  for (const Plane& p : facePlanes(m))
    for (const Vec3& v : m.vertices) ASSERT_LE(p.n.dot(v), p.d + kPlaneTol);
}

// Points of the primitive's surface inside the polyhedron.
void expectHolds(const Mesh& m, const std::function<Vec3(std::mt19937_64&)>& surface) {
  const std::vector<Plane> planes = facePlanes(m);
  std::mt19937_64 rng(7);
  for (int i = 0; i < kSurfacePoints; ++i) {
    const Vec3 x = surface(rng);
    for (const Plane& p : planes) ASSERT_LE(p.n.dot(x), p.d + kPlaneTol) << x.transpose();
  }
}

Vec3 unitVector(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

TEST(PrimitiveMesh, SphereMeshHoldsTheBallWithEveryFacePlaneOutsideIt) {
  for (int segments : {3, 8, 24, 48}) {
    const double r = 0.7;
    const Mesh m = detail::sphereMesh(r, segments);
    EXPECT_TRUE(diagnoseMesh(m).isSolid()) << segments;
    expectConvex(m);
    for (const Plane& p : facePlanes(m)) EXPECT_GE(p.d, r) << segments;
    expectHolds(m, [&](std::mt19937_64& rng) -> Vec3 { return r * unitVector(rng); });
    if (segments == 48) {
      EXPECT_LT(diagnoseMesh(m).volume, 1.01 * 4.0 / 3.0 * std::numbers::pi * r * r * r);
    }
  }
}

TEST(PrimitiveMesh, CylinderMeshHoldsTheCylinder) {
  for (int segments : {3, 7, 48}) {
    const double r = 0.3, length = 1.1;
    const Mesh m = detail::cylinderMesh(r, length, segments);
    EXPECT_TRUE(diagnoseMesh(m).isSolid());
    expectConvex(m);
    expectHolds(m, [&](std::mt19937_64& rng) -> Vec3 {
      const double a = uniform(rng, 0.0, 2.0 * std::numbers::pi);
      if (uniform(rng, 0.0, 1.0) < 0.5)  // the side
        return Vec3(r * std::cos(a), r * std::sin(a), uniform(rng, -0.5, 0.5) * length);
      const double rho = r * std::sqrt(uniform(rng, 0.0, 1.0));  // a cap
      return Vec3(rho * std::cos(a), rho * std::sin(a),
                  (uniform(rng, 0, 1) < 0.5 ? -0.5 : 0.5) * length);
    });
    // The circumscribed polygon's prism: segments · r² · tan(π / segments) · length.
    EXPECT_NEAR(diagnoseMesh(m).volume,
                segments * r * r * std::tan(std::numbers::pi / segments) * length, 1e-12);
  }
}

TEST(PrimitiveMesh, CapsuleMeshHoldsTheCapsule) {
  for (int segments : {4, 12, 48}) {
    const double r = 0.2, length = 0.9;
    const Mesh m = detail::capsuleMesh(r, length, segments);
    EXPECT_TRUE(diagnoseMesh(m).isSolid()) << segments;
    expectConvex(m);
    expectHolds(m, [&](std::mt19937_64& rng) -> Vec3 {
      const Vec3 u = unitVector(rng);
      if (uniform(rng, 0.0, 1.0) < 0.5)  // the side
        return Vec3(r * u.x() / std::hypot(u.x(), u.y()), r * u.y() / std::hypot(u.x(), u.y()),
                    uniform(rng, -0.5, 0.5) * length);
      return Vec3(r * u + Vec3(0.0, 0.0, (u.z() < 0.0 ? -0.5 : 0.5) * length));  // a cap
    });
    const double exact = std::numbers::pi * r * r * (length + 4.0 / 3.0 * r);
    EXPECT_GT(diagnoseMesh(m).volume, exact);
    if (segments == 48) {
      EXPECT_LT(diagnoseMesh(m).volume, 1.01 * exact);
    }
  }
}

TEST(PrimitiveMesh, EllipsoidMeshHoldsTheEllipsoid) {
  const Vec3 radii(0.4, 0.1, 0.25);
  for (int segments : {6, 48}) {
    const Mesh m = detail::ellipsoidMesh(radii, segments);
    EXPECT_TRUE(diagnoseMesh(m).isSolid());
    expectConvex(m);
    expectHolds(
        m, [&](std::mt19937_64& rng) -> Vec3 { return Vec3(unitVector(rng).cwiseProduct(radii)); });
  }
}

TEST(PrimitiveMesh, BoxMeshIsTheBox) {
  const Mesh m = detail::boxMesh(Vec3(0.2, 0.3, 0.4));
  EXPECT_TRUE(diagnoseMesh(m).isSolid());
  expectConvex(m);
  EXPECT_NEAR(diagnoseMesh(m).volume, 0.2 * 0.3 * 0.4, 1e-15);
}

}  // namespace
}  // namespace sphereset

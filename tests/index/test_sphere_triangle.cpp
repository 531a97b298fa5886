// The per-triangle closed form against closed forms and a brute-force quadrature of the
// region t ∩ D, for every case of the paper's Fig. 3 and the tangencies between them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "index/oracles.hpp"
#include "sphereset/solid_index.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::kPi;

struct Quadrature {
  double area = 0.0, omega = 0.0;
};

// Midpoint rule on an N×N grid over the disk's bounding square, in the triangle's plane.
Quadrature quadrature(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o, double r,
                      int N = 2000) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  const double h = n.dot(a - o);
  Quadrature q;
  if (std::abs(h) >= r) return q;
  const double rho = std::sqrt(r * r - h * h);
  const Vec3 c0 = o + h * n;
  const Vec3 u = (b - a).normalized(), v = n.cross(u);
  const double cell = 2 * rho / N;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const double x = -rho + (i + 0.5) * cell, y = -rho + (j + 0.5) * cell;
      if (x * x + y * y > rho * rho) continue;
      const Vec3 p = c0 + x * u + y * v;
      const double w0 = n.dot((b - a).cross(p - a)), w1 = n.dot((c - b).cross(p - b)),
                   w2 = n.dot((a - c).cross(p - c));
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      q.area += cell * cell;
      q.omega += cell * cell * std::abs(h) / std::pow(h * h + x * x + y * y, 1.5);
    }
  return q;
}

TriangleBallTerms terms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o, double r) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  return triangleBallTerms(a, b, c, n, o, r);
}

void expectMatchesQuadrature(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o, double r) {
  const TriangleBallTerms t = terms(a, b, c, o, r);
  const Quadrature q = quadrature(a, b, c, o, r);
  const double scale_a = kPi * r * r, scale_o = 2 * kPi;
  EXPECT_NEAR(t.area, q.area, 2e-3 * scale_a) << "area";
  EXPECT_NEAR(t.solid_angle, q.omega, 2e-3 * scale_o) << "solid angle";
}

const Vec3 O = Vec3::Zero();

TEST(SphereTriangle, CaseA_AllVerticesInside) {
  const Vec3 a(-0.3, -0.2, 0.4), b(0.4, -0.1, 0.35), c(0.0, 0.5, 0.5);
  const TriangleBallTerms t = terms(a, b, c, O, 1.0);
  EXPECT_NEAR(t.area, 0.5 * (b - a).cross(c - a).norm(), 1e-15);
  EXPECT_NEAR(t.solid_angle, std::abs(triangleSolidAngle(a, b, c, O)), 1e-15);
  expectMatchesQuadrature(a, b, c, O, 1.0);
}

TEST(SphereTriangle, CaseB_DiskInsideTriangleIsASphericalCap) {
  const double r = 1.3, h = 0.45;
  const Vec3 a(-10, -10, h), b(10, -10, h), c(0, 15, h);
  const TriangleBallTerms t = terms(a, b, c, O, r);
  const double rho2 = r * r - h * h;
  EXPECT_NEAR(t.area, kPi * rho2, 1e-12);
  EXPECT_NEAR(t.solid_angle, 2 * kPi * (1 - h / r), 1e-12);
  // SOTV = (r³Ω - |h|A)/3 equals the cap volume π k² (r - k/3), k = r - h.
  const double sotv = (r * r * r * t.solid_angle - h * t.area) / 3;
  const double k = r - h;
  EXPECT_NEAR(sotv, kPi * k * k * (r - k / 3), 1e-12);
}

TEST(SphereTriangle, CaseC_OneVertexInside) {
  expectMatchesQuadrature(Vec3(0.2, 0.1, 0.3), Vec3(2.0, 0.5, 0.3), Vec3(0.4, 2.5, 0.3), O, 1.0);
}

TEST(SphereTriangle, CaseD_TwoVerticesInside) {
  expectMatchesQuadrature(Vec3(-0.4, -0.3, -0.2), Vec3(0.5, -0.2, -0.2), Vec3(0.1, 3.0, -0.2), O,
                          1.0);
}

TEST(SphereTriangle, EdgeCutsDiskWithNoVertexInside) {
  expectMatchesQuadrature(Vec3(-3, 0.5, 0.2), Vec3(3, 0.5, 0.2), Vec3(0, 5, 0.2), O, 1.0);
  // And the complement: disk mostly inside, one chord cut off.
  expectMatchesQuadrature(Vec3(-5, -0.5, 0.2), Vec3(5, -0.5, 0.2), Vec3(0, 8, 0.2), O, 1.0);
}

TEST(SphereTriangle, ThreeChordsAroundTheCentre) {
  // Triangle's edges all cut the disk; the foot of o lies inside the triangle.
  expectMatchesQuadrature(Vec3(-1.2, -0.6, 0.1), Vec3(1.2, -0.6, 0.1), Vec3(0, 1.1, 0.1), O, 1.0);
}

TEST(SphereTriangle, FootOutsideTriangle) {
  expectMatchesQuadrature(Vec3(0.3, 0.2, -0.4), Vec3(1.5, 0.2, -0.4), Vec3(0.3, 1.4, -0.4), O, 1.0);
}

TEST(SphereTriangle, TangentEdgeIsContinuous) {
  // Edge on the line y = ρ: tangent to the disk. Moving it by ±ε changes the terms by O(ε^1.5).
  const double h = 0.3, r = 1.0, rho = std::sqrt(r * r - h * h);
  for (double eps : {0.0, 1e-12, -1e-12, 1e-9, -1e-9}) {
    const Vec3 a(-4, rho + eps, h), b(4, rho + eps, h), c(0, -6, h);
    const TriangleBallTerms t = terms(c, a, b, O, r);  // edge (a, b) tangent; disk inside
    EXPECT_NEAR(t.area, kPi * rho * rho, 1e-6) << eps;
    EXPECT_NEAR(t.solid_angle, 2 * kPi * (1 - h / r), 1e-6) << eps;
  }
  // Tangent from the other side: the triangle touches the disk at one point only.
  for (double eps : {0.0, 1e-12, -1e-12}) {
    const Vec3 a(-4, rho + eps, h), b(4, rho + eps, h), c(0, 6, h);
    const TriangleBallTerms t = terms(a, b, c, O, r);
    EXPECT_NEAR(t.area, 0.0, 1e-9) << eps;
    EXPECT_NEAR(t.solid_angle, 0.0, 1e-9) << eps;
  }
}

TEST(SphereTriangle, VertexExactlyOnSphere) {
  // Vertex a on the sphere; compare with the vertex nudged in and out.
  const double r = 1.0;
  const Vec3 a = Vec3(0.6, 0.0, 0.8), b(0.0, 0.3, 0.2), c(0.2, -0.4, 0.1);
  const TriangleBallTerms on = terms(a, b, c, O, r);
  for (double s : {1 - 1e-12, 1 + 1e-12}) {
    const TriangleBallTerms t = terms(a * s, b, c, O, r);
    EXPECT_NEAR(t.area, on.area, 1e-9);
    EXPECT_NEAR(t.solid_angle, on.solid_angle, 1e-9);
  }
  expectMatchesQuadrature(a, b, c, O, r);
}

TEST(SphereTriangle, VertexJustOutsideWithShortArc) {
  // A vertex slightly outside the sphere: a tiny arc between two nearby edge exits. Its
  // angle must be ≈0, not ≈2π.
  const double r = 1.0, h = 0.2, rho = std::sqrt(r * r - h * h);
  const Vec3 a(0.0, rho + 1e-9, h), b(-0.5, -0.3, h), c(0.5, -0.3, h);
  const TriangleBallTerms t = terms(b, c, a, O, r);
  const TriangleBallTerms inside = terms(b, c, Vec3(0.0, rho - 1e-9, h), O, r);
  EXPECT_NEAR(t.area, inside.area, 1e-7);
  EXPECT_NEAR(t.solid_angle, inside.solid_angle, 1e-7);
}

TEST(SphereTriangle, PlaneTangentToSphereGivesZero) {
  const Vec3 a(-1, -1, 1.0), b(1, -1, 1.0), c(0, 1, 1.0);
  const TriangleBallTerms t = terms(a, b, c, O, 1.0);
  EXPECT_EQ(t.area, 0.0);
  EXPECT_EQ(t.solid_angle, 0.0);
  const TriangleBallTerms t2 = terms(a, b, c, O, 1.0 + 1e-12);
  EXPECT_NEAR(t2.area, 0.0, 1e-10);
  EXPECT_NEAR(t2.solid_angle, 0.0, 1e-10);
}

TEST(SphereTriangle, CentreInPlaneOutsideTriangle) {
  // h = 0, foot outside t: the solid angle vanishes and the centre is not on the triangle.
  const TriangleBallTerms t = terms(Vec3(0.2, 0.1, 0), Vec3(2, 0.1, 0), Vec3(0.2, 2, 0), O, 1.0);
  EXPECT_FALSE(t.center_on_triangle);
  EXPECT_EQ(t.solid_angle, 0.0);
  EXPECT_GT(t.area, 0.0);
  // Near the plane from either side the solid angle tends to 0 as well.
  const TriangleBallTerms up =
      terms(Vec3(0.2, 0.1, 1e-9), Vec3(2, 0.1, 1e-9), Vec3(0.2, 2, 1e-9), O, 1.0);
  EXPECT_NEAR(up.solid_angle, 0.0, 1e-6);
}

TEST(SphereTriangle, CentreOnTriangleIsFlagged) {
  const TriangleBallTerms t = terms(Vec3(-1, -1, 0), Vec3(2, -1, 0), Vec3(-1, 2, 0), O, 0.5);
  EXPECT_TRUE(t.center_on_triangle);
}

TEST(SphereTriangle, NeedleAndSliverTriangles) {
  // Needle: 6 long, at most 1e-3 wide, crossing the unit ball in the plane z = 0.3. Area and
  // solid angle of t ∩ B by a fine midpoint rule along its length: across the needle the
  // integrands are constant to about 1e-5 relative, so the sums are accurate to that.
  const Vec3 a(-3, 0.1, 0.3), b(3, 0.1, 0.3), c(3, 0.1 + 1e-3, 0.3);
  const TriangleBallTerms t = terms(a, b, c, O, 1.0);
  constexpr int kSteps = 200000;
  double area = 0.0, omega = 0.0;
  const double dx = 6.0 / kSteps;
  for (int i = 0; i < kSteps; ++i) {
    const double x = -3.0 + (i + 0.5) * dx;
    const double width = 1e-3 * (x + 3.0) / 6.0;  // y runs over [0.1, 0.1 + width]
    const double y_max2 = 1.0 - 0.09 - x * x;     // the ball's section at this x
    if (y_max2 <= 0.01) continue;
    const double y1 = std::min(0.1 + width, std::sqrt(y_max2));
    const double len = y1 - 0.1, y_mid = 0.5 * (0.1 + y1);
    area += len * dx;
    omega += len * dx * 0.3 / std::pow(x * x + y_mid * y_mid + 0.09, 1.5);
  }
  EXPECT_NEAR(t.area, area, 1e-5 * area);
  EXPECT_NEAR(t.solid_angle, omega, 1e-5 * omega);
  EXPECT_GT(area, 9e-4);  // the oracle integrated the needle (about 1e-3 x 0.95)
  // Sliver: three almost collinear vertices inside the ball, so t ∩ B = t: its area, and the
  // solid angle of the whole triangle (Van Oosterom–Strackee).
  const Vec3 d(-0.5, 0, 0.4), e(0.5, 0, 0.4), f(0, 1e-7, 0.4);
  const TriangleBallTerms sl = terms(d, e, f, O, 1.0);
  EXPECT_NEAR(sl.area, 0.5e-7, 1e-15);
  const double want = std::abs(triangleSolidAngle(d, e, f, O));
  EXPECT_GT(want, 1e-8);
  EXPECT_NEAR(sl.solid_angle, want, 1e-6 * want);
}

TEST(SphereTriangle, ScalesWithRadius) {
  const Vec3 a(0.2, 0.1, 0.3), b(2.0, 0.5, 0.3), c(0.4, 2.5, 0.3);
  const TriangleBallTerms t1 = terms(a, b, c, O, 1.0);
  for (double s : {1e-6, 1e-3, 1e3, 1e6}) {
    const TriangleBallTerms ts = terms(a * s, b * s, c * s, O, s);
    EXPECT_NEAR(ts.area / (s * s), t1.area, 1e-12 * t1.area);
    EXPECT_NEAR(ts.solid_angle, t1.solid_angle, 1e-12);
  }
}

TEST(SphereTriangle, RandomTrianglesAgainstQuadrature) {
  std::srand(7);
  auto rnd = [] { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  for (int k = 0; k < 12; ++k) {
    const Vec3 a(1.5 * rnd(), 1.5 * rnd(), 0.8 * rnd());
    const Vec3 b(1.5 * rnd(), 1.5 * rnd(), 0.8 * rnd());
    const Vec3 c(1.5 * rnd(), 1.5 * rnd(), 0.8 * rnd());
    if ((b - a).cross(c - a).norm() < 1e-2) continue;
    expectMatchesQuadrature(a, b, c, O, 1.0);
  }
}

}  // namespace
}  // namespace sphereset

// Mean value coordinates (Ju, Schaefer, Warren 2005): linear precision and affine invariance
// inside and outside the solid, partition of unity, agreement with a brute-force quadrature of
// the defining integral, and robustness at and near the surface.
#include <gtest/gtest.h>

#include <random>

#include "sphereset/animate.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using test::makeBox;
using test::makeIcosphere;
using test::makeTorus;

Vec3 combine(const Mesh& m, const std::vector<double>& w) {
  Vec3 x = Vec3::Zero();
  for (size_t j = 0; j < w.size(); ++j) x += w[j] * m.vertices[j];
  return x;
}

double sum(const std::vector<double>& w) {
  double s = 0.0;
  for (double x : w) s += x;
  return s;
}

// Points inside and outside a convex and a non-convex solid.
struct SolidPoints {
  Mesh mesh;
  std::vector<Vec3> points;
};

std::vector<SolidPoints> cases() {
  return {
      {makeIcosphere(1.0, 2),
       {{0.1, 0.2, -0.3},
        {0.5, 0.5, 0.3},
        {0.0, 0.0, 0.0},
        {2.0, 0.5, 1.0},
        {0.0, 3.0, 0.0},
        {0.7, 0.7, 0.2}}},
      {makeTorus(2.0, 0.6, 24, 12),
       {{2.0, 0.0, 0.1},
        {0.0, -2.2, -0.2},
        {0.0, 0.0, 0.0},
        {0.3, 0.2, 0.5},
        {5.0, 1.0, 2.0},
        {2.0, 0.0, 1.0}}},
  };
}

TEST(MeanValue, LinearPrecisionAndPartitionOfUnityInsideAndOutside) {
  for (const SolidPoints& c : cases())
    for (const Vec3& x : c.points) {
      const std::vector<double> w = meanValueCoordinates(c.mesh, x);
      ASSERT_EQ(w.size(), c.mesh.vertices.size());
      EXPECT_NEAR(sum(w), 1.0, 1e-10);
      EXPECT_LT((combine(c.mesh, w) - x).norm(), 1e-9) << x.transpose();
    }
}

TEST(MeanValue, OutsidePointsHaveNegativeWeightsInsideNone) {
  const Mesh m = makeIcosphere(1.0, 2);
  const auto inside = meanValueCoordinates(m, Vec3(0.2, 0.1, 0.0));
  EXPECT_GE(*std::min_element(inside.begin(), inside.end()), 0.0);  // convex: all positive
  const auto outside = meanValueCoordinates(m, Vec3(3.0, 0.0, 0.0));
  EXPECT_LT(*std::min_element(outside.begin(), outside.end()), 0.0);
}

TEST(MeanValue, AffineMapOfTheMeshMovesThePointByTheSameMap) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const SolidPoints& c : cases()) {
    Eigen::Affine3d a = Eigen::Affine3d::Identity();
    Eigen::Matrix3d lin;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) lin(i, j) = (i == j ? 1.5 : 0.0) + 0.4 * u(rng);
    a.linear() = lin;
    a.translation() = Vec3(u(rng), u(rng), u(rng)) * 3.0;
    Mesh moved = c.mesh;
    for (Vec3& v : moved.vertices) v = a * v;
    const Eigen::MatrixXd mw = meanValueMatrix(c.mesh, c.points).value();
    ASSERT_EQ(mw.rows(), static_cast<Eigen::Index>(c.points.size()));
    for (size_t i = 0; i < c.points.size(); ++i) {
      Vec3 y = Vec3::Zero();
      for (size_t j = 0; j < moved.vertices.size(); ++j)
        y += mw(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * moved.vertices[j];
      EXPECT_LT((y - a * c.points[i]).norm(), 1e-8);
    }
  }
}

// w_j ∝ ∫_S φ_j(p) n·(p - x) / |p - x|⁴ dA (the mean value integral over the unit sphere
// written on the surface, signed), by the midpoint rule on triangles split 4^depth times.
std::vector<double> quadrature(const Mesh& m, const Vec3& x, int depth) {
  std::vector<double> w(m.vertices.size(), 0.0);
  const int k = 1 << depth;
  for (const Triangle& t : m.triangles) {
    const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const Vec3 n2 = (b - a).cross(c - a);  // twice the area times the unit normal
    const double sub = 1.0 / (double(k) * k);
    // Sub-triangles of a k × k barycentric grid: their centroids.
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j)
        for (int up = 0; up < 2; ++up) {
          if (up == 1 && i + j + 1 >= k) continue;
          const double bi = up == 0 ? (i + 1.0 / 3.0) / k : (i + 2.0 / 3.0) / k;
          const double bj = up == 0 ? (j + 1.0 / 3.0) / k : (j + 2.0 / 3.0) / k;
          const double ba = 1.0 - bi - bj;
          const Vec3 p = ba * a + bi * b + bj * c;
          const Vec3 r = p - x;
          const double f = 0.5 * sub * n2.dot(r) / std::pow(r.squaredNorm(), 2);
          w[t[0]] += ba * f;
          w[t[1]] += bi * f;
          w[t[2]] += bj * f;
        }
  }
  const double s = sum(w);
  for (double& v : w) v /= s;
  return w;
}

TEST(MeanValue, AgreesWithBruteForceQuadratureOfTheIntegral) {
  const Mesh box = makeBox(Vec3(0, 0, 0), Vec3(1, 1.5, 2));
  const Mesh torus = makeTorus(2.0, 0.6, 12, 8);
  const std::vector<std::pair<const Mesh*, Vec3>> at = {{&box, {0.3, 0.6, 0.9}},
                                                        {&box, {0.5, 0.5, 1.5}},
                                                        {&box, {2.0, 0.4, -0.7}},
                                                        {&torus, {2.0, 0.1, 0.0}},
                                                        {&torus, {0.0, 0.0, 0.5}}};
  for (const auto& [m, x] : at) {
    const std::vector<double> w = meanValueCoordinates(*m, x);
    const std::vector<double> q = quadrature(*m, x, 6);
    double worst = 0.0, scale = 0.0;
    for (size_t j = 0; j < w.size(); ++j) {
      worst = std::max(worst, std::abs(w[j] - q[j]));
      scale = std::max(scale, std::abs(w[j]));
    }
    EXPECT_LT(worst, 2e-3 * scale) << x.transpose();
  }
}

TEST(MeanValue, RobustAtAndNearTheSurface) {
  const Mesh m = makeIcosphere(1.0, 1);
  const Triangle t = m.triangles[5];
  const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 inner = 0.2 * a + 0.3 * b + 0.5 * c;
  // At a vertex: that vertex alone.
  const auto wv = meanValueCoordinates(m, a);
  EXPECT_DOUBLE_EQ(wv[t[0]], 1.0);
  EXPECT_DOUBLE_EQ(sum(wv), 1.0);
  // On the triangle: its barycentric coordinates.
  const auto wt = meanValueCoordinates(m, inner);
  EXPECT_NEAR(wt[t[0]], 0.2, 1e-9);
  EXPECT_NEAR(wt[t[1]], 0.3, 1e-9);
  EXPECT_NEAR(wt[t[2]], 0.5, 1e-9);
  // Just off the triangle, an edge and a vertex, on both sides: finite, reproducing the point
  // (exactly, or within the band where it is taken to be on the surface), and close to the
  // on-surface coordinates.
  const Vec3 edge = 0.4 * a + 0.6 * b;
  for (const Vec3& base : {inner, edge, a})
    for (double h : {1e-13, 1e-11, 1e-9, 1e-7, 1e-6, 1e-5, -1e-5, -1e-6, -1e-9, -1e-13}) {
      const Vec3 x = base + h * n;
      const auto w = meanValueCoordinates(m, x);
      for (double v : w) ASSERT_TRUE(std::isfinite(v));
      EXPECT_NEAR(sum(w), 1.0, 1e-9);
      // Within about 1e-5 of the triangle's size, the point is taken to be on the triangle.
      EXPECT_LT((combine(m, w) - x).norm(), 1e-5) << h;
      const auto w0 = meanValueCoordinates(m, base);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(w[t[i]], w0[t[i]], 1e-3) << h;
    }
}

}  // namespace
}  // namespace sphereset

namespace sphereset {
namespace {

// The per-frame update (single-precision weights, displacement form): exact at the rest pose,
// and an affine map of the mesh moves the points by the map up to the weights' rounding.
TEST(MeanValue, PerFrameUpdateFollowsAnAffineMap) {
  const Mesh m = test::makeTorus(2.0, 0.6, 24, 12);
  const std::vector<Vec3> pts = {{2.0, 0.0, 0.1}, {0.0, -2.2, -0.2}, {0.3, 0.2, 0.5}};
  const MeanValueWeights w = meanValueWeights(m, pts).value();
  const std::vector<Vec3> same = meanValuePoints(w, m.vertices).value();
  for (size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(same[i], pts[i]);
  Eigen::Affine3d a(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  a.translation() = Vec3(0.5, -1.0, 2.0);
  a.linear() *= 1.3;
  std::vector<Vec3> moved;
  for (const Vec3& v : m.vertices) moved.push_back(a * v);
  const std::vector<Vec3> got = meanValuePoints(w, moved).value();
  for (size_t i = 0; i < pts.size(); ++i) EXPECT_LT((got[i] - a * pts[i]).norm(), 1e-5);
}

}  // namespace
}  // namespace sphereset

#include <tbb/global_control.h>

namespace sphereset {
namespace {

TEST(MeanValue, UpdateDoesNotDependOnTheThreadCount) {
  // Large enough (points × vertices) for the update to run in parallel.
  const Mesh m = test::makeIcosphere(1.0, 4);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<Vec3> pts(512);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  const MeanValueWeights w = meanValueWeights(m, pts).value();
  std::vector<Vec3> moved;
  for (const Vec3& v : m.vertices) moved.push_back(Vec3(1.2 * v.x(), v.y() + 0.3 * v.x(), v.z()));
  const std::vector<Vec3> many = meanValuePoints(w, moved).value();
  std::vector<Vec3> one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = meanValuePoints(w, moved).value();
    const MeanValueWeights w1 = meanValueWeights(m, pts).value();
    EXPECT_TRUE(w1.weights == w.weights);
  }
  EXPECT_EQ(one, many);
}

// A point at 1e30 (within the coordinate limit) used to get weights of ±inf: the weights of
// every point are finite numbers, or the point is named as too far for double precision.
TEST(MeanValue, AFarPointIsRefusedNotInfinite) {
  const Mesh m = makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  for (double far : {1e6, 1e30}) {
    auto w = meanValueWeights(m, {Vec3(0.1, 0.2, 0.3), Vec3(far, 0, 0)});
    auto mat = meanValueMatrix(m, {Vec3(0.1, 0.2, 0.3), Vec3(far, 0, 0)});
    if (w) {
      EXPECT_TRUE(w->weights.allFinite()) << far;
      ASSERT_TRUE(mat);
      EXPECT_TRUE(mat->allFinite()) << far;
      continue;
    }
    EXPECT_EQ(w.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(w.error().message.find("point 1: its mean value coordinates are not finite"),
              std::string::npos)
        << w.error().message;
    ASSERT_FALSE(mat);
    EXPECT_EQ(mat.error().message, w.error().message);
  }
  EXPECT_FALSE(meanValueWeights(m, {Vec3(1e30, 1e30, 0)}));
}

}  // namespace
}  // namespace sphereset

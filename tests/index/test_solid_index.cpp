// Point-in-solid, distance, segment and neighbourhood queries against brute force and
// analytic answers, including the degenerate positions that break naive ray casting.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "index/oracles.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

TEST(SolidIndex, ClassifiesPointsOnVerticesEdgesAndFacesAsBoundary) {
  const Mesh cube = test::makeBox(Vec3::Zero(), Vec3::Ones());
  const SolidIndex idx(cube);
  for (const Vec3& v : cube.vertices) EXPECT_EQ(idx.classify(v), Containment::kBoundary);
  EXPECT_EQ(idx.classify(Vec3(0.5, 0, 0)), Containment::kBoundary);        // edge
  EXPECT_EQ(idx.classify(Vec3(0.5, 0.5, 1.0)), Containment::kBoundary);    // face (diagonal)
  EXPECT_EQ(idx.classify(Vec3(0.25, 0.75, 0.0)), Containment::kBoundary);  // face
}

TEST(SolidIndex, PointsAlignedWithEdgesAndVerticesAreClassifiedCorrectly) {
  // Points on the lines through the cube's vertices and edges, along the axes and diagonals:
  // the directions in which a single fixed ray would graze an edge or a vertex.
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  int checked = 0;
  for (double a : {-1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0})
    for (double b : {-0.5, 0.0, 0.5, 1.0, 1.5})
      for (double c : {-0.5, 0.0, 0.5, 1.0, 1.5}) {
        const Vec3 p(a, b, c);
        const bool inside = (p.array() > 0.0).all() && (p.array() < 1.0).all();
        const bool on = !((p.array() < 0.0).any() || (p.array() > 1.0).any()) && !inside;
        const Containment want =
            inside ? Containment::kInside : (on ? Containment::kBoundary : Containment::kOutside);
        EXPECT_EQ(idx.classify(p), want) << p.transpose();
        ++checked;
      }
  EXPECT_EQ(checked, 200);
}

TEST(SolidIndex, ClassifyAgreesWithWindingNumberOnRandomPoints) {
  const Mesh torus = test::makeTorus(1.0, 0.4, 32, 16);
  const SolidIndex idx(torus);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1.6, 1.6);
  int inside = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(U(rng), U(rng), 0.5 * U(rng));
    const double w = windingNumber(idx, p);
    ASSERT_TRUE(std::abs(w) < 1e-6 || std::abs(w - 1) < 1e-6) << w;
    const Containment c = idx.classify(p);
    EXPECT_EQ(c == Containment::kInside, w > 0.5) << p.transpose();
    inside += c == Containment::kInside;
  }
  EXPECT_GT(inside, 100);
}

TEST(SolidIndex, ClassifyOnGridAlignedWithMeshVertices) {
  // An icosphere has vertices on the coordinate axes; rays from points on the axes through
  // those vertices must not be miscounted.
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  for (double s : {-2.0, -0.99, -0.5, 0.0, 0.5, 0.99, 2.0})
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 p = Vec3::Zero();
      p[axis] = s;
      const Containment want = std::abs(s) < 0.9 ? Containment::kInside : Containment::kOutside;
      if (std::abs(std::abs(s) - 0.99) < 1e-9) continue;  // near the polyhedral surface
      EXPECT_EQ(idx.classify(p), want) << p.transpose();
    }
}

double bruteDistance(const Mesh& m, const Vec3& p) {
  // Dense sampling of each triangle gives an upper bound; exact for vertices.
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : m.triangles) {
    const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const int N = 40;
    for (int i = 0; i <= N; ++i)
      for (int j = 0; i + j <= N; ++j) {
        const Vec3 q = a + (b - a) * (double(i) / N) + (c - a) * (double(j) / N);
        best = std::min(best, (q - p).norm());
      }
  }
  return best;
}

TEST(SolidIndex, DistanceMatchesBruteForce) {
  const Mesh torus = test::makeTorus(1.0, 0.4, 16, 8);
  const SolidIndex idx(torus);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(-2.0, 2.0);
  for (int k = 0; k < 30; ++k) {
    const Vec3 p(U(rng), U(rng), U(rng));
    const double d = idx.distance(p);
    const double b = bruteDistance(torus, p);
    EXPECT_LE(d, b + 1e-12);
    EXPECT_GE(d, b - 0.02);  // sampling resolution of the oracle
  }
}

TEST(SolidIndex, TrianglesNearBallMatchesBruteForce) {
  const Mesh torus = test::makeTorus(1.0, 0.4, 24, 12);
  const SolidIndex idx(torus);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-1.5, 1.5);
  for (int k = 0; k < 50; ++k) {
    const Sphere s{Vec3(U(rng), U(rng), 0.4 * U(rng)), 0.05 + 0.02 * k};
    std::vector<int32_t> want;
    for (int32_t t = 0; t < static_cast<int32_t>(torus.triangles.size()); ++t) {
      Aabb b;
      for (int32_t v : torus.triangles[t]) b.extend(torus.vertices[v]);
      const Vec3 d = (b.min - s.center).cwiseMax(s.center - b.max).cwiseMax(0.0);
      if (d.squaredNorm() <= s.radius * s.radius) want.push_back(t);
    }
    EXPECT_EQ(trianglesNearBall(idx, s), want);
  }
}

TEST(SolidIndex, OutsideLengthOfSegmentsThroughABox) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  EXPECT_NEAR(idx.outsideLength(Vec3(-1, 0.5, 0.5), Vec3(2, 0.5, 0.5)), 2.0, 1e-12);
  EXPECT_NEAR(idx.outsideLength(Vec3(0.2, 0.5, 0.5), Vec3(0.8, 0.5, 0.5)), 0.0, 1e-12);
  // Along a face (grazing): the segment lies on the boundary, which counts as inside.
  EXPECT_NEAR(idx.outsideLength(Vec3(-1, 0.0, 0.5), Vec3(2, 0.0, 0.5)), 2.0, 1e-12);
  // Through an edge diagonally.
  EXPECT_NEAR(idx.outsideLength(Vec3(-1, -1, 0.5), Vec3(2, 2, 0.5)), 2 * std::sqrt(2.0), 1e-12);
  // Surface to surface through a concavity: torus, across the hole.
  const SolidIndex tor(test::makeTorus(1.0, 0.3, 64, 32));
  const double len = tor.outsideLength(Vec3(-1.3, 0, 0), Vec3(1.3, 0, 0));
  EXPECT_NEAR(len, 1.4, 0.01);
}

TEST(SolidIndex, RaycastMatchesBruteForceOverTriangles) {
  const Mesh torus = test::makeTorus(1.0, 0.4, 40, 20);
  const SolidIndex idx(torus);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 o(u(rng), u(rng), u(rng));
    const Vec3 d = Vec3(u(rng), u(rng), u(rng)).normalized();
    // Brute force: Möller-Trumbore over every triangle.
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : torus.triangles) {
      const Vec3 &a = torus.vertices[t[0]], &b = torus.vertices[t[1]], &c = torus.vertices[t[2]];
      const Vec3 e1 = b - a, e2 = c - a, pv = d.cross(e2);
      const double det = e1.dot(pv);
      if (std::abs(det) < 1e-14) continue;
      const Vec3 tv = o - a;
      const double bu = tv.dot(pv) / det;
      const Vec3 qv = tv.cross(e1);
      const double bv = d.dot(qv) / det;
      const double tt = e2.dot(qv) / det;
      if (bu >= 0 && bv >= 0 && bu + bv <= 1 && tt > 0 && tt < best) best = tt;
    }
    RayHit h;
    const bool hit = idx.raycast(o, d, 0.0, 100.0, &h);
    ASSERT_EQ(hit, std::isfinite(best)) << k;
    EXPECT_EQ(idx.occluded(o, d, 0.0, 100.0), hit);
    if (hit) {
      ++hits;
      EXPECT_NEAR(h.t, best, 1e-9);
      // The normal faces the ray where it enters the solid (the origin outside).
      if (idx.classify(o) == Containment::kOutside) {
        EXPECT_LT(h.normal.dot(d), 0.0);
      }
    }
  }
  EXPECT_GT(hits, 200);
}

}  // namespace
}  // namespace sphereset

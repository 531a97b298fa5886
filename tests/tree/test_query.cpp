// Queries on sphere trees against brute force over all spheres or pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sphereset/query.hpp"
#include "sphereset/sphere_tree.hpp"
#include "tree/query_oracles.hpp"

namespace sphereset {
namespace {

std::vector<Sphere> blob(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> r(0.05, 0.4);
  std::vector<Sphere> out(n);
  for (Sphere& s : out) s = {Vec3(2.0 * g(rng), g(rng), 0.5 * g(rng)), r(rng)};
  return out;
}

Pose randomPose(std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> g(0.0, 1.0);
  Pose p;
  const Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  p.rotation = q.normalized().toRotationMatrix();
  p.translation = spread * Vec3(g(rng), g(rng), g(rng));
  return p;
}

Vec3 randomPoint(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(Query, PointQueriesMatchBruteForce) {
  for (int n : {1, 64, 500}) {
    const auto s = blob(n, n);
    const SphereTree t = queryTree(s);
    ASSERT_TRUE(checkSphereTree(t).ok());
    std::mt19937_64 rng(7);
    for (int k = 0; k < 500; ++k) {
      const Vec3 p = randomPoint(rng);
      const PointQuery a = pointDistance(t, p), b = pointDistanceBruteForce(s, p);
      EXPECT_NEAR(a.distance, b.distance, 1e-12);
      ASSERT_GE(a.sphere, 0);
      EXPECT_NEAR((p - t.nodes[a.sphere].center).norm() - t.nodes[a.sphere].radius, a.distance,
                  1e-12);
      EXPECT_EQ(containsPoint(t, p), containsPointBruteForce(s, p));
      EXPECT_EQ(containsPoint(t, p), b.distance <= 0.0);
    }
  }
}

TEST(Query, SegmentOutsideLengthMatchesBruteForceAndClosedForm) {
  // Two overlapping unit balls on the x axis: the segment from -2 to 4 is inside over
  // [-1, 2], so 3 of its 6 units are outside; overlaps count once.
  const std::vector<Sphere> two = {{Vec3(0, 0, 0), 1.0}, {Vec3(1, 0, 0), 1.0}};
  EXPECT_NEAR(segmentOutsideLength(queryTree(two), Vec3(-2, 0, 0), Vec3(4, 0, 0)), 3.0, 1e-12);
  // A chord off the centre: at y = 0.6 the unit ball spans x in [-0.8, 0.8], so 4 - 1.6 of
  // the segment from x = -2 to 2 is outside.
  const std::vector<Sphere> unit = {{Vec3::Zero(), 1.0}};
  EXPECT_NEAR(segmentOutsideLength(queryTree(unit), Vec3(-2, 0.6, 0), Vec3(2, 0.6, 0)), 2.4, 1e-12);
  const auto s = blob(300, 3);
  const SphereTree t = queryTree(s);
  std::mt19937_64 rng(11);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 a = randomPoint(rng), b = randomPoint(rng);
    EXPECT_NEAR(segmentOutsideLength(t, a, b), segmentOutsideLengthBruteForce(s, a, b), 1e-12);
  }
}

TEST(Query, SeparationAndOverlapMatchBruteForceUnderRandomPoses) {
  std::mt19937_64 rng(13);
  int overlapping = 0, apart = 0;
  for (int k = 0; k < 200; ++k) {
    const auto sa = blob(20 + k % 90, 100 + k), sb = blob(10 + k % 70, 500 + k);
    const SphereTree ta = queryTree(sa, 4 + k % 5), tb = queryTree(sb);
    ASSERT_TRUE(checkSphereTree(ta).ok() && checkSphereTree(tb).ok());
    const Pose pa = randomPose(rng, 1.0), pb = randomPose(rng, 4.0);
    const PairQuery q = separation(ta, pa, tb, pb);
    const PairQuery o = separationBruteForce(sa, pa, sb, pb);
    EXPECT_NEAR(q.distance, o.distance, 1e-12);
    // The returned pair attains the distance.
    ASSERT_GE(q.sphere_a, 0);
    ASSERT_GE(q.sphere_b, 0);
    const Sphere wa{pa.apply(ta.nodes[q.sphere_a].center), ta.nodes[q.sphere_a].radius};
    const Sphere wb{pb.apply(tb.nodes[q.sphere_b].center), tb.nodes[q.sphere_b].radius};
    EXPECT_NEAR((wa.center - wb.center).norm() - wa.radius - wb.radius, q.distance, 1e-12);
    PairQuery hit;
    const bool ov = overlaps(ta, pa, tb, pb, &hit);
    EXPECT_EQ(ov, overlapsBruteForce(sa, pa, sb, pb));
    EXPECT_EQ(ov, o.distance < 0.0);
    if (ov) {
      EXPECT_LT(hit.distance, 0.0);
      ++overlapping;
    } else {
      ++apart;
    }
  }
  // Both outcomes were exercised.
  EXPECT_GT(overlapping, 20);
  EXPECT_GT(apart, 20);
}

TEST(Query, TreeVisitsFewerPairsThanBruteForce) {
  const auto sa = blob(1000, 1), sb = blob(1000, 2);
  const SphereTree ta = queryTree(sa), tb = queryTree(sb);
  Pose pb;
  pb.translation = Vec3(12.0, 0.0, 0.0);
  const PairQuery q = separation(ta, Pose{}, tb, pb);
  EXPECT_NEAR(q.distance, separationBruteForce(sa, Pose{}, sb, pb).distance, 1e-12);
  EXPECT_LT(q.visited, 1000 * 1000 / 50);
}

}  // namespace
}  // namespace sphereset

// Queries on sphere trees against brute force over all spheres or pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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
      const PointQuery a = *pointDistance(t, p), b = pointDistanceBruteForce(s, p);
      EXPECT_NEAR(a.distance, b.distance, 1e-12);
      ASSERT_GE(a.sphere, 0);
      EXPECT_NEAR((p - t.nodes[a.sphere].center).norm() - t.nodes[a.sphere].radius, a.distance,
                  1e-12);
      EXPECT_EQ(*containsPoint(t, p), containsPointBruteForce(s, p));
      EXPECT_EQ(*containsPoint(t, p), b.distance <= 0.0);
    }
  }
}

TEST(Query, SegmentOutsideLengthMatchesBruteForceAndClosedForm) {
  // Two overlapping unit balls on the x axis: the segment from -2 to 4 is inside over
  // [-1, 2], so 3 of its 6 units are outside; overlaps count once.
  const std::vector<Sphere> two = {{Vec3(0, 0, 0), 1.0}, {Vec3(1, 0, 0), 1.0}};
  EXPECT_NEAR(*segmentOutsideLength(queryTree(two), Vec3(-2, 0, 0), Vec3(4, 0, 0)), 3.0, 1e-12);
  // A chord off the centre: at y = 0.6 the unit ball spans x in [-0.8, 0.8], so 4 - 1.6 of
  // the segment from x = -2 to 2 is outside.
  const std::vector<Sphere> unit = {{Vec3::Zero(), 1.0}};
  EXPECT_NEAR(*segmentOutsideLength(queryTree(unit), Vec3(-2, 0.6, 0), Vec3(2, 0.6, 0)), 2.4,
              1e-12);
  const auto s = blob(300, 3);
  const SphereTree t = queryTree(s);
  std::mt19937_64 rng(11);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 a = randomPoint(rng), b = randomPoint(rng);
    EXPECT_NEAR(*segmentOutsideLength(t, a, b), segmentOutsideLengthBruteForce(s, a, b), 1e-12);
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
    const PairQuery q = *separation(ta, pa, tb, pb);
    const PairQuery o = separationBruteForce(sa, pa, sb, pb);
    EXPECT_NEAR(q.distance, o.distance, 1e-12);
    // The returned pair attains the distance.
    ASSERT_GE(q.sphere_a, 0);
    ASSERT_GE(q.sphere_b, 0);
    const Sphere wa{pa.apply(ta.nodes[q.sphere_a].center), ta.nodes[q.sphere_a].radius};
    const Sphere wb{pb.apply(tb.nodes[q.sphere_b].center), tb.nodes[q.sphere_b].radius};
    EXPECT_NEAR((wa.center - wb.center).norm() - wa.radius - wb.radius, q.distance, 1e-12);
    PairQuery hit;
    const bool ov = *overlaps(ta, pa, tb, pb, &hit);
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
  const PairQuery q = *separation(ta, Pose{}, tb, pb);
  EXPECT_NEAR(q.distance, separationBruteForce(sa, Pose{}, sb, pb).distance, 1e-12);
  EXPECT_LT(q.visited, 1000 * 1000 / 50);
}

// A NaN point used to be "outside, inf" and a segment of length 1.7e154 "inf of inf outside":
// every query now refuses what it cannot answer in finite numbers.
TEST(Query, NonFiniteOrHugeInputsAreRefused) {
  const SphereTree t = queryTree({{Vec3::Zero(), 1.0}, {Vec3(3, 0, 0), 1.0}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto p = pointDistance(t, Vec3(nan, 0, 0));
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(p.error().message.find("point (nan 0 0): coordinates must be finite"),
            std::string::npos)
      << p.error().message;
  EXPECT_FALSE(containsPoint(t, Vec3(0, std::numeric_limits<double>::infinity(), 0)));
  const auto seg = segmentOutsideLength(t, Vec3::Zero(), Vec3::Constant(1e154));
  ASSERT_FALSE(seg);
  EXPECT_NE(seg.error().message.find("segment end"), std::string::npos) << seg.error().message;
  // Up to the limit, lengths stay finite.
  const auto far = segmentOutsideLength(t, Vec3::Zero(), Vec3::Constant(1e30));
  ASSERT_TRUE(far);
  EXPECT_TRUE(std::isfinite(*far));
  Pose skew;
  skew.rotation(0, 1) = 0.5;  // not orthonormal
  EXPECT_FALSE(separation(t, Pose{}, t, skew));
  Pose nan_pose;
  nan_pose.translation.x() = nan;
  const auto ov = overlaps(t, nan_pose, t, Pose{});
  ASSERT_FALSE(ov);
  EXPECT_NE(ov.error().message.find("pose_a translation"), std::string::npos);
}

// Bradshaw's trees may end a branch above the last level. Root over two children, only the
// first of which has children: the second is a leaf, and a query at its centre is inside it
// (it used to answer "outside, 6", and exports dropped the node).
TEST(SphereTreeData, ChildlessNodesAboveTheLastLevelAreLeaves) {
  const Sphere none{Vec3::Zero(), -1.0};
  std::vector<Sphere> slots = {{Vec3::Zero(), 10.0},
                               {Vec3(-3, 0, 0), 4.0},
                               {Vec3(5, 0, 0), 2.0},
                               {Vec3(-4, 0, 0), 1.0},
                               {Vec3(-2, 0, 0), 1.0},
                               none,
                               none};
  const auto t = makeSphereTree(2, 2, slots);
  ASSERT_TRUE(t) << t.error().message;
  const std::vector<Sphere> leaves = t->leaves();
  ASSERT_EQ(leaves.size(), 3u);
  EXPECT_EQ(leaves[2].center, Vec3(5, 0, 0));
  const auto q = pointDistance(*t, Vec3(5, 0, 0));
  ASSERT_TRUE(q);
  EXPECT_DOUBLE_EQ(q->distance, -2.0);
  EXPECT_TRUE(*containsPoint(*t, Vec3(5.5, 0, 0)));
  EXPECT_TRUE(checkSphereTree(*t).ok());
  // A root alone is the only leaf.
  const auto root = makeSphereTree(2, 0, {{Vec3::Zero(), 10.0}});
  ASSERT_TRUE(root);
  EXPECT_DOUBLE_EQ(pointDistance(*root, Vec3::Zero())->distance, -10.0);
  // A used node with a NaN centre is refused, not silently unused.
  slots[2].center.x() = std::numeric_limits<double>::quiet_NaN();
  const auto bad = makeSphereTree(2, 2, slots);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("node 2"), std::string::npos) << bad.error().message;
}

}  // namespace
}  // namespace sphereset

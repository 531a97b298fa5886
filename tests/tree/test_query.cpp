// Queries on sphere trees against brute force over all spheres or pairs.
#include <gtest/gtest.h>

#include <algorithm>
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
    const SphereTree t = *queryTree(s);
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
  EXPECT_NEAR(*segmentOutsideLength(*queryTree(two), Vec3(-2, 0, 0), Vec3(4, 0, 0)), 3.0, 1e-12);
  // A chord off the centre: at y = 0.6 the unit ball spans x in [-0.8, 0.8], so 4 - 1.6 of
  // the segment from x = -2 to 2 is outside.
  const std::vector<Sphere> unit = {{Vec3::Zero(), 1.0}};
  EXPECT_NEAR(*segmentOutsideLength(*queryTree(unit), Vec3(-2, 0.6, 0), Vec3(2, 0.6, 0)), 2.4,
              1e-12);
  const auto s = blob(300, 3);
  const SphereTree t = *queryTree(s);
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
    const SphereTree ta = *queryTree(sa, 4 + k % 5), tb = *queryTree(sb);
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
  const SphereTree ta = *queryTree(sa), tb = *queryTree(sb);
  Pose pb;
  pb.translation = Vec3(12.0, 0.0, 0.0);
  const PairQuery q = *separation(ta, Pose{}, tb, pb);
  EXPECT_NEAR(q.distance, separationBruteForce(sa, Pose{}, sb, pb).distance, 1e-12);
  EXPECT_LT(q.visited, 1000 * 1000 / 50);
}

// A NaN point used to be "outside, inf" and a segment of length 1.7e154 "inf of inf outside":
// every query now refuses what it cannot answer in finite numbers.
TEST(Query, NonFiniteOrHugeInputsAreRefused) {
  const SphereTree t = *queryTree({{Vec3::Zero(), 1.0}, {Vec3(3, 0, 0), 1.0}});
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

// A set the layout cannot hold used to become an empty tree, so that a sphere's own centre was
// "outside, signed distance inf": it is refused, naming the limit.
TEST(Query, ASetTooLargeForATreeIsRefusedNotEmpty) {
  EXPECT_EQ(maxQueryTreeSpheres(8), int64_t{1} << 21);
  EXPECT_EQ(maxQueryTreeSpheres(2), int64_t{1} << 21);
  const std::vector<Sphere> many(static_cast<size_t>(maxQueryTreeSpheres(8)) + 1,
                                 Sphere{Vec3::Zero(), 1.0});
  const auto t = queryTree(many);
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(t.error().message.find("2097153 spheres: a query tree of branching 8 holds at most "
                                   "2097152"),
            std::string::npos)
      << t.error().message;
  EXPECT_FALSE(queryTree({{Vec3::Zero(), 1.0}}, 1));
  EXPECT_FALSE(queryTree({{Vec3::Zero(), 1.0}}, kMaxQueryBranching + 1));
}

// Sphere values beyond the coordinate limit used to load and answer "inside, signed distance
// inf": the one sphere rule refuses them.
TEST(Query, SpheresBeyondTheCoordinateLimitAreRefused) {
  for (const Sphere& bad : {Sphere{Vec3(1e200, 0, 0), 1.0}, Sphere{Vec3::Zero(), 1e31}}) {
    const auto t = queryTree({{Vec3::Zero(), 1.0}, bad});
    ASSERT_FALSE(t);
    EXPECT_NE(t.error().message.find("sphere 1: a value beyond 1e+30 in magnitude"),
              std::string::npos)
        << t.error().message;
  }
}

// The sets that made the Lloyd-built tree quadratic (thousands of identical or random spheres):
// the median tree answers exactly as brute force does, every leaf slot names its sphere, and the
// parents enclose their children.
TEST(Query, LargeAndDegenerateSetsBuildAndAnswerExactly) {
  const std::vector<Sphere> same(32769, Sphere{Vec3(1, 2, 3), 0.5});
  std::vector<int64_t> where;
  const auto ts = queryTree(same, 8, &where);
  ASSERT_TRUE(ts);
  EXPECT_TRUE(checkSphereTree(*ts).ok());
  EXPECT_TRUE(*containsPoint(*ts, Vec3(1, 2, 3.4)));
  EXPECT_FALSE(*containsPoint(*ts, Vec3(1, 2, 3.6)));
  std::vector<int> seen(same.size(), 0);
  for (int64_t w : where)
    if (w >= 0) ++seen[static_cast<size_t>(w)];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(same.size()));

  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-10.0, 10.0), r(0.01, 0.2);
  std::vector<Sphere> random(40000);
  for (Sphere& s : random) s = {Vec3(u(rng), u(rng), u(rng)), r(rng)};
  for (int branching : {2, 8, 27}) {
    std::vector<int64_t> slot;
    const auto t = queryTree(random, branching, &slot);
    ASSERT_TRUE(t);
    EXPECT_TRUE(checkSphereTree(*t, 1e-9).ok());
    for (size_t i = 0; i < random.size(); i += 997) {
      const auto q = pointDistance(*t, random[i].center);
      ASSERT_TRUE(q);
      EXPECT_NEAR(q->distance, pointDistanceBruteForce(random, random[i].center).distance, 1e-12);
      EXPECT_TRUE(*containsPoint(*t, random[i].center));
      const auto& leaf = t->nodes[static_cast<size_t>(q->sphere)];
      const auto& named = random[static_cast<size_t>(slot[static_cast<size_t>(q->sphere)])];
      EXPECT_EQ(leaf.center, named.center);
      EXPECT_EQ(leaf.radius, named.radius);
    }
  }
}

// A tree edited in the view so that a parent no longer holds its children, saved and read back:
// queried as it is, 4 of its 8 leaf centres were "outside". The tree every door queries
// (queryTreeOf) answers as the leaves do, naming the given tree's slots.
TEST(Query, ATreeWhoseParentsDoNotHoldTheirLeavesIsQueriedByItsLeaves) {
  std::vector<Sphere> leaves;
  for (int i = 0; i < 8; ++i) leaves.push_back({Vec3(i % 2, (i / 2) % 2, i / 4) * 2.0, 0.5});
  SphereTree t = *queryTree(leaves, 2);
  ASSERT_EQ(t.depth, 3);
  ASSERT_TRUE(checkSphereTree(t).ok());
  t.nodes[1].radius = 0.1;  // a parent of four leaves shrunk by an edit
  ASSERT_FALSE(checkSphereTree(t).ok());
  int missed = 0;
  for (const Sphere& l : leaves) missed += !*containsPoint(t, l.center);
  EXPECT_EQ(missed, 4);  // what the tree as it is answers
  std::vector<int64_t> slot_of;
  const auto q = queryTreeOf(t, &slot_of);
  ASSERT_TRUE(q);
  EXPECT_TRUE(checkSphereTree(*q).ok());
  for (const Sphere& l : leaves) {
    EXPECT_TRUE(*containsPoint(*q, l.center));
    const auto d = pointDistance(*q, l.center);
    ASSERT_TRUE(d);
    const int64_t slot = slot_of[static_cast<size_t>(d->sphere)];
    EXPECT_EQ(t.nodes[static_cast<size_t>(slot)].center, l.center);
  }
  // A tree that holds its rule is used as it is.
  const SphereTree good = *queryTree(leaves, 2);
  std::vector<int64_t> none;
  const auto same = queryTreeOf(good, &none);
  ASSERT_TRUE(same);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(same->nodes.size(), good.nodes.size());
}

}  // namespace
}  // namespace sphereset

// Self-intersections: the triangle–triangle cases (shared vertex, shared edge, coplanar,
// duplicated), the BVH search against the all-pairs oracle, invariance under similarity
// transforms, and truncation at max_pairs.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "mesh/triangle_intersection.hpp"
#include "sphereset/mesh_defects.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using Pairs = std::vector<std::array<int32_t, 2>>;

// A mesh of two triangles given by their corners; shared corners are listed once in `vertices`.
Mesh twoTriangles(std::vector<Vec3> vertices, Triangle a, Triangle b) {
  Mesh m;
  m.vertices = std::move(vertices);
  m.triangles = {a, b};
  return m;
}

bool intersects(const Mesh& m) { return findSelfIntersections(m).any(); }

Eigen::Matrix3d someRotation() {
  return Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
}

TEST(SelfIntersections, CleanMeshesHaveNone) {
  EXPECT_FALSE(intersects(test::makeIcosphere(1.0, 3)));
  EXPECT_FALSE(intersects(test::makeBox(Vec3::Zero(), Vec3(1.0, 2.0, 3.0))));
  EXPECT_FALSE(intersects(test::makeTorus(2.0, 0.5, 48, 24)));
  // Tiny and huge copies: the tolerance is relative.
  EXPECT_FALSE(intersects(
      test::transformed(test::makeTorus(2.0, 0.5, 48, 24), someRotation(), Vec3(1e3, 0, 0), 1e-4)));
  EXPECT_FALSE(intersects(
      test::transformed(test::makeIcosphere(1.0, 3), someRotation(), Vec3::Zero(), 1e6)));
}

TEST(SelfIntersections, TwoOverlappingBoxes) {
  const Mesh m = test::joined(test::makeBox(Vec3::Zero(), Vec3::Ones()),
                              test::makeBox(Vec3::Constant(0.5), Vec3::Constant(1.5)));
  const SelfIntersections r = findSelfIntersections(m);
  ASSERT_TRUE(r.any());
  EXPECT_FALSE(r.truncated);
  EXPECT_TRUE(std::is_sorted(r.pairs.begin(), r.pairs.end()));
  for (const auto& [a, b] : r.pairs) {
    EXPECT_LT(a, 12);  // one triangle of each box
    EXPECT_GE(b, 12);
  }
  // Boxes that merely sit apart do not intersect.
  EXPECT_FALSE(intersects(test::joined(test::makeBox(Vec3::Zero(), Vec3::Ones()),
                                       test::makeBox(Vec3::Constant(1.5), Vec3::Constant(2.5)))));
}

TEST(SelfIntersections, DuplicatedFace) {
  Mesh m = test::makeBox(Vec3::Zero(), Vec3::Ones());
  m.triangles.push_back(m.triangles[5]);
  EXPECT_EQ(findSelfIntersections(m).pairs, (Pairs{{5, 12}}));
  // The same face with the opposite orientation.
  m.triangles.back() = {m.triangles[5][0], m.triangles[5][2], m.triangles[5][1]};
  EXPECT_EQ(findSelfIntersections(m).pairs, (Pairs{{5, 12}}));
}

TEST(SelfIntersections, SharedEdge) {
  const std::vector<Vec3> v = {{0, 0, 0},     {1, 0, 0},      {0, 1, 0},
                               {0.5, 0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0.1}};
  // Folded: coplanar, third vertices on the same side of the common edge.
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {1, 0, 3})));
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {0, 1, 3})));
  // Flat neighbours: opposite sides.
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {1, 0, 4})));
  // A sharp but real dihedral angle.
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {1, 0, 5})));
}

TEST(SelfIntersections, SharedVertex) {
  const std::vector<Vec3> v = {{0, 0, 0},       {1, 0, 0},  {0, 1, 0},  {0.3, 0.3, -1},
                               {0.3, 0.3, 1},   {-1, 0, 1}, {0, -1, 1}, {1, 1, 0},
                               {-1, 2, 0},      {-1, 0, 0}, {0, -1, 0}, {0.2, 0.2, 0.5},
                               {0.2, 0.2, -0.5}};
  // A plane through v cutting the other triangle along its diagonal.
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {0, 3, 4})));
  // A smaller upright triangle whose far edge crosses the first one's interior.
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {0, 11, 12})));
  // Touching at v only.
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {0, 5, 6})));
  // Coplanar, overlapping wedges at v.
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {0, 7, 8})));
  // Coplanar, opposite wedges (a bow tie).
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {0, 9, 10})));
}

TEST(SelfIntersections, NoSharedVertex) {
  const std::vector<Vec3> v = {{0, 0, 0},      {1, 0, 0},     {0, 1, 0},
                               {0.2, 0.2, 0},  {2, 0.2, 0},   {0.2, 2, 0},  // coplanar, overlapping
                               {3, 0, 0},      {4, 0, 0},     {3, 1, 0},    // coplanar, apart
                               {0.2, 0.2, -1}, {0.2, 0.2, 1}, {1, 1, 1}};   // piercing
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {3, 4, 5})));
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {6, 7, 8})));
  EXPECT_TRUE(intersects(twoTriangles(v, {0, 1, 2}, {9, 10, 11})));
  // A triangle above the plane: no contact.
  Mesh above = twoTriangles(v, {0, 1, 2}, {9, 10, 11});
  above.vertices[9].z() = 0.5;
  EXPECT_FALSE(intersects(above));
}

TEST(SelfIntersections, DegenerateTrianglesAreSkipped) {
  // A zero-area triangle lying across a real one.
  const std::vector<Vec3> v = {{0, 0, 0},      {1, 0, 0},     {0, 1, 0},
                               {0.2, 0.2, -1}, {0.2, 0.2, 0}, {0.2, 0.2, 1}};
  EXPECT_FALSE(intersects(twoTriangles(v, {0, 1, 2}, {3, 4, 5})));
  Mesh real = twoTriangles(v, {0, 1, 2}, {3, 4, 5});
  real.vertices[4].x() = 0.6;
  EXPECT_TRUE(intersects(real));
}

// Seeded random soups: small independent triangles, and triangles over a small shared vertex
// pool (many shared vertices and edges).
Mesh randomSoup(uint32_t seed, bool shared_pool) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Mesh m;
  if (shared_pool) {
    for (int i = 0; i < 40; ++i) m.vertices.emplace_back(unit(rng), unit(rng), 0.3 * unit(rng));
    std::uniform_int_distribution<int32_t> pick(0, 39);
    while (m.triangles.size() < 150) {
      const Triangle t{pick(rng), pick(rng), pick(rng)};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
    }
    // Flat triangles in one plane, some sharing vertices.
    for (auto& v : m.vertices)
      if (v.z() < 0.1) v.z() = 0.0;
  } else {
    for (int i = 0; i < 400; ++i) {
      const Vec3 c(unit(rng), unit(rng), unit(rng));
      const int32_t base = static_cast<int32_t>(m.vertices.size());
      for (int k = 0; k < 3; ++k)
        m.vertices.push_back(c + 0.1 * Vec3(unit(rng), unit(rng), unit(rng)));
      m.triangles.push_back({base, base + 1, base + 2});
    }
  }
  return m;
}

TEST(SelfIntersections, MatchesAllPairsOracle) {
  for (uint32_t seed = 1; seed <= 4; ++seed)
    for (bool pool : {false, true}) {
      const Mesh m = randomSoup(seed, pool);
      const Pairs oracle = detail::selfIntersectionsAllPairs(m);
      const SelfIntersections r = findSelfIntersections(m);
      EXPECT_FALSE(oracle.empty());
      EXPECT_EQ(r.pairs, oracle) << "seed " << seed << " pool " << pool;
    }
}

TEST(SelfIntersections, InvariantUnderSimilarity) {
  const Mesh boxes = test::joined(test::makeBox(Vec3::Zero(), Vec3::Ones()),
                                  test::makeBox(Vec3::Constant(0.5), Vec3::Constant(1.5)));
  for (const Mesh& m : {boxes, randomSoup(7, false), randomSoup(8, true)}) {
    const Pairs base = findSelfIntersections(m).pairs;
    ASSERT_FALSE(base.empty());
    for (double s : {1e-3, 1.0, 1e4}) {
      const Mesh t = test::transformed(m, someRotation(), Vec3(10.0, -3.0, 2.0), s);
      EXPECT_EQ(findSelfIntersections(t).pairs, base) << "scale " << s;
    }
  }
}

TEST(SelfIntersections, StopsAtMaxPairs) {
  const Mesh m = test::joined(
      test::makeIcosphere(1.0, 3),
      test::transformed(test::makeIcosphere(1.0, 3), someRotation(), Vec3(0.5, 0.0, 0.0), 1.0));
  const SelfIntersections all = findSelfIntersections(m);
  ASSERT_GT(all.pairs.size(), 10u);
  EXPECT_FALSE(all.truncated);
  SelfIntersectionOptions options;
  options.max_pairs = 10;
  const SelfIntersections few = findSelfIntersections(m, options);
  EXPECT_TRUE(few.truncated);
  EXPECT_EQ(few.pairs, Pairs(all.pairs.begin(), all.pairs.begin() + 10));
  options.max_pairs = static_cast<int64_t>(all.pairs.size());
  EXPECT_FALSE(findSelfIntersections(m, options).truncated);
}

}  // namespace
}  // namespace sphereset

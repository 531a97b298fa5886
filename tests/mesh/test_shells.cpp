// Shells: edge-connected components with their own diagnosis, crossings between shells, and
// the nesting of closed shells (parent, depth), including inward-facing and non-nested cases.
#include <gtest/gtest.h>

#include <vector>

#include "sphereset/mesh_defects.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

Mesh flipped(Mesh m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

Mesh box(double lo, double hi) { return test::makeBox(Vec3::Constant(lo), Vec3::Constant(hi)); }

TEST(Shells, OneCleanShell) {
  const Mesh m = test::makeIcosphere(1.0, 2);
  const ShellAnalysis a = analyzeShells(m);
  ASSERT_EQ(a.shells.size(), 1u);
  const Shell& s = a.shells[0];
  EXPECT_TRUE(s.clean());
  EXPECT_EQ(s.triangles.size(), m.triangles.size());
  EXPECT_GT(s.volume, 0.0);
  EXPECT_EQ(s.parent, -1);
  EXPECT_EQ(s.depth, 0);
  EXPECT_TRUE(a.intersecting.empty());
}

TEST(Shells, OverlappingBoxesIntersectAndDoNotNest) {
  const ShellAnalysis a = analyzeShells(test::joined(box(0.0, 1.0), box(0.5, 1.5)));
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_EQ(a.intersecting, (std::vector<std::array<int32_t, 2>>{{0, 1}}));
  EXPECT_TRUE(a.intersections.any());
  for (const Shell& s : a.shells) {
    EXPECT_TRUE(s.clean());  // each box is fine on its own
    EXPECT_EQ(s.parent, -1);
    EXPECT_EQ(s.depth, 0);
    EXPECT_NEAR(s.volume, 1.0, 1e-12);
  }
}

TEST(Shells, NestedBoxes) {
  // Listed inner first so that the parent is not simply the previous shell.
  for (bool inward : {false, true}) {
    const Mesh inner = inward ? flipped(box(1.0, 2.0)) : box(1.0, 2.0);
    const ShellAnalysis a =
        analyzeShells(test::joined(test::joined(inner, box(0.0, 3.0)), box(-1.0, 4.0)));
    ASSERT_EQ(a.shells.size(), 3u);
    EXPECT_FALSE(a.intersections.any());
    EXPECT_TRUE(a.intersecting.empty());
    EXPECT_EQ(a.shells[0].parent, 1) << inward;
    EXPECT_EQ(a.shells[0].depth, 2);
    EXPECT_EQ(a.shells[1].parent, 2);
    EXPECT_EQ(a.shells[1].depth, 1);
    EXPECT_EQ(a.shells[2].parent, -1);
    EXPECT_EQ(a.shells[2].depth, 0);
    EXPECT_EQ(a.shells[0].volume < 0.0, inward);
    EXPECT_TRUE(a.shells[0].oriented);
  }
}

TEST(Shells, InsideAnInwardFacingContainer) {
  const ShellAnalysis a = analyzeShells(test::joined(flipped(box(0.0, 3.0)), box(1.0, 2.0)));
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_EQ(a.shells[1].parent, 0);
  EXPECT_EQ(a.shells[1].depth, 1);
  EXPECT_EQ(a.shells[0].parent, -1);
}

TEST(Shells, BoundingBoxContainmentIsNotEnough) {
  // A small box in the hole of a torus: inside its bounding box, outside the solid.
  const ShellAnalysis a =
      analyzeShells(test::joined(test::makeTorus(2.0, 0.5, 32, 16), box(-0.2, 0.2)));
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_EQ(a.shells[1].parent, -1);
  EXPECT_EQ(a.shells[1].depth, 0);
  // In the tube itself it is nested.
  const ShellAnalysis b =
      analyzeShells(test::joined(test::makeTorus(2.0, 0.5, 32, 16),
                                 test::makeBox(Vec3(1.9, -0.1, -0.1), Vec3(2.1, 0.1, 0.1))));
  EXPECT_EQ(b.shells[1].parent, 0);
}

TEST(Shells, OpenShellsDoNotNest) {
  Mesh open = box(0.0, 3.0);
  open.triangles.resize(10);  // one face missing
  const ShellAnalysis a = analyzeShells(test::joined(open, box(1.0, 2.0)));
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_FALSE(a.shells[0].closed);
  EXPECT_TRUE(a.shells[1].closed);
  EXPECT_EQ(a.shells[1].parent, -1);
  EXPECT_EQ(a.shells[1].depth, 0);
}

TEST(Shells, SelfIntersectingShell) {
  Mesh m = test::joined(box(0.0, 1.0), box(5.0, 6.0));
  m.triangles.push_back(m.triangles[3]);  // a duplicated face of the first box
  const ShellAnalysis a = analyzeShells(m);
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_TRUE(a.shells[0].self_intersecting);
  EXPECT_FALSE(a.shells[0].clean());
  EXPECT_FALSE(a.shells[1].self_intersecting);
  EXPECT_TRUE(a.shells[1].clean());
  EXPECT_TRUE(a.intersecting.empty());
}

TEST(Shells, ManySmallShellsInOneContainer) {
  // 20 × 20 × 5 small boxes inside one big box, plus the same number outside it.
  Mesh m = box(-1.0, 21.0);
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j)
        for (int k = 0; k < 5; ++k) {
          const Vec3 lo(i + 0.25 + 30.0 * side, j + 0.25, k + 0.25);
          m = test::joined(std::move(m), test::makeBox(lo, lo + Vec3::Constant(0.5)));
        }
  const ShellAnalysis a = analyzeShells(m);
  ASSERT_EQ(a.shells.size(), 4001u);
  int nested = 0;
  for (size_t s = 1; s < a.shells.size(); ++s)
    if (a.shells[s].parent == 0 && a.shells[s].depth == 1) ++nested;
  EXPECT_EQ(nested, 2000);
  EXPECT_EQ(a.shells[0].depth, 0);
}

TEST(Shells, SubmeshDropsUnusedVertices) {
  const Mesh m = test::joined(box(0.0, 1.0), box(2.0, 3.0));
  const std::vector<int32_t> second = {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
  const Mesh sub = submesh(m, second);
  EXPECT_EQ(sub.vertices.size(), 8u);
  ASSERT_EQ(sub.triangles.size(), 12u);
  for (size_t t = 0; t < 12; ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(sub.vertices[sub.triangles[t][k]], m.vertices[m.triangles[12 + t][k]]);
  EXPECT_TRUE(diagnoseMesh(sub).isSolid());
}

}  // namespace
}  // namespace sphereset

// The nesting plan's roles on nested cubes: a solid, a cavity in it, an island in the cavity, an
// outward cube inside another without a cavity, an inside-out cube; by the nested-shells rules
// (nothing crosses) and by the union rules (two other cubes cross), where they differ.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>
#include <vector>

#include "broken_meshes.hpp"
#include "repair/nesting_plan.hpp"

namespace sphereset::test {
namespace {

using detail::ShellRole;

// An axis-aligned cube from lo to hi in every coordinate, facing outward or inward.
Mesh cube(double lo, double hi, bool inward = false) {
  Mesh m = makeBox(Vec3::Constant(lo), Vec3::Constant(hi));
  if (inward)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// The cubes as one mesh; shell i is the i-th cube.
Mesh cubes(std::initializer_list<Mesh> parts) {
  Mesh m;
  for (const Mesh& p : parts) m = joined(m, p);
  return m;
}

std::vector<ShellRole> roles(const Mesh& m, bool fill_cavities) {
  const ShellAnalysis sa = analyzeShells(m);
  const auto plan = detail::planNesting(sa, fill_cavities);
  if (!plan) return {};
  return plan->roles;
}

// A solid with a cavity and an island in the cavity, a cube inside another without a cavity,
// and an inside-out cube.
Mesh nestingExamples() {
  return cubes({cube(0, 10), cube(1, 9, true), cube(2, 8),  // solid, cavity, island
                cube(20, 30), cube(21, 29),                 // outward inside outward
                cube(40, 41, true)});                       // inside out
}

TEST(NestingPlan, SolidCavityIslandAndNestedCubeByTheNestedShellsRules) {
  const ShellAnalysis sa = analyzeShells(nestingExamples());
  ASSERT_EQ(sa.shells.size(), 6u);
  ASSERT_TRUE(sa.intersecting.empty());
  const auto plan = detail::planNesting(sa, false);
  ASSERT_TRUE(plan.has_value());
  EXPECT_FALSE(plan->union_rules);
  EXPECT_EQ(plan->roles, (std::vector<ShellRole>{
                             ShellRole::kOuter, ShellRole::kCavity, ShellRole::kIsland,
                             ShellRole::kOuter, ShellRole::kDroppedInside, ShellRole::kInsideOut}));
  // From the outermost in: the three outermost cubes, the two inside them, then the island.
  EXPECT_EQ(plan->order, (std::vector<size_t>{0, 3, 5, 1, 4, 2}));
}

TEST(NestingPlan, FilledCavityTakesItsIslandWithIt) {
  // The island lies inside the solid once the cavity is filled: dropped like the nested cube.
  EXPECT_EQ(roles(nestingExamples(), true),
            (std::vector<ShellRole>{ShellRole::kOuter, ShellRole::kFilledCavity,
                                    ShellRole::kDroppedInside, ShellRole::kOuter,
                                    ShellRole::kDroppedInside, ShellRole::kInsideOut}));
}

TEST(NestingPlan, CrossingCubesSwitchToTheUnionRules) {
  // The same cubes and two that cross: the nested cube is united (the union absorbs it) rather
  // than dropped; the cavity and its island are kept apart from the union.
  Mesh m = cubes({nestingExamples(), cube(50, 52), cube(51, 53)});
  const ShellAnalysis sa = analyzeShells(m);
  ASSERT_EQ(sa.intersecting.size(), 1u);
  const auto plan = detail::planNesting(sa, false);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE(plan->union_rules);
  EXPECT_EQ(plan->roles,
            (std::vector<ShellRole>{ShellRole::kOuter, ShellRole::kCavity, ShellRole::kIsland,
                                    ShellRole::kOuter, ShellRole::kUnitedInside,
                                    ShellRole::kInsideOut, ShellRole::kOuter, ShellRole::kOuter}));
  EXPECT_EQ(roles(m, true), (std::vector<ShellRole>{ShellRole::kOuter, ShellRole::kFilledCavity,
                                                    ShellRole::kDroppedInside, ShellRole::kOuter,
                                                    ShellRole::kUnitedInside, ShellRole::kInsideOut,
                                                    ShellRole::kOuter, ShellRole::kOuter}));
}

TEST(NestingPlan, WhatLiesInsideAnIslandDependsOnTheRules) {
  // Solid, cavity, island; in the island a cavity and in that an island; in the first cavity
  // also an inward cube beside the island, and in the first island an outward cube.
  const Mesh nest = cubes({cube(0, 20), cube(1, 19, true), cube(2, 10),  // solid, cavity, island
                           cube(3, 9, true), cube(4, 8),                 // inside the island
                           cube(11, 18, true), cube(12, 17),             // beside the island
                           cube(2.5, 2.9)});                             // in the island
  // Nested-shells rules: an island is a solid; an inward cube in a kept cavity adds nothing and
  // what lies in it is planned as if it lay in the cavity.
  EXPECT_EQ(
      roles(nest, false),
      (std::vector<ShellRole>{ShellRole::kOuter, ShellRole::kCavity, ShellRole::kIsland,
                              ShellRole::kCavity, ShellRole::kIsland, ShellRole::kDroppedInside,
                              ShellRole::kIsland, ShellRole::kDroppedInside}));
  // Union rules: what an island or a cavity holds is filled when inward, kept apart when an
  // outward island, and what a filled cube holds is filled with it.
  EXPECT_EQ(roles(cubes({nest, cube(50, 52), cube(51, 53)}), false),
            (std::vector<ShellRole>{ShellRole::kOuter, ShellRole::kCavity, ShellRole::kIsland,
                                    ShellRole::kFilledCavity, ShellRole::kDroppedInside,
                                    ShellRole::kFilledCavity, ShellRole::kDroppedInside,
                                    ShellRole::kIsland, ShellRole::kOuter, ShellRole::kOuter}));
}

TEST(NestingPlan, OpenOrSelfIntersectingShellsAreNotPlanned) {
  Mesh open = cube(0, 1);
  open.triangles.pop_back();
  EXPECT_FALSE(detail::planNesting(analyzeShells(open), true).has_value());
  EXPECT_FALSE(detail::planNesting(analyzeShells(bowTiePrism()), true).has_value());
  EXPECT_TRUE(detail::planNesting(analyzeShells(cube(0, 1)), true).has_value());
}

}  // namespace
}  // namespace sphereset::test

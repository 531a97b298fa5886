// Self-collision pairs by sampling the joint space on the three-link test robot with hand-made
// spheres: MoveIt's reasons (adjacent from the joints, default at the default pose, a pair made
// to collide in most samples, pairs that never collide), the same counts on one thread and two,
// the exact mesh check, the option table, and cuRobo's ignore list from the result.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using Reasons = std::map<std::string, std::string>;  // "a/b" -> reason

Reasons reasons(const CollisionMatrix& m) {
  Reasons out;
  for (const DisabledPair& p : m.disabled)
    out[p.link1 + "/" + p.link2] = disableReasonName(p.reason);
  return out;
}

CollisionSamplingOptions withSamples(int samples) {
  CollisionSamplingOptions o;
  o.samples = samples;
  return o;
}

const DisabledPair* findPair(const CollisionMatrix& m, const std::string& a, const std::string& b) {
  for (const DisabledPair& p : m.disabled)
    if (p.link1 == a && p.link2 == b) return &p;
  return nullptr;
}

// At the zero pose (see test_self_collision.cpp): base-link2 and base-tool overlap, link2-tool
// are joined. link1's sphere is 0.2 from joint2's centre and tool's 0.5: never closer than 0.3.
std::vector<LinkSpheres> matrixHandSpheres() {
  return {{"base_link", {Sphere{Vec3(0.5, 0, 0.5), 0.1}}},
          {"link1", {Sphere{Vec3(0, 0, 0.2), 0.05}}},
          {"link2", {Sphere{Vec3(0.45, 0, 0), 0.05}}},
          {"tool", {Sphere{Vec3(0, 0, 0), 0.05}}}};
}

// In link1's frame tool's origin is at (0, 0, 0.4) + 0.5 (cos q2, 0, -sin q2). link1's sphere of
// radius 0.7 centred on that circle at q2 = 0.25 and tool's of radius 0.0675 overlap when the
// chord 2 · 0.5 sin(|q2 - 0.25| / 2) is below 0.7675: for q2 in (-1.5006, 2], 87.5 % of
// [-2, 2]; at q2 = -2 the chord is 0.902, apart. The base sphere is below anything's reach.
std::vector<LinkSpheres> mostlyTouching() {
  const double q = 0.25;
  return {{"base_link", {Sphere{Vec3(0, 0, -1), 0.01}}},
          {"link1", {Sphere{Vec3(0.5 * std::cos(q), 0, 0.4 - 0.5 * std::sin(q)), 0.7}}},
          {"link2", {Sphere{Vec3(0, 0, 0), 0.01}}},
          {"tool", {Sphere{Vec3(0, 0, 0), 0.0675}}}};
}

TEST(CollisionMatrix, ReasonsAtTheZeroPose) {
  const Robot robot = test::threeLinkRobot();
  CollisionSamplingOptions o;
  o.samples = 2000;
  auto m = sampleSelfCollisions(robot, matrixHandSpheres(), o);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(reasons(*m), (Reasons{{"base_link/link1", "Adjacent"},
                                  {"link1/link2", "Adjacent"},
                                  {"link2/tool", "Adjacent"},
                                  {"base_link/link2", "Default"},
                                  {"base_link/tool", "Default"},
                                  {"link1/tool", "Never"}}));
  EXPECT_EQ(m->samples, 2000);
  EXPECT_EQ(m->pairs, 6);
  EXPECT_EQ(m->enabled, 0);
  EXPECT_EQ(m->count(DisableReason::kAdjacent), 3);
  EXPECT_EQ(m->count(DisableReason::kDefault), 2);
  EXPECT_EQ(m->count(DisableReason::kNever), 1);
  // Sorted by the robot's link order.
  ASSERT_EQ(m->disabled.size(), 6u);
  EXPECT_EQ(m->disabled.front().link1, "base_link");
  EXPECT_EQ(m->disabled.back().link1, "link2");
}

TEST(CollisionMatrix, AlwaysAboveTheFractionAndDefaultPoseFirst) {
  const Robot robot = test::threeLinkRobot();
  CollisionSamplingOptions o;
  o.samples = 4000;
  o.always_fraction = 0.8;
  o.default_pose = {{"joint2", -2.0}};
  auto m = sampleSelfCollisions(robot, mostlyTouching(), o);
  ASSERT_TRUE(m.ok()) << m.error().message;
  const DisabledPair* p = findPair(*m, "link1", "tool");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(disableReasonName(p->reason), std::string("Always"));
  EXPECT_GT(p->collisions, 0.85 * 4000);  // 87.5 % expected
  EXPECT_LT(p->collisions, 0.90 * 4000);
  EXPECT_EQ(disableReasonName(findPair(*m, "base_link", "tool")->reason), std::string("Never"));
  EXPECT_EQ(disableReasonName(findPair(*m, "base_link", "link2")->reason), std::string("Never"));
  // MoveIt's 95 %: the pair is left to check.
  o.always_fraction = 0.95;
  m = sampleSelfCollisions(robot, mostlyTouching(), o);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(findPair(*m, "link1", "tool"), nullptr);
  EXPECT_EQ(m->enabled, 1);
  // At the zero pose the pair collides: "Default" comes before "Always".
  o.default_pose.clear();
  o.always_fraction = 0.8;
  m = sampleSelfCollisions(robot, mostlyTouching(), o);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(disableReasonName(findPair(*m, "link1", "tool")->reason), std::string("Default"));
}

// Revolute limits of ±1e308 used to make every sampled configuration infinite, every sample was
// skipped and a pair that collides was written "Never" (SRDF, cuRobo's ignore list): the joint is
// sampled over one turn, where link1 and tool touch for q2 in (-1.501, 2.001), 55.7 % of it.
TEST(CollisionMatrix, HugeRevoluteLimitsSampleOneTurn) {
  Robot robot = test::threeLinkRobot();
  for (RobotJoint& j : robot.joints)
    if (j.name == "joint2") {
      j.lower = -1e308;
      j.upper = 1e308;
    }
  CollisionSamplingOptions o;
  o.samples = 4000;
  o.default_pose = {{"joint2", -2.0}};
  auto m = sampleSelfCollisions(robot, mostlyTouching(), o);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(findPair(*m, "link1", "tool"), nullptr) << "a pair that collides was disabled";
  EXPECT_EQ(m->enabled, 1);
  // Limits no pose can use (a robot made in code, not read): an error, never "Never".
  for (RobotJoint& j : robot.joints)
    if (j.name == "joint2") j.type = RobotJoint::Type::kPrismatic;
  m = sampleSelfCollisions(robot, mostlyTouching(), o);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("sampled configuration"), std::string::npos)
      << m.error().message;
}

TEST(CollisionMatrix, SameOnAnyThreadCountAndSeedMatters) {
  const Robot robot = test::threeLinkRobot();
  CollisionSamplingOptions o;
  o.samples = 3000;
  o.always_fraction = 0.8;
  o.default_pose = {{"joint2", -2.0}};
  auto collisions = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    auto m = sampleSelfCollisions(robot, mostlyTouching(), o);
    EXPECT_TRUE(m.ok());
    return m.ok() ? findPair(*m, "link1", "tool")->collisions : int64_t{-1};
  };
  const int64_t one = collisions(1);
  EXPECT_GT(one, 0);
  EXPECT_EQ(collisions(2), one);
  EXPECT_EQ(collisions(4), one);
  o.seed = 2;
  EXPECT_NE(collisions(2), one);  // other configurations
}

TEST(CollisionMatrix, DefaultSampleCountFromTheMovableJoints) {
  const Robot robot = test::threeLinkRobot();
  EXPECT_EQ(defaultSampleCount(robot), 4000);  // two revolute joints
  auto m = sampleSelfCollisions(robot, matrixHandSpheres(), {});
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->samples, 4000);
  Robot fixed = robot;
  for (RobotJoint& j : fixed.joints) j.type = RobotJoint::Type::kFixed;
  EXPECT_EQ(defaultSampleCount(fixed), 1000);
}

TEST(CollisionMatrix, LinksWithoutGeometryJoinTheirNeighbours) {
  const Robot robot = test::threeLinkRobot();
  std::vector<LinkSpheres> s = matrixHandSpheres();
  s[1].spheres.clear();  // link1 has none: base_link and link2 become adjacent
  s.push_back({"no_such_link", {Sphere{Vec3(0, 0, 0), 1.0}}});
  auto m = sampleSelfCollisions(robot, s, withSamples(500));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(reasons(*m), (Reasons{{"base_link/link2", "Adjacent"},
                                  {"link2/tool", "Adjacent"},
                                  {"base_link/tool", "Default"}}));
  EXPECT_EQ(m->pairs, 3);
}

TEST(CollisionMatrix, MeshesDecideWhenAsked) {
  const Robot robot = test::threeLinkRobot();
  // base_link's sphere reaches tool's at the zero pose, but its solid, a box below the reach of
  // tool (whose origin is never below z = 0), never meets tool's box.
  std::vector<LinkSpheres> s = matrixHandSpheres();
  s[0].spheres = {Sphere{Vec3(0.25, 0, 0), 0.8}};
  std::vector<CollisionSolid> solids = {
      {"base_link", test::makeBox(Vec3(-0.1, -0.1, -0.6), Vec3(0.1, 0.1, -0.4)), {}},
      {"tool", test::makeBox(Vec3(-0.02, -0.02, -0.02), Vec3(0.02, 0.02, 0.02)), {}}};
  CollisionSamplingOptions o;
  o.samples = 1000;
  auto spheres = sampleSelfCollisions(robot, s, o, solids);
  ASSERT_TRUE(spheres.ok());
  EXPECT_EQ(reasons(*spheres)["base_link/tool"], "Default");  // solids ignored
  o.check = CollisionCheck::kMeshes;
  auto meshes = sampleSelfCollisions(robot, s, o, solids);
  ASSERT_TRUE(meshes.ok());
  EXPECT_EQ(reasons(*meshes)["base_link/tool"], "Never");
  EXPECT_EQ(meshes->check, CollisionCheck::kMeshes);
  // Two bars crossing like a plus sign at tool's origin at the zero pose, (0.5, 0, 0.5): tool's
  // along x, base_link's along y; neither has a corner in the other, only triangles cross.
  solids[1].mesh = test::makeBox(Vec3(-0.3, -0.01, -0.01), Vec3(0.3, 0.01, 0.01));
  solids[0].mesh = test::makeBox(Vec3(0.49, -0.3, 0.49), Vec3(0.51, 0.3, 0.51));
  meshes = sampleSelfCollisions(robot, s, o, solids);
  ASSERT_TRUE(meshes.ok());
  EXPECT_EQ(reasons(*meshes)["base_link/tool"], "Default");
  // A box holding tool's box whole: no triangles cross, the containment test finds it.
  solids[0].mesh = test::makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  meshes = sampleSelfCollisions(robot, s, o, solids);
  ASSERT_TRUE(meshes.ok());
  EXPECT_EQ(reasons(*meshes)["base_link/tool"], "Default");
}

TEST(CollisionMatrix, BadOptionsAndPoseAreRefused) {
  const Robot robot = test::threeLinkRobot();
  CollisionSamplingOptions o;
  o.always_fraction = 0.3;
  auto m = sampleSelfCollisions(robot, matrixHandSpheres(), o);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(m.error().message.find("always_fraction '0.3'"), std::string::npos)
      << m.error().message;
  o = {};
  o.samples = -1;
  EXPECT_FALSE(sampleSelfCollisions(robot, matrixHandSpheres(), o).ok());
  o = {};
  o.default_pose = {{"joint9", 1.0}};
  m = sampleSelfCollisions(robot, matrixHandSpheres(), o);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("default_pose: no joint 'joint9'"), std::string::npos)
      << m.error().message;
}

TEST(CollisionMatrix, OptionTableSetsEveryRow) {
  CollisionSamplingOptions o;
  EXPECT_TRUE(setCollisionSamplingOption(&o, "collision_samples", "123").ok());
  EXPECT_TRUE(setCollisionSamplingOption(&o, "collision_seed", "18446744073709551615").ok());
  EXPECT_TRUE(setCollisionSamplingOption(&o, "always_fraction", "0.9").ok());
  EXPECT_TRUE(setCollisionSamplingOption(&o, "default_pose", "joint1=-0.5").ok());
  EXPECT_TRUE(setCollisionSamplingOption(&o, "collision_check", "meshes").ok());
  EXPECT_EQ(o.samples, 123);
  EXPECT_EQ(o.seed, 18446744073709551615ull);
  EXPECT_EQ(o.always_fraction, 0.9);
  EXPECT_EQ(o.default_pose.at("joint1"), -0.5);
  EXPECT_EQ(o.check, CollisionCheck::kMeshes);
  const Status bad = setCollisionSamplingOption(&o, "collision_check", "fcl");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("spheres or meshes"), std::string::npos)
      << bad.error().message;
  EXPECT_FALSE(setCollisionSamplingOption(&o, "collision_samples", "-3").ok());
  EXPECT_FALSE(setCollisionSamplingOption(&o, "samples", "3").ok());  // not a row
}

TEST(CollisionMatrix, CuroboIgnoresEveryDisabledPair) {
  const Robot robot = test::threeLinkRobot();
  auto m = sampleSelfCollisions(robot, matrixHandSpheres(), withSamples(500));
  ASSERT_TRUE(m.ok());
  const SelfCollisionPairs p = ignoredPairs(*m);
  EXPECT_EQ(p.adjacent,
            (test::LinkPairs{{"base_link", "link1"}, {"link1", "link2"}, {"link2", "tool"}}));
  EXPECT_EQ(p.overlapping,
            (test::LinkPairs{{"base_link", "link2"}, {"base_link", "tool"}, {"link1", "tool"}}));
}

}  // namespace
}  // namespace sphereset

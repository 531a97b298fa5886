// Self-collision pairs on the three-link test robot with hand-made spheres: adjacent pairs from
// the joints, overlapping pairs at the zero pose and at another value of joint2, ordering, and
// links without spheres.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"

namespace sphereset {
namespace {

using test::LinkPairs;

// Link frames at the zero pose (root frame): base_link at 0, link1 at (0, 0, 0.1), link2 at
// (0, 0, 0.5), tool at (0.5, 0, 0.5). joint2 turns link2 and tool about y through (0, 0, 0.5).
//   base_link: (0.5, 0, 0.5) r 0.1           -> world (0.5, 0, 0.5)
//   link1:     (0, 0, 0.2)   r 0.05          -> world (0, 0, 0.3)
//   link2:     (0.45, 0, 0)  r 0.05          -> world (0.45, 0, 0.5)
//   tool:      (0, 0, 0)     r 0.05          -> world (0.5, 0, 0.5)
// At zero: base-link2 0.05 < 0.15, base-tool 0 < 0.15, link2-tool 0.05 < 0.1 overlap; link1 is
// 0.5 or more from the others. At joint2 = 1 rad a point (x, 0, 0) of link2 is at
// (x cos 1, 0, 0.5 - x sin 1): link2's sphere at (0.2431, 0, 0.1213), 0.458 from base's centre,
// and tool at (0.2702, 0, 0.0793), 0.479 from it: only link2-tool (rigidly joined) overlaps.
std::vector<LinkSpheres> handSpheres() {
  return {{"base_link", {Sphere{Vec3(0.5, 0, 0.5), 0.1}}},
          {"link1", {Sphere{Vec3(0, 0, 0.2), 0.05}}},
          {"link2", {Sphere{Vec3(0.45, 0, 0), 0.05}}},
          {"tool", {Sphere{Vec3(0, 0, 0), 0.05}}}};
}

TEST(SelfCollision, AdjacentPairsFromJoints) {
  const Robot robot = test::threeLinkRobot();
  const SelfCollisionPairs p = *selfCollisionPairs(robot, handSpheres());
  EXPECT_EQ(p.adjacent, (LinkPairs{{"base_link", "link1"}, {"link1", "link2"}, {"link2", "tool"}}));
}

TEST(SelfCollision, OverlapAtZeroPose) {
  const Robot robot = test::threeLinkRobot();
  const SelfCollisionPairs p = *selfCollisionPairs(robot, handSpheres());
  EXPECT_EQ(p.overlapping,
            (LinkPairs{{"base_link", "link2"}, {"base_link", "tool"}, {"link2", "tool"}}));
}

TEST(SelfCollision, OverlapSeparatesAtAnotherJointValue) {
  const Robot robot = test::threeLinkRobot();
  const SelfCollisionPairs p = *selfCollisionPairs(robot, handSpheres(), {{"joint2", 1.0}});
  EXPECT_EQ(p.overlapping, (LinkPairs{{"link2", "tool"}}));
  // Adjacency does not depend on the pose.
  EXPECT_EQ(p.adjacent.size(), 3u);
  // The base sphere is off joint1's axis (z): joint1 = 1.5 rad takes link2's sphere to
  // (0.0318, 0.4489, 0.5), 0.649 from it, and tool further.
  const SelfCollisionPairs q = *selfCollisionPairs(robot, handSpheres(), {{"joint1", 1.5}});
  EXPECT_EQ(q.overlapping, (LinkPairs{{"link2", "tool"}}));
}

TEST(SelfCollision, TouchingIsNotOverlapping) {
  const Robot robot = test::threeLinkRobot();
  // base's sphere at 0 r 0.25 and link1's at world (0, 0, 0.1 + 0.4) r 0.25 touch (distance
  // 0.5 = 0.25 + 0.25, exact in binary); a radius a little larger overlaps.
  std::vector<LinkSpheres> s = {{"base_link", {Sphere{Vec3(0, 0, 0), 0.25}}},
                                {"link1", {Sphere{Vec3(0, 0, 0.4), 0.25}}}};
  EXPECT_TRUE(selfCollisionPairs(robot, s)->overlapping.empty());
  s[0].spheres[0].radius = 0.2501;
  EXPECT_EQ(selfCollisionPairs(robot, s)->overlapping, (LinkPairs{{"base_link", "link1"}}));
}

TEST(SelfCollision, InputOrderAndEmptyLinksDoNotMatter) {
  const Robot robot = test::threeLinkRobot();
  std::vector<LinkSpheres> s = handSpheres();
  std::reverse(s.begin(), s.end());
  const SelfCollisionPairs p = *selfCollisionPairs(robot, s);
  EXPECT_EQ(p.overlapping,
            (LinkPairs{{"base_link", "link2"}, {"base_link", "tool"}, {"link2", "tool"}}));
  // A link without spheres overlaps nothing; unknown links are skipped.
  s = handSpheres();
  s[3].spheres.clear();
  s.push_back({"no_such_link", {Sphere{Vec3(0.5, 0, 0.5), 1.0}}});
  const SelfCollisionPairs q = *selfCollisionPairs(robot, s);
  EXPECT_EQ(q.overlapping, (LinkPairs{{"base_link", "link2"}}));
  EXPECT_EQ(q.adjacent.size(), 3u);
}

}  // namespace
}  // namespace sphereset

// The synthetic robot of the robot tests (tests/data/robot/three_link.urdf) and its package.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "test_meshes.hpp"

namespace sphereset::test {

// Link-name pairs, as SelfCollisionPairs and the planner files list them.
using LinkPairs = std::vector<std::array<std::string, 2>>;

inline std::string robotDir() { return dataPath("robot"); }
inline std::string threeLinkUrdf() { return dataPath("robot/three_link.urdf"); }
inline std::string threeLinkStl() {
  return dataPath("robot/three_link_description/meshes/link.stl");
}

// The robot loaded from its package folder alone (not ROS_PACKAGE_PATH); a failure fails the
// test and gives an empty robot.
inline Robot threeLinkRobot() {
  RobotLoadOptions o;
  o.package_paths = {robotDir()};
  o.use_ros_package_path = false;
  auto r = loadRobot(threeLinkUrdf(), o);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? *r : Robot{};
}

}  // namespace sphereset::test

// A build without MuJoCo: an MJCF robot is refused with the reason and how to build with it,
// never read as something else.
#include <gtest/gtest.h>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "test_support.hpp"

namespace sphereset::test {
namespace {

TEST(MjcfMissing, XmlRobotsAreRefusedWithTheReason) {
  EXPECT_FALSE(mujocoAvailable());
  const std::string in = dataPath("robot/mjcf/arm.xml");
  EXPECT_TRUE(isRobotDescriptionPath(in));
  expectError(loadRobot(in), ErrorCode::kUnreadable, in, "SPHERESET_WITH_MUJOCO=ON");
  const std::string out = tempPath("never.xml").string();
  expectError(formatSphereMjcf(threeLinkUrdf(), out, {}, {}), ErrorCode::kUnreadable, out,
              "built without MuJoCo");
}

}  // namespace
}  // namespace sphereset::test

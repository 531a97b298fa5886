// Fuzz target: readTrajectory on a .csv file (header of joint names, one waypoint per row) for a
// two-joint robot built in code, then the joint state of every waypoint it accepts.
#include "fuzz_input.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_query.hpp"

namespace {

sphereset::Robot twoJoints() {
  sphereset::Robot r;
  r.name = "fuzz";
  r.root = "base";
  for (const char* l : {"base", "upper", "lower"}) r.links.push_back({l, {}, false});
  sphereset::RobotJoint j1, j2;
  j1.name = "joint1";
  j1.parent = "base";
  j1.child = "upper";
  j1.type = sphereset::RobotJoint::Type::kRevolute;
  j1.lower = -1.0;
  j1.upper = 1.0;
  j2.name = "joint2";
  j2.parent = "upper";
  j2.child = "lower";
  j2.type = sphereset::RobotJoint::Type::kContinuous;
  r.joints = {j1, j2};
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".csv");
  static const sphereset::Robot robot = twoJoints();
  auto waypoints = sphereset::readTrajectory(file.write(data, size), robot);
  if (waypoints)
    for (const auto& w : *waypoints) (void)sphereset::jointState(robot, w);
  return 0;
}

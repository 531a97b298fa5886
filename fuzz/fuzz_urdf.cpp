// Fuzz target: loadRobot on a .urdf file (the nesting check, urdfdom and TinyXML, the project's
// own reading of collision and visual elements), then the link poses at the zero configuration.
#include "fuzz_input.hpp"
#include "sphereset/robot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".urdf");
  sphereset::RobotLoadOptions o;
  o.use_ros_package_path = false;
  auto robot = sphereset::loadRobot(file.write(data, size), o);
  if (robot) (void)sphereset::linkPoses(*robot, {});
  return 0;
}

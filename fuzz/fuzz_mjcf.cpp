// Fuzz target: loadRobot on an .xml file (an MJCF): the project's checks of the text, MuJoCo's
// parser and compiler under those limits with its fatal errors caught, the conversion of the
// compiled model (bodies, joints, geoms, meshes, the collision filter), then the link poses and
// each link's mesh.
#include "fuzz_input.hpp"
#include "sphereset/robot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".xml");
  auto robot = sphereset::loadRobot(file.write(data, size));
  if (!robot) return 0;
  (void)sphereset::linkPoses(*robot, {});
  for (const sphereset::RobotLink& link : robot->links) (void)sphereset::linkMesh(link, 8);
  return 0;
}

// sphereset query ROBOT.urdf SPHERES: the posed robot's spheres against a point cloud or
// obstacle spheres, at one configuration or along a trajectory (cmd_query_robot.cpp).
#pragma once

#include <string>
#include <vector>

namespace sphereset::cli {

struct RobotQueryArgs {
  std::string urdf, spheres;  // the robot and its spheres (cuRobo YAML, JSON, ... or sphere URDF)
  RobotLoadArgs load;
  std::string joint_positions, trajectory;
  std::string points, obstacle_spheres;  // exactly one of them
  bool json = false;
};

int runRobotQuery(const RobotQueryArgs& a);

}  // namespace sphereset::cli

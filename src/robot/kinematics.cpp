// Forward kinematics of a robot's joint tree: the pose of every link frame in the root frame
// for given joint values (revolute and continuous joints rotate about their axis, prismatic
// ones slide along it; fixed and other joints stay at their origin).
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"

namespace sphereset {

std::map<std::string, Eigen::Isometry3d> linkPoses(
    const Robot& robot, const std::map<std::string, double>& joint_values) {
  std::map<std::string, std::vector<const RobotJoint*>> children;
  for (const RobotJoint& j : robot.joints) children[j.parent].push_back(&j);

  std::map<std::string, Eigen::Isometry3d> poses;
  if (robot.root.empty()) return poses;
  poses[robot.root] = Eigen::Isometry3d::Identity();
  std::vector<std::string> stack = {robot.root};
  while (!stack.empty()) {
    const std::string parent = stack.back();
    stack.pop_back();
    const auto it = children.find(parent);
    if (it == children.end()) continue;
    for (const RobotJoint* j : it->second) {
      if (poses.count(j->child) != 0) continue;  // a loop: keep the first pose
      const auto v = joint_values.find(j->name);
      double q = v == joint_values.end() ? 0.0 : v->second;
      Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
      switch (j->type) {
        case RobotJoint::Type::kRevolute:
          q = std::clamp(q, std::min(j->lower, j->upper), std::max(j->lower, j->upper));
          motion.linear() = Eigen::AngleAxisd(q, j->axis).toRotationMatrix();
          break;
        case RobotJoint::Type::kContinuous:
          motion.linear() = Eigen::AngleAxisd(q, j->axis).toRotationMatrix();
          break;
        case RobotJoint::Type::kPrismatic:
          q = std::clamp(q, std::min(j->lower, j->upper), std::max(j->lower, j->upper));
          motion.translation() = q * j->axis;
          break;
        case RobotJoint::Type::kFixed:
        case RobotJoint::Type::kOther:
          break;
      }
      poses[j->child] = poses[parent] * j->origin * motion;
      stack.push_back(j->child);
    }
  }
  return poses;
}

}  // namespace sphereset

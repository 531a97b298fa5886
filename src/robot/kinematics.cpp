// Forward kinematics of a robot's joint tree: the pose of every link frame in the root frame
// for given joint values (revolute and continuous joints rotate about their axis, through the
// anchor of an MJCF joint, prismatic ones slide along it, both by the value less the joint's
// reference; fixed and other joints stay at their origin). Reference: the URDF
// specification (wiki.ros.org/urdf/XML/joint): limits, and <mimic> with
// value = multiplier · value(leader) + offset.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "util/number_text.hpp"

namespace sphereset {
namespace {

// Two values of a mimic joint are the same when they differ by less than this (rad or m): a
// value read back from a file of the state that was written.
constexpr double kMimicTolerance = 1e-9;

bool limited(const RobotJoint& j) {
  return j.type == RobotJoint::Type::kRevolute || j.type == RobotJoint::Type::kPrismatic;
}

// The value within the joint's limits, noting a clamp.
double clampToLimits(const RobotJoint& j, double q, std::vector<std::string>* notes) {
  if (!limited(j)) return q;
  const double lo = std::min(j.lower, j.upper), hi = std::max(j.lower, j.upper);
  if (q >= lo && q <= hi) return q;
  const double c = std::clamp(q, lo, hi);
  if (notes)
    notes->push_back("joint '" + j.name + "': " + detail::numberText(q) + " is beyond its " +
                     (q > hi ? "upper" : "lower") + " limit " + detail::numberText(c) +
                     ", clamped");
  return c;
}

}  // namespace

Expected<JointState> jointState(const Robot& robot,
                                const std::map<std::string, double>& joint_values) {
  std::map<std::string, const RobotJoint*> by_name;
  for (const RobotJoint& j : robot.joints) by_name.emplace(j.name, &j);
  for (const auto& [name, q] : joint_values) {
    if (by_name.count(name) == 0)
      return Error{ErrorCode::kInvalidArgument,
                   "no joint '" + name + "' in robot '" + robot.name + "'"};
    if (!std::isfinite(q))
      return Error{ErrorCode::kInvalidArgument,
                   "joint '" + name + "': " + detail::numberText(q) + " is not a finite number"};
  }
  JointState state;
  for (const RobotJoint& j : robot.joints) {
    if (j.mimic) {
      if (by_name.count(j.mimic->joint) == 0)
        return Error{ErrorCode::kInvalidData, "joint '" + j.name + "' mimics '" + j.mimic->joint +
                                                  "', which is not a joint of the robot"};
      continue;
    }
    const auto v = joint_values.find(j.name);
    state.values[j.name] =
        clampToLimits(j, v == joint_values.end() ? j.reference : v->second, &state.notes);
  }
  // Mimic joints, leaders first: each round settles those whose leader is settled; a round that
  // settles none leaves a cycle.
  for (bool progress = true; progress;) {
    progress = false;
    for (const RobotJoint& j : robot.joints) {
      if (!j.mimic || state.values.count(j.name) != 0) continue;
      const auto leader = state.values.find(j.mimic->joint);
      if (leader == state.values.end()) continue;
      const double q = j.mimic->multiplier * leader->second + j.mimic->offset;
      state.values[j.name] = clampToLimits(j, q, nullptr);
      progress = true;
    }
  }
  for (const RobotJoint& j : robot.joints)
    if (state.values.count(j.name) == 0)
      return Error{ErrorCode::kInvalidData,
                   "joint '" + j.name + "': its <mimic> joints form a cycle"};
  for (const auto& [name, q] : joint_values) {
    const RobotJoint& j = *by_name.at(name);
    if (j.mimic && std::fabs(state.values.at(name) - q) > kMimicTolerance)
      return Error{ErrorCode::kInvalidArgument, "joint '" + name + "' mimics '" + j.mimic->joint +
                                                    "' (value " +
                                                    detail::numberText(state.values.at(name)) +
                                                    "): give '" + j.mimic->joint + "' instead"};
  }
  return state;
}

Expected<std::map<std::string, Eigen::Isometry3d>> linkPoses(
    const Robot& robot, const std::map<std::string, double>& joint_values) {
  auto state = jointState(robot, joint_values);
  if (!state) return state.error();
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
      const double q = state->values.at(j->name);
      Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
      switch (j->type) {
        case RobotJoint::Type::kRevolute:
        case RobotJoint::Type::kContinuous:
          // About the axis through the anchor (MJCF; the origin in a URDF).
          motion.linear() = Eigen::AngleAxisd(q - j->reference, j->axis).toRotationMatrix();
          motion.translation() = j->anchor - motion.linear() * j->anchor;
          break;
        case RobotJoint::Type::kPrismatic:
          motion.translation() = (q - j->reference) * j->axis;
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

// The self-collision sampling's options as one table (robot_collision.hpp): the command line's
// flags of `sphereset robot` are made from it, and the library parses and checks what users type
// through it. Also MoveIt's reason strings and the default sample count.
#include <algorithm>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "sphereset/robot_collision.hpp"

namespace sphereset {
namespace {

constexpr double kAnyJointValue = std::numeric_limits<double>::max();
constexpr const char* kCheckNames[] = {"spheres", "meshes"};

constexpr OptionSpec kCollisionOptions[] = {
    {"collision_samples",
     "--collision-samples",
     OptionType::kInteger,
     0,
     10000000,
     {},
     "0",
     "Random configurations sampled for the self-collision pairs (0: 2000 per movable joint, "
     "from 1000 to 100000)"},
    {"collision_seed",
     "--collision-seed",
     OptionType::kUnsigned,
     0,
     0,
     {},
     "1",
     "Seed of the sampled configurations"},
    {"always_fraction",
     "--always-fraction",
     OptionType::kReal,
     0.5,
     1,
     {},
     "0.95",
     "A pair in collision in at least this fraction of the samples is disabled as \"Always\""},
    {"default_pose",
     "--default-pose",
     OptionType::kReal,
     -kAnyJointValue,
     kAnyJointValue,
     {},
     "0 each",
     "JOINT=VALUE: the joint's value (rad or m) in the default pose; repeatable",
     "JOINT"},
    {"collision_check", "--collision-check", OptionType::kChoice, 0, 0, kCheckNames, "spheres",
     "What a self-collision is measured on: spheres (the fitted sets) or meshes (the link "
     "solids, exactly)"},
};

}  // namespace

const char* disableReasonName(DisableReason reason) {
  switch (reason) {
    case DisableReason::kAdjacent:
      return "Adjacent";
    case DisableReason::kDefault:
      return "Default";
    case DisableReason::kAlways:
      return "Always";
    case DisableReason::kNever:
      return "Never";
  }
  return "Never";
}

std::span<const OptionSpec> collisionSamplingOptionTable() { return kCollisionOptions; }

Status setCollisionSamplingOption(CollisionSamplingOptions* o, const std::string& name,
                                  const std::string& text) {
  auto parsed = parseTableOption(kCollisionOptions, "collision", name, text);
  if (!parsed) return parsed.error();
  const OptionValue& v = parsed->value;
  const std::string_view n = parsed->spec->name;
  if (n == "collision_samples") o->samples = static_cast<int>(v.integer);
  if (n == "collision_seed") o->seed = v.unsigned_integer;
  if (n == "always_fraction") o->always_fraction = v.real;
  if (n == "default_pose") o->default_pose[v.key] = v.real;
  if (n == "collision_check")
    o->check = v.choice == "meshes" ? CollisionCheck::kMeshes : CollisionCheck::kSpheres;
  return {};
}

Status checkCollisionSamplingOptions(const CollisionSamplingOptions& o) {
  const std::pair<const char*, double> values[] = {{"collision_samples", o.samples},
                                                   {"always_fraction", o.always_fraction}};
  for (const auto& [name, value] : values)
    if (Status st = checkTableValue(kCollisionOptions, "collision", name, value); !st) return st;
  for (const auto& [joint, value] : o.default_pose)
    if (Status st = checkTableValue(kCollisionOptions, "collision", "default_pose", value, joint);
        !st)
      return st;
  return {};
}

int defaultSampleCount(const Robot& robot) {
  int movable = 0;
  for (const RobotJoint& j : robot.joints)
    if (!j.mimic && isMovable(j)) ++movable;
  return std::clamp(2000 * movable, 1000, 100000);
}

}  // namespace sphereset

// The link pairs a planner may leave out of self-collision checking, found as MoveIt's setup
// assistant finds them: by sampling the joint space. And the files that carry them: MoveIt's
// SRDF and Lula's (Isaac Sim's) robot description.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/options.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Why a pair is left out, with MoveIt's SRDF reason strings. A pair gets the first reason that
// applies, in this order (MoveIt's): adjacent, default, always, never.
enum class DisableReason {
  kAdjacent,  // "Adjacent": joined by a joint, or through links without geometry
  kDefault,   // "Default": in collision at the default pose
  kAlways,    // "Always": in collision in at least always_fraction of the samples
  kNever,     // "Never": in collision in none of the samples
};
const char* disableReasonName(DisableReason reason);

// What a collision between two links is measured on.
enum class CollisionCheck {
  kSpheres,  // their sphere sets overlap (strictly: touching is not overlapping)
  kMeshes,  // their solids touch or one holds the other (CollisionSolid; links given none: spheres)
};

struct CollisionSamplingOptions {
  // Random configurations sampled. 0: chosen from the robot, defaultSampleCount.
  int samples = 0;
  uint64_t seed = 1;
  // A pair in collision in at least this fraction of the samples is "Always" (MoveIt: 95 %).
  double always_fraction = 0.95;
  // The default pose (joint -> radians or metres; joints not given at 0), through jointState:
  // clamped to the limits, mimic joints following.
  std::map<std::string, double> default_pose;
  CollisionCheck check = CollisionCheck::kSpheres;
  // Called from the calling thread after each block of configurations (stage "self-collision",
  // about a hundred blocks in all). It may throw to cancel: the exception leaves
  // sampleSelfCollisions.
  std::function<void(const RobotProgress&)> progress;
};

// CollisionSamplingOptions as one table (options.hpp): collision_samples, collision_seed,
// always_fraction, default_pose (keyed JOINT=VALUE) and collision_check (spheres or meshes).
// The command line's flags of `sphereset robot` are made from it. setCollisionSamplingOption
// sets a row from the text a user typed; checkCollisionSamplingOptions checks a struct against
// the rows with the same messages.
std::span<const OptionSpec> collisionSamplingOptionTable();
Status setCollisionSamplingOption(CollisionSamplingOptions* o, const std::string& name,
                                  const std::string& text);
Status checkCollisionSamplingOptions(const CollisionSamplingOptions& o);

// Configuration `i` of the sampling with `seed` (joint -> value, the joints sampleSelfCollisions
// draws): to pose a sample again, e.g. to see a pair in contact.
std::map<std::string, double> collisionSampleConfiguration(const Robot& robot, uint64_t seed,
                                                           int64_t i);

// The sample count when none is asked for: 2000 per movable joint that is not a mimic joint
// (revolute, continuous, prismatic), at least 1000 and at most 100000.
int defaultSampleCount(const Robot& robot);

// A link's solid for CollisionCheck::kMeshes, in the link frame: a closed, outward-oriented mesh
// (e.g. RepairResult::walls of the link's fit, or ::solid when no openings were closed), and
// its sphere primitives, exact.
struct CollisionSolid {
  std::string link;
  Mesh mesh;
  std::vector<Sphere> primitives;
};

// The solids of every link with geometry: its walls (linkSolid with `repair`, whose
// fill_openings is ignored: links collide where their walls meet, never their envelopes) and its
// sphere primitives; a link of primitives alone has no mesh. Errors: those of linkSolid.
Expected<std::vector<CollisionSolid>> robotCollisionSolids(const Robot& robot,
                                                           const RepairOptions& repair);
// The same from a robot fit, without repairing again: each link not skipped, its walls as the
// fit made them (RepairResult::walls when its solid is an envelope, else ::solid).
std::vector<CollisionSolid> fitCollisionSolids(const Robot& robot, const RobotFitResult& fit);

// One pair left out of self-collision checking; link1 comes before link2 in the robot's order.
struct DisabledPair {
  std::string link1, link2;
  DisableReason reason = DisableReason::kNever;
  int64_t collisions = 0;  // Always: the samples in collision; 0 for the others (not sampled)
};

struct CollisionMatrix {
  std::vector<DisabledPair> disabled;  // sorted by the robot's link order
  int64_t pairs = 0;                   // pairs of links with geometry
  int64_t enabled = 0;                 // pairs left to check: in collision in some samples only
  std::array<int64_t, 4> counts{};     // disabled pairs per reason, indexed by DisableReason
  int samples = 0;                     // configurations sampled
  CollisionCheck check = CollisionCheck::kSpheres;
  double seconds = 0.0;
  int64_t count(DisableReason r) const { return counts[static_cast<int>(r)]; }
};

// The pairs of links a planner may skip, as MoveIt's setup assistant computes them. The links
// taking part are those with spheres in `spheres` (in each link's frame) that the root reaches;
// entries naming no link of the robot are ignored, a link named twice counts as one set.
// `samples` configurations are drawn uniformly within the joint limits (continuous joints over
// [-π, π], mimic joints following their leaders, other joints at 0), configuration i from its
// own generator seeded by (seed, i), so the result is the same on any number of threads; they
// are checked in parallel. Each pair of links is tested first on one bounding sphere per link,
// then on the spheres (or, with CollisionCheck::kMeshes, on the solids of `solids`, exactly:
// triangles that meet, or a point of one inside the other). Adjacent: links joined by a joint,
// or joined through links without geometry (MoveIt's rule). Errors (kInvalidArgument, one
// line): options outside the table's rows, a default pose jointState refuses (its message).
Expected<CollisionMatrix> sampleSelfCollisions(const Robot& robot,
                                               const std::vector<LinkSpheres>& spheres,
                                               const CollisionSamplingOptions& options,
                                               const std::vector<CollisionSolid>& solids = {});

// The pairs for cuRobo's self_collision_ignore: the adjacent pairs, and every other disabled pair
// (default, always, never) in `overlapping`.
SelfCollisionPairs ignoredPairs(const CollisionMatrix& matrix);

// The pairs found in collision in none of the samples ("Never"): those an MJCF's
// <contact><exclude> may skip without losing a contact the links can make.
std::vector<std::array<std::string, 2>> neverPairs(const CollisionMatrix& matrix);

// The serial chain a planning group is made of: the path from the root to the link reached
// through the most movable joints that are not mimic joints (ties: the link first in the
// file), from the parent of its first movable joint to the child of its last. Nullopt when the
// robot has no movable joint.
struct RobotChain {
  std::string base_link, tip_link;
  std::vector<std::string> joints;  // the movable joints along it, from the base
};
std::optional<RobotChain> longestChain(const Robot& robot);

// MoveIt's SRDF: <robot name="...">, a group "manipulator" with the chain of longestChain (when
// there is one), and one <disable_collisions link1 link2 reason/> per disabled pair.
std::string formatSrdf(const Robot& robot, const CollisionMatrix& matrix);
// The <disable_collisions> pairs of an SRDF file (MoveIt's), each with link1 before link2 in
// the robot's order and its reason (unknown reasons, "User" included, read as kNever), sorted
// by the robot's link order. Errors: the file missing or unreadable (kUnreadable), not XML or
// not an SRDF, a pair without both links, a link the robot lacks (kInvalidData, with the line).
Expected<std::vector<DisabledPair>> readSrdfDisabledPairs(const std::string& path,
                                                          const Robot& robot);
// Written atomically.
Status writeSrdf(const std::string& path, const Robot& robot, const CollisionMatrix& matrix);

// Lula's robot description (Isaac Sim's robot_description.yaml): api_version 1.0; cspace, the
// movable joints that are not mimic joints in file order; root_link; default_q, their values at
// `default_pose` (through jointState); cspace_to_urdf_rules, the mimic joints held at their
// value there ({name, rule: fixed, value}); composite_task_spaces (empty); collision_spheres,
// a list of {LINK: [{center: [x, y, z], radius: r}, ...]} in the order of `spheres`. Errors:
// those of jointState; kInvalidData for a sphere with a NaN, an infinite value or a negative
// radius; kInvalidArgument for an empty or repeated link name.
Expected<std::string> formatLulaDescription(const Robot& robot,
                                            const std::vector<LinkSpheres>& spheres,
                                            const std::map<std::string, double>& default_pose);
// Written atomically.
Status writeLulaDescription(const std::string& path, const Robot& robot,
                            const std::vector<LinkSpheres>& spheres,
                            const std::map<std::string, double>& default_pose);

}  // namespace sphereset

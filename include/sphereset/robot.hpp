// Robot descriptions (URDF, and MJCF through MuJoCo where the build has it): the links with their
// collision geometry in the link frame, the joint tree, each link's geometry as one mesh, and
// forward kinematics. Plain data and free functions; the URDF parser (urdfdom) stays behind this
// header.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

struct RobotLoadOptions {
  // Folders searched, in order, for the packages of `package://NAME/...` mesh paths.
  std::vector<std::string> package_paths;
  // Also search the folders of the ROS_PACKAGE_PATH environment variable (colon-separated),
  // after `package_paths`.
  bool use_ros_package_path = true;
  // MJCF: the geoms of this group (0-5) are a body's collision geometry. -1 (the default): the
  // geoms MuJoCo collides, those with a non-zero contype or conaffinity.
  int mjcf_collision_group = -1;
};

// Whether this build reads and writes MJCF (MuJoCo, the CMake option SPHERESET_WITH_MUJOCO).
// Without it, loadRobot of an .xml file and writeSphereMjcf fail with kUnreadable, saying so.
bool mujocoAvailable();

// One <collision> element of a link (or one <visual> element when the link has no collision);
// in an MJCF, one collision geom of a body.
struct LinkGeometry {
  enum class Kind { kMesh, kBox, kCylinder, kSphere, kCapsule, kEllipsoid, kTriangles };
  Kind kind = Kind::kBox;
  std::string mesh_path;      // kMesh: the resolved file path (an existing file)
  Vec3 scale = Vec3::Ones();  // kMesh: scale of the mesh's own coordinates
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // element frame in the link frame
  Vec3 box_size = Vec3::Zero();  // kBox: full edge lengths along x, y, z, centred on the origin
  double radius = 0.0;           // kCylinder, kSphere, kCapsule
  double length = 0.0;        // kCylinder, kCapsule (between the caps' centres): along z, centred
  Vec3 radii = Vec3::Zero();  // kEllipsoid: semi-axes along x, y, z
  // kTriangles: the mesh itself (an MJCF mesh as MuJoCo compiled it: scaled and re-centred into
  // the geom's frame), shared by the geoms that use it.
  std::shared_ptr<const Mesh> triangles;
};

struct RobotLink {
  std::string name;
  std::vector<LinkGeometry> geometry;  // empty for links without geometry (e.g. a world link)
  bool from_visual = false;            // the geometry is the visual one (no collision given)
};

struct RobotJoint {
  enum class Type { kFixed, kRevolute, kContinuous, kPrismatic, kOther };
  std::string name;
  std::string parent;  // parent link name
  std::string child;   // child link name
  Type type = Type::kFixed;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // joint frame in the parent frame
  Vec3 axis = Vec3::UnitX();  // unit axis in the joint frame (revolute, continuous, prismatic)
  double lower = 0.0;         // limits (rad or m) of revolute and prismatic joints
  double upper = 0.0;
  // <mimic joint="J" multiplier="m" offset="o">: this joint's value is m · value(J) + o (then
  // clamped to its own limits), whatever is given for it (a gripper's second finger).
  struct Mimic {
    std::string joint;
    double multiplier = 1.0;
    double offset = 0.0;
  };
  std::optional<Mimic> mimic;
  // MJCF: the point of the joint frame the axis goes through (MuJoCo's joint `pos`) and the
  // value at which the joint is at its origin (`ref`, MuJoCo's qpos0). Zero in a URDF.
  Vec3 anchor = Vec3::Zero();
  double reference = 0.0;
};

struct Robot {
  std::string name;
  std::string root;                // the root link's name
  std::vector<RobotLink> links;    // in file order
  std::vector<RobotJoint> joints;  // in file order
  // Link pairs the description itself never checks for contact, first name first in `links`
  // order: in an MJCF, MuJoCo's filtering (bodies welded together or to a parent, contype and
  // conaffinity that never match) and <contact><exclude>. Empty for a URDF. The self-collision
  // functions treat them as adjacent.
  std::vector<std::array<std::string, 2>> excluded_pairs;
};

// How far a long robot computation is, for a door to show: `done` of `total` units of `stage`
// ("link curves": the budget's quick fits, one unit per link; "link fits": one unit per fit;
// "self-collision": sampled configurations), with the link just finished where there is one.
struct RobotProgress {
  std::string stage;
  int64_t done = 0, total = 0;
  std::string link;
};

// A joint type as the URDF spells it ("fixed", "revolute", "continuous", "prismatic"; "other" for
// the rest), for every front door that names joints.
const char* jointTypeName(RobotJoint::Type type);

// "J1=V1,J2=V2" (radians or metres) as joint values, each number read whatever the locale.
// kInvalidArgument "ITEM: expected JOINT=VALUE (a number)", or "joint 'J' is given twice" (a
// repeated value used to keep the last one silently). Names and values are checked against a
// robot by jointState.
Expected<std::map<std::string, double>> parseJointValues(const std::string& text);

// Whether `path` names a robot description: a URDF (".urdf") or an MJCF (".xml"), in any case
// ("arm.URDF" too). The one test of every door that takes a mesh or a robot.
bool isRobotDescriptionPath(const std::string& path);

// Whether a joint moves (revolute, continuous, prismatic): the one definition for every door.
bool isMovable(const RobotJoint& j);

// The interval a movable joint's value is sampled and posed over (the self-collision sampling,
// the view's sliders), low first: a continuous joint, and a revolute joint whose limits span a
// full turn or more (±1e308 included), over [-π, π], which reaches every pose such a joint
// has; other joints over their limits. Finite whenever the robot was read by readUrdf (its
// limits are checked there).
std::pair<double, double> jointSampleRange(const RobotJoint& j);

// Reads a URDF file and resolves every mesh path (relative to the URDF's folder, absolute,
// file://, package://NAME/... through the package search folders). Errors (one line): the
// file missing or unreadable (kUnreadable), not a valid URDF (kInvalidData), a mesh file not
// found (kUnreadable, naming the link and every path tried).
// An ".xml" path is an MJCF, read and compiled by MuJoCo itself (mj_loadXML: defaults,
// classes, includes, fromto, meshdir, mesh scale and re-centring), docs/robots.md "MJCF":
// every body is a link (the world body is the root "world"), a body's joints its joint (a body
// with several gets a link "BODY/JOINT" per joint but its last, without geometry), hinge and
// slide joints with their limits, anchor and ref; ball, free and unlimited slide joints stay
// at their reference (kOther); the collision geoms are the link's geometry in the body frame
// (planes and height fields of the world body are left out). Errors: MuJoCo's message with the
// file and line (kInvalidData), and what sphereset refuses before MuJoCo reads it
// (mjcfLimits, docs/robots.md).
Expected<Robot> loadRobot(const std::string& urdf_path, const RobotLoadOptions& options = {});

// The link's geometry as one mesh in the link frame: meshes loaded, scaled and placed by their
// origin; boxes exactly, and cylinders (`cylinder_segments` sides), spheres, capsules and
// ellipsoids as convex polyhedra that contain them (primitive_mesh.hpp: whatever covers the
// mesh covers the primitive); all elements concatenated (separate shells, not united). A link
// without geometry gives an empty mesh. Errors: those of loadMesh, with the link's name.
Expected<Mesh> linkMesh(const RobotLink& link, int cylinder_segments = 48);

// The link's sphere primitives as exact spheres in the link frame.
std::vector<Sphere> linkSpheres(const RobotLink& link);

// What the robot command fits for a link: its geometry other than sphere primitives (which
// stay exact spheres), as one mesh in the link frame, cleaned and repaired into a solid like a
// mesh file (repair.hpp); `name` prefixes messages (e.g. "robot.urdf: link 'elbow'"). Errors:
// kInvalidArgument when the link has no geometry other than spheres; those of linkMesh,
// cleanMesh and repairMesh otherwise.
Expected<SolidInput> linkSolid(const RobotLink& link, const RepairOptions& options,
                               const std::string& name);

// A configuration of the robot from the values a user gave (joint -> radians or metres):
// every joint's value, with joints not given at their reference (0 in a URDF), revolute and
// prismatic values clamped to their limits, and mimic joints following their leaders. Errors
// (kInvalidArgument): a name that is not a joint of the robot, a value that is not a finite number,
// a value for a mimic joint that differs from what its leader gives; kInvalidData: a mimic of a
// joint that does not exist, or mimics in a cycle. `notes` says what was changed ("joint 'joint1':
// 100 is beyond its upper limit 2.97, clamped"), one line each, for the doors to show as warnings.
struct JointState {
  std::map<std::string, double> values;  // every joint of the robot
  std::vector<std::string> notes;
};
Expected<JointState> jointState(const Robot& robot,
                                const std::map<std::string, double>& joint_values = {});

// Forward kinematics: each link reachable from the root -> the pose of its frame in the root
// frame, at jointState(robot, joint_values) (its errors too); joints of other types (floating,
// planar) stay at their origin.
Expected<std::map<std::string, Eigen::Isometry3d>> linkPoses(
    const Robot& robot, const std::map<std::string, double>& joint_values = {});

// The pairs for `robot` with the spheres of its links (in each link's frame) placed by
// linkPoses(robot, joint_values): one pose (the pairs over the whole joint space, as planners'
// setup tools find them, are sampleSelfCollisions', robot_collision.hpp). Two links overlap when
// some sphere of one and some sphere of the other have |ca - cb| < ra + rb (touching is not
// overlapping). Links without spheres, and entries of `spheres` naming no link of the robot or a
// link the root does not reach, take no part in overlaps; entries naming the same link twice count
// as one set. Adjacent pairs come from every joint between two links of the robot, and from
// Robot::excluded_pairs, whatever their spheres. Errors: those of jointState.
Expected<SelfCollisionPairs> selfCollisionPairs(
    const Robot& robot, const std::vector<LinkSpheres>& spheres,
    const std::map<std::string, double>& joint_values = {});

// The URDF file `in_urdf` with the collisions of the links listed in `spheres` replaced by their
// spheres: each listed link loses all its <collision> elements and gets, where the first of them
// was (else at its end), one <collision name="sphere_i"> per sphere i with
// <origin xyz="x y z" rpy="0 0 0"/><geometry><sphere radius="r"/></geometry> (shortest
// round-trip decimal numbers). A listed link with no spheres is left with no collision. Links not
// listed, visuals, joints, comments and attributes are kept; the text is re-indented by the XML
// library (TinyXML). Mesh paths are copied as they are, so relative paths resolve only when the
// output is written beside the input (package:// paths resolve anywhere). Errors (one line,
// naming the file): unreadable (kUnreadable), not XML or no <robot> root (kInvalidData), a listed
// link that the URDF does not have or that is listed twice (kInvalidArgument), a sphere with a
// NaN, an infinite value or a negative radius (kInvalidData).
Expected<std::string> formatSphereUrdf(const std::string& in_urdf,
                                       const std::vector<LinkSpheres>& spheres);
// The same, written atomically to `out_path`; kInvalidArgument when `out_path` is `in_urdf`
// (checkOutputPath).
Status writeSphereUrdf(const std::string& in_urdf, const std::string& out_path,
                       const std::vector<LinkSpheres>& spheres);

// The robot `in_robot` (an MJCF, or a URDF through MuJoCo's own URDF reader) as an MJCF that
// MuJoCo loads, to be written at `out_path`: every collision geom of each link listed in
// `spheres` (those loadRobot reads with `options`) replaced, where the first of them was, by
// one sphere geom per sphere, named "LINK_sphere_i" and keeping the first replaced geom's
// class, group, contype, conaffinity, condim and friction; visual geoms, joints, actuators,
// defaults and the rest as MuJoCo writes the model back (mj_saveLastXML: defaults and
// includes resolved into one file); asset files named by paths that resolve from `out_path`'s
// folder; and one <contact><exclude> per pair of `exclude` that MuJoCo does not already filter.
// From a URDF the starting model is MuJoCo's reading of the URDF with the listed links'
// collisions already spheres (formatSphereUrdf), every link kept as a body (fusestatic off)
// and visuals left out (MuJoCo's default for a URDF). Errors: those of loadRobot; a listed link
// that is not a body of the model, or listed twice (kInvalidArgument); a sphere with a NaN, an
// infinite value or a negative radius (kInvalidData); no MuJoCo in this build (kUnreadable).
Expected<std::string> formatSphereMjcf(const std::string& in_robot, const std::string& out_path,
                                       const std::vector<LinkSpheres>& spheres,
                                       const std::vector<std::array<std::string, 2>>& exclude,
                                       const RobotLoadOptions& options = {});
// The same, written atomically to `out_path`; kInvalidArgument when `out_path` is `in_robot`.
Status writeSphereMjcf(const std::string& in_robot, const std::string& out_path,
                       const std::vector<LinkSpheres>& spheres,
                       const std::vector<std::array<std::string, 2>>& exclude,
                       const RobotLoadOptions& options = {});

}  // namespace sphereset

// A posed robot against its surroundings: the spheres of each link placed by forward kinematics,
// and per link whether they collide with obstacles (a point cloud or a set of spheres), the
// least signed distance and the closest obstacle, for one configuration or along a trajectory.
// The readers of the inputs a motion planner has at hand (point clouds, a trajectory as CSV,
// the spheres of a sphere URDF) are here too.
//
// Collision: a link collides when its least signed distance is < 0, i.e. some sphere of it and
// some obstacle overlap with positive depth; touching (distance exactly 0) is not a collision,
// as in overlaps() (query.hpp) and selfCollisionPairs. A point is an obstacle of radius 0.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

// Obstacles prepared for many queries: the spheres as given and a sphere tree over them, built
// by median splits (fast for millions of points; parents are minimal enclosing balls).
struct Obstacles {
  std::vector<Sphere> spheres;      // as given, in order
  SphereTree tree;                  // its leaves are `spheres`, in an order of the tree's own
  std::vector<int64_t> leaf_index;  // tree slot -> position in `spheres` (-1: not a leaf)
};

// Checks and prepares obstacle spheres / points (radius 0). `name` starts messages (a file
// name). Errors (kInvalidData): none given, more than limits::kMaxObstacles, a coordinate that is
// NaN, infinite or beyond limits::kMaxCoordinate, a radius that is negative or not finite; the
// message names the obstacle's position ("cloud.ply: point 17 (nan 0 0): ...").
Expected<Obstacles> makeObstacles(std::vector<Sphere> spheres, const std::string& name);
Expected<Obstacles> makeObstacles(const std::vector<Vec3>& points, const std::string& name);

// A point cloud file's points, by extension: .ply, .off (every vertex, through the project's
// own readers; faces are allowed and ignored), .obj (every "v x y z" line), .xyz, .pts, .txt
// (one "x y z" per line; blank lines and '#' comments skipped). Nothing is welded or dropped.
// Errors: kUnreadable (missing, another extension, not parseable), kInvalidData (a line that is
// not three numbers, naming the line; no points).
Expected<std::vector<Vec3>> readPointCloud(const std::string& path);

// The sphere collisions of a sphere URDF (as `sphereset robot -o X.urdf` writes): for each link
// whose <collision> geometry is all spheres, those spheres in the link frame, in link order.
// Links with other collision geometry, or with none (their visual geometry does not count),
// are left out.
std::vector<LinkSpheres> urdfLinkSpheres(const Robot& sphere_robot);

// The spheres of each entry of `spheres` (link frames) in the root frame, placed by
// linkPoses(robot, joint_values); same entries, same order. Errors: those of linkPoses;
// kInvalidData for an entry naming no link of the robot or a link the root does not reach, a
// link listed twice, a sphere with a coordinate that is not finite (or beyond
// limits::kMaxCoordinate) or a negative radius (naming the link and the sphere's position).
Expected<std::vector<LinkSpheres>> posedLinkSpheres(
    const Robot& robot, const std::vector<LinkSpheres>& spheres,
    const std::map<std::string, double>& joint_values = {});

// What a picture of the robot shows: link geometry (linkMesh, every link's concatenated) and
// spheres, in one frame.
struct RobotScene {
  Mesh mesh;
  std::vector<Sphere> spheres;
};

// The posed robot in the root frame: every link the root reaches, its geometry and the spheres
// `spheres` gives it placed by linkPoses(robot, joint_values). Errors: those of
// posedLinkSpheres, and of linkMesh (naming the link).
Expected<RobotScene> robotScene(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                                const std::map<std::string, double>& joint_values = {});

// One link alone in its own frame: its geometry and its spheres. Errors: kInvalidArgument
// naming `link` when the robot has no such link ("no link 'elbow' in robot 'three_link' (it has
// base_link, link1, ...)"); those of posedLinkSpheres (on `spheres`) and linkMesh.
Expected<RobotScene> linkScene(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                               const std::string& link);

// One link against the obstacles.
struct LinkContact {
  std::string link;
  bool collides = false;  // distance < 0
  // min over the link's spheres s and the obstacles o of |c_s - c_o| - r_s - r_o; +infinity
  // when the link has no spheres.
  double distance = 0.0;
  int64_t sphere = -1;    // the link's sphere attaining it (position in its list), -1: none
  int64_t obstacle = -1;  // the obstacle attaining it (position in Obstacles::spheres)
};

// The robot at one configuration.
struct RobotContacts {
  std::vector<LinkContact> links;  // one per entry of the sphere list, in its order
  bool collides = false;           // some link collides
  double distance = 0.0;           // least over the links (+infinity: no spheres at all)
  int64_t closest_link = -1;       // the link attaining it (position in `links`), -1: none
  std::vector<std::string> notes;  // jointState's notes (values clamped to limits)
};

// The posed robot (posedLinkSpheres: its errors) against `obstacles`. Exact: the least signed
// distance over every pair of a link sphere and an obstacle, found by the dual traversal of
// separation() (query.hpp) of a tree over the link's spheres and the obstacles' tree; ties go to
// whichever pair the traversal meets first.
Expected<RobotContacts> robotContacts(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                                      const Obstacles& obstacles,
                                      const std::map<std::string, double>& joint_values = {});

// The same for each waypoint of a trajectory, in parallel; the results do not depend on the
// thread count. `first_collision` is the least index of a waypoint that collides, -1 when none
// does. Errors: those of robotContacts, the first failing waypoint's, prefixed with
// "waypoint K: ".
struct TrajectoryContacts {
  std::vector<RobotContacts> waypoints;
  int64_t first_collision = -1;
};
Expected<TrajectoryContacts> trajectoryContacts(
    const Robot& robot, const std::vector<LinkSpheres>& spheres, const Obstacles& obstacles,
    const std::vector<std::map<std::string, double>>& waypoints);

// A trajectory file: CSV with a header row of joint names of `robot`, then one waypoint per row
// (values in radians or metres, as --joint-positions takes them; joints not in the header at 0).
// Cells are trimmed of spaces; blank lines are skipped. Errors, naming the file and line
// ("traj.csv:4: ..."): kUnreadable (missing), kInvalidData for an empty file, a header cell
// that is empty, not a joint of the robot or repeated, a row with another number of cells than
// the header, a cell that is not a finite number, no waypoints, more than limits::kMaxWaypoints.
Expected<std::vector<std::map<std::string, double>>> readTrajectory(const std::string& path,
                                                                    const Robot& robot);

}  // namespace sphereset

// sphereset query: point, segment and set-to-set queries on a sphere set or tree; with a robot
// (.urdf) first, the posed robot's spheres against obstacles (cmd_query_robot.cpp).
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "query_robot.hpp"
#include "sphereset/query.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::cli {
namespace {

struct QueryArgs {
  std::string path, other_path;
  std::vector<double> points, segments, other_pose;
  bool json = false;
  RobotQueryArgs robot;  // the robot mode's own options (path, json and spheres set at run)
};

template <class... Args>
std::string format(const char* f, Args... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}

// A file that holds a sphere tree is queried through it; a plain set gets one built.
Expected<SphereTree> treeFor(const SphereTree& t) { return queryTreeOf(t); }

// The --point and --segment queries, printed or added to `out`. Every query is answered before
// anything is printed, so that a refused one prints nothing but its error.
int pointAndSegmentQueries(const QueryArgs& a, const SphereTree& qa, nlohmann::json* out) {
  std::vector<std::string> lines;
  const std::vector<double>& pts = a.points;
  for (size_t i = 0; i + 2 < pts.size(); i += 3) {
    const Vec3 p(pts[i], pts[i + 1], pts[i + 2]);
    const auto pq = pointDistance(qa, p);
    if (!pq) return fail(pq.error());
    const bool in = *containsPoint(qa, p);  // the point passed the same check
    if (a.json)
      (*out)["points"].push_back({{"point", vec(p)}, {"inside", in}, {"distance", pq->distance}});
    else
      lines.push_back(format("point %g %g %g: %s, signed distance %.9g", p.x(), p.y(), p.z(),
                             in ? "inside" : "outside", pq->distance));
  }
  const std::vector<double>& sg = a.segments;
  for (size_t i = 0; i + 5 < sg.size(); i += 6) {
    const Vec3 pa(sg[i], sg[i + 1], sg[i + 2]);
    const Vec3 pb(sg[i + 3], sg[i + 4], sg[i + 5]);
    const auto len = segmentOutsideLength(qa, pa, pb);
    if (!len) return fail(len.error());
    if (a.json)
      (*out)["segments"].push_back({{"a", vec(pa)}, {"b", vec(pb)}, {"outside_length", *len}});
    else
      lines.push_back(format("segment %g %g %g -> %g %g %g: %.9g of %.9g outside", pa.x(), pa.y(),
                             pa.z(), pb.x(), pb.y(), pb.z(), *len, (pb - pa).norm()));
  }
  for (const std::string& line : lines) std::printf("%s\n", line.c_str());
  return kOk;
}

// The --other query (separation and overlap under --pose), printed or added to `out`.
int otherQuery(const QueryArgs& a, const SphereTree& qa, nlohmann::json* out) {
  auto tb = readSphereTree(a.other_path);
  if (!tb) return fail(tb.error());
  Pose pose;
  const std::vector<double>& op = a.other_pose;
  if (!op.empty()) {
    Eigen::Quaterniond q(op[3], op[4], op[5], op[6]);
    if (!(q.norm() > 0.0) || !std::isfinite(q.norm()))
      return fail(Error{ErrorCode::kInvalidArgument, "--pose: the quaternion is zero"});
    pose.rotation = q.normalized().toRotationMatrix();
    pose.translation = Vec3(op[0], op[1], op[2]);
    // The quaternion's NaNs are caught above; the translation is checked by the query.
  }
  const auto qb = treeFor(*tb);
  if (!qb) return fail(qb.error());
  const auto found = separation(qa, Pose{}, *qb, pose);
  if (!found) return fail(found.error());
  const PairQuery& pq = *found;
  const bool hit = pq.distance < 0.0;
  if (a.json)
    (*out)["other"] = {{"file", a.other_path},
                       {"overlap", hit},
                       {"distance", pq.distance},
                       {"closest_pair",
                        {{"a", vec(qa.nodes[pq.sphere_a].center)},
                         {"b", vec(pose.apply(qb->nodes[pq.sphere_b].center))}}}};
  else
    std::printf("against %s: %s, signed distance %.9g\n", a.other_path.c_str(),
                hit ? "overlap" : "apart", pq.distance);
  return kOk;
}

int runQuery(const QueryArgs& a) {
  const bool robot_options = !a.robot.spheres.empty() || a.robot.load.given() ||
                             !a.robot.joint_positions.empty() || !a.robot.trajectory.empty() ||
                             !a.robot.points.empty() || !a.robot.obstacle_spheres.empty();
  if (isRobotDescriptionPath(a.path)) {
    if (!a.points.empty() || !a.segments.empty() || !a.other_path.empty())
      return fail(Error{ErrorCode::kInvalidArgument,
                        a.path + ": --point, --segment and --other query a sphere set; a robot "
                                 "takes --points or --spheres"});
    RobotQueryArgs r = a.robot;
    r.urdf = a.path;
    r.json = a.json;
    return runRobotQuery(r);
  }
  if (robot_options)
    return fail(Error{ErrorCode::kInvalidArgument,
                      a.path + ": a second file, --points, --spheres, --trajectory, "
                               "--joint-positions and --package-path need a robot (.urdf) first"});
  if (a.points.size() % 3 != 0 || a.segments.size() % 6 != 0)
    return fail(
        Error{ErrorCode::kInvalidArgument, "--point takes x,y,z and --segment ax,ay,az,bx,by,bz"});
  auto ta = readSphereTree(a.path);
  if (!ta) return fail(ta.error());
  nlohmann::json out;
  const auto qa = treeFor(*ta);
  if (!qa) return fail(qa.error());
  if (const int rc = pointAndSegmentQueries(a, *qa, &out); rc != kOk) return rc;
  if (!a.other_path.empty()) {
    const int rc = otherQuery(a, *qa, &out);
    if (rc != kOk) return rc;
  }
  if (a.json) std::cout << jsonText(out) << '\n';
  return kOk;
}

}  // namespace

Command registerQuery(CLI::App& app) {
  auto a = std::make_shared<QueryArgs>();
  CLI::App* cmd =
      app.add_subcommand("query", "Point, segment and set-to-set queries on a sphere set or tree");
  cmd->add_option("spheres", a->path,
                  "Sphere set or tree (.txt, .json, .sph, .yaml), or a robot (.urdf)")
      ->required();
  cmd->add_option("robot_spheres", a->robot.spheres,
                  "Robot: its spheres in the link frames (cuRobo .yml, .json, ... or the sphere "
                  ".urdf of `robot`)");
  cmd->add_option("--point", a->points, "x,y,z: inside? and signed distance to the set")
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--segment", a->segments,
                  "ax,ay,az,bx,by,bz: length of the segment outside the spheres")
      ->delimiter(',')
      ->expected(6)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--other", a->other_path, "A second set or tree: separation and overlap");
  cmd->add_option("--pose", a->other_pose,
                  "tx,ty,tz,qw,qx,qy,qz: rigid pose of the second set (default identity)")
      ->delimiter(',')
      ->expected(7);
  addRobotLoadArgs(cmd, &a->robot.load, "Robot: ");
  auto* joints = cmd->add_option("--joint-positions", a->robot.joint_positions,
                                 "Robot: JOINT=VALUE,... (default: all joints at 0)");
  cmd->add_option("--trajectory", a->robot.trajectory,
                  "Robot: CSV of waypoints (a header of joint names, one row each)")
      ->excludes(joints);
  auto* cloud =
      cmd->add_option("--points", a->robot.points,
                      "Robot: obstacle point cloud (.ply, .off, .obj vertices, or .xyz/.txt "
                      "lines x y z)");
  cmd->add_option("--spheres", a->robot.obstacle_spheres,
                  "Robot: obstacle spheres (.txt, .json, .sph, .yaml)")
      ->excludes(cloud);
  cmd->add_flag("--json", a->json, "Print one JSON object");
  return {cmd, [a] { return runQuery(*a); }};
}

}  // namespace sphereset::cli

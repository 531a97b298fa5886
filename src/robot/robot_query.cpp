// A posed robot's spheres against obstacles: per link, the least signed distance to a point
// cloud or a set of obstacle spheres and whether they collide, at one configuration or at each
// waypoint of a trajectory. Each link's spheres get a tree in the link frame (built once), the
// obstacles one tree in the root frame (medianTree); the link tree is moved by the link's pose
// and the two are compared by separation() (query.hpp), whose dual traversal is exact.
#include "sphereset/robot_query.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <set>
#include <span>

#include "sphereset/limits.hpp"
#include "sphereset/query.hpp"
#include "tree/median_tree.hpp"
#include "util/number_text.hpp"

namespace sphereset {
namespace {

constexpr double kNoContact = std::numeric_limits<double>::infinity();

// The checked spheres of each listed link and a tree over each non-empty set, in list order.
struct PreparedLinks {
  std::vector<std::string> names;
  std::vector<detail::IndexedTree> trees;  // empty tree: a link without spheres
};

Expected<PreparedLinks> checkedLinkTrees(const Robot& robot,
                                         const std::vector<LinkSpheres>& spheres) {
  auto rest = linkPoses(robot);  // which links the root reaches: the same at every pose
  if (!rest) return rest.error();
  std::set<std::string> robot_links, seen;
  for (const RobotLink& l : robot.links) robot_links.insert(l.name);
  PreparedLinks out;
  for (const LinkSpheres& ls : spheres) {
    const std::string what = "link '" + ls.link + "'";
    if (robot_links.count(ls.link) == 0)
      return Error{ErrorCode::kInvalidData, what + " is not a link of robot '" + robot.name + "'"};
    if (rest->count(ls.link) == 0)
      return Error{ErrorCode::kInvalidData,
                   what + " is not reached from the root link '" + robot.root + "'"};
    if (!seen.insert(ls.link).second)
      return Error{ErrorCode::kInvalidData, what + " is listed twice"};
    for (size_t i = 0; i < ls.spheres.size(); ++i)
      if (Status st = checkSphere(what + " sphere " + std::to_string(i), ls.spheres[i]); !st)
        return st.error();
    if (static_cast<int64_t>(ls.spheres.size()) > limits::kMaxObstacles)
      return Error{ErrorCode::kInvalidData,
                   what + ": more than " + std::to_string(limits::kMaxObstacles) + " spheres"};
    out.names.push_back(ls.link);
    out.trees.push_back(ls.spheres.empty() ? detail::IndexedTree{}
                                           : detail::medianTree(ls.spheres));
  }
  return out;
}

Pose poseOf(const Eigen::Isometry3d& iso) {
  Pose p;
  p.rotation = iso.linear();
  p.translation = iso.translation();
  return p;
}

// The contacts at one configuration, the links prepared.
Expected<RobotContacts> contactsAt(const Robot& robot, const PreparedLinks& links,
                                   const Obstacles& obstacles,
                                   const std::map<std::string, double>& joint_values) {
  auto state = jointState(robot, joint_values);
  if (!state) return state.error();
  auto poses = linkPoses(robot, joint_values);
  if (!poses) return poses.error();
  RobotContacts out;
  out.notes = std::move(state->notes);
  out.distance = kNoContact;
  for (size_t k = 0; k < links.names.size(); ++k) {
    LinkContact c;
    c.link = links.names[k];
    c.distance = kNoContact;
    const detail::IndexedTree& lt = links.trees[k];
    if (!lt.tree.nodes.empty()) {
      const Pose pose = poseOf(poses->at(c.link));
      auto q = separation(lt.tree, pose, obstacles.tree, Pose{});
      if (!q) return Error{q.error().code, "link '" + c.link + "': " + q.error().message};
      c.distance = q->distance;
      c.sphere = lt.leaf_index[q->sphere_a];
      c.obstacle = obstacles.leaf_index[q->sphere_b];
      c.collides = c.distance < 0.0;
    }
    if (c.distance < out.distance) {
      out.distance = c.distance;
      out.closest_link = static_cast<int64_t>(k);
    }
    out.collides = out.collides || c.collides;
    out.links.push_back(std::move(c));
  }
  return out;
}

// Appends `m` moved by `pose` to `all`.
void appendMesh(Mesh* all, const Mesh& m, const Eigen::Isometry3d& pose) {
  const auto base = static_cast<int32_t>(all->vertices.size());
  for (const Vec3& v : m.vertices) all->vertices.push_back(pose * v);
  for (const Triangle& t : m.triangles)
    all->triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

Status checkPrepared(const Obstacles& o) {
  if (o.tree.nodes.empty() || o.leaf_index.size() != o.tree.nodes.size())
    return Error{ErrorCode::kInvalidArgument, "obstacles: not prepared (use makeObstacles)"};
  return {};
}

}  // namespace

Expected<Obstacles> makeObstacles(std::vector<Sphere> spheres, const std::string& name) {
  if (spheres.empty()) return Error{ErrorCode::kInvalidData, name + ": no obstacles"};
  if (static_cast<int64_t>(spheres.size()) > limits::kMaxObstacles)
    return Error{ErrorCode::kInvalidData, name + ": " + std::to_string(spheres.size()) +
                                              " obstacles, at most " +
                                              std::to_string(limits::kMaxObstacles)};
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st = checkSphere(name + ": sphere " + std::to_string(i), spheres[i]); !st)
      return st.error();
  Obstacles out;
  detail::IndexedTree t = detail::medianTree(spheres);
  out.spheres = std::move(spheres);
  out.tree = std::move(t.tree);
  out.leaf_index = std::move(t.leaf_index);
  return out;
}

Expected<Obstacles> makeObstacles(const std::vector<Vec3>& points, const std::string& name) {
  if (points.empty()) return Error{ErrorCode::kInvalidData, name + ": no points"};
  std::vector<Sphere> spheres(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    if (Status st = limits::checkCoordinates(name + ": point " + std::to_string(i),
                                             std::span<const double>(p.data(), 3));
        !st)
      return Error{ErrorCode::kInvalidData, st.error().message};
    spheres[i] = Sphere{p, 0.0};
  }
  return makeObstacles(std::move(spheres), name);
}

std::vector<LinkSpheres> urdfLinkSpheres(const Robot& sphere_robot) {
  std::vector<LinkSpheres> out;
  for (const RobotLink& link : sphere_robot.links) {
    if (link.from_visual || link.geometry.empty()) continue;
    bool all = true;
    for (const LinkGeometry& g : link.geometry) all = all && g.kind == LinkGeometry::Kind::kSphere;
    if (all) out.push_back({link.name, linkSpheres(link)});
  }
  return out;
}

Expected<std::vector<LinkSpheres>> posedLinkSpheres(
    const Robot& robot, const std::vector<LinkSpheres>& spheres,
    const std::map<std::string, double>& joint_values) {
  auto links = checkedLinkTrees(robot, spheres);
  if (!links) return links.error();
  auto poses = linkPoses(robot, joint_values);
  if (!poses) return poses.error();
  std::vector<LinkSpheres> out;
  for (const LinkSpheres& ls : spheres) {
    const Eigen::Isometry3d& pose = poses->at(ls.link);
    LinkSpheres& w = out.emplace_back();
    w.link = ls.link;
    for (const Sphere& s : ls.spheres) w.spheres.push_back({pose * s.center, s.radius});
  }
  return out;
}

Expected<RobotScene> robotScene(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                                const std::map<std::string, double>& joint_values) {
  auto posed = posedLinkSpheres(robot, spheres, joint_values);
  if (!posed) return posed.error();
  auto poses = linkPoses(robot, joint_values);
  if (!poses) return poses.error();
  RobotScene out;
  for (const RobotLink& link : robot.links) {
    const auto pose = poses->find(link.name);
    if (pose == poses->end()) continue;
    auto m = linkMesh(link);
    if (!m) return m.error();
    appendMesh(&out.mesh, *m, pose->second);
  }
  for (const LinkSpheres& ls : *posed)
    out.spheres.insert(out.spheres.end(), ls.spheres.begin(), ls.spheres.end());
  return out;
}

Expected<RobotScene> linkScene(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                               const std::string& link) {
  auto checked = posedLinkSpheres(robot, spheres);
  if (!checked) return checked.error();
  const RobotLink* found = nullptr;
  std::string names;
  for (const RobotLink& l : robot.links) {
    if (l.name == link) found = &l;
    names += (names.empty() ? "" : ", ") + l.name;
  }
  if (!found)
    return Error{ErrorCode::kInvalidArgument,
                 "no link '" + link + "' in robot '" + robot.name + "' (it has " + names + ")"};
  RobotScene out;
  auto m = linkMesh(*found);
  if (!m) return m.error();
  out.mesh = std::move(m).value();
  for (const LinkSpheres& ls : spheres)
    if (ls.link == link) out.spheres = ls.spheres;
  return out;
}

Expected<RobotContacts> robotContacts(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                                      const Obstacles& obstacles,
                                      const std::map<std::string, double>& joint_values) {
  if (Status st = checkPrepared(obstacles); !st) return st.error();
  auto links = checkedLinkTrees(robot, spheres);
  if (!links) return links.error();
  return contactsAt(robot, *links, obstacles, joint_values);
}

Expected<TrajectoryContacts> trajectoryContacts(
    const Robot& robot, const std::vector<LinkSpheres>& spheres, const Obstacles& obstacles,
    const std::vector<std::map<std::string, double>>& waypoints) {
  if (Status st = checkPrepared(obstacles); !st) return st.error();
  if (static_cast<int64_t>(waypoints.size()) > limits::kMaxWaypoints)
    return Error{ErrorCode::kInvalidArgument, std::to_string(waypoints.size()) +
                                                  " waypoints, at most " +
                                                  std::to_string(limits::kMaxWaypoints)};
  auto links = checkedLinkTrees(robot, spheres);
  if (!links) return links.error();
  std::vector<Expected<RobotContacts>> each(waypoints.size(), Error{ErrorCode::kInvalidData, ""});
  tbb::parallel_for(size_t{0}, waypoints.size(), [&](size_t i) {
    each[i] = contactsAt(robot, *links, obstacles, waypoints[i]);
  });
  TrajectoryContacts out;
  for (size_t i = 0; i < each.size(); ++i) {
    if (!each[i])
      return Error{each[i].error().code,
                   "waypoint " + std::to_string(i) + ": " + each[i].error().message};
    if (each[i]->collides && out.first_collision < 0) out.first_collision = static_cast<int64_t>(i);
    out.waypoints.push_back(std::move(each[i]).value());
  }
  return out;
}

}  // namespace sphereset

// The link pairs a self-collision checker can skip, in the form of cuRobo's robot configuration
// (its self_collision_ignore): links joined by a joint, and links whose spheres overlap at one
// pose of the robot (spheres placed by forward kinematics).
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/robot.hpp"

namespace sphereset {
namespace {

// Whether some sphere of `a` and some sphere of `b` overlap (strictly).
bool overlap(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
  for (const Sphere& sa : a)
    for (const Sphere& sb : b) {
      const double reach = sa.radius + sb.radius;
      if ((sa.center - sb.center).squaredNorm() < reach * reach) return true;
    }
  return false;
}

}  // namespace

Expected<SelfCollisionPairs> selfCollisionPairs(const Robot& robot,
                                                const std::vector<LinkSpheres>& spheres,
                                                const std::map<std::string, double>& joint_values) {
  auto found = linkPoses(robot, joint_values);
  if (!found) return found.error();
  const std::map<std::string, Eigen::Isometry3d>& poses = *found;
  // Link name -> its index in the robot's link order (the first, if a name repeats).
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < robot.links.size(); ++i) index.emplace(robot.links[i].name, i);

  SelfCollisionPairs out;
  std::set<std::pair<size_t, size_t>> adjacent;
  auto join = [&](const std::string& x, const std::string& y) {
    const auto p = index.find(x);
    const auto c = index.find(y);
    if (p == index.end() || c == index.end() || p->second == c->second) return;
    adjacent.emplace(std::min(p->second, c->second), std::max(p->second, c->second));
  };
  for (const RobotJoint& j : robot.joints) join(j.parent, j.child);
  for (const auto& [x, y] : robot.excluded_pairs) join(x, y);
  for (const auto& [a, b] : adjacent)
    out.adjacent.push_back({robot.links[a].name, robot.links[b].name});

  // The spheres of each link in the root frame, by link index.
  std::map<size_t, std::vector<Sphere>> placed;
  for (const LinkSpheres& ls : spheres) {
    const auto i = index.find(ls.link);
    const auto pose = poses.find(ls.link);
    if (i == index.end() || pose == poses.end()) continue;
    for (const Sphere& s : ls.spheres)
      placed[i->second].push_back(Sphere{pose->second * s.center, s.radius});
  }
  for (auto a = placed.begin(); a != placed.end(); ++a)
    for (auto b = std::next(a); b != placed.end(); ++b)
      if (overlap(a->second, b->second))
        out.overlapping.push_back({robot.links[a->first].name, robot.links[b->first].name});
  return out;
}

}  // namespace sphereset

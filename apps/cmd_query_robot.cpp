// sphereset query ROBOT.urdf SPHERES: per link, collision with obstacles and the least signed
// distance, at one configuration or at each waypoint of a trajectory (robot_query.hpp).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "query_robot.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_query.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

// The robot's spheres: a sphere URDF's sphere collisions, or a file of per-link spheres.
Expected<std::vector<LinkSpheres>> robotSpheres(const RobotQueryArgs& a,
                                                const RobotLoadOptions& lo) {
  if (isRobotDescriptionPath(a.spheres)) {
    auto sphere_robot = loadRobot(a.spheres, lo);
    if (!sphere_robot) return sphere_robot.error();
    std::vector<LinkSpheres> out = urdfLinkSpheres(*sphere_robot);
    if (out.empty())
      return Error{ErrorCode::kInvalidData, a.spheres + ": no link has sphere collisions"};
    return out;
  }
  return readLinkSpheres(a.spheres);
}

Expected<Obstacles> readObstacles(const RobotQueryArgs& a) {
  if (!a.points.empty()) {
    auto cloud = readPointCloud(a.points);
    if (!cloud) return cloud.error();
    return makeObstacles(*cloud, a.points);
  }
  auto spheres = readSpheres(a.obstacle_spheres);
  if (!spheres) return spheres.error();
  return makeObstacles(std::move(spheres).value(), a.obstacle_spheres);
}

nlohmann::json linkJson(const LinkContact& c, const Obstacles& o) {
  nlohmann::json j = {{"link", c.link}, {"collides", c.collides}, {"distance", c.distance}};
  if (c.obstacle >= 0) {
    const Sphere& s = o.spheres[c.obstacle];
    j["sphere"] = c.sphere;
    j["obstacle"] = {{"index", c.obstacle}, {"center", vec(s.center)}, {"radius", s.radius}};
  }
  return j;  // a link without spheres: distance null (infinite), no sphere or obstacle
}

std::string distanceText(double d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", d);
  return buf;
}

// "link2 sphere 3 with obstacle 5311 (signed distance -0.012)".
std::string contactText(const LinkContact& c) {
  return c.link + " sphere " + std::to_string(c.sphere) + " with obstacle " +
         std::to_string(c.obstacle) + " (signed distance " + distanceText(c.distance) + ")";
}

int printConfiguration(const RobotQueryArgs& a, const RobotContacts& r, const Obstacles& o,
                       nlohmann::json out) {
  if (a.json) {
    out["collides"] = r.collides;
    out["distance"] = r.distance;
    for (const LinkContact& c : r.links) out["links"].push_back(linkJson(c, o));
    std::cout << jsonText(out) << '\n';
    return kOk;
  }
  for (const LinkContact& c : r.links) {
    if (c.sphere < 0)
      std::printf("%s: no spheres\n", c.link.c_str());
    else
      std::printf("%s: %s, signed distance %s (sphere %lld, obstacle %lld)\n", c.link.c_str(),
                  c.collides ? "collides" : "clear", distanceText(c.distance).c_str(),
                  static_cast<long long>(c.sphere), static_cast<long long>(c.obstacle));
  }
  if (r.closest_link < 0)
    std::printf("robot: no spheres\n");
  else
    std::printf("robot: %s, least: %s\n", r.collides ? "collides" : "clear",
                contactText(r.links[r.closest_link]).c_str());
  return kOk;
}

int printTrajectory(const RobotQueryArgs& a, const TrajectoryContacts& t, nlohmann::json out) {
  const auto k = t.first_collision;
  const RobotContacts* first = k >= 0 ? &t.waypoints[k] : nullptr;
  if (a.json) {
    out["waypoints"] = t.waypoints.size();
    out["first_collision"] = nullptr;
    if (first) {
      const LinkContact& c = first->links[first->closest_link];
      nlohmann::json links = nlohmann::json::array();
      for (const LinkContact& l : first->links)
        if (l.collides) links.push_back(l.link);
      out["first_collision"] = {{"waypoint", k},          {"link", c.link},
                                {"sphere", c.sphere},     {"obstacle", c.obstacle},
                                {"distance", c.distance}, {"colliding_links", links}};
    }
    nlohmann::json per = nlohmann::json::array();
    for (const RobotContacts& w : t.waypoints)
      per.push_back({{"collides", w.collides},
                     {"distance", w.distance},
                     {"link", w.closest_link >= 0 ? w.links[w.closest_link].link : ""}});
    out["per_waypoint"] = per;
    std::cout << jsonText(out) << '\n';
    return kOk;
  }
  size_t least = 0;
  for (size_t i = 1; i < t.waypoints.size(); ++i)
    if (t.waypoints[i].distance < t.waypoints[least].distance) least = i;
  const RobotContacts& l = t.waypoints[least];
  if (first)
    std::printf("waypoints: %zu, first collision at waypoint %lld: %s\n", t.waypoints.size(),
                static_cast<long long>(k), contactText(first->links[first->closest_link]).c_str());
  else
    std::printf("waypoints: %zu, no collision\n", t.waypoints.size());
  if (l.closest_link >= 0)
    std::printf("least signed distance %s at waypoint %zu (%s)\n", distanceText(l.distance).c_str(),
                least, l.links[l.closest_link].link.c_str());
  return kOk;
}

}  // namespace

int runRobotQuery(const RobotQueryArgs& a) {
  if (a.points.empty() == a.obstacle_spheres.empty())
    return fail(Error{ErrorCode::kInvalidArgument,
                      "a robot query needs obstacles: --points CLOUD or --spheres OBSTACLES"});
  if (a.spheres.empty())
    return fail(Error{ErrorCode::kInvalidArgument,
                      a.urdf + ": a robot query needs the robot's spheres (query ROBOT.urdf "
                               "SPHERES ...)"});
  const RobotLoadOptions lo = robotLoadOptions(a.load);
  auto robot = loadRobot(a.urdf, lo);
  if (!robot) return fail(robot.error());
  auto spheres = robotSpheres(a, lo);
  if (!spheres) return fail(spheres.error());
  // The sphere file's links checked against the robot, its name on the message.
  if (auto posed = posedLinkSpheres(*robot, *spheres); !posed)
    return fail(Error{posed.error().code, a.spheres + ": " + posed.error().message});
  auto obstacles = readObstacles(a);
  if (!obstacles) return fail(obstacles.error());
  nlohmann::json out = {{"robot", robot->name},
                        {"spheres", a.spheres},
                        {"obstacles",
                         {{"file", a.points.empty() ? a.obstacle_spheres : a.points},
                          {"kind", a.points.empty() ? "spheres" : "points"},
                          {"count", obstacles->spheres.size()}}}};
  if (a.trajectory.empty()) {
    auto joints = parseJointPositions(a.joint_positions, *robot);
    if (!joints) return fail(joints.error());
    auto r = robotContacts(*robot, *spheres, *obstacles, *joints);
    if (!r) return fail(r.error());
    return printConfiguration(a, *r, *obstacles, std::move(out));
  }
  auto waypoints = readTrajectory(a.trajectory, *robot);
  if (!waypoints) return fail(waypoints.error());
  auto t = trajectoryContacts(*robot, *spheres, *obstacles, *waypoints);
  if (!t) return fail(Error{t.error().code, a.trajectory + ": " + t.error().message});
  for (size_t i = 0; i < t->waypoints.size(); ++i)
    for (const std::string& note : t->waypoints[i].notes)
      std::fprintf(stderr, "sphereset: warning: %s: waypoint %zu: %s\n", a.trajectory.c_str(), i,
                   note.c_str());
  out["trajectory"] = a.trajectory;
  return printTrajectory(a, *t, std::move(out));
}

}  // namespace sphereset::cli

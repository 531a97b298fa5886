// The link solids the exact mesh check of the self-collision sampling takes
// (robot_collision.hpp): each link's walls, its own solid as the repair makes it (never the
// envelope that closes its openings: two links collide where their walls meet), and its exact
// sphere primitives. One rule for the command (from its fit), Python and the benchmark.
#include <string>
#include <utility>
#include <vector>

#include "sphereset/robot_collision.hpp"

namespace sphereset {

Expected<std::vector<CollisionSolid>> robotCollisionSolids(const Robot& robot,
                                                           const RepairOptions& repair) {
  RepairOptions walls = repair;
  walls.fill_openings = 0.0;
  std::vector<CollisionSolid> out;
  for (const RobotLink& l : robot.links) {
    if (l.geometry.empty()) continue;
    CollisionSolid s{l.name, {}, linkSpheres(l)};
    if (s.primitives.size() < l.geometry.size()) {
      auto solid = linkSolid(l, walls, robot.name + ": link '" + l.name + "'");
      if (!solid) return solid.error();
      s.mesh = std::move(solid->repair.solid);
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<CollisionSolid> fitCollisionSolids(const Robot& robot, const RobotFitResult& fit) {
  std::vector<CollisionSolid> out;
  for (const RobotLinkFit& j : fit.links) {
    if (j.skipped) continue;
    CollisionSolid s;
    s.link = j.link;
    if (j.fitted) s.mesh = envelopeWalls(j.repair) ? j.repair.walls : j.repair.solid;
    for (const RobotLink& l : robot.links)
      if (l.name == j.link) s.primitives = linkSpheres(l);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace sphereset

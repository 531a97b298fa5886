// Fuzz target for the planner files: a URDF read by loadRobot, then every file a planner reads
// written from it (MoveIt's SRDF, Lula's robot description, the URDF with sphere collisions)
// and read back by the library's own readers. Whatever the names hold (line breaks, quotes,
// '<', YAML keys, bytes that are not UTF-8), a written file must read back as the same links
// with the same spheres: no name may inject a key, an element or a sphere.
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "io/sphere_formats.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "util/utf8.hpp"

namespace {

using sphereset::fuzz::check;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace d = sphereset::detail;
  static sphereset::fuzz::InputFile file(".urdf");
  sphereset::RobotLoadOptions o;
  o.use_ros_package_path = false;
  const std::string& path = file.write(data, size);
  auto robot = sphereset::loadRobot(path, o);
  if (!robot) return 0;
  // One sphere per link, each link's own: a sphere read back under another link is an injection.
  std::vector<sphereset::LinkSpheres> spheres;
  std::set<std::string> names;
  for (size_t i = 0; i < robot->links.size(); ++i) {
    const double x = static_cast<double>(i);
    spheres.push_back({robot->links[i].name, {sphereset::Sphere{{x, 0.5, -x}, 0.25 + x}}});
    names.insert(d::validUtf8(robot->links[i].name));
  }
  // Names that are not UTF-8 are written repaired; two of them may then coincide.
  const bool distinct = names.size() == spheres.size();

  (void)sphereset::formatSrdf(*robot, sphereset::CollisionMatrix{});
  auto lula = sphereset::formatLulaDescription(*robot, spheres, {});
  if (lula && distinct) {
    auto back = d::parseLinkSpheres(sphereset::SphereFormat::kYaml, *lula, "lula");
    check(back.ok(), "a Lula description written does not read back");
    check(back->size() == spheres.size(), "a Lula description reads back other links");
    for (size_t l = 0; l < spheres.size(); ++l)
      check((*back)[l].link == d::validUtf8(spheres[l].link) && (*back)[l].spheres.size() == 1 &&
                (*back)[l].spheres[0].radius == spheres[l].spheres[0].radius,
            "a link of a Lula description reads back otherwise");
  }
  auto urdf = sphereset::formatSphereUrdf(path, spheres);
  if (urdf) {
    static sphereset::fuzz::InputFile out(".urdf");
    auto again = sphereset::loadRobot(
        out.write(reinterpret_cast<const uint8_t*>(urdf->data()), urdf->size()), o);
    check(again.ok(), "a URDF with spheres written does not read back");
    check(again->links.size() == robot->links.size(), "a URDF with spheres has other links");
    for (size_t l = 0; l < again->links.size(); ++l) {
      size_t balls = 0;
      for (const auto& g : again->links[l].geometry)
        balls += g.kind == sphereset::LinkGeometry::Kind::kSphere;
      check(again->links[l].name == robot->links[l].name && balls == 1,
            "a link of a URDF with spheres reads back otherwise");
    }
  }
  return 0;
}

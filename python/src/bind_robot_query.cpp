// Bindings of the posed-robot queries (robot_query.hpp): per link, collision with obstacles (a
// point cloud or obstacle spheres) and the least signed distance, at one configuration or at each
// waypoint of a trajectory.
#include <map>
#include <string>
#include <vector>

#include "common.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_query.hpp"

namespace sphereset::python {
namespace {

// (P, 3) points or (M, 4) spheres, checked and prepared by the library.
Obstacles obstaclesFrom(const py::object& o) {
  py::array a;
  try {
    a = py::array::ensure(o);
  } catch (const py::error_already_set&) {
  }
  if (a && a.ndim() == 2 && a.shape(1) == 4)
    return unwrap(makeObstacles(spheresFromArray(o, "obstacles"), "obstacles"));
  return unwrap(makeObstacles(pointsFromArray(o, "obstacles", false), "obstacles"));
}

std::map<std::string, double> jointMap(const py::object& o) {
  std::map<std::string, double> out;
  if (o.is_none()) return out;
  for (auto [k, v] : o.cast<py::dict>()) out[k.cast<std::string>()] = v.cast<double>();
  return out;
}

py::dict contactsDict(const RobotContacts& r) {
  py::dict d;
  d["collides"] = r.collides;
  d["distance"] = r.distance;
  d["link"] = r.closest_link >= 0 ? py::object(py::str(r.links[r.closest_link].link)) : py::none();
  py::list links;
  for (const LinkContact& c : r.links) {
    py::dict l;
    l["link"] = c.link;
    l["collides"] = c.collides;
    l["distance"] = c.distance;
    l["sphere"] = c.sphere;
    l["obstacle"] = c.obstacle;
    links.append(l);
  }
  d["links"] = links;
  return d;
}

void warnNotes(const std::vector<std::string>& notes, const std::string& prefix) {
  for (const std::string& note : notes)
    if (PyErr_WarnEx(PyExc_UserWarning, (prefix + note).c_str(), 1) != 0)
      throw py::error_already_set();
}

}  // namespace

void bindRobotQuery(py::module_& m) {
  m.def(
      "robot_contacts",
      [](const Robot& robot, const py::object& spheres, const py::object& obstacles,
         const py::object& joints) {
        const std::vector<LinkSpheres> links = linkSpheresFrom(spheres);
        const Obstacles o = obstaclesFrom(obstacles);
        const std::map<std::string, double> values = jointMap(joints);
        RobotContacts r;
        {
          py::gil_scoped_release release;
          r = unwrap(robotContacts(robot, links, o, values));
        }
        warnNotes(r.notes, "");
        return contactsDict(r);
      },
      py::arg("robot"), py::arg("spheres"), py::arg("obstacles"),
      py::arg("joint_values") = py::none(),
      "The posed robot against obstacles ((P, 3) points or (M, 4) spheres): {'collides', "
      "'distance', 'link' (the closest), 'links': [{'link', 'collides', 'distance', 'sphere', "
      "'obstacle'}...]} for {link: (N, 4)} spheres in the link frames. A link collides when its "
      "least signed distance is < 0 (touching is not a collision).");
  m.def(
      "trajectory_contacts",
      [](const Robot& robot, const py::object& spheres, const py::object& obstacles,
         const py::list& waypoints) {
        const std::vector<LinkSpheres> links = linkSpheresFrom(spheres);
        const Obstacles o = obstaclesFrom(obstacles);
        std::vector<std::map<std::string, double>> values;
        for (const py::handle& w : waypoints)
          values.push_back(jointMap(py::reinterpret_borrow<py::object>(w)));
        TrajectoryContacts t;
        {
          py::gil_scoped_release release;
          t = unwrap(trajectoryContacts(robot, links, o, values));
        }
        py::list per;
        for (size_t i = 0; i < t.waypoints.size(); ++i) {
          warnNotes(t.waypoints[i].notes, "waypoint " + std::to_string(i) + ": ");
          per.append(contactsDict(t.waypoints[i]));
        }
        py::dict d;
        d["first_collision"] = t.first_collision;
        d["waypoints"] = per;
        return d;
      },
      py::arg("robot"), py::arg("spheres"), py::arg("obstacles"), py::arg("waypoints"),
      "robot_contacts at each waypoint ({joint: value} dicts), in parallel: {'first_collision': "
      "the first colliding waypoint or -1, 'waypoints': [robot_contacts' dict...]}.");
}

}  // namespace sphereset::python

// Binding of the whole-robot fit (robot_fit.hpp: fitRobot), what `sphereset robot` runs: every
// link of a URDF fitted, a budget split over the links, per-link certificates; and the
// self-collision pairs by sampling the joint space (robot_collision.hpp: sampleSelfCollisions).
#include <cmath>
#include <map>
#include <memory>

#include "solid.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/robot_fit.hpp"

namespace sphereset::python {
namespace {

py::dict linkDict(const RobotLinkFit& j) {
  py::dict d = fieldsDict(robotLinkFields(j));
  d["spheres"] = spheresToArray(j.spheres);
  d["repair"] = j.fitted ? py::object(repairDict(j.repair)) : py::object(py::none());
  d["eval"] = j.fitted ? py::object(fieldsDict(evalResultFields(j.eval))) : py::object(py::none());
  return d;
}

// The link solids the mesh check needs, made as the robot command makes them (the repair of
// this build, default options); links of sphere primitives alone keep those.
std::vector<CollisionSolid> robotSolids(const Robot& robot) {
  return unwrap(robotCollisionSolids(robot, repairOptions("auto", -1.0, true, 0.0, 0.0, "0")));
}

py::dict collisionDict(const CollisionMatrix& m) {
  py::list disabled;
  for (const DisabledPair& p : m.disabled)
    disabled.append(py::make_tuple(text(p.link1), text(p.link2),
                                   std::string(disableReasonName(p.reason)), p.collisions));
  py::dict d;
  d["samples"] = m.samples;
  d["check"] = m.check == CollisionCheck::kMeshes ? "meshes" : "spheres";
  d["pairs"] = m.pairs;
  d["enabled"] = m.enabled;
  d["adjacent"] = m.count(DisableReason::kAdjacent);
  d["default"] = m.count(DisableReason::kDefault);
  d["always"] = m.count(DisableReason::kAlways);
  d["never"] = m.count(DisableReason::kNever);
  d["seconds"] = m.seconds;
  d["disabled"] = disabled;
  return d;
}

}  // namespace

void bindRobotFit(py::module_& m) {
  m.def(
      "_fit_robot",
      [](const Path& urdf_arg, const py::dict& options, const py::dict& fit_options,
         const std::vector<std::string>& package_paths, bool use_ros_package_path,
         int collision_group, const std::string& repair, const py::object& weld, bool fill,
         double alpha, double offset, const std::string& openings) {
        const std::string urdf = urdf_arg.string();
        // The rows of the robot table and the fit table's quality and seed, parsed and checked
        // by the library (its messages) before anything is read.
        RobotFitOptions fo;
        setOptions(options, [&](const std::string& name, const std::string& text) {
          return setRobotFitOption(&fo, name, text);
        });
        FitRequest request;
        setOptions(fit_options, [&](const std::string& name, const std::string& text) {
          return setFitRequestOption(&request, name, text);
        });
        fo.quality = request.quality;
        fo.seed = request.seed;
        fo.repair = repairOptions(repair, weld.is_none() ? -1.0 : weld.cast<double>(), fill, alpha,
                                  offset, openings);
        fo.name = urdf;
        // Ctrl-C: Python runs signal handlers on the main thread only, which fits links too;
        // there the check raises KeyboardInterrupt and the exception cancels the whole fit.
        fo.progress = [](const std::string&, const FitProgress&) {
          py::gil_scoped_acquire gil;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
        RobotLoadOptions lo;
        lo.package_paths = package_paths;
        lo.use_ros_package_path = use_ros_package_path;
        lo.mjcf_collision_group = collision_group;
        Robot robot;
        RobotFitResult r;
        {
          py::gil_scoped_release release;
          robot = unwrap(loadRobot(urdf, lo));
          r = unwrap(fitRobot(robot, fo));
        }
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        py::list links;
        for (const RobotLinkFit& j : r.links) links.append(linkDict(j));
        py::dict d = fieldsDict(robotFitFields(r));
        d["robot"] = text(robot.name);
        d["urdf"] = text(urdf);
        d["links"] = links;
        return d;
      },
      py::arg("urdf"), py::arg("options"), py::arg("fit_options"), py::arg("package_paths"),
      py::arg("use_ros_package_path"), py::arg("collision_group"), py::arg("repair"),
      py::arg("weld_tolerance"), py::arg("fill_cavities"), py::arg("wrap_alpha"),
      py::arg("wrap_offset"), py::arg("fill_openings"));
  m.def("_robot_option_table", [] { return optionTable(robotFitOptionTable()); });
  m.def(
      "_sample_self_collisions",
      [](const std::shared_ptr<Robot>& robot, const py::object& spheres, const py::dict& options) {
        // The rows of the sampling table, parsed and checked by the library (its messages).
        CollisionSamplingOptions co;
        setOptions(options, [&](const std::string& name, const std::string& text) {
          return setCollisionSamplingOption(&co, name, text);
        });
        const std::vector<LinkSpheres> links = linkSpheresFrom(spheres);
        const std::vector<CollisionSolid> solids = co.check == CollisionCheck::kMeshes
                                                       ? robotSolids(*robot)
                                                       : std::vector<CollisionSolid>{};
        // Ctrl-C between blocks of configurations (called from this, the main, thread).
        co.progress = [](const RobotProgress&) {
          py::gil_scoped_acquire gil;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
        Expected<CollisionMatrix> matrix = CollisionMatrix{};
        {
          py::gil_scoped_release release;
          matrix = sampleSelfCollisions(*robot, links, co, solids);
        }
        return collisionDict(unwrap(std::move(matrix)));
      },
      py::arg("robot"), py::arg("spheres"), py::arg("options"));
  m.def("_collision_option_table", [] { return optionTable(collisionSamplingOptionTable()); });
}

}  // namespace sphereset::python

// Bindings of robots (robot.hpp, robot_fit.hpp): a URDF's links, joints, link meshes, sphere
// primitives, forward kinematics, self-collision pairs, the URDF with sphere collisions, and the
// budget split. The per-robot pipeline of `sphereset robot` (which links to fit, the curves, the
// fits) is the command's own; Python builds it from these pieces and sphereset.fit.
#include <memory>

#include "solid.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"

namespace sphereset::python {
namespace {

const char* geometryKind(LinkGeometry::Kind k) {
  switch (k) {
    case LinkGeometry::Kind::kMesh:
      return "mesh";
    case LinkGeometry::Kind::kBox:
      return "box";
    case LinkGeometry::Kind::kCylinder:
      return "cylinder";
    case LinkGeometry::Kind::kSphere:
      return "sphere";
    case LinkGeometry::Kind::kCapsule:
      return "capsule";
    case LinkGeometry::Kind::kEllipsoid:
      return "ellipsoid";
    case LinkGeometry::Kind::kTriangles:
      return "triangles";
  }
  return "mesh";
}

const RobotLink& findLink(const Robot& r, const std::string& name) {
  for (const RobotLink& l : r.links)
    if (l.name == name) return l;
  raise(ErrorCode::kInvalidArgument, r.name + ": no link '" + name + "'");
}

// {joint: value} as given; the library checks names and values (jointState), and what it
// clamps becomes a Python warning.
std::map<std::string, double> jointValues(const Robot& r, const py::object& o) {
  std::map<std::string, double> out;
  if (o.is_none()) return out;
  for (auto [k, v] : o.cast<py::dict>()) out[k.cast<std::string>()] = v.cast<double>();
  JointState state = unwrap(jointState(r, out));
  for (const std::string& note : state.notes)
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
  // The whole state, clamped and with the mimics resolved: the callee's own pass over it finds
  // nothing left to change.
  return std::move(state.values);
}

py::list pairList(const std::vector<std::array<std::string, 2>>& v) {
  py::list out;
  for (const auto& p : v) out.append(py::make_tuple(p[0], p[1]));
  return out;
}

}  // namespace

void bindRobot(py::module_& m) {
  py::class_<Robot, std::shared_ptr<Robot>>(m, "Robot", R"doc(
A robot description read from a URDF (load_robot): links with their collision geometry (visual
geometry when a link has none), joints, forward kinematics.)doc")
      .def_readonly("name", &Robot::name)
      .def_readonly("root", &Robot::root, "The root link's name.")
      .def_property_readonly(
          "links",
          [](const Robot& r) {
            py::list out;
            for (const RobotLink& l : r.links) out.append(l.name);
            return out;
          },
          "Link names in file order.")
      .def(
          "link_geometry",
          [](const Robot& r, const std::string& link) {
            const RobotLink& l = findLink(r, link);
            py::list out;
            for (const LinkGeometry& g : l.geometry) {
              py::dict d;
              d["kind"] = geometryKind(g.kind);
              d["origin"] = isometryToArray(g.origin);
              if (g.kind == LinkGeometry::Kind::kMesh) {
                d["mesh_path"] = g.mesh_path;
                d["scale"] = py::make_tuple(g.scale.x(), g.scale.y(), g.scale.z());
              }
              if (g.kind == LinkGeometry::Kind::kBox)
                d["size"] = py::make_tuple(g.box_size.x(), g.box_size.y(), g.box_size.z());
              using K = LinkGeometry::Kind;
              if (g.kind == K::kCylinder || g.kind == K::kSphere || g.kind == K::kCapsule)
                d["radius"] = g.radius;
              if (g.kind == K::kCylinder || g.kind == K::kCapsule) d["length"] = g.length;
              if (g.kind == K::kEllipsoid)
                d["radii"] = py::make_tuple(g.radii.x(), g.radii.y(), g.radii.z());
              if (g.kind == K::kTriangles && g.triangles)
                d["triangles"] = static_cast<int64_t>(g.triangles->triangles.size());
              d["from_visual"] = l.from_visual;
              out.append(d);
            }
            return out;
          },
          py::arg("link"),
          "The link's geometry elements as dicts (kind: mesh, box, cylinder, sphere, capsule, "
          "ellipsoid or triangles (an MJCF mesh as MuJoCo compiled it); origin 4x4, "
          "mesh_path/scale, size, radius, length, radii, triangles (their count), from_visual).")
      .def_property_readonly(
          "excluded_pairs", [](const Robot& r) { return pairList(r.excluded_pairs); },
          "Link pairs the description itself never checks (an MJCF's collision filter and "
          "<contact><exclude>), as (a, b) tuples; empty for a URDF.")
      .def_property_readonly(
          "joints",
          [](const Robot& r) {
            py::list out;
            for (const RobotJoint& j : r.joints) {
              py::dict d;
              d["name"] = j.name;
              d["parent"] = j.parent;
              d["child"] = j.child;
              d["type"] = jointTypeName(j.type);
              d["origin"] = isometryToArray(j.origin);
              d["axis"] = py::make_tuple(j.axis.x(), j.axis.y(), j.axis.z());
              d["lower"] = j.lower;
              d["upper"] = j.upper;
              d["anchor"] = py::make_tuple(j.anchor.x(), j.anchor.y(), j.anchor.z());
              d["reference"] = j.reference;
              if (j.mimic)
                d["mimic"] = py::make_tuple(j.mimic->joint, j.mimic->multiplier, j.mimic->offset);
              else
                d["mimic"] = py::none();
              out.append(d);
            }
            return out;
          },
          "Joints in file order, as dicts (name, parent, child, type, origin, axis, lower, "
          "upper, anchor and reference (an MJCF joint's pos and ref), mimic: (leader, "
          "multiplier, offset) or None).")
      .def(
          "link_mesh",
          [](const Robot& r, const std::string& link, int cylinder_segments) {
            const RobotLink& l = findLink(r, link);
            if (cylinder_segments < 3)
              raise(ErrorCode::kInvalidArgument, "cylinder_segments must be >= 3");
            Expected<Mesh> mesh = Error{ErrorCode::kInvalidArgument, "not run"};
            {
              py::gil_scoped_release release;
              mesh = linkMesh(l, cylinder_segments);
            }
            auto pm = std::make_shared<PyMesh>();
            pm->loaded.mesh = unwrap(std::move(mesh));
            pm->loaded.report.path = r.name + ": link '" + link + "'";
            return pm;
          },
          py::arg("link"), py::arg("cylinder_segments") = 48,
          "The link's geometry as one Mesh in the link frame (elements concatenated, not "
          "cleaned: pass it to Mesh(m.vertices, m.faces) for the clean-up the robot command "
          "applies).")
      .def(
          "link_spheres",
          [](const Robot& r, const std::string& link) {
            return spheresToArray(linkSpheres(findLink(r, link)));
          },
          py::arg("link"), "The link's sphere primitives (exact), (K, 4), in the link frame.")
      .def(
          "link_poses",
          [](const Robot& r, const py::object& joints) {
            const auto poses = unwrap(linkPoses(r, jointValues(r, joints)));
            py::dict out;
            for (const RobotLink& l : r.links) {
              auto it = poses.find(l.name);
              if (it != poses.end()) out[py::str(l.name)] = isometryToArray(it->second);
            }
            return out;
          },
          py::arg("joint_values") = py::none(),
          "Forward kinematics: {link: 4x4 pose in the root frame} for the links the root "
          "reaches; joints not given are at 0, values beyond the limits are clamped (with a "
          "UserWarning), mimic joints follow their leaders.")
      .def(
          "self_collision_pairs",
          [](const Robot& r, const py::object& spheres, const py::object& joints) {
            const SelfCollisionPairs p =
                unwrap(selfCollisionPairs(r, linkSpheresFrom(spheres), jointValues(r, joints)));
            py::dict d;
            d["adjacent"] = pairList(p.adjacent);
            d["overlapping"] = pairList(p.overlapping);
            return d;
          },
          py::arg("spheres"), py::arg("joint_values") = py::none(),
          "Pairs of links to leave out of self-collision checks, as cuRobo lists them: "
          "{'adjacent': [(a, b)...], 'overlapping': [...]} for {link: (N, 4)} spheres in the link "
          "frames at the given joint values.")
      .def("__repr__", [](const Robot& r) {
        return "<sphereset.Robot '" + r.name + "': " + std::to_string(r.links.size()) + " links, " +
               std::to_string(r.joints.size()) + " joints>";
      });

  m.def(
      "load_robot",
      [](const Path& urdf_arg, const std::vector<std::string>& package_paths,
         bool use_ros_package_path, int collision_group) {
        const std::string urdf = urdf_arg.string();
        RobotLoadOptions lo;
        lo.package_paths = package_paths;
        lo.use_ros_package_path = use_ros_package_path;
        lo.mjcf_collision_group = collision_group;
        py::gil_scoped_release release;
        return std::make_shared<Robot>(unwrap(loadRobot(urdf, lo)));
      },
      py::arg("urdf"), py::kw_only(), py::arg("package_paths") = std::vector<std::string>{},
      py::arg("use_ros_package_path") = true, py::arg("collision_group") = -1,
      "Reads a URDF and resolves its mesh paths (relative, absolute, file://, package:// through "
      "package_paths then ROS_PACKAGE_PATH), or an MJCF (.xml) through MuJoCo: its collision "
      "geoms are those MuJoCo collides, or those of collision_group (0-5).");
  m.def("mujoco_available", &mujocoAvailable, "Whether this build reads and writes MJCF (MuJoCo).");

  m.def(
      "write_robot_spheres",
      [](const Path& path_arg, const py::object& links, const std::shared_ptr<Robot>& robot,
         const py::object& joints, const std::string& source) {
        const std::string path = path_arg.string();
        const std::vector<LinkSpheres> l = linkSpheresFrom(links);
        SphereFileMeta meta;
        meta.source_mesh = source;
        if (!robot) {
          check(writeRobotSpheres(path, l, nullptr, meta));
          return;
        }
        const SelfCollisionPairs p =
            unwrap(selfCollisionPairs(*robot, l, jointValues(*robot, joints)));
        check(writeRobotSpheres(path, l, &p, meta));
      },
      py::arg("path"), py::arg("links"), py::kw_only(), py::arg("robot") = nullptr,
      py::arg("joint_values") = py::none(), py::arg("source") = "",
      "Writes {link: (N, 4)} as cuRobo YAML; with `robot`, followed by self_collision_ignore "
      "(adjacent links and links overlapping at joint_values) and self_collision_buffer.");

  m.def(
      "write_sphere_urdf",
      [](const Path& in_urdf_arg, const Path& out_path_arg, const py::object& links) {
        const std::string in_urdf = in_urdf_arg.string();
        const std::string out_path = out_path_arg.string();
        const std::vector<LinkSpheres> l = linkSpheresFrom(links);
        py::gil_scoped_release release;
        check(writeSphereUrdf(in_urdf, out_path, l));
      },
      py::arg("in_urdf"), py::arg("out_path"), py::arg("links"),
      "Writes the URDF with the collisions of the given links replaced by their spheres.");
  m.def(
      "format_sphere_urdf",
      [](const Path& in_urdf_arg, const py::object& links) {
        const std::string in_urdf = in_urdf_arg.string();
        return unwrap(formatSphereUrdf(in_urdf, linkSpheresFrom(links)));
      },
      py::arg("in_urdf"), py::arg("links"), "The text write_sphere_urdf writes.");
  m.def(
      "write_sphere_mjcf",
      [](const Path& in_arg, const Path& out_arg, const py::object& links,
         const std::vector<std::array<std::string, 2>>& exclude, int collision_group) {
        const std::string in = in_arg.string(), out = out_arg.string();
        const std::vector<LinkSpheres> l = linkSpheresFrom(links);
        RobotLoadOptions lo;
        lo.mjcf_collision_group = collision_group;
        py::gil_scoped_release release;
        check(writeSphereMjcf(in, out, l, exclude, lo));
      },
      py::arg("in_robot"), py::arg("out_path"), py::arg("links"), py::kw_only(),
      py::arg("exclude") = std::vector<std::array<std::string, 2>>{},
      py::arg("collision_group") = -1,
      "Writes the robot (MJCF or URDF) as an MJCF that MuJoCo loads, the collision geoms of the "
      "given links replaced by sphere geoms, with a <contact><exclude> per pair of `exclude` "
      "that MuJoCo does not already filter.");

  m.def(
      "split_budget",
      [](const std::vector<std::pair<std::vector<int>, std::vector<double>>>& curves,
         const std::vector<int>& fixed, int budget) {
        std::vector<LinkFitCurve> c;
        for (const auto& [counts, volumes] : curves) {
          if (counts.empty() || counts.size() != volumes.size())
            raise(ErrorCode::kInvalidArgument,
                  "each curve is (counts, outside_volumes) of equal, non-zero length");
          c.push_back({counts, volumes});
        }
        if (fixed.size() != c.size())
          raise(ErrorCode::kInvalidArgument, "fixed must hold one count per curve");
        return unwrap(splitBudget(c, fixed, budget));
      },
      py::arg("curves"), py::arg("fixed"), py::arg("budget"),
      "Sphere counts per link for a budget: curves are (counts, outside volumes) per link, "
      "fixed[i] >= 0 fixes link i's count, -1 leaves it to the budget (robot_fit.hpp).");
  m.def(
      "curve_volume",
      [](const std::vector<int>& counts, const std::vector<double>& volumes, int k) {
        if (counts.size() != volumes.size())
          raise(ErrorCode::kInvalidArgument, "counts and volumes of equal length");
        return unwrap(curveVolume({counts, volumes}, k));
      },
      py::arg("counts"), py::arg("outside_volumes"), py::arg("k"),
      "A link's outside volume at k spheres interpolated on its measured curve.");
}

}  // namespace sphereset::python

// Bindings of the sphere files (sphere_io.hpp: text, JSON, .sph, cuRobo YAML; sets, robots'
// link sets and trees) and of the sphere-set meshes (export.hpp).
#include "common.hpp"
#include "sphereset/export.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::python {
namespace {

SphereFileMeta meta(const std::string& name, const std::string& source_mesh) {
  SphereFileMeta m;
  m.name = name;
  m.source_mesh = source_mesh;
  return m;
}

SphereFormat formatFromName(const std::string& s) { return unwrap(sphereFormatFromName(s)); }

const char* formatName(SphereFormat f) { return sphereFormatName(f); }

// dict (or list of pairs) link name -> (N, 4) spheres, in the given order.
std::vector<LinkSpheres> linksFrom(const py::object& o) {
  std::vector<LinkSpheres> out;
  py::iterable items =
      py::isinstance<py::dict>(o) ? py::iterable(o.attr("items")()) : py::iterable(o);
  for (py::handle item : items) {
    py::tuple pair = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
    if (pair.size() != 2)
      raise(ErrorCode::kInvalidArgument, "links: expected (name, spheres) pairs");
    const std::string name = pair[0].cast<std::string>();
    out.push_back({name, spheresFromArray(pair[1], "link '" + name + "'")});
  }
  return out;
}

}  // namespace

std::vector<LinkSpheres> linkSpheresFrom(const py::object& o) { return linksFrom(o); }

void bindIo(py::module_& m) {
  m.def(
      "sphere_format",
      [](const Path& path_arg) {
        const std::string path = path_arg.string();
        return formatName(unwrap(sphereFormatFromPath(path)));
      },
      py::arg("path"),
      "The sphere format a path's extension names: 'txt' (.txt, .xyzr), 'json', 'sph', 'yaml' "
      "(.yaml, .yml). InvalidArgumentError for anything else.");
  m.def(
      "read_spheres",
      [](const Path& path_arg) {
        const std::string path = path_arg.string();
        std::vector<Sphere> s;
        {
          py::gil_scoped_release release;
          s = unwrap(readSpheres(path));
        }
        return spheresToArray(s);
      },
      py::arg("path"),
      "Reads a sphere set (.txt, .json, .sph: its deepest level, .yaml: one link) as (N, 4).");
  m.def(
      "write_spheres",
      [](const Path& path_arg, const py::object& spheres, const std::string& name,
         const std::string& source_mesh) {
        const std::string path = path_arg.string();
        const std::vector<Sphere> s = spheresFromArray(spheres, "spheres");
        py::gil_scoped_release release;
        check(writeSpheres(path, s, meta(name, source_mesh)));
      },
      py::arg("path"), py::arg("spheres"), py::kw_only(), py::arg("name") = "object",
      py::arg("source_mesh") = "",
      "Writes (N, 4) spheres in the format of the extension, atomically. `name` is the link "
      "name of .yaml output; `source_mesh` is recorded in .json output.");
  m.def(
      "format_spheres",
      [](const std::string& format, const py::object& spheres, const std::string& name,
         const std::string& source_mesh) {
        return formatSpheres(formatFromName(format), spheresFromArray(spheres, "spheres"),
                             meta(name, source_mesh));
      },
      py::arg("format"), py::arg("spheres"), py::kw_only(), py::arg("name") = "object",
      py::arg("source_mesh") = "",
      "The text write_spheres writes, for format 'txt', 'json', "
      "'sph' or 'yaml'.");
  m.def(
      "read_link_spheres",
      [](const Path& path_arg) {
        const std::string path = path_arg.string();
        std::vector<LinkSpheres> links;
        {
          py::gil_scoped_release release;
          links = unwrap(readLinkSpheres(path));
        }
        py::dict out;
        for (const LinkSpheres& l : links) out[py::str(l.link)] = spheresToArray(l.spheres);
        return out;
      },
      py::arg("path"),
      "Every link of a cuRobo YAML file, in file order: {link: (N, 4)}. Other formats give one "
      "link named after the file's stem.");
  m.def(
      "write_link_spheres",
      [](const Path& path_arg, const py::object& links, const std::string& source_mesh) {
        const std::string path = path_arg.string();
        const std::vector<LinkSpheres> l = linksFrom(links);
        py::gil_scoped_release release;
        check(writeLinkSpheres(path, l, meta("object", source_mesh)));
      },
      py::arg("path"), py::arg("links"), py::kw_only(), py::arg("source_mesh") = "",
      "Writes {link: (N, 4)} as one cuRobo YAML file (.yaml/.yml), atomically.");
  m.def(
      "read_sphere_tree",
      [](const Path& path_arg) {
        const std::string path = path_arg.string();
        py::gil_scoped_release release;
        return unwrap(readSphereTree(path));
      },
      py::arg("path"),
      "Reads a .sph tree or a JSON tree; a plain sphere set gives a one-level tree.");
  m.def(
      "write_sphere_tree",
      [](const Path& path_arg, const SphereTree& tree, const std::string& source_mesh) {
        const std::string path = path_arg.string();
        py::gil_scoped_release release;
        check(writeSphereTree(path, tree, meta("object", source_mesh)));
      },
      py::arg("path"), py::arg("tree"), py::kw_only(), py::arg("source_mesh") = "",
      "Writes a SphereTree as .sph (Bradshaw's layout) or .json, atomically.");
  m.def(
      "format_sphere_tree",
      [](const std::string& format, const SphereTree& tree) {
        return formatSphereTree(formatFromName(format), tree, {});
      },
      py::arg("format"), py::arg("tree"), "The text write_sphere_tree writes ('sph' or 'json').");
  m.def(
      "write_sphere_mesh",
      [](const Path& path_arg, const py::object& spheres, int subdivisions) {
        const std::string path = path_arg.string();
        const std::vector<Sphere> s = spheresFromArray(spheres, "spheres");
        py::gil_scoped_release release;
        check(writeSphereSetMesh(path, s, subdivisions));
      },
      py::arg("path"), py::arg("spheres"), py::arg("subdivisions") = 2,
      "Writes the spheres as one triangle mesh (.ply, .obj, .gltf, .glb) to view beside the "
      "model: each sphere a subdivided icosahedron, coloured.");
}

}  // namespace sphereset::python

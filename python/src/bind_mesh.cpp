// Bindings of meshes: sphereset.Mesh (numpy arrays in and out), loading, the diagnosis that
// `sphereset check` reports, and sphereset.Solid (the repaired, indexed solid).
#include <cmath>
#include <memory>

#include "solid.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/mesh_defects.hpp"
#include "sphereset/repair.hpp"

#ifdef SPHERESET_WITH_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset::python {

RepairOptions repairOptions(const std::string& repair, double weld_tolerance, bool fill_cavities,
                            double wrap_alpha, double wrap_offset,
                            const std::string& fill_openings) {
  // The library's table checks every value, with the messages of every door.
  RepairOptions ro;
  check(setRepairOption(&ro, "repair", repair));
  check(setRepairOption(&ro, "fill_openings", fill_openings));
  ro.weld_tolerance = weld_tolerance;
  ro.fill_cavities = fill_cavities;
  ro.wrap_alpha = wrap_alpha;
  ro.wrap_offset = wrap_offset;
  check(checkRepairOptions(ro));
#ifdef SPHERESET_WITH_REPAIR
  ro.operations = cgalSolidOperations();
#endif
  return ro;
}

py::dict repairDict(const RepairResult& r) { return fieldsDict(repairResultFields(r)); }

py::dict diagnosisDict(const MeshDiagnosis& d) { return fieldsDict(meshDiagnosisFields(d)); }

namespace {

py::dict loadReportDict(const LoadReport& r) {
  py::dict d = fieldsDict(loadReportFields(r));
  d["path"] = text(r.path);
  d["format"] = r.format;
  return d;
}

py::array_t<int32_t> facesToArray(const Mesh& mesh) {
  py::array_t<int32_t> out({static_cast<py::ssize_t>(mesh.triangles.size()), py::ssize_t{3}});
  auto v = out.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int j = 0; j < 3; ++j) v(static_cast<py::ssize_t>(i), j) = mesh.triangles[i][j];
  return out;
}

// Faces from an integer array-like; kInvalidData for indices that no vertex has.
std::vector<Triangle> facesFromArray(const py::handle& a, size_t vertices,
                                     const std::string& name) {
  py::array arr = py::array::ensure(a);
  if (!arr) raise(ErrorCode::kInvalidArgument, name + ": faces must be an array of integers");
  const char kind = arr.dtype().kind();
  if (arr.size() > 0 && kind != 'i' && kind != 'u')
    raise(ErrorCode::kInvalidArgument, name + ": faces must have an integer dtype (got " +
                                           std::string(py::str(arr.dtype())) + ")");
  if (arr.ndim() != 2 || arr.shape(1) != 3) {
    if (arr.size() == 0) return {};
    raise(ErrorCode::kInvalidArgument, name + ": faces must be an (F, 3) array");
  }
  // Unsigned indices are read as unsigned: 2^64 - 1 is that number, not vertex -1.
  std::vector<Triangle> out(static_cast<size_t>(arr.shape(0)));
  auto read = [&](auto zero) {
    using Index = decltype(zero);
    auto f = py::array_t<Index, py::array::c_style | py::array::forcecast>::ensure(arr);
    const Index* d = f.data();
    for (size_t t = 0; t < out.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Index i = d[3 * t + static_cast<size_t>(k)];
        if (i < 0 || static_cast<uint64_t>(i) >= vertices ||
            static_cast<uint64_t>(i) > static_cast<uint64_t>(INT32_MAX))
          raise(ErrorCode::kInvalidData, name + ": triangle " + std::to_string(t) +
                                             " references vertex " + std::to_string(i) + " of " +
                                             std::to_string(vertices));
        out[t][static_cast<size_t>(k)] = static_cast<int32_t>(i);
      }
  };
  if (kind == 'u')
    read(uint64_t{0});
  else
    read(int64_t{0});
  return out;
}

std::shared_ptr<PyMesh> meshFromArrays(const py::handle& vertices, const py::handle& faces,
                                       bool clean, double weld_tolerance, const std::string& name) {
  // cleanMesh checks the coordinates itself, with the loader's message.
  std::vector<Vec3> v = pointsFromArray(vertices, name + ": vertices", false);
  std::vector<Triangle> f = facesFromArray(faces, v.size(), name);
  auto out = std::make_shared<PyMesh>();
  if (clean) {
    LoadOptions lo;
    lo.weld_tolerance = weld_tolerance;
    py::gil_scoped_release release;
    out->loaded = unwrap(cleanMesh(std::move(v), std::move(f), lo, name));
    return out;
  }
  for (size_t i = 0; i < v.size(); ++i)
    if (!v[i].allFinite())
      raise(ErrorCode::kInvalidData,
            name + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  if (f.empty()) raise(ErrorCode::kInvalidData, name + ": no triangles");
  out->loaded.report.path = name;
  out->loaded.report.file_vertices = static_cast<int64_t>(v.size());
  out->loaded.report.file_faces = static_cast<int64_t>(f.size());
  out->loaded.mesh.vertices = std::move(v);
  out->loaded.mesh.triangles = std::move(f);
  return out;
}

}  // namespace

void bindMesh(py::module_& m) {
  py::class_<PyMesh, std::shared_ptr<PyMesh>>(m, "Mesh", R"doc(
An indexed triangle mesh.

Mesh(vertices, faces, *, clean=True, weld_tolerance=0.0, name="mesh")

vertices: (V, 3) array-like of floats; faces: (F, 3) array-like of integer vertex indices
(counter-clockwise seen from outside). With clean=True (the default) the arrays get the
clean-up `load_mesh` gives a file: exactly coincident vertices merged, degenerate and duplicate
triangles dropped, unused vertices removed, the orientation flipped when the volume is negative.
Raises InvalidDataError for NaN/infinite coordinates, indices out of range or no triangles.)doc")
      .def(py::init([](const py::object& vertices, const py::object& faces, bool clean,
                       double weld_tolerance, const std::string& name) {
             return meshFromArrays(vertices, faces, clean, weld_tolerance, name);
           }),
           py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("clean") = true,
           py::arg("weld_tolerance") = 0.0, py::arg("name") = "mesh")
      .def_property_readonly(
          "vertices", [](const PyMesh& pm) { return pointsToArray(pm.loaded.mesh.vertices); },
          "(V, 3) float64 array (a copy).")
      .def_property_readonly(
          "faces", [](const PyMesh& pm) { return facesToArray(pm.loaded.mesh); },
          "(F, 3) int32 array of vertex indices (a copy).")
      .def_property_readonly(
          "name", [](const PyMesh& pm) { return pm.loaded.report.path; },
          "The file path, or the name given to the constructor.")
      .def_property_readonly(
          "load_report", [](const PyMesh& pm) { return loadReportDict(pm.loaded.report); },
          "What loading and the clean-up did (dict, as `sphereset check --json` reports it).")
      .def_property_readonly(
          "volume", [](const PyMesh& pm) { return signedVolume(pm.loaded.mesh); },
          "Signed volume (positive for an outward-oriented closed mesh).")
      .def_property_readonly(
          "area", [](const PyMesh& pm) { return surfaceArea(pm.loaded.mesh); }, "Surface area.")
      .def("__len__", [](const PyMesh& pm) { return pm.loaded.mesh.triangles.size(); })
      .def("__repr__", [](const PyMesh& pm) {
        return text("<sphereset.Mesh '" + pm.loaded.report.path +
                    "': " + std::to_string(pm.loaded.mesh.vertices.size()) + " vertices, " +
                    std::to_string(pm.loaded.mesh.triangles.size()) + " triangles>");
      });

  m.def("_repair_option_table", [] { return optionTable(repairOptionTable()); });
  m.def(
      "_check_repair_options",
      [](const std::string& repair, double weld_tolerance, bool fill_cavities, double wrap_alpha,
         double wrap_offset, const std::string& fill_openings) {
        repairOptions(repair, weld_tolerance, fill_cavities, wrap_alpha, wrap_offset,
                      fill_openings);
      },
      py::arg("repair"), py::arg("weld_tolerance"), py::arg("fill_cavities"), py::arg("wrap_alpha"),
      py::arg("wrap_offset"), py::arg("fill_openings"),
      "Raises the library's InvalidArgumentError when a repair option is outside its table row.");
  m.def(
      "_repair_option_values",
      [](const py::dict& texts) {
        RepairOptions ro;
        for (const auto& [name, text] : texts)
          check(setRepairOption(&ro, py::str(name), py::str(text)));
        py::dict d;
        d["repair"] = ro.enabled ? "auto" : "off";
        d["weld_tolerance"] = ro.weld_tolerance;
        d["wrap_alpha"] = ro.wrap_alpha;
        d["wrap_offset"] = ro.wrap_offset;
        d["fill_cavities"] = ro.fill_cavities;
        d["fill_openings"] = ro.fill_openings == kAutomatic
                                 ? py::object(py::str("auto"))
                                 : py::object(py::float_(ro.fill_openings));
        return d;
      },
      py::arg("texts"),
      "The repair options {name: text} as users type them, parsed and checked by the library's "
      "table; the values of every row (defaults for those not given), and fill_cavities' default.");

  m.def(
      "_load_mesh",
      [](const Path& path_arg, double weld_tolerance) {
        const std::string path = path_arg.string();
        LoadOptions lo;
        lo.weld_tolerance = weld_tolerance;
        auto out = std::make_shared<PyMesh>();
        py::gil_scoped_release release;
        out->loaded = unwrap(loadMesh(path, lo));
        return out;
      },
      py::arg("path"), py::arg("weld_tolerance") = 0.0);

  m.def(
      "_diagnose",
      [](const PyMesh& pm) {
        MeshDiagnosis d;
        {
          py::gil_scoped_release release;
          d = diagnoseMesh(pm.loaded.mesh);
        }
        return diagnosisDict(d);
      },
      py::arg("mesh"));

  m.def(
      "_shells",
      [](const PyMesh& pm) {
        ShellAnalysis sa;
        {
          py::gil_scoped_release release;
          sa = analyzeShells(pm.loaded.mesh);
        }
        py::dict c = fieldsDict(shellCountFields(countShells(sa)));
        c["intersecting_pairs"] = sa.intersections.pairs;
        return c;
      },
      py::arg("mesh"));

  py::class_<PySolid, std::shared_ptr<PySolid>>(m, "Solid", R"doc(
A mesh made a solid the fit can run on, indexed for the fit and the evaluation.

Solid(mesh, *, repair="auto", weld_tolerance=None, fill_cavities=True, wrap_alpha=0.0,
      wrap_offset=0.0, fill_openings="0")

The repair is the one `sphereset fit` applies (welding, re-orienting, capping holes, uniting
crossing shells, wrapping); repair="off" accepts only a clean closed solid. Build it once to fit
and evaluate the same mesh several times. Raises NotSolidError when no solid can be made.)doc")
      .def(py::init([](std::shared_ptr<const PyMesh> mesh, const std::string& repair,
                       const py::object& weld, bool fill, double alpha, double offset,
                       const std::string& openings) {
             const double w = weld.is_none() ? -1.0 : weld.cast<double>();
             RepairOptions ro = repairOptions(repair, w, fill, alpha, offset, openings);
             auto s = std::make_shared<PySolid>();
             s->input = mesh;
             s->name = mesh->loaded.report.path;
             py::gil_scoped_release release;
             s->repair = unwrap(repairMesh(mesh->loaded.mesh, ro, s->name));
             s->index = std::make_unique<SolidIndex>(s->repair.solid);
             return s;
           }),
           py::arg("mesh"), py::kw_only(), py::arg("repair") = "auto",
           py::arg("weld_tolerance") = py::none(),
           py::arg("fill_cavities") = RepairOptions{}.fill_cavities,
           py::arg("wrap_alpha") = RepairOptions{}.wrap_alpha,
           py::arg("wrap_offset") = RepairOptions{}.wrap_offset, py::arg("fill_openings") = "0")
      .def_property_readonly(
          "mesh",
          [](const PySolid& s) {
            auto pm = std::make_shared<PyMesh>();
            pm->loaded.mesh = s.repair.solid;
            pm->loaded.report.path = s.name;
            return pm;
          },
          "The solid that is fitted (the input itself when it needed no repair).")
      .def_property_readonly(
          "input", [](const PySolid& s) { return s.input; }, "The mesh the solid was made from.")
      .def_property_readonly(
          "original",
          [](const PySolid& s) -> py::object {
            if (!s.original()) return py::none();
            auto pm = std::make_shared<PyMesh>();
            pm->loaded.mesh = *s.original();
            pm->loaded.report.path = s.name;
            return py::cast(pm);
          },
          "The input's triangles that fit and evaluation also cover, when the solid differs "
          "from them; else None.")
      .def_property_readonly(
          "repair", [](const PySolid& s) { return repairDict(s.repair); },
          "What the repair did (dict, as `sphereset fit --json` reports it).")
      .def_property_readonly("name", [](const PySolid& s) { return s.name; })
      .def_property_readonly("volume",
                             [](const PySolid& s) { return signedVolume(s.repair.solid); })
      .def(
          "contains",
          [](const PySolid& s, const py::object& points) {
            const std::vector<Vec3> p = pointsFromArray(points, "points");
            py::array_t<bool> out(static_cast<py::ssize_t>(p.size()));
            auto v = out.mutable_unchecked<1>();
            py::gil_scoped_release release;
            for (size_t i = 0; i < p.size(); ++i)
              v(static_cast<py::ssize_t>(i)) = s.index->classify(p[i]) != Containment::kOutside;
            return out;
          },
          py::arg("points"), "Whether each point of a (P, 3) array is inside or on the solid.")
      .def(
          "distance",
          [](const PySolid& s, const py::object& points) {
            const std::vector<Vec3> p = pointsFromArray(points, "points");
            py::array_t<double> out(static_cast<py::ssize_t>(p.size()));
            auto v = out.mutable_unchecked<1>();
            py::gil_scoped_release release;
            for (size_t i = 0; i < p.size(); ++i)
              v(static_cast<py::ssize_t>(i)) = s.index->distance(p[i]);
            return out;
          },
          py::arg("points"), "Unsigned distance from each point of a (P, 3) array to the surface.")
      .def(
          "outside_volume",
          [](const PySolid& s, const py::object& spheres) {
            const std::vector<Sphere> sp = spheresFromArray(spheres, "spheres");
            py::array_t<double> out(static_cast<py::ssize_t>(sp.size()));
            auto v = out.mutable_unchecked<1>();
            py::gil_scoped_release release;
            for (size_t i = 0; i < sp.size(); ++i)
              v(static_cast<py::ssize_t>(i)) = s.index->outsideVolume(sp[i]).volume;
            return out;
          },
          py::arg("spheres"), "Exact volume of each sphere of an (N, 4) array outside the solid.")
      .def("__repr__", [](const PySolid& s) {
        return text("<sphereset.Solid '" + s.name + "': repair " + repairName(s.repair.kind) +
                    ", " + std::to_string(s.repair.solid.triangles.size()) + " triangles>");
      });
}

}  // namespace sphereset::python

// Bindings of the evaluation: sphereset.evaluate with the defaults of `sphereset eval`.
#include <memory>

#include "solid.hpp"
#include "sphereset/evaluate.hpp"

namespace sphereset::python {

void bindEval(py::module_& m) {
  m.def(
      "_evaluate",
      [](const std::shared_ptr<PySolid>& solid, const py::object& spheres, uint64_t seed,
         int64_t samples, int segments, const std::string& up, int shadow_resolution,
         int shadow_lights, int surface_max_depth, int interior_max_depth) {
        const std::vector<Sphere> sp = spheresFromArray(spheres, "spheres");
        if (sp.empty()) raise(ErrorCode::kInvalidData, "spheres: no spheres");
        if (up != "x" && up != "y" && up != "z")
          raise(ErrorCode::kInvalidArgument, "up must be 'x', 'y' or 'z'");
        if (samples < 0 || segments < 0 || shadow_resolution < 0 || shadow_lights < 1 ||
            surface_max_depth < 0 || interior_max_depth < 0)
          raise(ErrorCode::kInvalidArgument,
                "samples, segments, shadow_resolution and the depths must be >= 0, "
                "shadow_lights >= 1");
        EvalOptions eo;
        eo.seed = seed;
        eo.union_samples = samples;
        eo.proximity_segments = segments;
        eo.up_axis = up[0] - 'x';
        eo.shadow_resolution = shadow_resolution;
        eo.shadow_lights = shadow_lights;
        eo.surface_max_depth = surface_max_depth;
        eo.interior_max_depth = interior_max_depth;
        eo.original = solid->original();
        EvalResult r;
        {
          py::gil_scoped_release release;
          r = evaluateSpheres(*solid->index, sp, eo);
        }
        py::dict d;
        d["spheres"] = sp.size();
        d["mesh_volume"] = r.mesh_volume;
        d["bbox_diagonal"] = r.bbox_diagonal;
        d["er_sum"] = r.er_sum;
        d["er_union"] = r.er_union;
        d["er_union_stderr"] = r.er_union_stderr;
        d["outside_volume"] = py::array_t<double>(static_cast<py::ssize_t>(r.outside_volume.size()),
                                                  r.outside_volume.data());
        d["surface_covered"] = r.surface_covered;
        d["max_surface_gap"] = r.max_surface_gap;
        d["surface_uncertified_area"] = r.surface_uncertified_area;
        d["uncovered_triangles"] = r.uncovered_triangles;
        d["original_covered"] = r.original_covered;
        d["max_original_gap"] = r.max_original_gap;
        d["original_uncovered_triangles"] = r.original_uncovered_triangles;
        d["interior_covered"] = r.interior_covered;
        d["max_interior_gap"] = r.max_interior_gap;
        d["interior_uncertified_cells"] = r.interior_uncertified_cells;
        d["proximity_error"] = r.proximity_error;
        d["shadow_error_sky"] = r.shadow_error_sky;
        d["shadow_error_lights"] = r.shadow_error_lights;
        d["seconds"] = r.seconds;
        d["repair"] = repairDict(solid->repair);
        return d;
      },
      py::arg("solid"), py::arg("spheres"), py::arg("seed"), py::arg("samples"),
      py::arg("segments"), py::arg("up"), py::arg("shadow_resolution"), py::arg("shadow_lights"),
      py::arg("surface_max_depth"), py::arg("interior_max_depth"));
}

}  // namespace sphereset::python

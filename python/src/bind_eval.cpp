// Bindings of the evaluation: sphereset.evaluate with the defaults of `sphereset eval`.
#include <memory>

#include "solid.hpp"
#include "sphereset/evaluate.hpp"

namespace sphereset::python {

void bindEval(py::module_& m) {
  m.def(
      "_evaluate",
      [](const std::shared_ptr<PySolid>& solid, const py::object& spheres,
         const py::dict& options) {
        EvalOptions eo;
        eo.original = solid->original();
        setOptions(options, [&](const std::string& name, const std::string& text) {
          return setEvalOption(&eo, name, text);
        });
        // Ctrl-C: the signal handlers run here, from the calling thread, about every quarter
        // second; KeyboardInterrupt leaves evaluateSpheres as an exception.
        eo.poll = [] {
          py::gil_scoped_acquire gil;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
        const std::vector<Sphere> sp = spheresFromArray(spheres, "spheres");
        Expected<EvalResult> evaluated = Error{ErrorCode::kInvalidArgument, ""};
        {
          py::gil_scoped_release release;
          evaluated = evaluateSpheres(*solid->index, sp, eo);
        }
        const EvalResult r = unwrap(std::move(evaluated));
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
      py::arg("solid"), py::arg("spheres"), py::arg("options"));
  m.def("_eval_option_table", [] { return optionTable(evalOptionTable()); });
  m.def("_check_eval_options", [](const py::dict& options) {
    EvalOptions eo;
    setOptions(options, [&](const std::string& name, const std::string& text) {
      return setEvalOption(&eo, name, text);
    });
  });
}

}  // namespace sphereset::python

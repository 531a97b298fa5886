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
        eo.walls = solid->walls();
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
        py::dict d = fieldsDict(evalResultFields(r));
        d["spheres"] = sp.size();
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

// Bindings of the fit: sphereset.fit with the options and defaults of `sphereset fit`, the
// progress callback, and cancellation by Ctrl-C.
#include <memory>
#include <span>

#include "fit_args.hpp"
#include "solid.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::python {

FitRequest fitRequest(const py::dict& options) {
  FitRequest rq;
  for (const auto& [key, value] : options) {
    if (value.is_none()) continue;
    check(setFitRequestOption(&rq, py::str(key), py::str(value)));
  }
  return rq;
}

FitOptions fitOptions(const py::dict& options) { return fitOptionsFor(fitRequest(options)); }

py::list optionTable(std::span<const OptionSpec> table) {
  py::list rows;
  for (const OptionSpec& o : table) {
    py::dict d;
    d["name"] = o.name;
    d["flag"] = o.flag;
    d["type"] = o.type == OptionType::kChoice ? "choice"
                : o.type == OptionType::kReal ? "real"
                                              : "integer";
    d["min"] = o.min;
    d["max"] = o.max;
    py::list choices;
    for (const char* c : o.choices) choices.append(c);
    d["choices"] = choices;
    d["default"] = o.default_text;
    d["help"] = o.help;
    d["key"] = o.key ? py::object(py::str(o.key)) : py::object(py::none());
    rows.append(d);
  }
  return rows;
}

void installProgress(FitOptions* fo, const py::object& progress) {
  const py::object* cb = &progress;
  fo->progress = [cb](const FitProgress& p) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (cb->is_none()) return;
    py::dict d;
    d["phase"] = p.phase;
    d["iteration"] = p.iteration;
    d["energy"] = p.energy;
    d["spheres"] = p.spheres;
    d["seconds"] = p.seconds;
    (*cb)(d);
  };
}

py::dict fitResultDict(const FitResult& r, double volume) {
  py::dict d;
  d["spheres"] = spheresToArray(r.spheres);
  d["outside_volume"] = py::array_t<double>(static_cast<py::ssize_t>(r.outside_volume.size()),
                                            r.outside_volume.data());
  d["energy_history"] = py::array_t<double>(static_cast<py::ssize_t>(r.energy_history.size()),
                                            r.energy_history.data());
  d["energy"] = r.energy;
  d["energy_before_bounding"] = r.energy_before_bounding;
  d["mesh_volume"] = volume;
  d["er_sum"] = r.energy / volume;
  d["er_sum_before_bounding"] = r.energy_before_bounding / volume;
  d["rounds"] = r.iterations;
  d["converged"] = r.converged;
  d["teleports"] = r.teleports;
  d["teleports_kept"] = r.teleports_accepted;
  d["points"] = r.points;
  d["interior_points"] = r.interior_points;
  d["sov_queries"] = r.sov_queries;
  d["sov_queries_culled"] = r.sov_queries_culled;
  d["optimizer_queries"] = r.optimizer_queries;
  d["bounding_enlarged"] = r.bounding_enlarged;
  d["bounding_pieces"] = r.bounding_pieces;
  d["bounding_queries"] = r.bounding_queries;
  d["bounding_interior_cells"] = r.bounding_interior_cells;
  d["shrink_passes"] = r.shrink_passes;
  d["decimated"] = r.decimated;
  d["idle_teleports"] = r.idle_teleports;
  d["restart"] = r.restart;
  py::dict s;
  s["total"] = r.seconds.total;
  s["sampling"] = r.seconds.sampling;
  s["assignment"] = r.seconds.assignment;
  s["update"] = r.seconds.update;
  s["teleport"] = r.seconds.teleport;
  s["bounding"] = r.seconds.bounding;
  d["seconds"] = s;
  return d;
}

namespace {

py::dict optionsDict(const FitOptions& fo) {
  py::dict d;
  d["n"] = fo.num_spheres;
  d["seed"] = fo.seed;
  d["method"] = fitMethodName(fo.method);
  d["points"] = fo.target_points;
  d["interior_share"] = fo.interior_share;
  d["iterations"] = fo.max_iterations;
  d["tolerance"] = fo.tolerance;
  d["max_failed_teleports"] = fo.max_failed_teleports;
  d["init"] = fitInitName(fo.init);
  d["optimizer"] = sphereOptimizerName(fo.optimizer);
  d["optimizer_evaluations"] = fo.optimizer_evaluations;
  d["padding"] = fo.padding;
  d["shrink_passes"] = fo.shrink_passes;
  d["decimation"] = fo.decimation;
  d["restarts"] = fo.restarts;
  return d;
}

}  // namespace

void bindFit(py::module_& m) {
  m.def(
      "_fit",
      [](const std::shared_ptr<PySolid>& solid, const py::dict& options,
         const py::object& progress) {
        FitOptions fo = fitOptions(options);
        fo.original = solid->original();
        installProgress(&fo, progress);
        Expected<FitResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = fitSpheres(*solid->index, fo);
        }
        if (!r) raise(r.error().code, solid->name + ": " + r.error().message);
        py::dict d = fitResultDict(*r, signedVolume(solid->repair.solid));
        d["options"] = optionsDict(fo);
        d["repair"] = repairDict(solid->repair);
        return d;
      },
      py::arg("solid"), py::arg("options"), py::arg("progress"));
  m.def(
      "_check_fit_options", [](const py::dict& options) { fitRequest(options); },
      py::arg("options"));
  m.def("_fit_option_table", [] { return optionTable(fitRequestOptions()); });
}

}  // namespace sphereset::python

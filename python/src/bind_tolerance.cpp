// The tolerance search and the curve of a run (evaluate.hpp: fitToTolerance, fitCurve) as
// Python sees them: after each count the caller's callback gets its point, then Ctrl-C is
// checked; within each count's fit Ctrl-C is checked at every progress report.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common.hpp"
#include "fit_args.hpp"
#include "solid.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::python {
namespace {

py::dict curvePointDict(const CurvePoint& c) {
  py::dict p;
  p["n"] = c.n;
  p["er_sum"] = c.er_sum;
  p["protrusion"] = c.protrusion;
  p["covered"] = c.covered;
  p["meets"] = c.meets;
  p["seconds"] = c.seconds;
  return p;
}

// The callbacks of a run of counts: `progress` (None or a callable) gets each count's point,
// then Python's signal handlers run; each count's fit runs them at its progress reports.
struct CountCallbacks {
  std::function<void(const CurvePoint&)> count;
  std::function<void(const FitProgress&)> fit;
};
CountCallbacks countCallbacks(const py::object& progress) {
  const py::object* cb = &progress;
  CountCallbacks c;
  c.count = [cb](const CurvePoint& p) {
    py::gil_scoped_acquire gil;
    if (!cb->is_none()) (*cb)(curvePointDict(p));  // every count finished is reported
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  c.fit = [](const FitProgress&) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  return c;
}

}  // namespace

void bindToleranceFits(py::module_& m) {
  m.def(
      "_fit_to_tolerance",
      [](const std::shared_ptr<PySolid>& solid, const py::dict& options, const py::dict& tolerance,
         const py::object& progress) {
        const FitRequest rq = fitRequest(options);
        ToleranceOptions to = toleranceOptions(tolerance);
        const CountCallbacks callbacks = countCallbacks(progress);
        to.progress = callbacks.count;
        to.fit_progress = callbacks.fit;
        to.original = solid->original();
        to.walls = solid->walls();
        Expected<ToleranceFitResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = fitToTolerance(*solid->index, rq, to);
        }
        if (!r) raise(r.error().code, solid->name + ": " + r.error().message);
        py::dict fit = fitResultDict(r->fit, signedVolume(solid->repair.solid));
        FitRequest at = rq;
        at.num_spheres = r->n;
        fit["options"] = optionsDict(fitOptionsFor(at));
        fit["repair"] = repairDict(solid->repair);
        py::list curve;
        for (const CurvePoint& c : r->curve) curve.append(curvePointDict(c));
        py::dict d;
        d["met"] = r->met;
        d["n"] = r->n;
        d["protrusion_limit"] = r->protrusion_limit;
        d["fit"] = fit;
        d["eval"] = fieldsDict(evalResultFields(r->eval));
        d["curve"] = curve;
        d["seconds"] = r->seconds;
        return d;
      },
      py::arg("solid"), py::arg("options"), py::arg("tolerance"), py::arg("progress"));
  m.def(
      "_fit_curve",
      [](const std::shared_ptr<PySolid>& solid, const py::dict& options,
         const std::vector<int>& counts, std::optional<int> max_spheres,
         const py::object& progress) {
        const FitRequest rq = fitRequest(options);
        CurveOptions co;
        co.counts = counts;
        if (max_spheres) co.max_spheres = *max_spheres;  // else the library's default
        const CountCallbacks callbacks = countCallbacks(progress);
        co.progress = callbacks.count;
        co.fit_progress = callbacks.fit;
        co.original = solid->original();
        co.walls = solid->walls();
        Expected<CurveResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = fitCurve(*solid->index, rq, co);
        }
        if (!r) raise(r.error().code, solid->name + ": " + r.error().message);
        py::list curve, spheres;
        for (const CurvePoint& c : r->points) curve.append(curvePointDict(c));
        for (const std::vector<Sphere>& set : r->spheres) spheres.append(spheresToArray(set));
        py::dict d;
        d["curve"] = curve;
        d["spheres"] = spheres;
        d["progressive"] = r->progressive;
        d["seconds"] = r->seconds;
        return d;
      },
      py::arg("solid"), py::arg("options"), py::arg("counts"), py::arg("max_spheres"),
      py::arg("progress"));
  m.def(
      "_check_curve",
      [](const py::dict& options, const std::vector<int>& counts, std::optional<int> max_spheres) {
        CurveOptions co;
        co.counts = counts;
        if (max_spheres) co.max_spheres = *max_spheres;
        if (Status st = checkCurveOptions(fitRequest(options), co); !st)
          raise(st.error().code, st.error().message);
      },
      py::arg("options"), py::arg("counts"), py::arg("max_spheres"));
  m.def("_tolerance_option_table", [] { return optionTable(toleranceOptionTable()); });
  m.def(
      "_check_tolerance",
      [](const py::dict& tolerance) {
        if (Status st = checkToleranceOptions(toleranceOptions(tolerance)); !st)
          raise(st.error().code, st.error().message);
      },
      py::arg("tolerance"));
}

}  // namespace sphereset::python

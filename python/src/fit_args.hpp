// The fit's keyword arguments as the Python functions take them (fit, tree): the options of
// `sphereset fit`, a quality preset with explicit overrides (fit.hpp: FitRequest), and the
// progress callback that also makes Ctrl-C cancel the fit.
#pragma once

#include <optional>
#include <string>

#include "common.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::python {

struct FitArgs {
  int n = 32;
  std::string quality = "default";
  uint64_t seed = 1;
  double padding = 0.0;
  int64_t points = 0;
  py::object iterations, restarts, decimation;  // None: the preset's
  std::string optimizer = "powell", init = "fps", method = "variational";
};

// The FitOptions `sphereset fit` runs with for the same options (kInvalidArgument for names
// the CLI does not accept).
FitOptions fitOptions(const FitArgs& a);

// Installs a progress callback on `fo` that reacquires the GIL, runs Python's signal handlers
// (Ctrl-C raises KeyboardInterrupt there) and calls `progress` (a callable or None) with a dict
// {"phase", "iteration", "energy", "spheres", "seconds"}. A Python exception raised in either
// propagates out of fitSpheres as py::error_already_set: the fit is abandoned (fit.hpp allows
// the callback to throw). `progress` must outlive the fit.
void installProgress(FitOptions* fo, const py::object& progress);

py::dict fitResultDict(const FitResult& r, double volume);

}  // namespace sphereset::python

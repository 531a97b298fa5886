// The fit's keyword arguments as the Python functions take them (fit, tree): the options of
// `sphereset fit`, a quality preset with explicit overrides (fit.hpp: FitRequest), and the
// progress callback that also makes Ctrl-C cancel the fit.
#pragma once

#include <optional>
#include <string>

#include "common.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::python {

// The fit's keyword arguments, by the names of the library's fit table (fitRequestOptions():
// n, quality, seed, points, ...); a value of None keeps the preset's. Each value is handed to
// setFitRequestOption as its text (str()), so that the library parses and checks it exactly as
// it does the command line's and the manifest's; its error is raised.
FitRequest fitRequest(const py::dict& options);

// fitOptionsFor(fitRequest(options)): the FitOptions `sphereset fit` runs with for the same
// options.
FitOptions fitOptions(const py::dict& options);

// Installs a progress callback on `fo` that reacquires the GIL, runs Python's signal handlers
// (Ctrl-C raises KeyboardInterrupt there) and calls `progress` (a callable or None) with a dict
// {"phase", "iteration", "energy", "spheres", "seconds"}. A Python exception raised in either
// propagates out of fitSpheres as py::error_already_set: the fit is abandoned (fit.hpp allows
// the callback to throw). `progress` must outlive the fit.
void installProgress(FitOptions* fo, const py::object& progress);

py::dict fitResultDict(const FitResult& r, double volume);

// A tolerance search's keyword arguments, by the names of the library's tolerance table
// (toleranceOptionTable(): max_protrusion as a length or "P%", max_er, max_spheres); None keeps
// a limit unset. Parsed by setToleranceOption, whose error is raised.
ToleranceOptions toleranceOptions(const py::dict& tolerance);

}  // namespace sphereset::python

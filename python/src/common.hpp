// Shared pieces of the Python bindings: library errors raised as Python exceptions, numpy
// conversions of points and spheres, and the registration function of each topic's file.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/mesh.hpp"
#include "sphereset/options.hpp"
#include "sphereset/result_fields.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/status.hpp"

namespace sphereset::python {

namespace py = pybind11;
// Path arguments: str or os.PathLike.
using Path = std::filesystem::path;

// A library error on its way to Python: module.cpp turns it into the exception class of its
// code (sphereset.InvalidArgumentError, UnreadableError, ...) carrying the message.
class LibraryError : public std::runtime_error {
 public:
  explicit LibraryError(Error e) : std::runtime_error(e.message), error_(std::move(e)) {}
  const Error& error() const { return error_; }

 private:
  Error error_;
};

[[noreturn]] inline void raise(const Error& e) { throw LibraryError(e); }
[[noreturn]] inline void raise(ErrorCode code, std::string message) {
  throw LibraryError(Error{code, std::move(message)});
}
inline void check(const Status& s) {
  if (!s) raise(s.error());
}
template <class T>
T unwrap(Expected<T>&& e) {
  if (!e) raise(e.error());
  return std::move(e).value();
}

// (N, 4) rows x, y, z, r from any array-like of numbers; kInvalidArgument names `what` when the
// shape is wrong, kInvalidData when a value is NaN/infinite or a radius negative.
std::vector<Sphere> spheresFromArray(const py::handle& a, const std::string& what);
py::array_t<double> spheresToArray(const std::vector<Sphere>& spheres);
// (P, 3) points (a single (3,) point is one row); kInvalidData for NaN/infinite coordinates
// unless check_finite is false.
std::vector<Vec3> pointsFromArray(const py::handle& a, const std::string& what,
                                  bool check_finite = true);
py::array_t<double> pointsToArray(const std::vector<Vec3>& points);
// A 4x4 homogeneous rigid transform from an array-like (identity for None).
Eigen::Isometry3d isometryFromArray(const py::handle& a, const std::string& what);
py::array_t<double> isometryToArray(const Eigen::Isometry3d& t);
// {link: (N, 4)} (or (name, spheres) pairs), in order.
std::vector<LinkSpheres> linkSpheresFrom(const py::object& o);

void bindMesh(py::module_& m);
void bindFit(py::module_& m);
void bindToleranceFits(py::module_& m);  // bind_tolerance.cpp: fit_to_tolerance, fit_curve
// A FitOptions as the fit result's "options" dict (bind_fit.cpp).
py::dict optionsDict(const FitOptions& fo);
void bindEval(py::module_& m);
void bindTree(py::module_& m);
void bindIo(py::module_& m);
void bindRobot(py::module_& m);
void bindBatch(py::module_& m);
void bindAnimate(py::module_& m);
void bindRobotFit(py::module_& m);
void bindRobotQuery(py::module_& m);

// A keyword's value as the text the library's tables parse, one rule for every keyword: a
// float as the library writes a number (optionText: 4.0 is "4", which an integer row takes,
// where str() gave "4.0", refused while '4' was taken), a bool refused for a number row (str()
// gave "True"), anything else as str() gives it (a number's text, as on the command line and
// in a manifest, parsed by the library like theirs).
inline std::string optionValueText(const std::string& name, const py::handle& v) {
  if (py::isinstance<py::bool_>(v))
    raise(ErrorCode::kInvalidArgument,
          name + " '" + std::string(py::str(v)) + "': expected a number or a name, not a bool");
  if (!py::isinstance<py::float_>(v)) return py::str(v);
  return optionText(v.cast<double>());
}

// Keyword options by the names of a library option table: each value that is not None is handed
// to `set(name, text)` as its text (optionValueText), so that the library parses and checks it
// exactly as it does the command line's; its error is raised. A dict value is a keyed row's
// ({link: value}): each item is handed over as KEY=VALUE.
template <class Set>
void setOptions(const py::dict& options, Set&& set) {
  for (const auto& [key, value] : options) {
    if (value.is_none()) continue;
    const std::string name = py::str(key);
    if (py::isinstance<py::dict>(value)) {
      for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(value))
        if (Status st = set(name, std::string(py::str(k)) + "=" + optionValueText(name, v)); !st)
          raise(st.error());
      continue;
    }
    if (Status st = set(name, optionValueText(name, value)); !st) raise(st.error());
  }
}

// A result's fields (result_fields.hpp) as a dict: numbers, bools, float64 arrays; "group.name"
// nests in a dict of its own.
py::dict fieldsDict(const std::vector<ResultField>& fields);

// An option table as Python sees it: one dict per row (name, flag, type, min, max, above_min,
// percent, choices, default, help, key, automatic).
py::list optionTable(std::span<const OptionSpec> table);

// A Python str from library text that may hold file names in bytes that are not UTF-8: decoded
// as os.fsdecode does (undecodable bytes become surrogates), never a UnicodeDecodeError.
inline py::str text(const std::string& bytes) {
  PyObject* o =
      PyUnicode_DecodeFSDefaultAndSize(bytes.data(), static_cast<Py_ssize_t>(bytes.size()));
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

}  // namespace sphereset::python

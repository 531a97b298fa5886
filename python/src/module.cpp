// The extension module `sphereset._sphereset`: exception classes for the library's error codes
// and the registration of every topic (bind_*.cpp). The public API is the package around it
// (python/sphereset/__init__.py).
#include <cmath>

#include "common.hpp"
#include "sphereset/exit_codes.hpp"

namespace sphereset::python {

std::vector<Sphere> spheresFromArray(const py::handle& a, const std::string& what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> arr;
  try {
    arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  } catch (const py::error_already_set&) {
  }
  if (!arr) raise(ErrorCode::kInvalidArgument, what + ": expected an array of numbers");
  if (arr.ndim() == 1 && arr.shape(0) == 0) return {};
  if (arr.ndim() != 2 || arr.shape(1) != 4)
    raise(ErrorCode::kInvalidArgument, what + ": expected an (N, 4) array of x, y, z, r rows");
  std::vector<Sphere> out(static_cast<size_t>(arr.shape(0)));
  auto v = arr.unchecked<2>();
  for (py::ssize_t i = 0; i < arr.shape(0); ++i) {
    Sphere& s = out[static_cast<size_t>(i)];
    s.center = Vec3(v(i, 0), v(i, 1), v(i, 2));
    s.radius = v(i, 3);
    if (Status st = checkSphere(what + ": sphere " + std::to_string(i), s); !st) check(st);
  }
  return out;
}

py::array_t<double> spheresToArray(const std::vector<Sphere>& spheres) {
  py::array_t<double> out({static_cast<py::ssize_t>(spheres.size()), py::ssize_t{4}});
  auto v = out.mutable_unchecked<2>();
  for (size_t i = 0; i < spheres.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    for (int j = 0; j < 3; ++j) v(k, j) = spheres[i].center[j];
    v(k, 3) = spheres[i].radius;
  }
  return out;
}

std::vector<Vec3> pointsFromArray(const py::handle& a, const std::string& what, bool check_finite) {
  py::array_t<double, py::array::c_style | py::array::forcecast> arr;
  try {
    arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  } catch (const py::error_already_set&) {
  }
  if (!arr) raise(ErrorCode::kInvalidArgument, what + ": expected an array of numbers");
  if (arr.ndim() == 1 && arr.shape(0) == 0) return {};
  const bool one = arr.ndim() == 1 && arr.shape(0) == 3;
  if (!one && (arr.ndim() != 2 || arr.shape(1) != 3))
    raise(ErrorCode::kInvalidArgument, what + ": expected a (P, 3) array of points");
  const py::ssize_t rows = one ? 1 : arr.shape(0);
  std::vector<Vec3> out(static_cast<size_t>(rows));
  const double* d = arr.data();
  for (py::ssize_t i = 0; i < rows; ++i) {
    out[static_cast<size_t>(i)] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
    if (check_finite && !out[static_cast<size_t>(i)].allFinite())
      raise(ErrorCode::kInvalidData,
            what + ": point " + std::to_string(i) + " has a NaN or infinite coordinate");
  }
  return out;
}

py::array_t<double> pointsToArray(const std::vector<Vec3>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto v = out.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i)
    for (int j = 0; j < 3; ++j) v(static_cast<py::ssize_t>(i), j) = points[i][j];
  return out;
}

Eigen::Isometry3d isometryFromArray(const py::handle& a, const std::string& what) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (a.is_none()) return t;
  py::array_t<double, py::array::c_style | py::array::forcecast> arr;
  try {
    arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  } catch (const py::error_already_set&) {
  }
  if (!arr || arr.ndim() != 2 || arr.shape(0) != 4 || arr.shape(1) != 4)
    raise(ErrorCode::kInvalidArgument, what + ": expected a 4x4 homogeneous transform");
  auto v = arr.unchecked<2>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) t.matrix()(i, j) = v(i, j);
  if (!t.matrix().allFinite())
    raise(ErrorCode::kInvalidData, what + ": the transform has a NaN or infinite value");
  return t;
}

py::array_t<double> isometryToArray(const Eigen::Isometry3d& t) {
  py::array_t<double> out({py::ssize_t{4}, py::ssize_t{4}});
  auto v = out.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v(i, j) = t.matrix()(i, j);
  return out;
}

}  // namespace sphereset::python

namespace {

using sphereset::ErrorCode;
namespace py = pybind11;

// New exception classes: sphereset.Error and one subclass per error code, each also deriving
// from the built-in it is a kind of (ValueError for bad arguments and data, OSError for files).
PyObject* newException(py::module_& m, const char* name, const char* doc, PyObject* bases) {
  const std::string qualified = std::string("sphereset.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (!cls) throw py::error_already_set();
  m.add_object(name, py::handle(cls));
  return cls;
}

}  // namespace

PYBIND11_MODULE(_sphereset, m) {
  using namespace sphereset::python;
  m.doc() = "Bindings of the sphereset C++ library (use the `sphereset` package).";

  static PyObject* base = newException(
      m, "Error", "Base of every error the sphereset library reports.", PyExc_Exception);
  auto pair = [](PyObject* a, PyObject* b) {
    return py::make_tuple(py::handle(a), py::handle(b)).release().ptr();
  };
  static PyObject* invalid_argument =
      newException(m, "InvalidArgumentError", "An option or argument out of range.",
                   pair(base, PyExc_ValueError));
  static PyObject* unreadable =
      newException(m, "UnreadableError", "A file is missing, unreadable or not in a known format.",
                   pair(base, PyExc_OSError));
  static PyObject* invalid_data = newException(
      m, "InvalidDataError", "The data parsed but is bad (NaN, index out of range, empty).",
      pair(base, PyExc_ValueError));
  static PyObject* not_solid =
      newException(m, "NotSolidError",
                   "The mesh is not a closed solid and the repair could not or may not "
                   "make one.",
                   pair(base, PyExc_ValueError));
  static PyObject* write_failed = newException(
      m, "WriteError", "An output file could not be written.", pair(base, PyExc_OSError));

  // Each class names the exit code the command gives its errors (exit_codes.hpp).
  for (const auto& [cls, code] :
       {std::pair<PyObject*, int>{base, sphereset::kExitInternal},
        {invalid_argument, sphereset::exitCodeFor(ErrorCode::kInvalidArgument)},
        {unreadable, sphereset::exitCodeFor(ErrorCode::kUnreadable)},
        {invalid_data, sphereset::exitCodeFor(ErrorCode::kInvalidData)},
        {not_solid, sphereset::exitCodeFor(ErrorCode::kNotSolid)},
        {write_failed, sphereset::exitCodeFor(ErrorCode::kWriteFailed)}})
    py::handle(cls).attr("exit_code") = code;

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const LibraryError& e) {
      PyObject* cls = base;
      switch (e.error().code) {
        case ErrorCode::kInvalidArgument:
          cls = invalid_argument;
          break;
        case ErrorCode::kUnreadable:
          cls = unreadable;
          break;
        case ErrorCode::kInvalidData:
          cls = invalid_data;
          break;
        case ErrorCode::kNotSolid:
          cls = not_solid;
          break;
        case ErrorCode::kWriteFailed:
          cls = write_failed;
          break;
      }
      // The message may name files in bytes that are not UTF-8: decoded as os.fsdecode does.
      PyErr_SetObject(cls, text(e.error().message).ptr());
    }
  });

  bindMesh(m);
  bindFit(m);
  bindEval(m);
  bindTree(m);
  bindIo(m);
  bindRobot(m);
  bindBatch(m);
  bindAnimate(m);
  bindRobotFit(m);
  bindRobotQuery(m);
}

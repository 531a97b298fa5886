// Bindings of the animation of sphere sets (paper Sec. 6, animate.hpp): mean value coordinates,
// skinned assets read through assimp, and animateSpheres with per-frame certificates; the frame
// loop releases the GIL and Ctrl-C cancels it between frames.
#include <chrono>
#include <memory>
#include <optional>

#include "solid.hpp"
#include "sphereset/animate.hpp"

namespace sphereset::python {
namespace {

py::array_t<double> matrixToArray(const Eigen::MatrixXd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  auto v = out.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      v(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = m(i, j);
  return out;
}

// A (rows, cols) float64 matrix from an array-like; rows or cols < 0 accepts any count (the
// library checks the shapes it needs).
Eigen::MatrixXd matrixFromArray(const py::handle& a, const std::string& what, py::ssize_t rows,
                                py::ssize_t cols = -1) {
  py::array_t<double, py::array::c_style | py::array::forcecast> arr;
  try {
    arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  } catch (const py::error_already_set&) {
  }
  if (!arr || arr.ndim() != 2)
    raise(ErrorCode::kInvalidArgument, what + ": expected a 2-D array of numbers");
  if ((rows >= 0 && arr.shape(0) != rows) || (cols >= 0 && arr.shape(1) != cols))
    raise(ErrorCode::kInvalidArgument,
          what + ": expected " + std::to_string(rows) + " rows" +
              (cols >= 0 ? " and " + std::to_string(cols) + " columns" : std::string()) + " (got " +
              std::to_string(arr.shape(0)) + " x " + std::to_string(arr.shape(1)) + ")");
  Eigen::MatrixXd m(arr.shape(0), arr.shape(1));
  auto v = arr.unchecked<2>();
  for (py::ssize_t i = 0; i < arr.shape(0); ++i)
    for (py::ssize_t j = 0; j < arr.shape(1); ++j) m(i, j) = v(i, j);
  if (!m.allFinite()) raise(ErrorCode::kInvalidData, what + ": a NaN or infinite value");
  return m;
}

// (B, 4, 4) affine bone transforms.
std::vector<Eigen::Affine3d> bonesFromArray(const py::handle& a, const std::string& what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> arr;
  try {
    arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  } catch (const py::error_already_set&) {
  }
  if (!arr || arr.ndim() != 3 || arr.shape(1) != 4 || arr.shape(2) != 4)
    raise(ErrorCode::kInvalidArgument, what + ": expected a (B, 4, 4) array of transforms");
  std::vector<Eigen::Affine3d> out(static_cast<size_t>(arr.shape(0)));
  auto v = arr.unchecked<3>();
  for (size_t b = 0; b < out.size(); ++b) {
    out[b].matrix().setIdentity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) out[b].matrix()(i, j) = v(static_cast<py::ssize_t>(b), i, j);
    if (!out[b].matrix().allFinite())
      raise(ErrorCode::kInvalidData, what + ": a NaN or infinite value");
  }
  return out;
}

py::array_t<double> bonesToArray(const std::vector<Eigen::Affine3d>& bones) {
  py::array_t<double> out({static_cast<py::ssize_t>(bones.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto v = out.mutable_unchecked<3>();
  for (size_t b = 0; b < bones.size(); ++b)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) v(static_cast<py::ssize_t>(b), i, j) = bones[b].matrix()(i, j);
  return out;
}

// The rest mesh must be a clean closed solid (mean value coordinates need one), as the command
// line demands.
void requireSolid(const PyMesh& pm) {
  MeshDiagnosis d;
  {
    py::gil_scoped_release release;
    d = diagnoseMesh(pm.loaded.mesh);
  }
  if (!d.isSolid())
    raise(ErrorCode::kNotSolid,
          pm.loaded.report.path +
              ": the rest mesh is not a closed, consistently oriented solid (boundary edges " +
              std::to_string(d.boundary_edges) + ", non-manifold edges " +
              std::to_string(d.nonmanifold_edges) + ")");
}

py::dict frameDict(const AnimateFrameResult& f) {
  py::dict d = fieldsDict(animateFrameFields(f));
  d["time"] = f.time;
  d["spheres"] = spheresToArray(f.spheres);
  return d;
}

}  // namespace

void bindAnimate(py::module_& m) {
  m.def(
      "_mean_value_coordinates",
      [](const PyMesh& pm, const py::object& point) {
        const std::vector<Vec3> p = pointsFromArray(point, "point");
        if (p.size() != 1) raise(ErrorCode::kInvalidArgument, "point: expected one (3,) point");
        std::vector<double> w;
        {
          py::gil_scoped_release release;
          w = meanValueCoordinates(pm.loaded.mesh, p[0]);
        }
        return py::array_t<double>(static_cast<py::ssize_t>(w.size()), w.data());
      },
      py::arg("mesh"), py::arg("point"));

  m.def(
      "_mean_value_weights",
      [](const PyMesh& pm, const py::object& points) {
        const std::vector<Vec3> p = pointsFromArray(points, "points");
        Expected<Eigen::MatrixXd> w = Error{ErrorCode::kInvalidArgument, "not run"};
        const auto t0 = std::chrono::steady_clock::now();
        {
          py::gil_scoped_release release;
          w = meanValueMatrix(pm.loaded.mesh, p);
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return py::make_tuple(matrixToArray(unwrap(std::move(w))), seconds);
      },
      py::arg("mesh"), py::arg("points"));

  m.def(
      "_point_bone_weights",
      [](const PyMesh& pm, const py::object& bone_weights, const py::object& points,
         int neighbours) {
        SkinWeights skin;
        skin.vertex_weights = matrixFromArray(bone_weights, "bone_weights", -1);
        skin.bones = static_cast<int>(skin.vertex_weights.cols());
        const std::vector<Vec3> p = pointsFromArray(points, "points");
        Expected<Eigen::MatrixXd> w = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          w = pointBoneWeights(pm.loaded.mesh, skin, p, neighbours);
        }
        return matrixToArray(unwrap(std::move(w)));
      },
      py::arg("mesh"), py::arg("bone_weights"), py::arg("points"), py::arg("neighbours"));

  m.def(
      "_skin_points",
      [](const py::object& points, const py::object& weights, const py::object& bones) {
        const std::vector<Vec3> p = pointsFromArray(points, "points");
        const std::vector<Eigen::Affine3d> b = bonesFromArray(bones, "bones");
        const Eigen::MatrixXd w = matrixFromArray(weights, "weights", -1);
        Expected<std::vector<Vec3>> out = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          out = skinPoints(p, w, b);
        }
        return pointsToArray(unwrap(std::move(out)));
      },
      py::arg("points"), py::arg("weights"), py::arg("bones"));

  m.def(
      "_load_animation",
      [](const Path& path, const std::string& clip, const py::dict& options) {
        SkinnedLoadOptions so;
        so.clip = clip;
        setOptions(options, [&](const std::string& name, const std::string& text) {
          return setSkinnedLoadOption(&so, name, text);
        });
        LoadedAnimation a;
        {
          py::gil_scoped_release release;
          a = unwrap(loadAnimation(path.string(), so));
        }
        auto rest = std::make_shared<PyMesh>();
        rest->loaded.mesh = a.asset.rest;
        rest->loaded.report.path = path.string();
        rest->loaded.report.file_vertices = static_cast<int64_t>(a.asset.rest.vertices.size());
        rest->loaded.report.file_faces = static_cast<int64_t>(a.asset.rest.triangles.size());
        py::list frames, bones;
        py::array_t<double> times(static_cast<py::ssize_t>(a.frames.size()));
        auto t = times.mutable_unchecked<1>();
        for (size_t i = 0; i < a.frames.size(); ++i) {
          t(static_cast<py::ssize_t>(i)) = a.frames[i].time;
          frames.append(pointsToArray(a.frames[i].vertices));
          bones.append(bonesToArray(a.frames[i].bones));
        }
        py::dict d;
        d["path"] = path.string();
        d["rest"] = rest;
        d["frames"] = frames;
        d["times"] = times;
        d["bone_weights"] = matrixToArray(a.asset.skin.vertex_weights);
        d["bone_transforms"] = bones;
        d["bone_names"] = a.asset.bone_names;
        d["clip"] = a.clip;
        d["clips"] = a.asset.clips;
        d["duration"] = a.duration;
        return d;
      },
      py::arg("path"), py::arg("clip"), py::arg("options"));

  m.def(
      "_animate",
      [](const std::shared_ptr<PyMesh>& rest, const py::object& spheres_arg,
         const py::list& frame_vertices, const py::object& times, const py::object& bone_weights,
         const py::object& bone_transforms, const py::object& bind_pose, const py::dict& options,
         bool rebound, bool fresh_fit, const py::object& progress) {
        const std::string& name = rest->loaded.report.path;
        // The rows of the library's animation table (weighting, bone_neighbours,
        // max_crossings), parsed and checked there before anything else.
        AnimateOptions o;
        setOptions(options, [&](const std::string& key, const std::string& text) {
          return setAnimateOption(&o, key, text);
        });
        requireSolid(*rest);
        const std::vector<Sphere> spheres = spheresFromArray(spheres_arg, "spheres");
        const bool skinned = !bone_weights.is_none();

        // A frame is a Mesh (its triangles are checked against the rest mesh's) or an array of
        // vertices; the library checks counts and triangles.
        std::vector<AnimationFrame> frames(frame_vertices.size());
        for (size_t i = 0; i < frames.size(); ++i) {
          const py::handle f = frame_vertices[i];
          if (py::isinstance<PyMesh>(f)) {
            const PyMesh& fm = f.cast<const PyMesh&>();
            frames[i].vertices = fm.loaded.mesh.vertices;
            frames[i].triangles = fm.loaded.mesh.triangles;
          } else {
            frames[i].vertices = pointsFromArray(f, "frame " + std::to_string(i));
          }
          frames[i].time = static_cast<double>(i);
        }
        if (!times.is_none()) {
          const auto t =
              py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(times);
          if (!t || t.ndim() != 1 || static_cast<size_t>(t.shape(0)) != frames.size())
            raise(ErrorCode::kInvalidArgument, "times: expected one time per frame");
          for (size_t i = 0; i < frames.size(); ++i)
            frames[i].time = t.at(static_cast<py::ssize_t>(i));
        }
        SkinWeights skin;
        if (skinned) {
          skin.vertex_weights = matrixFromArray(bone_weights, "bone_weights", -1);
          skin.bones = static_cast<int>(skin.vertex_weights.cols());
          if (bind_pose.is_none())
            raise(ErrorCode::kInvalidArgument, "bone_weights need the bind pose they belong to");
          skin.bind_pose = bind_pose.cast<const PyMesh&>().loaded.mesh;
          // The frames' bone transforms, when given: the library checks their count against
          // the skin's where the weighting uses them.
          if (!bone_transforms.is_none()) {
            const py::list bt(bone_transforms);
            if (bt.size() != frames.size())
              raise(ErrorCode::kInvalidArgument,
                    "bone_transforms: expected one (B, 4, 4) array per frame");
            for (size_t i = 0; i < frames.size(); ++i)
              frames[i].bones = bonesFromArray(bt[i], "bone_transforms " + std::to_string(i));
          }
        }

        o.rebound = rebound;
        o.fresh_fit = fresh_fit;
        o.fit.restarts = 1;  // as `sphereset animate --fresh-fit`
        // Between frames: run Python's signal handlers (Ctrl-C raises KeyboardInterrupt, which
        // abandons the animation) and report progress.
        const py::object* cb = &progress;
        o.progress = [cb](int f, int n) {
          py::gil_scoped_acquire gil;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
          if (!cb->is_none()) (*cb)(f, n);
        };
        Expected<AnimateResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = animateSpheres(rest->loaded.mesh, spheres, frames, o, skinned ? &skin : nullptr);
        }
        if (!r) raise(r.error().code, name + ": " + r.error().message);
        py::list fl;
        for (const AnimateFrameResult& f : r->frames) fl.append(frameDict(f));
        py::dict d = fieldsDict(animateResultFields(*r));
        d["frames"] = fl;
        d["rebound"] = rebound;
        return d;
      },
      py::arg("rest"), py::arg("spheres"), py::arg("frames"), py::arg("times"),
      py::arg("bone_weights"), py::arg("bone_transforms"), py::arg("bind_pose"), py::arg("options"),
      py::arg("rebound"), py::arg("fresh_fit"), py::arg("progress"));
  m.def("_animate_option_table", [] { return optionTable(animateOptionTable()); });
  m.def("_skinned_load_option_table", [] { return optionTable(skinnedLoadOptionTable()); });
}

}  // namespace sphereset::python

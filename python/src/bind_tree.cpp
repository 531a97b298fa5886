// Bindings of sphere trees (tree.hpp, sphere_tree.hpp) and of the queries on sphere sets and
// trees (query.hpp): point distance and containment, segment outside length, set-to-set
// separation and overlap.
#include <map>
#include <memory>
#include <tuple>

#include "fit_args.hpp"
#include "solid.hpp"
#include "sphereset/query.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"

namespace sphereset::python {
namespace {

// A query target: a tree as given, or a plain set with its query tree and the position in the
// set of each leaf slot (queries on a set report positions, as query.hpp promises for vectors).
struct Target {
  SphereTree tree;
  std::vector<int64_t> slot_to_index;  // empty: slots are the given tree's own
  int64_t id(int64_t slot) const {
    if (slot < 0 || slot_to_index.empty()) return slot;
    return slot_to_index[static_cast<size_t>(slot)];
  }
};

Target target(const py::object& o, const std::string& what) {
  Target t;
  if (py::isinstance<SphereTree>(o)) {
    // The library's rule for a given tree: queried as it is only where its parents enclose
    // their children (queryTreeOf); answers name the given tree's slots either way.
    t.tree = unwrap(queryTreeOf(o.cast<const SphereTree&>(), &t.slot_to_index));
    return t;
  }
  const std::vector<Sphere> s = spheresFromArray(o, what);
  if (s.empty()) raise(ErrorCode::kInvalidData, what + ": no spheres");
  t.tree = unwrap(queryTree(s, 8, &t.slot_to_index));
  return t;
}

Pose pose(const py::object& o, const std::string& what) {
  const Eigen::Isometry3d t = isometryFromArray(o, what);
  Pose p;
  p.rotation = t.linear();
  p.translation = t.translation();
  return p;
}

// The layout from Python's keywords, set and checked through the library's tree table.
TreeOptions layoutFrom(int branching, int depth, const std::string& parents) {
  TreeOptions to;
  check(setTreeOption(&to, "parents", parents));
  to.branching = branching;
  to.depth = depth;
  check(checkTreeOptions(to));
  return to;
}

py::list levelsList(const TreeResult& r, double volume) {
  py::list out;
  for (const TreeLevelStats& l : r.levels) out.append(fieldsDict(treeLevelFields(l, volume)));
  return out;
}

py::dict pairDict(const PairQuery& q, const Target& a, const Target& b) {
  py::dict d;
  d["distance"] = q.distance;
  d["sphere_a"] = a.id(q.sphere_a);
  d["sphere_b"] = b.id(q.sphere_b);
  d["visited"] = q.visited;
  return d;
}

}  // namespace

void bindTree(py::module_& m) {
  py::class_<SphereTree>(m, "SphereTree", R"doc(
A complete B-ary sphere tree in Bradshaw's flat layout: level l holds B**l slots from
(B**l - 1) / (B - 1); unused slots have a negative radius; every parent encloses its children.

SphereTree(nodes, branching, depth) checks the layout and the enclosure (InvalidDataError).)doc")
      .def(py::init([](const py::object& nodes, int branching, int depth) {
             // Negative radii mark unused slots: read the rows without the radius check.
             py::array_t<double, py::array::c_style | py::array::forcecast> arr =
                 py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(nodes);
             if (!arr || arr.ndim() != 2 || arr.shape(1) != 4)
               raise(ErrorCode::kInvalidArgument, "nodes: expected an (M, 4) array");
             auto v = arr.unchecked<2>();
             std::vector<Sphere> slots;
             for (py::ssize_t i = 0; i < arr.shape(0); ++i)
               slots.push_back(Sphere{Vec3(v(i, 0), v(i, 1), v(i, 2)), v(i, 3)});
             return unwrap(makeSphereTree(branching, depth, std::move(slots)));
           }),
           py::arg("nodes"), py::arg("branching"), py::arg("depth"))
      .def_readonly("branching", &SphereTree::branching)
      .def_readonly("depth", &SphereTree::depth)
      .def_property_readonly(
          "nodes", [](const SphereTree& t) { return spheresToArray(t.nodes); },
          "(M, 4) array of every slot (unused slots have a negative radius).")
      .def_property_readonly("levels", &SphereTree::levels, "depth + 1")
      .def(
          "level",
          [](const SphereTree& t, int l) {
            if (l < 0 || l > t.depth)
              raise(ErrorCode::kInvalidArgument, "level must be in 0.." + std::to_string(t.depth));
            return spheresToArray(t.level(l));
          },
          py::arg("level"), "The used spheres of one level (0 is the root), (K, 4).")
      .def(
          "leaves", [](const SphereTree& t) { return spheresToArray(t.leaves()); },
          "The used spheres of the last level, (K, 4).")
      .def(
          "check",
          [](const SphereTree& t, double tolerance) { check(checkSphereTree(t, tolerance)); },
          py::arg("tolerance") = 0.0, "Raises InvalidDataError when an invariant is broken.")
      .def("__repr__", [](const SphereTree& t) {
        return "<sphereset.SphereTree branching " + std::to_string(t.branching) + ", depth " +
               std::to_string(t.depth) + ", " + std::to_string(t.leaves().size()) + " leaves>";
      });

  m.def("_tree_option_table", [] { return optionTable(treeOptionTable()); });
  m.def(
      "_build_tree",
      [](const py::object& leaves, int branching, int depth, const std::string& parents,
         int iterations, uint64_t seed, const std::shared_ptr<PySolid>& solid) {
        const std::vector<Sphere> s = spheresFromArray(leaves, "leaves");
        TreeOptions to = layoutFrom(branching, depth, parents);
        to.max_iterations = iterations;
        to.seed = seed;
        if (to.parents == TreeParents::kOutsideVolume && !solid)
          raise(ErrorCode::kInvalidArgument, "parents='outside' needs the solid");
        Expected<TreeResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = buildSphereTree(s, to, solid ? solid->index.get() : nullptr);
        }
        TreeResult t = unwrap(std::move(r));
        py::dict d;
        d["tree"] = t.tree;
        d["levels"] = levelsList(t, solid ? signedVolume(solid->repair.solid) : 0.0);
        d["seconds"] = t.seconds;
        return d;
      },
      py::arg("leaves"), py::arg("branching"), py::arg("depth"), py::arg("parents"),
      py::arg("iterations"), py::arg("seed"), py::arg("solid"));

  m.def(
      "_fit_tree",
      [](const std::shared_ptr<PySolid>& solid, int branching, int depth,
         const std::string& parents, const py::dict& fit_options, const py::object& progress) {
        FitRequest rq = fitRequest(fit_options);
        if (!fit_options.contains("n") || fit_options["n"].is_none()) rq.num_spheres = 0;
        TreeOptions to = layoutFrom(branching, depth, parents);
        FitOptions fo = fitOptionsFor(unwrap(treeFitRequest(rq, to)));
        fo.original = solid->original();
        installProgress(&fo, progress);
        to.seed = fo.seed;
        Expected<TreeFitResult> r = Error{ErrorCode::kInvalidArgument, "not run"};
        {
          py::gil_scoped_release release;
          r = fitSphereTree(*solid->index, fo, to);
        }
        if (!r) raise(r.error().code, solid->name + ": " + r.error().message);
        const double volume = signedVolume(solid->repair.solid);
        py::dict d;
        d["tree"] = r->tree.tree;
        d["levels"] = levelsList(r->tree, volume);
        d["seconds"] = r->tree.seconds;
        d["fit"] = fitResultDict(r->fit, volume);
        d["repair"] = repairDict(solid->repair);
        return d;
      },
      py::arg("solid"), py::arg("branching"), py::arg("depth"), py::arg("parents"),
      py::arg("fit_options"), py::arg("progress"));

  m.def(
      "_point_distance",
      [](const py::object& set, const py::object& points) {
        const Target t = target(set, "spheres");
        // Finite and in range: the library's check (its message, as the command line's).
        const std::vector<Vec3> p = pointsFromArray(points, "points", false);
        const auto np = static_cast<py::ssize_t>(p.size());
        py::array_t<double> dist(np);
        py::array_t<int64_t> ids(np);
        py::array_t<bool> inside(np);
        auto dv = dist.mutable_unchecked<1>();
        auto iv = ids.mutable_unchecked<1>();
        auto cv = inside.mutable_unchecked<1>();
        Status failed;
        {
          py::gil_scoped_release release;
          for (py::ssize_t i = 0; i < np && failed; ++i) {
            const auto q = pointDistance(t.tree, p[static_cast<size_t>(i)]);
            if (!q) {
              failed = q.error();
              break;
            }
            dv(i) = q->distance;
            iv(i) = t.id(q->sphere);
            cv(i) = *containsPoint(t.tree, p[static_cast<size_t>(i)]);  // same point, checked
          }
        }
        check(failed);
        return py::make_tuple(dist, ids, inside);
      },
      py::arg("spheres"), py::arg("points"));

  m.def(
      "_segment_outside_length",
      [](const py::object& set, const py::object& a, const py::object& b) {
        const Target t = target(set, "spheres");
        const std::vector<Vec3> pa = pointsFromArray(a, "a", false);
        const std::vector<Vec3> pb = pointsFromArray(b, "b", false);
        if (pa.size() != pb.size())
          raise(ErrorCode::kInvalidArgument, "a and b must hold as many points");
        py::array_t<double> out(static_cast<py::ssize_t>(pa.size()));
        auto v = out.mutable_unchecked<1>();
        Status failed;
        {
          py::gil_scoped_release release;
          for (size_t i = 0; i < pa.size(); ++i) {
            const auto len = segmentOutsideLength(t.tree, pa[i], pb[i]);
            if (!len) {
              failed = len.error();
              break;
            }
            v(static_cast<py::ssize_t>(i)) = *len;
          }
        }
        check(failed);
        return out;
      },
      py::arg("spheres"), py::arg("a"), py::arg("b"));

  m.def(
      "_separation",
      [](const py::object& a, const py::object& b, const py::object& pose_a,
         const py::object& pose_b, bool stop_at_overlap) {
        const Target ta = target(a, "a");
        const Target tb = target(b, "b");
        const Pose pa = pose(pose_a, "pose_a");
        const Pose pb = pose(pose_b, "pose_b");
        PairQuery q;
        bool any = false;
        Status failed;
        {
          py::gil_scoped_release release;
          if (stop_at_overlap) {
            const auto hit = overlaps(ta.tree, pa, tb.tree, pb, &q);
            if (hit)
              any = *hit;
            else
              failed = hit.error();
          } else {
            const auto found = separation(ta.tree, pa, tb.tree, pb);
            if (found)
              q = *found;
            else
              failed = found.error();
          }
        }
        check(failed);
        py::dict d = pairDict(q, ta, tb);
        if (stop_at_overlap) d["overlap"] = any;
        return d;
      },
      py::arg("a"), py::arg("b"), py::arg("pose_a"), py::arg("pose_b"), py::arg("stop_at_overlap"));

  m.def(
      "_query_tree",
      [](const py::object& spheres, int branching) {
        const std::vector<Sphere> s = spheresFromArray(spheres, "spheres");
        if (s.empty()) raise(ErrorCode::kInvalidData, "spheres: no spheres");
        return unwrap(queryTree(s, branching));
      },
      py::arg("spheres"), py::arg("branching") = 8);
}

}  // namespace sphereset::python

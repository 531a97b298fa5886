// The interior certificate's octree kept between calls (cell_forest.hpp).
//
// A cube's verdict (cellVerdict) depends on the spheres only through which of them hold its
// corners or its centre, and, for a cube refuted at its centre, the distance from the centre to
// the union. So after one ball changes from B to B', a cube keeps its verdict, and the cubes
// below it theirs, when neither B nor B' comes within the largest gap G stored below it: no
// point of the cube is in either ball (the containment tests are unchanged), and at a refuted
// centre c, with gap(c) <= G < d(c, B) and d(c, B'), the nearest ball is neither (the distance
// to the union is unchanged). Such subtrees are skipped; the others are judged again, cube by
// cube from the root, skipping again below wherever the test allows.
#include "eval/cell_forest.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace sphereset::detail {
namespace {

// Margin of the proximity test, as a fraction of the magnitudes involved (coordinates, radius,
// reach): far above the relative rounding (~1e-16) of the distances the coverage tests compute,
// far below any geometric scale, so it only makes the test conservative.
constexpr double kNearMarginRel = 1e-9;

// A tree is compacted once its nodes outnumber the cubes of its walk by this factor (and this
// many nodes): the memory of a long run of edits stays within a few times the walk's.
constexpr int64_t kCompactRatio = 2;
constexpr int64_t kCompactMinNodes = 64;

}  // namespace

bool ballNearBox(const Sphere& b, const Vec3& lo, const Vec3& hi, double reach) {
  const double magnitude = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  const double margin =
      kNearMarginRel * (magnitude + b.center.cwiseAbs().maxCoeff() + b.radius + reach);
  const Vec3 nearest = b.center.cwiseMax(lo).cwiseMin(hi);
  const double distance = (b.center - nearest).norm();
  // A distance that overflows says nothing: near, to be safe.
  return !std::isfinite(distance) || !(distance - b.radius > reach + margin);
}

struct CellForest::Walk {
  const SphereGrid* grown;
  std::span<const Sphere> changed;
  int64_t judged = 0;
};

CellForest::CellForest(const SolidIndex& index, int max_depth)
    : index_(&index), max_depth_(max_depth), trees_(kRootCells) {}

void CellForest::walk(Tree* tree, int64_t node, const Vec3& mn, double size, int depth, bool force,
                      Walk* w, const CellGeometry* parent) const {
  if (!force) {
    const Vec3 mx = mn + Vec3::Constant(size);
    const double reach = tree->nodes[node].gap;
    bool near = false;
    for (const Sphere& b : w->changed) near = near || ballNearBox(b, mn, mx, reach);
    if (!near) return;  // verdicts below unchanged (see the top of the file)
  }
  pollCancel();
  ++w->judged;
  Node& n = tree->nodes[node];
  double gap = 0.0;
  const CellVerdict before = n.verdict;
  const CellVerdict verdict =
      cellVerdict(*index_, *w->grown, mn, size, depth, max_depth_, &n.geometry, &gap, parent);
  n.verdict = verdict;
  n.cells = 1;
  if (verdict != CellVerdict::kSplit) {
    n.gap = verdict == CellVerdict::kGap ? gap : 0.0;
    n.undecided = verdict == CellVerdict::kUndecided ? 1 : 0;
    return;
  }
  // The children's stored figures are of the set before the change only if this cube was split
  // then too (and they were current: not forced from above).
  const bool force_children = force || before != CellVerdict::kSplit || n.children < 0;
  if (n.children < 0) {
    n.children = static_cast<int64_t>(tree->nodes.size());
    tree->nodes.resize(tree->nodes.size() + 8);  // invalidates n
  }
  const int64_t first = tree->nodes[node].children;
  const CellGeometry geometry = tree->nodes[node].geometry;  // the walk may move the nodes
  const double h = 0.5 * size;
  double g = 0.0;
  int64_t undecided = 0, cells = 1;
  for (int k = 0; k < 8; ++k) {
    walk(tree, first + k, childCell(mn, h, k), h, depth + 1, force_children, w, &geometry);
    const Node& c = tree->nodes[first + k];
    g = std::max(g, c.gap);
    undecided += c.undecided;
    cells += c.cells;
  }
  Node& m = tree->nodes[node];
  m.gap = g;
  m.undecided = undecided;
  m.cells = cells;
}

void CellForest::compact(Tree* tree) {
  const int64_t cells = tree->nodes[0].cells;
  if (static_cast<int64_t>(tree->nodes.size()) <= std::max(kCompactRatio * cells, kCompactMinNodes))
    return;
  // The nodes of the walk, in the same layout: each split cube's eight children in a row.
  Tree out;
  out.nodes.reserve(static_cast<size_t>(cells));
  out.nodes[0] = tree->nodes[0];
  for (size_t i = 0; i < out.nodes.size(); ++i) {
    const int64_t old = out.nodes[i].children;
    if (out.nodes[i].verdict != CellVerdict::kSplit || old < 0) {
      out.nodes[i].children = -1;  // the figures below a cube that does not split are stale
      continue;
    }
    out.nodes[i].children = static_cast<int64_t>(out.nodes.size());
    for (int k = 0; k < 8; ++k) out.nodes.push_back(tree->nodes[old + k]);
  }
  *tree = std::move(out);
}

int64_t CellForest::certifyAll(const SphereGrid& grown) {
  std::vector<int64_t> judged(kRootCells, 0);
  tbb::parallel_for(0, kRootCells, [&](int k) {
    Walk w{&grown, {}, 0};
    double size = 0.0;
    const Vec3 mn = rootCell(index_->bounds(), k, &size);
    walk(&trees_[k], 0, mn, size, 0, true, &w);
    compact(&trees_[k]);
    judged[k] = w.judged;
  });
  int64_t total = 0;
  for (int64_t j : judged) total += j;
  return total;
}

int64_t CellForest::update(const SphereGrid& grown, std::span<const Sphere> changed) {
  // The root cubes the changed balls come near, then those in parallel.
  std::vector<int> touched;
  for (int k = 0; k < kRootCells; ++k) {
    double size = 0.0;
    const Vec3 mn = rootCell(index_->bounds(), k, &size);
    const Vec3 mx = mn + Vec3::Constant(size);
    for (const Sphere& b : changed)
      if (ballNearBox(b, mn, mx, trees_[k].nodes[0].gap)) {
        touched.push_back(k);
        break;
      }
  }
  std::vector<int64_t> judged(touched.size(), 0);
  tbb::parallel_for(size_t{0}, touched.size(), [&](size_t i) {
    const int k = touched[i];
    Walk w{&grown, changed, 0};
    double size = 0.0;
    const Vec3 mn = rootCell(index_->bounds(), k, &size);
    walk(&trees_[k], 0, mn, size, 0, false, &w);
    compact(&trees_[k]);
    judged[i] = w.judged;
  });
  int64_t total = 0;
  for (int64_t j : judged) total += j;
  return total;
}

std::vector<PieceCover> CellForest::roots() const {
  std::vector<PieceCover> r(kRootCells);
  for (int k = 0; k < kRootCells; ++k)
    r[k] = {trees_[k].nodes[0].gap, static_cast<double>(trees_[k].nodes[0].undecided)};
  return r;
}

int64_t CellForest::cellCount() const {
  int64_t total = 0;
  for (const Tree& t : trees_) total += t.nodes[0].cells;
  return total;
}

}  // namespace sphereset::detail

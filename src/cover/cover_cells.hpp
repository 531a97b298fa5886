// Private: coverage tests shared by the bounding step of the fit and the evaluation.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cover/sphere_grid.hpp"
#include "sphereset/solid_index.hpp"
#include "util/poll.hpp"

namespace sphereset::detail {

// What a cube's verdict needs of the solid: whether the surface may pass through it (the
// distance from its centre to the surface is at most its half diagonal) and where its centre
// lies. It depends on the cube alone, not on the spheres, so a caller that meets the same cube
// again (the incremental certificate) may keep it.
struct CellGeometry {
  bool known = false;
  bool has_surface = false;
  Containment where = Containment::kOutside;
  double distance = 0.0;  // from its centre to the surface
};

// Where p lies, `distance` from the surface, given a point `gap` away from it on side
// `near_side`, `near_distance` from the surface (none: a near_distance of 0). When gap is less
// than near_distance, the ball of that radius around the near point misses the surface and holds
// both points, so on a closed surface they lie on the same side: the near point's, unless either
// is within the boundary tolerance, where classify() answers kBoundary. So the answer is
// classify()'s either way, without its ray for most points (all but those near the surface). The
// interior walk (a cube's centre is its half diagonal from its parent's) and the protrusion's
// search (src/eval/protrusion.cpp) take it.
inline Containment sideNear(const SolidIndex& index, const Vec3& p, double distance,
                            Containment near_side, double near_distance, double gap) {
  if (near_side != Containment::kBoundary && gap < near_distance &&
      distance > index.boundaryTolerance())
    return near_side;
  return index.classify(p);
}

// The verdict on one cube of the interior walk, the one rule both walks below follow:
// - kHeld: one sphere holds its eight corners (then the whole cube: convexity);
// - kEmpty: no surface in it and its centre outside the solid;
// - kGap: its centre is in the solid (or on its boundary) but in no sphere, at distance *gap
//   from the union;
// - kUndecided: none of these at max_depth;
// - kSplit: none of these above max_depth: its eight children decide.
enum class CellVerdict : uint8_t { kHeld, kEmpty, kGap, kUndecided, kSplit };

inline CellVerdict cellVerdict(const SolidIndex& index, const SphereGrid& spheres, const Vec3& mn,
                               double size, int depth, int max_depth, CellGeometry* geometry,
                               double* gap, const CellGeometry* parent = nullptr) {
  Vec3 corners[8];
  for (int k = 0; k < 8; ++k)
    corners[k] = mn + size * Vec3((k & 1) ? 1 : 0, (k & 2) ? 1 : 0, (k & 4) ? 1 : 0);
  if (oneSphereHolds(spheres, corners, 8)) return CellVerdict::kHeld;
  const Vec3 center = mn + Vec3::Constant(0.5 * size);
  if (!geometry->known) {
    const double half_diag = 0.5 * std::sqrt(3.0) * size;
    geometry->distance = index.distance(center);
    geometry->has_surface = geometry->distance <= half_diag;
    geometry->where = parent && parent->known ? sideNear(index, center, geometry->distance,
                                                         parent->where, parent->distance, half_diag)
                                              : index.classify(center);
    geometry->known = true;
  }
  if (!geometry->has_surface && geometry->where == Containment::kOutside)
    return CellVerdict::kEmpty;
  if (geometry->where != Containment::kOutside) {
    *gap = gapToUnion(spheres, center);
    if (*gap > 0.0) return CellVerdict::kGap;
  }
  return depth >= max_depth ? CellVerdict::kUndecided : CellVerdict::kSplit;
}

// The k-th of the eight children (half side h) of the cube with lowest corner mn.
inline Vec3 childCell(const Vec3& mn, double h, int k) {
  return mn + h * Vec3((k & 1) ? 1 : 0, (k & 2) ? 1 : 0, (k & 4) ? 1 : 0);
}

// The root cubes of the walk: an 8³ grid of cubes of side max extent / 8 from bounds.min.
inline Vec3 rootCell(const Aabb& b, int k, double* size) {
  *size = (b.max - b.min).maxCoeff() / 8.0;
  return b.min + *size * Vec3(k % 8, (k / 8) % 8, k / 64);
}
constexpr int kRootCells = 512;

// The geometry of one root cube's cubes kept between walks of the same solid, for a caller
// whose walks meet the same cubes again (the local bounds of a progressive run, which walk the
// same region for set after set): each cube's CellGeometry, its eight children in a row once it
// has split. A memo: a walk with it judges every cube as one without it does.
struct GeometryTree {
  struct Node {
    CellGeometry geometry;
    int64_t children = -1;  // the first of its eight children; -1 before it splits
  };
  std::vector<Node> nodes = std::vector<Node>(1);
  void clear() { nodes.assign(1, Node{}); }
};
// One GeometryTree per root cube (rootCell), of one solid and one bounds grid. A walk touches
// only its own root cube's tree, so the root cubes may be walked in parallel. trim(), before a
// walk, drops every tree once together they hold more than kMaxNodes cubes, so the forest holds
// at most that plus one walk's cubes (the trees raised the peak memory of the curves 1 ... 64
// of spot.obj and armadillo by 11 and 6 MB).
struct GeometryForest {
  static constexpr int64_t kMaxNodes = int64_t{1} << 22;  // 96 MB at 24 bytes a cube
  std::vector<GeometryTree> trees = std::vector<GeometryTree>(kRootCells);
  void trim() {
    int64_t held = 0;
    for (const GeometryTree& t : trees) held += static_cast<int64_t>(t.nodes.size());
    if (held > kMaxNodes)
      for (GeometryTree& t : trees) t.clear();
  }
};

// Where a walk may look (both optional): `region`, a box the caller decides nothing outside of
// (a cube that misses it widened by kRegionSlackRel is neither judged nor split; the caller's
// own test decides at the region's edge), and `tree`, the walk's root cube's kept geometry
// (`node`: this cube's place in it).
struct WalkScope {
  const Aabb* region = nullptr;
  GeometryTree* tree = nullptr;
  int64_t node = 0;
};

// Whether the cube with lowest corner `lo` and side `s` misses `region` widened by `slack` (a
// length; none: never).
inline bool cubeMisses(const Aabb* region, const Vec3& lo, double s, double slack = 0.0) {
  return region && ((lo.array() > region->max.array() + slack).any() ||
                    ((lo.array() + s) < region->min.array() - slack).any());
}

// The widening of a walk's region before it skips a cube, relative to the largest coordinate
// of the region (a length per unit length): a child's corners are computed from its parent's and
// may round a few units of the last place beyond them, so a cube that just misses the region
// may have a child that meets it.
constexpr double kRegionSlackRel = 1e-9;
inline double regionSlack(const Aabb* region) {
  return region ? kRegionSlackRel *
                      std::max(region->min.cwiseAbs().maxCoeff(), region->max.cwiseAbs().maxCoeff())
                : 0.0;
}

// The interior coverage walk: cubes of an octree below an 8³ grid over `bounds`, judged by
// cellVerdict. Held and empty cubes are settled. On a gap, on_gap(min, size, depth, gap) is
// called and the walk goes on as for an undecided cube only if it returns true (the fit's bound
// grows a sphere and looks deeper; the certificate stops: the cube is refuted). Cubes still
// unsettled at max_depth go to on_undecided(min, size). Cubes that miss scope.region (widened:
// WalkScope) are skipped.
template <class OnGap, class OnUndecided>
void walkSolidCells(const SolidIndex& index, const SphereGrid& spheres, const Vec3& mn, double size,
                    int depth, int max_depth, OnGap&& on_gap, OnUndecided&& on_undecided,
                    const CellGeometry* parent = nullptr, WalkScope scope = {}) {
  pollCancel();
  if (cubeMisses(scope.region, mn, size, regionSlack(scope.region))) return;
  CellGeometry geometry = scope.tree ? scope.tree->nodes[scope.node].geometry : CellGeometry{};
  double gap = 0.0;
  const CellVerdict verdict =
      cellVerdict(index, spheres, mn, size, depth, max_depth, &geometry, &gap, parent);
  if (scope.tree) scope.tree->nodes[scope.node].geometry = geometry;
  if (verdict == CellVerdict::kHeld || verdict == CellVerdict::kEmpty) return;
  if (verdict == CellVerdict::kGap && !on_gap(mn, size, depth, gap)) return;
  if (depth >= max_depth) {
    on_undecided(mn, size);
    return;
  }
  WalkScope child = scope;
  if (scope.tree && scope.tree->nodes[scope.node].children < 0) {
    const size_t first = scope.tree->nodes.size();
    scope.tree->nodes.resize(first + 8);  // invalidates references into it
    scope.tree->nodes[scope.node].children = static_cast<int64_t>(first);
  }
  const double h = 0.5 * size;
  for (int k = 0; k < 8; ++k) {
    if (scope.tree) child.node = scope.tree->nodes[scope.node].children + k;
    walkSolidCells(index, spheres, childCell(mn, h, k), h, depth + 1, max_depth, on_gap,
                   on_undecided, &geometry, child);
  }
}

}  // namespace sphereset::detail

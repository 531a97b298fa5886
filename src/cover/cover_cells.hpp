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

// The interior coverage walk: cubes of an octree below an 8³ grid over `bounds`, judged by
// cellVerdict. Held and empty cubes are settled. On a gap, on_gap(min, size, depth, gap) is
// called and the walk goes on as for an undecided cube only if it returns true (the fit's bound
// grows a sphere and looks deeper; the certificate stops: the cube is refuted). Cubes still
// unsettled at max_depth go to on_undecided(min, size).
template <class OnGap, class OnUndecided>
void walkSolidCells(const SolidIndex& index, const SphereGrid& spheres, const Vec3& mn, double size,
                    int depth, int max_depth, OnGap&& on_gap, OnUndecided&& on_undecided,
                    const CellGeometry* parent = nullptr) {
  pollCancel();
  CellGeometry geometry;
  double gap = 0.0;
  const CellVerdict verdict =
      cellVerdict(index, spheres, mn, size, depth, max_depth, &geometry, &gap, parent);
  if (verdict == CellVerdict::kHeld || verdict == CellVerdict::kEmpty) return;
  if (verdict == CellVerdict::kGap && !on_gap(mn, size, depth, gap)) return;
  if (depth >= max_depth) {
    on_undecided(mn, size);
    return;
  }
  const double h = 0.5 * size;
  for (int k = 0; k < 8; ++k)
    walkSolidCells(index, spheres, childCell(mn, h, k), h, depth + 1, max_depth, on_gap,
                   on_undecided, &geometry);
}

// The root cubes of the walk: an 8³ grid of cubes of side max extent / 8 from bounds.min.
inline Vec3 rootCell(const Aabb& b, int k, double* size) {
  *size = (b.max - b.min).maxCoeff() / 8.0;
  return b.min + *size * Vec3(k % 8, (k / 8) % 8, k / 64);
}
constexpr int kRootCells = 512;

}  // namespace sphereset::detail

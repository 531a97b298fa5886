// Private: coverage tests shared by the bounding step of the fit and the evaluation.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "cover/sphere_grid.hpp"
#include "sphereset/solid_index.hpp"
#include "util/poll.hpp"

namespace sphereset::detail {

// The interior coverage walk: cubes of an octree below an 8³ grid over `bounds`. A cube is
// settled when one sphere holds its eight corners (covered) or when it holds no surface and
// its centre is outside the solid (empty). Otherwise, if its centre is inside the solid but
// in no sphere, on_gap(min, size, depth, gap) is called and the walk descends only if it
// returns true; cubes still unsettled at max_depth go to on_undecided(min, size).
template <class OnGap, class OnUndecided>
void walkSolidCells(const SolidIndex& index, const SphereGrid& spheres, const Vec3& mn, double size,
                    int depth, int max_depth, OnGap&& on_gap, OnUndecided&& on_undecided) {
  pollCancel();
  Vec3 corners[8];
  for (int k = 0; k < 8; ++k)
    corners[k] = mn + size * Vec3((k & 1) ? 1 : 0, (k & 2) ? 1 : 0, (k & 4) ? 1 : 0);
  if (oneSphereHolds(spheres, corners, 8)) return;
  const Vec3 center = mn + Vec3::Constant(0.5 * size);
  const double half_diag = 0.5 * std::sqrt(3.0) * size;
  const bool has_surface = index.distance(center) <= half_diag;
  const Containment where = index.classify(center);
  if (!has_surface && where == Containment::kOutside) return;
  if (where != Containment::kOutside) {
    const double gap = gapToUnion(spheres, center);
    if (gap > 0.0 && !on_gap(mn, size, depth, gap)) return;
  }
  if (depth >= max_depth) {
    if (where != Containment::kOutside || has_surface) on_undecided(mn, size);
    return;
  }
  const double h = 0.5 * size;
  for (int k = 0; k < 8; ++k)
    walkSolidCells(index, spheres, mn + h * Vec3((k & 1) ? 1 : 0, (k & 2) ? 1 : 0, (k & 4) ? 1 : 0),
                   h, depth + 1, max_depth, on_gap, on_undecided);
}

// The root cubes of the walk: an 8³ grid of cubes of side max extent / 8 from bounds.min.
inline Vec3 rootCell(const Aabb& b, int k, double* size) {
  *size = (b.max - b.min).maxCoeff() / 8.0;
  return b.min + *size * Vec3(k % 8, (k / 8) % 8, k / 64);
}
constexpr int kRootCells = 512;

}  // namespace sphereset::detail

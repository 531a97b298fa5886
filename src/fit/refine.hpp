// Private: the coverage-aware refinement of the variational fit after the bound.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// The coverage points' spacing, as a multiple of the spacing of the clustering's surface
// samples.
inline constexpr double kRefineSpacing = 1.0;

// The refinement bounds its result with pieces down to this fraction of the fit's min_edge (its
// coverage points are denser than the fit's bound, so its pieces must be too); the optimal
// radii split their units as finely.
inline constexpr double kRefineFineEdge = 0.25;

struct RefineStats {
  bool kept = false;    // the refined set had less outside volume and replaced the input
  int64_t points = 0;   // points kept covered by the penalty
  int64_t queries = 0;  // outside-volume evaluations
  double energy = 0.0;  // Σ outside volume at the end
};

// All spheres of `sp` (a set covering the surface of the index's mesh) moved at once to lower
// the total outside volume of a set covering the surface's points at `spacing` (coarser when
// that would make more than a few times `clustered`, the clustering's point count) and
// `interior`, then bounded exactly (pieces down to a fraction of `min_edge`); *sp is replaced only
// if that lowers its total outside volume. Deterministic whatever the number of threads.
RefineStats refineCoverage(const SolidIndex& index, const std::vector<Vec3>& interior,
                           double spacing, double min_edge, int64_t clustered,
                           std::vector<Sphere>* sp);

}  // namespace sphereset::detail

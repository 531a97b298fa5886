// Private: the per-triangle closed form with its solid angle split in two, so that callers
// summing many triangles can accumulate the atan2 terms without evaluating each one.
#pragma once

#include "index/angle_sum.hpp"
#include "index/oracles.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// As triangleBallTerms, except that `solid_angle` holds only the arcs' part; the rest,
// Σ atan2 pairs (ω/2 each), is added to `half_omega` with every numerator multiplied by
// `sign` (±1), so that half_omega accumulates sign · (Ω - solid_angle) / 2.
TriangleBallTerms triangleBallTermsSplit(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                         const Vec3& o, double r, AngleSum* half_omega,
                                         double sign);

}  // namespace sphereset::detail

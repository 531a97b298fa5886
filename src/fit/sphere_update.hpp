// Private: per-cluster sphere update (paper Sec. 5, eq. 5).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

struct SphereUpdate {
  Sphere sphere;        // best centre found, with the radius that encloses the points
  double sov = 0.0;     // its outside volume
  int64_t queries = 0;  // outside-volume evaluations spent
};

// R(c): the smallest radius about centre c that encloses what must be enclosed; writes ∇R
// to `grad` when it is not null.
using EnclosingRadius = std::function<double(const Vec3& c, Vec3* grad)>;

// Minimises SOV(c, R(c)) over the centre c from `start`, within `box` widened by the start
// radius; BOBYQA (derivative-free) or MMA (exact gradient). The best point evaluated is kept.
SphereUpdate minimiseOutsideVolume(const SolidIndex& index, const EnclosingRadius& radius_of,
                                   const Vec3& start, const Aabb& box, SphereOptimizer optimizer,
                                   int max_evaluations);

// Minimises over the centre c the outside volume of the smallest sphere about c enclosing
// `points`, starting from `start`.
SphereUpdate updateSphere(const SolidIndex& index, const std::vector<Vec3>& points,
                          const Vec3& start, SphereOptimizer optimizer, int max_evaluations);

}  // namespace sphereset::detail

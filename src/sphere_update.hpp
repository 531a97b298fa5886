// Private: per-cluster sphere update (paper Sec. 5, eq. 5).
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

struct SphereUpdate {
  Sphere sphere;        // best centre found, with the radius that encloses the points
  double sov = 0.0;     // its outside volume
  int64_t queries = 0;  // outside-volume evaluations spent
};

// Minimises over the centre c the outside volume of the smallest sphere about c enclosing
// `points`, starting from `start`.
SphereUpdate updateSphere(const SolidIndex& index, const std::vector<Vec3>& points,
                          const Vec3& start, SphereOptimizer optimizer, int max_evaluations);

}  // namespace sphereset::detail

// Private: small pieces shared by the phases of the fit: timing, the energy of a sphere set
// (paper Sec. 3: the sum over the spheres of their outside volume, Eq. 2 per sphere), and the
// centroid and farthest point of a point list.
#pragma once

#include <chrono>
#include <numeric>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

using FitClock = std::chrono::steady_clock;
inline double secondsSince(FitClock::time_point t) {
  return std::chrono::duration<double>(FitClock::now() - t).count();
}

// Outside volume of each sphere (in parallel).
std::vector<double> outsideVolumes(const SolidIndex& index, const std::vector<Sphere>& sp);

// Sum of the values in a fixed order (the energy, from outsideVolumes).
inline double totalOf(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

// Mean of the points (not empty).
Vec3 centroid(const std::vector<Vec3>& pts);

// The first of the points farthest from q; q itself if there are none.
Vec3 farthestFrom(const std::vector<Vec3>& pts, const Vec3& q);

}  // namespace sphereset::detail

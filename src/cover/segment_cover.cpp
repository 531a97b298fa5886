// The length of a segment outside a set of spheres. Reference: Wang et al. 2006, Sec. 7
// "Proximity Application": the segment's parameter intervals inside each sphere, merged.
#include "cover/segment_cover.hpp"

#include <algorithm>
#include <cmath>

#include "util/ray_sphere.hpp"

namespace sphereset::detail {

bool segmentInterval(const Sphere& s, const Vec3& a, const Vec3& d, double* t0, double* t1) {
  if (!lineSphere(s, a, d, t0, t1)) return false;
  *t0 = std::max(0.0, *t0);
  *t1 = std::min(1.0, *t1);
  return *t1 > *t0;
}

double uncoveredLength(std::vector<std::pair<double, double>>* in, double len) {
  std::sort(in->begin(), in->end());
  double covered = 0.0, cur0 = -1.0, cur1 = -1.0;
  for (const auto& [t0, t1] : *in) {
    if (t0 > cur1) {
      if (cur1 > cur0) covered += cur1 - cur0;
      cur0 = t0;
      cur1 = t1;
    } else {
      cur1 = std::max(cur1, t1);
    }
  }
  if (cur1 > cur0) covered += cur1 - cur0;
  return std::max(0.0, (1.0 - covered) * len);
}

double segmentOutsideSpheres(const std::vector<Sphere>& spheres, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  if (!(dd > 0.0)) return 0.0;
  std::vector<std::pair<double, double>> in;
  double t0, t1;
  for (const Sphere& s : spheres)
    if (segmentInterval(s, a, d, &t0, &t1)) in.emplace_back(t0, t1);
  return uncoveredLength(&in, std::sqrt(dd));
}

}  // namespace sphereset::detail

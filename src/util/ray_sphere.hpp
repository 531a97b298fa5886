// Private: where a line meets a ball (rendering, shadows, segment queries).
#pragma once

#include <cmath>

#include "sphereset/sphere.hpp"

namespace sphereset::detail {

// Parameters t0 < t1 where the line o + t d crosses the sphere's surface (d need not be a
// unit vector); false when the line misses it or only touches it.
inline bool lineSphere(const Sphere& s, const Vec3& o, const Vec3& d, double* t0, double* t1) {
  const Vec3 m = o - s.center;
  const double dd = d.squaredNorm();
  const double hb = m.dot(d), cc = m.squaredNorm() - s.radius * s.radius;
  const double disc = hb * hb - dd * cc;
  if (!(disc > 0.0) || !(dd > 0.0)) return false;
  const double sq = std::sqrt(disc);
  *t0 = (-hb - sq) / dd;
  *t1 = (-hb + sq) / dd;
  return true;
}

}  // namespace sphereset::detail

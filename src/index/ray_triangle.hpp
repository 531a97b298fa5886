// Private: ray and segment tests shared by point-in-solid and the outside-volume sum.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "index/bvh.hpp"

namespace sphereset::detail {

// Orientation determinants smaller than this fraction of their magnitude bound are treated
// as zero: the ray grazes an edge or vertex and another direction is tried.
constexpr double kRayDegenerateRelTol = 1e-12;

// Fixed, irregular ray directions (unit vectors from a golden-angle spiral), tried in order.
inline const std::array<Vec3, 16>& rayDirections() {
  static const std::array<Vec3, 16> dirs = [] {
    std::array<Vec3, 16> d;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < 16; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / 16.0 + 0.0123;
      const double rr = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = golden * i + 0.377;
      d[i] = Vec3(rr * std::cos(phi), rr * std::sin(phi), z).normalized();
    }
    return d;
  }();
  return dirs;
}

// Slab test of the ray p + t d, t in [0, tmax], against a box.
inline bool rayHitsBox(const Vec3& p, const Vec3& inv_d, double tmax, const Vec3& mn,
                       const Vec3& mx) {
  double t0 = 0.0, t1 = tmax;
  for (int k = 0; k < 3; ++k) {
    double ta = (mn[k] - p[k]) * inv_d[k];
    double tb = (mx[k] - p[k]) * inv_d[k];
    if (std::isnan(ta) || std::isnan(tb)) {  // d[k] == 0 and p on the slab plane
      if (p[k] < mn[k] || p[k] > mx[k]) return false;
      continue;
    }
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Orientation of the line p + t d against the triangle: u, v, w are d·(e1×e2), d·(e2×e0),
// d·(e0×e1) with e_i the vertices relative to p. The line meets the interior iff all three
// share a sign; det(e0, e1, e2) / (u + v + w) is the crossing parameter t.
struct LineTriangle {
  double u, v, w, det;
  double tol_u, tol_v, tol_w;
};
inline LineTriangle lineTriangle(const Vec3& p, const Vec3& d, const TriRecord& tri) {
  const Vec3 e0 = tri.a - p, e1 = tri.b - p, e2 = tri.c - p;
  const Vec3 c12 = e1.cross(e2), c20 = e2.cross(e0), c01 = e0.cross(e1);
  LineTriangle lt;
  lt.u = d.dot(c12);
  lt.v = d.dot(c20);
  lt.w = d.dot(c01);
  lt.det = e0.dot(c12);
  const double dn = d.norm();
  const double l0 = e0.norm(), l1 = e1.norm(), l2 = e2.norm();
  lt.tol_u = kRayDegenerateRelTol * dn * l1 * l2;
  lt.tol_v = kRayDegenerateRelTol * dn * l2 * l0;
  lt.tol_w = kRayDegenerateRelTol * dn * l0 * l1;
  return lt;
}

// What the ray p + t d, t > 0, does at a triangle: nothing, leave the solid (+1: d along the
// outward normal), enter it (-1), or graze an edge or vertex (the count would be unreliable;
// callers try another direction).
enum class RayCrossing { kNone, kLeave, kEnter, kGraze };
inline RayCrossing rayCrossing(const Vec3& p, const Vec3& d, const TriRecord& tri) {
  const LineTriangle lt = lineTriangle(p, d, tri);
  const bool pos = lt.u > lt.tol_u && lt.v > lt.tol_v && lt.w > lt.tol_w;
  const bool neg = lt.u < -lt.tol_u && lt.v < -lt.tol_v && lt.w < -lt.tol_w;
  const double sum = lt.u + lt.v + lt.w;
  if (!pos && !neg) {
    // The line misses, or grazes an edge or vertex; only a graze ahead of p matters.
    const bool maybe_pos = lt.u >= -lt.tol_u && lt.v >= -lt.tol_v && lt.w >= -lt.tol_w;
    const bool maybe_neg = lt.u <= lt.tol_u && lt.v <= lt.tol_v && lt.w <= lt.tol_w;
    if ((maybe_pos || maybe_neg) && (sum == 0.0 || lt.det / sum > 0.0)) return RayCrossing::kGraze;
    return RayCrossing::kNone;
  }
  if (!(lt.det / sum > 0.0)) return RayCrossing::kNone;  // behind p
  return pos ? RayCrossing::kLeave : RayCrossing::kEnter;
}

// Signed crossings (+1 leaving, -1 entering) of the ray p + t d, 0 < t <= tmax, with the
// triangles `use` accepts (use(tri) -> bool). False if the ray grazes an edge or vertex of one
// of them, in which case *winding is meaningless and the caller tries another direction.
template <class Use>
bool rayWinding(const Bvh& bvh, const Vec3& p, const Vec3& d, double tmax, Use&& use,
                int* winding) {
  const Vec3 inv_d = d.cwiseInverse();
  int count = 0;
  bool graze = false;
  bvh.traverse(
      [&](const Vec3& mn, const Vec3& mx) { return !graze && rayHitsBox(p, inv_d, tmax, mn, mx); },
      [&](int32_t i) {
        const TriRecord& t = bvh.tris[i];
        if (graze || !use(t)) return;
        switch (rayCrossing(p, d, t)) {
          case RayCrossing::kLeave:
            ++count;
            break;
          case RayCrossing::kEnter:
            --count;
            break;
          case RayCrossing::kGraze:
            graze = true;
            break;
          case RayCrossing::kNone:
            break;
        }
      });
  *winding = count;
  return !graze;
}

}  // namespace sphereset::detail

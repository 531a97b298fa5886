// Private: the per-triangle closed form of a ball against one triangle, and the same with its
// solid angle split in two, so that callers summing many triangles can accumulate the atan2
// terms without evaluating each one.
#pragma once

#include "index/angle_sum.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {

// Closed-form terms of one triangle t against the ball B(o, r); see outside_volume.hpp.
struct TriangleBallTerms {
  double h = 0.0;                   // signed distance of t's plane from o along t's outward normal
  double area = 0.0;                // A = area(t ∩ B)
  double solid_angle = 0.0;         // Ω = solid angle that t ∩ B subtends at o (unsigned, >= 0)
  bool center_on_triangle = false;  // o lies on t (within kOnPlaneRelTol): SOTV undefined
};

// The per-triangle closed form: triangle (a, b, c) counter-clockwise about its outward unit
// normal n, ball (o, r).
TriangleBallTerms triangleBallTerms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                    const Vec3& o, double r);

namespace detail {

// As triangleBallTerms, except that `solid_angle` holds only the arcs' part; the rest,
// Σ atan2 pairs (ω/2 each), is added to `half_omega` with every numerator multiplied by
// `sign` (±1), so that half_omega accumulates sign · (Ω - solid_angle) / 2.
TriangleBallTerms triangleBallTermsSplit(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                         const Vec3& o, double r, AngleSum* half_omega,
                                         double sign);

// What a caller summing triangles has already computed for triangle (a, b, c) and centre o:
// h = n · (a - o) and the squared distances of a, b and c from o.
struct TriangleFromCentre {
  double h, da, db, dc;
};

// As triangleBallTermsSplit, from those values (computed by the same expressions, so the
// terms are the same bits).
TriangleBallTerms triangleBallTermsKnown(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                         const Vec3& o, double r, const TriangleFromCentre& known,
                                         AngleSum* half_omega, double sign);

}  // namespace detail
}  // namespace sphereset

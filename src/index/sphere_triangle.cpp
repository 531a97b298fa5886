// Closed-form intersection terms of one triangle with one ball.
//
// Reference: Wang et al., "Variational Sphere Set Approximation for Solid Objects" (2006),
// Sec. 4.1 (SOTV), and the closed form of the project's design note on outside volume.
//
// For triangle t and ball B = (o, r) let h be the signed distance of t's plane from o,
// D the disk where the plane cuts B (centre c = o + h n, radius ρ = sqrt(r² - h²)) and
// R = t ∩ D. Then SOTV(t, B) = (r³ Ω - |h| A) / 3 with A = area(R) and Ω the solid angle R
// subtends at o. The paper splits this into four cases (a)-(d) and tabulates the "swing
// volume" of cases (c) and (d); here every case is one formula.
//
// Following the note, A and Ω are sums over the boundary of R seen from c0: each straight
// piece (p, q) of a triangle edge clipped to D contributes the planar triangle (c0, p, q) to A
// and its solid angle ω(c0, p, q) at o to Ω; each arc of ∂D of angle θ contributes ρ² θ / 2
// and θ (1 - |h| / r). Deviation from the note: instead of walking the arcs one by one, whose
// angles are ambiguous (≈0 or ≈2π) in floating point when their end points nearly coincide,
// as they do near tangencies, we use that the boundary winds once around c0 when c0 ∈ t and
// not at all otherwise. The total arc angle is then
//   Θ = 2π [c0 ∈ t] - Σ_pieces angle(p, q),
// which is continuous in the input, needs no case analysis, and costs no more than the
// pieces themselves:
//   A = Σ_pieces cross(p, q) / 2 + ρ² Θ / 2,
//   Ω = Σ_pieces ω(c0, p, q)     + Θ (1 - |h| / r).
#include "index/sphere_triangle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "index/winding.hpp"

namespace sphereset {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// |h| below this fraction of r means o lies in t's plane; the triangle's SOTV is then
// discontinuous (its one-sided limits are ±r³Ω/3) and the caller must handle the centre.
constexpr double kOnPlaneRelTol = 1e-13;

struct P2 {
  double x, y;
};
inline double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
inline double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }

// Signed solid angle at o of the planar triangle (c, p, q), as the pair (num, den) with
// ω = 2 atan2(num, den); c is the foot of o on the plane at distance |h|, p and q are 2D
// coordinates about c, and ω > 0 for counter-clockwise (p, q). Van Oosterom–Strackee with a = c -
// o, b = c + p - o, d = c + q - o, using the plane's geometry: a·b = a·d = h², det(a, b, d) = |h|
// cross(p, q), and
//   den = |h| (|b||d| + b·d) + h² (|b| + |d|).
// When the angle at c approaches π (c close to the segment pq, which happens for every centre
// near a mesh edge) |b||d| + b·d cancels catastrophically; it is then evaluated as
// |b × d|² / (|b||d| - b·d), with b × d = (h (p_y - q_y), h (q_x - p_x), cross(p, q)).
inline void fanSolidAngleTerms(double abs_h, P2 p, P2 q, double* num_out, double* den_out) {
  const double h2 = abs_h * abs_h;
  const double lb = std::sqrt(h2 + dot(p, p));
  const double lq = std::sqrt(h2 + dot(q, q));
  const double cr = cross(p, q);
  const double bd = h2 + dot(p, q);
  double sum;  // |b||d| + b·d
  if (bd >= 0.0) {
    sum = lb * lq + bd;
  } else {
    const double dx = p.x - q.x, dy = p.y - q.y;
    const double cross2 = h2 * (dx * dx + dy * dy) + cr * cr;
    sum = cross2 / (lb * lq - bd);
  }
  *num_out = abs_h * cr;
  *den_out = abs_h * sum + h2 * (lb + lq);
}

}  // namespace

double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o) {
  const Vec3 x = a - o, y = b - o, z = c - o;
  const double lx = x.norm(), ly = y.norm(), lz = z.norm();
  const double num = x.dot(y.cross(z));
  const double den = lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx;
  return 2.0 * std::atan2(num, den);
}

TriangleBallTerms detail::triangleBallTermsSplit(const Vec3& a, const Vec3& b, const Vec3& c,
                                                 const Vec3& n, const Vec3& o, double r,
                                                 AngleSum* half_omega, double sign) {
  return triangleBallTermsKnown(
      a, b, c, n, o, r,
      {n.dot(a - o), (a - o).squaredNorm(), (b - o).squaredNorm(), (c - o).squaredNorm()},
      half_omega, sign);
}

TriangleBallTerms detail::triangleBallTermsKnown(const Vec3& a, const Vec3& b, const Vec3& c,
                                                 const Vec3& n, const Vec3& o, double r,
                                                 const TriangleFromCentre& known,
                                                 AngleSum* half_omega, double sign) {
  TriangleBallTerms out;
  out.h = known.h;
  const double abs_h = std::abs(out.h);
  if (!(r > 0.0) || abs_h >= r) return out;  // the plane misses the ball

  const double r2 = r * r;
  const double da = known.da, db = known.db, dc = known.dc;
  const bool on_plane = abs_h <= kOnPlaneRelTol * r;

  // Case (a) of the paper: the whole triangle is inside the ball.
  if (da <= r2 && db <= r2 && dc <= r2) {
    out.area = 0.5 * (b - a).cross(c - a).norm();
    if (on_plane) {
      // o in the plane: inside t iff its three sub-triangles have consistent orientation.
      const double w0 = n.dot((b - o).cross(c - o)), w1 = n.dot((c - o).cross(a - o)),
                   w2 = n.dot((a - o).cross(b - o));
      out.center_on_triangle = w0 >= 0 && w1 >= 0 && w2 >= 0;
      return out;
    }
    const Vec3 x = a - o, y = b - o, z = c - o;
    const double lx = std::sqrt(da), ly = std::sqrt(db), lz = std::sqrt(dc);
    const double num = std::abs(x.dot(y.cross(z)));
    const double den = lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx;
    half_omega->add(sign * num, den);
    return out;
  }

  // General case: 2D frame (u, v) in the plane with u × v = n, origin at the foot c0.
  const Vec3 c0 = o + out.h * n;
  Vec3 u = b - a;
  const double ul = u.norm();
  if (!(ul > 0.0)) return out;  // degenerate input; clean meshes have none
  u /= ul;
  const Vec3 v = n.cross(u);
  const std::array<P2, 3> p = {P2{(a - c0).dot(u), (a - c0).dot(v)},
                               P2{(b - c0).dot(u), (b - c0).dot(v)},
                               P2{(c - c0).dot(u), (c - c0).dot(v)}};
  const double rho2 = std::max(0.0, r2 - out.h * out.h);

  // Signed distances of c0 from the edge lines, positive on the triangle's side. An edge
  // line with the whole disk on its outer side (s <= -ρ) means t ∩ D is empty.
  std::array<P2, 3> d;
  std::array<double, 3> dd, side;
  std::array<bool, 3> misses{};  // the edge's line misses the disk (c0 on the inner side)
  bool inside_all = true;        // foot c0 inside every edge half-plane (c0 ∈ t)
  for (int k = 0; k < 3; ++k) {
    const P2 p0 = p[k], p1 = p[(k + 1) % 3];
    d[k] = P2{p1.x - p0.x, p1.y - p0.y};
    dd[k] = dot(d[k], d[k]);
    side[k] = cross(p0, d[k]) + 0.0;  // + 0.0 turns -0 into +0, see the angle sum below
    // Distance of c0 from the line is side / |d|, compared with ρ without a square root.
    const bool far = side[k] * side[k] >= rho2 * dd[k];
    if (far && side[k] < 0.0) return out;
    misses[k] = far;
    if (side[k] < 0.0) inside_all = false;
  }

  // Angles are summed as arguments of complex products (one atan2 per sum, not per piece).
  double fan_area = 0.0;
  detail::AngleSum fan_angle;
  for (int k = 0; k < 3; ++k) {
    if (misses[k]) continue;  // the edge's line misses the disk
    const P2 p0 = p[k];
    // Piece of the edge inside D: roots of |p0 + t d|² = ρ², clipped to [0, 1].
    const double hb = dot(p0, d[k]);
    const double cc = dot(p0, p0) - rho2;
    const double disc = hb * hb - dd[k] * cc;
    if (!(disc > 0.0)) continue;
    const double sq = std::sqrt(disc);
    const double qq = -(hb + std::copysign(sq, hb));
    double t0 = qq / dd[k], t1 = cc / qq;
    if (t0 > t1) std::swap(t0, t1);
    t0 = std::max(t0, 0.0);
    t1 = std::min(t1, 1.0);
    if (!(t1 > t0)) continue;
    const P2 q0{p0.x + t0 * d[k].x, p0.y + t0 * d[k].y};
    const P2 q1{p0.x + t1 * d[k].x, p0.y + t1 * d[k].y};
    // cross(q0, q1) = (t1 - t0) cross(p0, d): computed this way its sign always agrees with
    // the side test, which keeps the angle sum below consistent when c0 lies on the edge's
    // line (there the piece's angle is +π exactly when c0 counts as inside t).
    const double cr = (t1 - t0) * side[k];
    fan_area += 0.5 * cr;
    fan_angle.add(cr, dot(q0, q1));
    if (!on_plane) {
      double num, den;
      fanSolidAngleTerms(abs_h, q0, q1, &num, &den);
      half_omega->add(sign * num, den);
    }
  }
  // The boundary of R winds once around c0 if c0 ∈ t (then c0 ∈ R) and not at all
  // otherwise, so the arcs' total angle is Θ = 2π [c0 ∈ t] - Σ (angles of the pieces at c0).
  const double theta = std::clamp((inside_all ? kTwoPi : 0.0) - fan_angle.value(), 0.0, kTwoPi);
  out.area = std::max(0.0, fan_area + 0.5 * rho2 * theta);
  if (on_plane) {
    out.center_on_triangle = inside_all;
    return out;
  }
  out.solid_angle = theta * (1.0 - abs_h / r);
  return out;
}

TriangleBallTerms triangleBallTerms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                    const Vec3& o, double r) {
  detail::AngleSum half_omega;
  TriangleBallTerms out = detail::triangleBallTermsSplit(a, b, c, n, o, r, &half_omega, 1.0);
  out.solid_angle = std::max(0.0, out.solid_angle + 2.0 * half_omega.value());
  return out;
}

}  // namespace sphereset

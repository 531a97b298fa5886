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
// Deviation from the note: the note walks the boundary of R and sums arcs one by one. The
// angle of a single arc from two nearly coincident end points is ambiguous (≈0 or ≈2π) in
// floating point, and near-tangent configurations produce exactly such arcs. We instead
// compute the straight boundary pieces by clipping each edge to D, and the total angle Θ of
// the circle ∂D that lies inside t as the measure of the intersection of three circular arcs
// (one per edge half-plane), each given in closed form by its edge's distance from c. Both
// parts are continuous in the input, so tangencies and vertices exactly on the sphere need
// no special case:
//   A = Σ_pieces cross(p, q) / 2 + ρ² Θ / 2,
//   Ω = Σ_pieces ω(c, p, q)      + Θ (1 - |h| / r),
// where ω is the signed solid angle of the planar triangle (c, p, q) seen from o.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "sphereset/solid_index.hpp"

namespace sphereset {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// |h| below this fraction of r means o lies in t's plane; the triangle's SOTV is then
// discontinuous (its one-sided limits are ±r³Ω/3) and the caller must handle the centre.
constexpr double kOnPlaneRelTol = 1e-13;

struct P2 {
  double x, y;
};
inline double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
inline double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }

// Signed solid angle at o of the planar triangle (c, p, q) where c is the foot of o on the
// plane at distance |h|; p, q are 2D coordinates about c. Positive for counter-clockwise
// (p, q). Van Oosterom–Strackee with a = c - o, b = c + p - o, d = c + q - o, using the
// plane's geometry: a·b = a·d = h², det(a, b, d) = |h| cross(p, q), and
//   den = |h| (|b||d| + b·d) + h² (|b| + |d|).
// When the angle at c approaches π (c close to the segment pq, which happens for every centre
// near a mesh edge) |b||d| + b·d cancels catastrophically; it is then evaluated as
// |b × d|² / (|b||d| - b·d), with b × d = (h (p_y - q_y), h (q_x - p_x), cross(p, q)).
inline double fanSolidAngle(double abs_h, P2 p, P2 q) {
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
  const double num = abs_h * cr;
  const double den = abs_h * sum + h2 * (lb + lq);
  return 2.0 * std::atan2(num, den);
}

// Measure of the intersection of circular arcs [start_k, start_k + len_k] (angles, radians).
double arcIntersectionMeasure(const std::array<double, 3>& start,
                              const std::array<double, 3>& len) {
  // Intervals on the real line, kept inside [start[0], start[0] + len[0]].
  std::array<std::array<double, 2>, 8> cur{}, next{};
  int ncur = 1;
  cur[0] = {start[0], start[0] + len[0]};
  for (int k = 1; k < 3; ++k) {
    if (len[k] >= kTwoPi) continue;  // the whole circle: no constraint
    // Shift the arc so its first copy starts in [start[0] - 2π, start[0]).
    double s = start[k] - start[0];
    s = s - kTwoPi * std::floor(s / kTwoPi) + start[0] - kTwoPi;
    int nnext = 0;
    for (int i = 0; i < ncur; ++i) {
      for (int copy = 0; copy < 3; ++copy) {
        const double a0 = s + copy * kTwoPi;
        const double lo = std::max(cur[i][0], a0);
        const double hi = std::min(cur[i][1], a0 + len[k]);
        if (hi > lo && nnext < 8) next[nnext++] = {lo, hi};
      }
    }
    cur = next;
    ncur = nnext;
    if (ncur == 0) return 0.0;
  }
  double total = 0.0;
  for (int i = 0; i < ncur; ++i) total += cur[i][1] - cur[i][0];
  return std::min(total, kTwoPi);
}

}  // namespace

double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o) {
  const Vec3 x = a - o, y = b - o, z = c - o;
  const double lx = x.norm(), ly = y.norm(), lz = z.norm();
  const double num = x.dot(y.cross(z));
  const double den = lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx;
  return 2.0 * std::atan2(num, den);
}

TriangleBallTerms triangleBallTerms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                    const Vec3& o, double r) {
  TriangleBallTerms out;
  out.h = n.dot(a - o);
  const double abs_h = std::abs(out.h);
  if (!(r > 0.0) || abs_h >= r) return out;  // the plane misses the ball

  const double r2 = r * r;
  const double da = (a - o).squaredNorm(), db = (b - o).squaredNorm(),
               dc = (c - o).squaredNorm();
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
    out.solid_angle = std::abs(triangleSolidAngle(a, b, c, o));
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
  const double rho = std::sqrt(rho2);

  double fan_area = 0.0, fan_omega = 0.0;
  std::array<double, 3> arc_start{}, arc_len{};
  bool inside_all = true;  // foot c0 inside every edge half-plane (c0 ∈ t)
  for (int k = 0; k < 3; ++k) {
    const P2 p0 = p[k], p1 = p[(k + 1) % 3];
    const P2 d{p1.x - p0.x, p1.y - p0.y};
    const double dd = dot(d, d);
    const double dl = std::sqrt(dd);
    // Signed distance of c0 from the edge line, positive on the triangle's side.
    const double s = cross(p0, d) / dl;
    if (s < 0.0) inside_all = false;
    // Arc of ∂D inside this edge's half-plane: [ψ_out + β, ψ_out + 2π - β].
    const double ratio = rho > 0.0 ? s / rho : (s >= 0.0 ? 1.0 : -1.0);
    const double beta = std::acos(std::clamp(ratio, -1.0, 1.0));
    arc_start[k] = std::atan2(d.y, d.x) - 0.5 * kPi + beta;
    arc_len[k] = kTwoPi - 2.0 * beta;

    // Piece of the edge inside D: roots of |p0 + t d|² = ρ², clipped to [0, 1].
    const double hb = dot(p0, d);
    const double cc = dot(p0, p0) - rho2;
    const double disc = hb * hb - dd * cc;
    if (!(disc > 0.0)) continue;
    const double sq = std::sqrt(disc);
    const double qq = -(hb + std::copysign(sq, hb));
    double t0 = qq / dd, t1 = cc / qq;
    if (t0 > t1) std::swap(t0, t1);
    t0 = std::max(t0, 0.0);
    t1 = std::min(t1, 1.0);
    if (!(t1 > t0)) continue;
    const P2 q0{p0.x + t0 * d.x, p0.y + t0 * d.y};
    const P2 q1{p0.x + t1 * d.x, p0.y + t1 * d.y};
    fan_area += 0.5 * cross(q0, q1);
    if (!on_plane) fan_omega += fanSolidAngle(abs_h, q0, q1);
  }
  const double theta = arcIntersectionMeasure(arc_start, arc_len);
  out.area = std::max(0.0, fan_area + 0.5 * rho2 * theta);
  if (on_plane) {
    out.center_on_triangle = inside_all;
    return out;
  }
  out.solid_angle = std::max(0.0, fan_omega + theta * (1.0 - abs_h / r));
  return out;
}

}  // namespace sphereset

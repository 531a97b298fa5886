// Sphere outside volume (SOV): the volume of a ball that lies outside a closed mesh.
//
// Reference: Wang et al. 2006, Sec. 4.2 (accumulating SOTV into SOV) and the project's design
// note on the closed form. Along each ray from o the "outside" indicator flips at every
// surface crossing, so
//   SOV(o, r) = [o outside] (4π/3) r³ + Σ_t sign(h_t) (r³ Ω_t - |h_t| A_t) / 3,
// which is the paper's rule for centres inside and outside in one expression. In the same
// pass:
//   dSOV/dr   = r² (4π [o outside] + Σ_t sign(h_t) Ω_t)   (outside area of the sphere),
//   ∇_o SOV   = Σ_t A_t n_t                             (vector area of the surface in B).
//
// Centre on the surface: there the indicator and the triangles through o are discontinuous
// while SOV itself is continuously differentiable in o. We evaluate at o ± δ d and average,
// which is exact to O(δ²); δ is kNudgeRel of the smaller of r and the mesh size, and far
// above the boundary tolerance. The direction is a fixed irregular one rather than a face
// normal, because a normal at an edge or corner can slide the centre along another face.
//
// Speed (beyond the paper): most triangles met by a large ball lie wholly inside it. Let Q be
// the set of those triangles. Their Σ h A and Σ A n are linear in o, so hierarchy nodes inside
// the ball contribute precomputed sums and are not opened. Their solid angles are not summed
// one by one either: Q is a surface whose boundary ∂Q consists of edges between a triangle of
// Q and a triangle crossing the sphere, so ∂Q is found from the crossing triangles alone, and
//   Ω(Q) = Ω(F) + 4π w,
// where F is the fan over ∂Q from an apex o + L d far along a direction d (each edge (u, v)
// contributes the limit of the solid angle of triangle (o + L d, u, v) as L → ∞), and w is
// the winding number about o of the closed surface Q - F, i.e. the signed count of triangles
// of Q crossed by the ray from o along -d, which the fan does not meet. A ray or fan that
// grazes an edge is detected and the next direction is used. Cost: proportional to the
// triangles crossing the sphere, plus one short ray query. Meshes without neighbour
// information (not closed) sum every triangle's solid angle instead.
//
// Repeated balls (beyond the paper): the fit asks for many balls again (a sphere update that
// retraces the last one, a teleport's split, the bound); the index keeps recent answers by
// the exact bits of the ball (sov_memo.hpp), so a repeat costs a hash lookup and returns
// the same bits; and the containment of recent centres, which the many radii the point
// assignment asks for about one centre share.
#include <cmath>
#include <numbers>
#include <vector>

#include "index/angle_sum.hpp"
#include "index/bvh.hpp"
#include "index/oracles.hpp"
#include "index/ray_triangle.hpp"
#include "index/solid_index_impl.hpp"
#include "index/sphere_triangle.hpp"

namespace sphereset {
namespace {

using detail::TriRecord;

constexpr double kNudgeRel = 1e-5;
// Same meaning as in sphere_triangle.cpp: |h| below this fraction of r is "in the plane".
constexpr double kOnPlaneRelTol = 1e-13;
// Nudge directions: irregular unit vectors, so that o ± δ d leaves the surface even at
// edges and corners of axis-aligned CAD meshes; the next one is tried if a side still
// lands on the surface.
const Vec3 kNudgeDirections[] = {Vec3(0.5377, 0.8183, 0.2031).normalized(),
                                 Vec3(-0.3122, 0.2450, 0.9179).normalized(),
                                 Vec3(0.7071, -0.5803, 0.4040).normalized()};

// Numerator and denominator of the Van Oosterom–Strackee formula for the solid angle of
// triangle (x, y, z) (positions relative to o, with lengths lx, ly, lz): Ω = 2 atan2(num, den)
// and num = det(x, y, z) = 2 h A.
struct SolidAngleTerms {
  double num, den;
};
inline SolidAngleTerms solidAngleTerms(const Vec3& x, const Vec3& y, const Vec3& z, double lx,
                                       double ly, double lz) {
  return {x.dot(y.cross(z)), lx * ly * lz + x.dot(y) * lz + x.dot(z) * ly + y.dot(z) * lx};
}

struct Accumulator {
  detail::AngleSum half_omega;  // Σ sign(h) Ω / 2 over terms given as atan2 pairs
  double omega = 0.0;           // Σ sign(h) Ω over terms given as numbers
  double h_area = 0.0;          // Σ h A
  Vec3 gradient = Vec3::Zero();
  int64_t tested = 0;
  bool center_on_surface = false;
  // With topology: solid angles of triangles inside the ball are left to Ω(Q); the edges of
  // ∂Q are collected instead, oriented as in their triangle of Q.
  bool use_boundary = false;
  const detail::Bvh* bvh = nullptr;
  std::vector<std::array<Vec3, 2>> boundary;

  void add(const TriRecord& t, const Vec3& o, double r, double r2) {
    // Cheap rejection by the triangle's bounding box, then by its plane.
    const Vec3 mn = t.a.cwiseMin(t.b).cwiseMin(t.c), mx = t.a.cwiseMax(t.b).cwiseMax(t.c);
    if (detail::boxPointSquaredDistance(mn, mx, o) >= r2) return;
    const double h = t.n.dot(t.a - o);
    if (std::abs(h) >= r) return;
    ++tested;
    const Vec3 x = t.a - o, y = t.b - o, z = t.c - o;
    const double dx = x.squaredNorm(), dy = y.squaredNorm(), dz = z.squaredNorm();
    const bool in_plane = std::abs(h) <= kOnPlaneRelTol * r;
    if (dx <= r2 && dy <= r2 && dz <= r2 && !in_plane) {
      // Case (a): the whole triangle in the ball. Same closed form as triangleBallTerms.
      h_area += h * t.area;
      gradient += t.area * t.n;
      if (use_boundary) return;  // its solid angle is part of Ω(Q)
      const SolidAngleTerms sa =
          solidAngleTerms(x, y, z, std::sqrt(dx), std::sqrt(dy), std::sqrt(dz));
      half_omega.add(sa.num, sa.den);
      return;
    }
    const double s = h > 0.0 ? 1.0 : (h < 0.0 ? -1.0 : 0.0);
    const TriangleBallTerms k =
        detail::triangleBallTermsKnown(t.a, t.b, t.c, t.n, o, r, {h, dx, dy, dz}, &half_omega, s);
    if (k.center_on_triangle) center_on_surface = true;
    if (k.area > 0.0) {
      omega += s * k.solid_angle;
      h_area += k.h * k.area;
      gradient += k.area * t.n;
    }
    if (!use_boundary || (dx <= r2 && dy <= r2 && dz <= r2)) return;
    // An edge of this crossing triangle with both ends in the ball borders Q when the
    // neighbour across it lies wholly in the ball.
    const Vec3* v[3] = {&t.a, &t.b, &t.c};
    const double d2[3] = {dx, dy, dz};
    for (int e = 0; e < 3; ++e) {
      if (d2[e] > r2 || d2[(e + 1) % 3] > r2) continue;
      const TriRecord& nb = bvh->tris[t.nbr[e]];
      if ((nb.a - o).squaredNorm() <= r2 && (nb.b - o).squaredNorm() <= r2 &&
          (nb.c - o).squaredNorm() <= r2)
        boundary.push_back({*v[(e + 1) % 3], *v[e]});  // as traversed by the neighbour
    }
  }

  // A hierarchy node wholly inside the ball: Σ h A = Σ det(a - o, b - o, c - o) / 2 and
  // Σ A n = Σ (b - a) × (c - a) / 2 from the node's sums.
  void addNode(const detail::NodeSums& ns, const Vec3& o) {
    h_area += 0.5 * (ns.det_q - (o - ns.q).dot(ns.cross));
    gradient += 0.5 * ns.cross;
  }
};

inline double farthestCornerSquaredDistance(const Vec3& mn, const Vec3& mx, const Vec3& p) {
  return (mn - p).cwiseAbs().cwiseMax((mx - p).cwiseAbs()).squaredNorm();
}

// Ω(Q) from the boundary edges of Q (see the top of the file); false if every direction
// grazed an edge (then the caller falls back to summing triangles).
bool solidAngleOfInside(const detail::Bvh& bvh, const std::vector<std::array<Vec3, 2>>& edges,
                        const Vec3& o, double r, double r2, double* omega) {
  for (const Vec3& d : detail::rayDirections()) {
    // Fan from the apex o + L d, L → ∞: for edge (u, v) the limit of the solid angle of
    // triangle (o + L d, u, v), Van Oosterom–Strackee divided through by L.
    detail::AngleSum half;
    bool degenerate = false;
    for (const auto& [u0, v0] : edges) {
      const Vec3 u = u0 - o, v = v0 - o;
      const double lu = u.norm(), lv = v.norm();
      const double num = u.dot(v.cross(d));
      const double den = lu * lv + u.dot(v) + u.dot(d) * lv + v.dot(d) * lu;
      // o on a strip (num ≈ 0 with the edge seen across o) makes the winding undefined.
      if (std::abs(num) <= detail::kRayDegenerateRelTol * lu * lv && den <= 0.0) {
        degenerate = true;
        break;
      }
      half.add(num, den);
    }
    if (degenerate) continue;
    // Winding: signed crossings of the ray o - t d, 0 < t <= r, with triangles of Q. (The
    // fan's apex o + L d lies on the other side, so this ray meets only Q.)
    int winding = 0;
    const bool clean = detail::rayWinding(
        bvh, o, -d, r,
        [&](const TriRecord& t) {
          return (t.a - o).squaredNorm() <= r2 && (t.b - o).squaredNorm() <= r2 &&
                 (t.c - o).squaredNorm() <= r2;
        },
        &winding);
    if (!clean) continue;
    *omega = 2.0 * half.value() + 4.0 * std::numbers::pi * winding;
    return true;
  }
  return false;
}

template <bool kBrute>
OutsideVolume evaluate(const SolidIndex& index, const SolidIndex::Impl& im, const Vec3& o, double r,
                       int depth) {
  OutsideVolume out;
  if (!(r > 0.0)) {
    out.center = index.classify(o);
    return out;
  }
  const double r2 = r * r;
  Accumulator acc;
  if constexpr (kBrute) {
    for (const TriRecord& t : im.bvh.tris) acc.add(t, o, r, r2);
  } else {
    const detail::Bvh& bvh = im.bvh;
    acc.bvh = &bvh;
    acc.use_boundary = bvh.closed;
    thread_local std::vector<std::array<Vec3, 2>> boundary_buffer;
    boundary_buffer.clear();
    acc.boundary.swap(boundary_buffer);
    constexpr int kPendingLeaves = 4;
    int32_t pending[kPendingLeaves];
    int pending_head = 0, pending_count = 0;
    auto runLeaf = [&](int32_t leaf) {
      const detail::BvhNode& ln = bvh.nodes[leaf];
      for (int32_t i = ln.first; i < ln.first + ln.count; ++i) acc.add(bvh.tris[i], o, r, r2);
    };
    int32_t stack[128];
    int top = 0;
    if (!bvh.nodes.empty()) stack[top++] = 0;
    while (top > 0) {
      const int32_t ni = stack[--top];
      const detail::BvhNode& node = bvh.nodes[ni];
      const Vec3 mn = node.min(), mx = node.max();
      if (detail::boxPointSquaredDistance(mn, mx, o) >= r2) continue;
      if (acc.use_boundary && farthestCornerSquaredDistance(mn, mx, o) <= r2) {
        acc.addNode(bvh.sums[ni], o);
        continue;
      }
      if (node.leaf()) {
        // Leaves wait in a short queue while their triangles are fetched and the traversal
        // goes on; the oldest is processed when the queue is full.
        const char* first = reinterpret_cast<const char*>(&bvh.tris[node.first]);
        const char* last = reinterpret_cast<const char*>(&bvh.tris[node.first + node.count]);
        for (const char* c = first; c < last; c += 64) __builtin_prefetch(c);
        if (pending_count == kPendingLeaves) {
          runLeaf(pending[pending_head]);
          pending[pending_head] = ni;
          pending_head = (pending_head + 1) % kPendingLeaves;
        } else {
          pending[(pending_head + pending_count++) % kPendingLeaves] = ni;
        }
      } else {
        // The children are adjacent; fetching them now hides the latency of the next pop.
        __builtin_prefetch(&bvh.nodes[node.first]);
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      }
    }
    for (int k = 0; k < pending_count; ++k) runLeaf(pending[(pending_head + k) % kPendingLeaves]);
    if (acc.use_boundary) {
      double omega_q = 0.0;
      if (solidAngleOfInside(bvh, acc.boundary, o, r, r2, &omega_q)) {
        acc.omega += omega_q;
        acc.tested += static_cast<int64_t>(acc.boundary.size());
      } else {
        acc.boundary.swap(boundary_buffer);
        return evaluate<true>(index, im, o, r, depth);
      }
    }
    acc.boundary.swap(boundary_buffer);
  }
  Containment where = Containment::kBoundary;
  if (!acc.center_on_surface && !im.centre_memo.find(detail::bitsOf(o), &where)) {
    where = index.classify(o);
    im.centre_memo.store(detail::bitsOf(o), where);
  }
  if (where == Containment::kBoundary && depth == 0) {
    const double delta =
        std::max(kNudgeRel * std::min(r, im.bounds.diagonal()), 100.0 * im.tolerance);
    OutsideVolume up, down;
    for (const Vec3& d : kNudgeDirections) {
      up = evaluate<kBrute>(index, im, o + delta * d, r, depth + 1);
      down = evaluate<kBrute>(index, im, o - delta * d, r, depth + 1);
      if (up.center != Containment::kBoundary && down.center != Containment::kBoundary) break;
    }
    out.volume = 0.5 * (up.volume + down.volume);
    out.d_radius = 0.5 * (up.d_radius + down.d_radius);
    out.gradient = 0.5 * (up.gradient + down.gradient);
    out.triangles_tested = acc.tested + up.triangles_tested + down.triangles_tested;
    out.center = Containment::kBoundary;
    return out;
  }
  // Past one nudge a boundary centre counts as half outside (the average of both sides).
  const double outside = where == Containment::kOutside    ? 1.0
                         : where == Containment::kBoundary ? 0.5
                                                           : 0.0;
  const double four_pi = 4.0 * std::numbers::pi;
  const double ball = four_pi / 3.0 * r * r2;
  const double omega = acc.omega + 2.0 * acc.half_omega.value();
  out.volume = std::clamp(outside * ball + (r * r2 * omega - acc.h_area) / 3.0, 0.0, ball);
  out.d_radius = std::clamp(r2 * (four_pi * outside + omega), 0.0, four_pi * r2);
  out.gradient = acc.gradient;
  out.triangles_tested = acc.tested;
  out.center = where;
  return out;
}

}  // namespace

OutsideVolume SolidIndex::outsideVolume(const Sphere& ball) const {
  OutsideVolume out;
  const auto key = detail::bitsOf(ball);
  if (impl_->sov_memo.find(key, &out)) return out;
  out = evaluate<false>(*this, *impl_, ball.center, ball.radius, 0);
  impl_->sov_memo.store(key, out);
  return out;
}

OutsideVolume outsideVolumeBruteForce(const SolidIndex& index, const Sphere& ball) {
  return evaluate<true>(index, index.impl(), ball.center, ball.radius, 0);
}

}  // namespace sphereset

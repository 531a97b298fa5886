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
// which is exact to O(δ²); δ is kNudgeRel of the smaller of r and the mesh size, and far above the boundary tolerance. The direction is a
// fixed irregular one rather than a face normal, because a normal at an edge or corner can
// slide the centre along another face.
#include <cmath>
#include <numbers>

#include "angle_sum.hpp"
#include "bvh.hpp"
#include "sphere_triangle.hpp"
#include "solid_index_impl.hpp"

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

// Van Oosterom–Strackee numerator and denominator of triangle (a, b, c) seen from o: the
// signed solid angle is 2 atan2(num, den) and num = det(a - o, b - o, c - o) = 2 h A.
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

  // Σ sign(h) Ω, the signed solid angle of the surface inside the ball.
  double signedOmega() const { return omega + 2.0 * half_omega.value(); }

  void add(const TriRecord& t, const Vec3& o, double r, double r2) {
    // Cheap rejection by the triangle's bounding box, then by its plane.
    const Vec3 mn = t.a.cwiseMin(t.b).cwiseMin(t.c), mx = t.a.cwiseMax(t.b).cwiseMax(t.c);
    if (detail::boxPointSquaredDistance(mn, mx, o) >= r2) return;
    const double h = t.n.dot(t.a - o);
    if (std::abs(h) >= r) return;
    ++tested;
    // Case (a), the whole triangle in the ball, inline: the same closed form as
    // triangleBallTerms (Ω of the triangle, A its area), with the solid angle accumulated as
    // an atan2 pair. A centre in the triangle's plane goes to the general kernel.
    const Vec3 x = t.a - o, y = t.b - o, z = t.c - o;
    const double dx = x.squaredNorm(), dy = y.squaredNorm(), dz = z.squaredNorm();
    if (dx <= r2 && dy <= r2 && dz <= r2 && std::abs(h) > kOnPlaneRelTol * r) {
      const SolidAngleTerms sa = solidAngleTerms(x, y, z, std::sqrt(dx), std::sqrt(dy), std::sqrt(dz));
      half_omega.add(sa.num, sa.den);
      h_area += h * t.area;
      gradient += t.area * t.n;
      return;
    }
    const double s = h > 0.0 ? 1.0 : (h < 0.0 ? -1.0 : 0.0);
    const TriangleBallTerms k =
        detail::triangleBallTermsSplit(t.a, t.b, t.c, t.n, o, r, &half_omega, s);
    if (k.center_on_triangle) center_on_surface = true;
    if (k.area <= 0.0) return;
    omega += s * k.solid_angle;
    h_area += k.h * k.area;
    gradient += k.area * t.n;
  }

  // A BVH node entirely inside the ball, with o outside the node's box: every triangle is in
  // case (a), so Σ sign(h) Ω_t is the solid angle of the node's surface patch and Σ h_t A_t is
  // half of Σ det(a - o, b - o, c - o), which is linear in o. The patch's solid angle equals
  // that of the fan from the box centre q over its boundary edges, because the patch and the
  // fan bound a closed surface inside the box, whose winding number about o is 0.
  void addPatch(const detail::Bvh& bvh, const detail::NodePatch& p, const Vec3& o) {
    const Vec3 x = p.q - o;
    const double lx = x.norm();
    for (int32_t l = p.loop_begin; l < p.loop_end; ++l) {
      const auto [first, end] = bvh.patch_loops[l];
      Vec3 y = bvh.patch_vertices[first] - o;
      double ly = y.norm();
      for (int32_t i = first + 1; i < end; ++i) {
        const Vec3 z = bvh.patch_vertices[i] - o;
        const double lz = z.norm();
        const SolidAngleTerms sa = solidAngleTerms(x, y, z, lx, ly, lz);
        half_omega.add(sa.num, sa.den);
        y = z;
        ly = lz;
      }
    }
    h_area += 0.5 * (p.det_q - (o - p.q).dot(p.cross));  // Σ det(a - o, ...) / 2
    gradient += 0.5 * p.cross;
    tested += p.edges;
  }
};

inline double farthestCornerSquaredDistance(const Vec3& mn, const Vec3& mx, const Vec3& p) {
  return (mn - p).cwiseAbs().cwiseMax((mx - p).cwiseAbs()).squaredNorm();
}

template <bool kBrute>
OutsideVolume evaluate(const SolidIndex& index, const SolidIndex::Impl& im, const Vec3& o,
                       double r, int depth) {
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
      const double near2 = detail::boxPointSquaredDistance(mn, mx, o);
      if (near2 >= r2) continue;
      if (near2 > 0.0 && farthestCornerSquaredDistance(mn, mx, o) <= r2 &&
          bvh.node_patch[ni] >= 0) {
        acc.addPatch(bvh, bvh.patches[bvh.node_patch[ni]], o);
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
  }
  Containment where = acc.center_on_surface ? Containment::kBoundary : index.classify(o);
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
  const double omega = acc.signedOmega();
  out.volume = std::clamp(outside * ball + (r * r2 * omega - acc.h_area) / 3.0, 0.0, ball);
  out.d_radius = std::clamp(r2 * (four_pi * outside + omega), 0.0, four_pi * r2);
  out.gradient = acc.gradient;
  out.triangles_tested = acc.tested;
  out.center = where;
  return out;
}

}  // namespace

OutsideVolume SolidIndex::outsideVolume(const Sphere& ball) const {
  return evaluate<false>(*this, *impl_, ball.center, ball.radius, 0);
}

OutsideVolume SolidIndex::outsideVolumeBruteForce(const Sphere& ball) const {
  return evaluate<true>(*this, *impl_, ball.center, ball.radius, 0);
}

}  // namespace sphereset

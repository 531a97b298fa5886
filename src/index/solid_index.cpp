// Spatial queries on a closed triangle mesh: point-in-solid, distance, segment crossings.
//
// Point in solid: signed ray crossings (each crossing counts +1 where the ray leaves the solid
// and -1 where it enters; non-zero total means inside). The ray-triangle test uses the three
// orientation determinants of the ray against the triangle's edges, so a ray passing exactly
// through an edge or vertex is detected (a determinant within kRayDegenerateRelTol of zero)
// and the query is repeated along another fixed direction instead of miscounting. Points
// within boundaryTolerance() of the surface are reported as on the boundary first, by a
// nearest-triangle query.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "index/bvh.hpp"
#include "index/ray_triangle.hpp"
#include "index/solid_index_impl.hpp"
#include "index/winding.hpp"

namespace sphereset {
namespace {

using detail::Bvh;
using detail::BvhNode;
using detail::LineTriangle;
using detail::lineTriangle;
using detail::rayDirections;
using detail::rayHitsBox;
using detail::TriRecord;

// Points closer than this fraction of the bounding-box diagonal to the surface are on it.
constexpr double kBoundaryRelTol = 1e-11;
// Closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Ray parameter of the line p + t d through a triangle, when it passes through it (edges and
// vertices included, up to the degeneracy tolerance of lineTriangle); NaN otherwise.
double rayTriangleT(const Vec3& p, const Vec3& d, const TriRecord& tri) {
  const LineTriangle lt = lineTriangle(p, d, tri);
  const bool maybe_pos = lt.u >= -lt.tol_u && lt.v >= -lt.tol_v && lt.w >= -lt.tol_w;
  const bool maybe_neg = lt.u <= lt.tol_u && lt.v <= lt.tol_v && lt.w <= lt.tol_w;
  const double sum = lt.u + lt.v + lt.w;
  if ((!maybe_pos && !maybe_neg) || sum == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return lt.det / sum;
}

}  // namespace

SolidIndex::SolidIndex(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->mesh = mesh;
  impl_->bvh.build(mesh);
  impl_->bounds = boundingBox(mesh);
  impl_->tolerance = kBoundaryRelTol * std::max(impl_->bounds.diagonal(), 1e-300);
}
SolidIndex::~SolidIndex() = default;
SolidIndex::SolidIndex(SolidIndex&&) noexcept = default;
SolidIndex& SolidIndex::operator=(SolidIndex&&) noexcept = default;

const Mesh& SolidIndex::mesh() const { return impl_->mesh; }
const Aabb& SolidIndex::bounds() const { return impl_->bounds; }
void SolidIndex::forgetAnswers() const {
  impl_->sov_memo.clear();
  impl_->centre_memo.clear();
}
double SolidIndex::boundaryTolerance() const { return impl_->tolerance; }
int64_t SolidIndex::nodeCount() const { return static_cast<int64_t>(impl_->bvh.nodes.size()); }

double SolidIndex::distance(const Vec3& p, int32_t* closest_triangle) const {
  const Bvh& bvh = impl_->bvh;
  double best2 = std::numeric_limits<double>::infinity();
  int32_t best = -1;
  if (bvh.nodes.empty()) return best2;
  // Depth-first, nearer child first, pruned by the best distance so far.
  int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = bvh.nodes[stack[--top]];
    if (detail::boxPointSquaredDistance(node.min(), node.max(), p) > best2) continue;
    if (node.leaf()) {
      for (int32_t i = node.first; i < node.first + node.count; ++i) {
        const TriRecord& t = bvh.tris[i];
        const double d2 = (closestPointOnTriangle(p, t.a, t.b, t.c) - p).squaredNorm();
        if (d2 < best2) {
          best2 = d2;
          best = i;
        }
      }
      continue;
    }
    const int32_t l = node.first, r = node.first + 1;
    const double dl = detail::boxPointSquaredDistance(bvh.nodes[l].min(), bvh.nodes[l].max(), p);
    const double dr = detail::boxPointSquaredDistance(bvh.nodes[r].min(), bvh.nodes[r].max(), p);
    if (dl <= dr) {
      stack[top++] = r;
      stack[top++] = l;
    } else {
      stack[top++] = l;
      stack[top++] = r;
    }
  }
  if (closest_triangle) *closest_triangle = best >= 0 ? bvh.original[best] : -1;
  return std::sqrt(best2);
}

Containment SolidIndex::classify(const Vec3& p) const {
  const Impl& im = *impl_;
  const double tol = im.tolerance;
  if ((p.array() < im.bounds.min.array() - tol).any() ||
      (p.array() > im.bounds.max.array() + tol).any())
    return Containment::kOutside;
  // On the surface: some triangle within tol (a ball query, far cheaper than the distance).
  bool near_surface = false;
  const double tol2 = tol * tol;
  im.bvh.traverse(
      [&](const Vec3& mn, const Vec3& mx) {
        return !near_surface && detail::boxPointSquaredDistance(mn, mx, p) <= tol2;
      },
      [&](int32_t i) {
        const TriRecord& t = im.bvh.tris[i];
        if (!near_surface && (closestPointOnTriangle(p, t.a, t.b, t.c) - p).squaredNorm() <= tol2)
          near_surface = true;
      });
  if (near_surface) return Containment::kBoundary;

  const double reach = 2.0 * im.bounds.diagonal() + (p - im.bounds.center()).norm();
  for (const Vec3& d : rayDirections()) {
    int winding = 0;
    if (detail::rayWinding(
            im.bvh, p, d, reach, [](const TriRecord&) { return true; }, &winding))
      return winding != 0 ? Containment::kInside : Containment::kOutside;
  }
  // Every direction grazed an edge: fall back to the exact winding number (p is off the
  // surface here, so it is an integer up to rounding).
  return windingNumber(*this, p) > 0.5 ? Containment::kInside : Containment::kOutside;
}

double windingNumber(const SolidIndex& index, const Vec3& p) {
  double total = 0.0;
  for (const TriRecord& t : index.impl().bvh.tris) total += triangleSolidAngle(t.a, t.b, t.c, p);
  return total / (4.0 * std::numbers::pi);
}

std::vector<double> SolidIndex::segmentCrossings(const Vec3& a, const Vec3& b) const {
  const Impl& im = *impl_;
  const Vec3 d = b - a;
  const Vec3 inv_d = d.cwiseInverse();
  std::vector<double> ts;
  im.bvh.traverse([&](const Vec3& mn, const Vec3& mx) { return rayHitsBox(a, inv_d, 1.0, mn, mx); },
                  [&](int32_t i) {
                    const double t = rayTriangleT(a, d, im.bvh.tris[i]);
                    if (t > 0.0 && t < 1.0) ts.push_back(t);
                  });
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

bool SolidIndex::raycast(const Vec3& o, const Vec3& d, double t_min, double t_max,
                         RayHit* hit) const {
  const Impl& im = *impl_;
  const Vec3 inv_d = d.cwiseInverse();
  double best = t_max;
  int32_t best_i = -1;
  im.bvh.traverse(
      [&](const Vec3& mn, const Vec3& mx) { return rayHitsBox(o, inv_d, best, mn, mx); },
      [&](int32_t i) {
        const double t = rayTriangleT(o, d, im.bvh.tris[i]);
        if (t > t_min && t <= best) {
          best = t;
          best_i = i;
        }
      });
  if (best_i < 0) return false;
  if (hit) {
    hit->t = best;
    hit->triangle = im.bvh.original[best_i];
    hit->normal = im.bvh.tris[best_i].n;
  }
  return true;
}

bool SolidIndex::occluded(const Vec3& o, const Vec3& d, double t_min, double t_max) const {
  const Impl& im = *impl_;
  const Vec3 inv_d = d.cwiseInverse();
  bool found = false;
  im.bvh.traverse(
      [&](const Vec3& mn, const Vec3& mx) { return !found && rayHitsBox(o, inv_d, t_max, mn, mx); },
      [&](int32_t i) {
        if (found) return;
        const double t = rayTriangleT(o, d, im.bvh.tris[i]);
        found = t > t_min && t <= t_max;
      });
  return found;
}

double SolidIndex::outsideLength(const Vec3& a, const Vec3& b) const {
  const std::vector<double> ts = segmentCrossings(a, b);
  const double len = (b - a).norm();
  double outside = 0.0;
  double prev = 0.0;
  for (size_t k = 0; k <= ts.size(); ++k) {
    const double next = k < ts.size() ? ts[k] : 1.0;
    if (next > prev) {
      const Vec3 mid = a + (0.5 * (prev + next)) * (b - a);
      if (classify(mid) == Containment::kOutside) outside += (next - prev) * len;
    }
    prev = next;
  }
  return outside;
}

std::vector<int32_t> trianglesNearBall(const SolidIndex& index, const Sphere& ball) {
  const SolidIndex::Impl& im = index.impl();
  const double r2 = ball.radius * ball.radius;
  std::vector<int32_t> out;
  im.bvh.traverse(
      [&](const Vec3& mn, const Vec3& mx) {
        return detail::boxPointSquaredDistance(mn, mx, ball.center) <= r2;
      },
      [&](int32_t i) {
        const TriRecord& t = im.bvh.tris[i];
        const Vec3 mn = t.a.cwiseMin(t.b).cwiseMin(t.c), mx = t.a.cwiseMax(t.b).cwiseMax(t.c);
        if (detail::boxPointSquaredDistance(mn, mx, ball.center) <= r2)
          out.push_back(im.bvh.original[i]);
      });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace sphereset

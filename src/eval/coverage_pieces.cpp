// The pieces of the coverage certificates (coverage_pieces.hpp): one rule for the full
// evaluation and the incremental certificate.
#include "eval/coverage_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "sphereset/cover.hpp"
#include "sphereset/limits.hpp"

namespace sphereset::detail {

Status checkSphereCount(size_t count) {
  if (count == 0) return Error{ErrorCode::kInvalidArgument, "no spheres to evaluate"};
  return limits::checkRange("spheres", static_cast<double>(count), 1, limits::kMaxSpheres);
}

Status checkSphere(const Sphere& s, size_t index) {
  if (!s.center.allFinite() || !(s.radius >= 0.0) || !std::isfinite(s.radius))
    return Error{ErrorCode::kInvalidArgument,
                 "sphere " + std::to_string(index) + " has a NaN, infinite or negative value"};
  return {};
}

Status checkSpheres(const std::vector<Sphere>& spheres) {
  if (Status st = checkSphereCount(spheres.size()); !st) return st;
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st = checkSphere(spheres[i], i); !st) return st;
  return {};
}

Sphere grownSphere(const Sphere& sphere, double diag) {
  return {sphere.center, sphere.radius + kCoverageToleranceRel * diag};
}

std::vector<Sphere> grownSpheres(const std::vector<Sphere>& spheres, double diag) {
  std::vector<Sphere> grown;
  grown.reserve(spheres.size());
  for (const Sphere& s : spheres) grown.push_back(grownSphere(s, diag));
  return grown;
}

namespace {

void coverTriangle(const SphereGrid& spheres, const Vec3& a, const Vec3& b, const Vec3& c,
                   int depth, int max_depth, PieceCover* st) {
  const Vec3 pts[3] = {a, b, c};
  if (oneSphereHolds(spheres, pts, 3)) return;
  const Vec3 g = (a + b + c) / 3.0;
  double gap = 0.0;
  for (const Vec3& p : {a, b, c, g}) gap = std::max(gap, gapToUnion(spheres, p));
  st->gap = std::max(st->gap, gap);
  if (gap > 0.0 && depth >= max_depth / 2) return;  // refuted; refine the gap a little only
  if (depth >= max_depth) {
    st->uncertified += 0.5 * (b - a).cross(c - a).norm();
    return;
  }
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  coverTriangle(spheres, a, ab, ca, depth + 1, max_depth, st);
  coverTriangle(spheres, ab, b, bc, depth + 1, max_depth, st);
  coverTriangle(spheres, ca, bc, c, depth + 1, max_depth, st);
  coverTriangle(spheres, ab, bc, ca, depth + 1, max_depth, st);
}

}  // namespace

PieceCover certifyTriangle(const SphereGrid& grown, const Vec3& a, const Vec3& b, const Vec3& c,
                           int max_depth) {
  PieceCover st;
  coverTriangle(grown, a, b, c, 0, max_depth, &st);
  return st;
}

PieceCover certifyTriangle(const SphereGrid& grown, const Mesh& mesh, size_t triangle,
                           int max_depth) {
  const auto& tri = mesh.triangles[triangle];
  return certifyTriangle(grown, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                         max_depth);
}

SurfaceCover summarizeSurface(std::span<const PieceCover> triangles, size_t spheres, double diag,
                              std::vector<int64_t>* uncovered_ids) {
  SurfaceCover c;
  if (uncovered_ids) uncovered_ids->clear();
  for (size_t t = 0; t < triangles.size(); ++t) {
    const PieceCover& s = triangles[t];
    c.max_gap = std::max(c.max_gap, s.gap);
    c.uncertified += s.uncertified;
    if (s.uncovered()) {
      ++c.uncovered;
      if (uncovered_ids) uncovered_ids->push_back(static_cast<int64_t>(t));
    }
  }
  c.max_gap /= diag;
  c.covered = spheres > 0 && c.uncovered == 0;
  return c;
}

InteriorCover summarizeInterior(std::span<const PieceCover> roots, size_t spheres, double diag,
                                bool surface_covered) {
  double gap = 0.0, unc = 0.0;
  for (const PieceCover& s : roots) {
    gap = std::max(gap, s.gap);
    unc += s.uncertified;
  }
  InteriorCover c;
  c.max_gap = gap / diag;
  c.uncertified_cells = static_cast<int64_t>(unc);
  c.covered = spheres > 0 && gap == 0.0 && surface_covered;
  return c;
}

}  // namespace sphereset::detail

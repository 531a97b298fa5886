// The pieces of the coverage certificates (coverage_pieces.hpp): one rule for the full
// evaluation and the incremental certificate.
#include "eval/coverage_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sphereset/cover.hpp"
#include "sphereset/limits.hpp"

namespace sphereset::detail {

// The evaluation's words for the one rule of sphere.hpp.
Status checkSphereCount(size_t count) { return sphereset::checkSphereCount(count, "evaluate"); }

Status checkSphere(const Sphere& s, size_t index) { return checkSphereValues(s, index); }

Status checkSpheres(const std::vector<Sphere>& spheres) {
  return checkSphereSet(spheres, "evaluate");
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

// Margin of the choice of spheres near a triangle, as a fraction of the magnitudes involved
// (coordinates, radii, reach): far above the relative rounding (~1e-16) of the distances
// compared, so the choice only ever keeps more spheres than it needs.
constexpr double kNearbyMarginRel = 1e-9;

// The spheres that can decide anything about the pieces of one triangle: every sphere that
// holds a point of it or is the nearest sphere to a point of it. With g the distance from the
// vertex a to the union and D the longest edge from a, the distance to the union is at most
// g + D anywhere on the triangle (it is 1-Lipschitz), so the nearest sphere to a point p is
// within g + D of p, hence within g + 2D of a; a sphere holding a point has distance <= 0.
// Tests against these spheres give exactly the answers of oneSphereHolds and gapToUnion over
// the whole set (the same expressions, a subset that holds every sphere that can win).
struct Nearby {
  const std::vector<Sphere>* spheres;
  std::vector<int32_t> ids;

  bool holds(const Vec3* pts, int n) const {
    for (int32_t i : ids) {
      const Sphere& s = (*spheres)[i];
      bool all = true;
      for (int k = 0; k < n && all; ++k) all = s.contains(pts[k]);
      if (all) return true;
    }
    return false;
  }
  double gap(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (int32_t i : ids) {
      const Sphere& s = (*spheres)[i];
      const double d = (p - s.center).norm() - s.radius;
      if (d <= 0.0) return 0.0;
      best = std::min(best, d);
    }
    return best;
  }
};

Nearby nearbySpheres(const SphereGrid& grid, const Vec3& a, const Vec3& b, const Vec3& c,
                     double gap_a) {
  Nearby near{&grid.spheres(), {}};
  const double reach = gap_a + 2.0 * std::max((b - a).norm(), (c - a).norm());
  const double magnitude = a.cwiseAbs().maxCoeff() + reach;
  grid.forEachWithin(a, reach + kNearbyMarginRel * magnitude, [&](int32_t i) {
    const Sphere& s = grid.spheres()[i];
    const double margin =
        kNearbyMarginRel * (magnitude + s.center.cwiseAbs().maxCoeff() + s.radius);
    const double distance = (a - s.center).norm();
    // Kept unless surely too far (a distance that overflows says nothing).
    if (!std::isfinite(distance) || !(distance - s.radius > reach + margin)) near.ids.push_back(i);
  });
  return near;
}

// The distance from a point to the union, computed once per point of the subdivision: a
// vertex is shared by the piece that made it and its children (NaN: not computed yet).
struct PointGap {
  Vec3 p;
  double gap = std::numeric_limits<double>::quiet_NaN();
  double get(const Nearby& near) {
    if (std::isnan(gap)) gap = near.gap(p);
    return gap;
  }
};

void coverTriangle(const Nearby& near, PointGap* a, PointGap* b, PointGap* c, int depth,
                   int max_depth, PieceCover* st) {
  const Vec3 pts[3] = {a->p, b->p, c->p};
  if (near.holds(pts, 3)) return;
  PointGap g{(a->p + b->p + c->p) / 3.0};
  double gap = 0.0;
  for (PointGap* q : {a, b, c, &g}) gap = std::max(gap, q->get(near));
  st->gap = std::max(st->gap, gap);
  if (gap > 0.0 && depth >= max_depth / 2) return;  // refuted; refine the gap a little only
  if (depth >= max_depth) {
    st->uncertified += 0.5 * (b->p - a->p).cross(c->p - a->p).norm();
    return;
  }
  PointGap ab{0.5 * (a->p + b->p)}, bc{0.5 * (b->p + c->p)}, ca{0.5 * (c->p + a->p)};
  coverTriangle(near, a, &ab, &ca, depth + 1, max_depth, st);
  coverTriangle(near, &ab, b, &bc, depth + 1, max_depth, st);
  coverTriangle(near, &ca, &bc, c, depth + 1, max_depth, st);
  coverTriangle(near, &ab, &bc, &ca, depth + 1, max_depth, st);
}

}  // namespace

PieceCover certifyTriangle(const SphereGrid& grown, const Vec3& a, const Vec3& b, const Vec3& c,
                           int max_depth) {
  PieceCover st;
  const Vec3 pts[3] = {a, b, c};
  // Most triangles lie in one sphere: one look at the grid settles them.
  if (grown.spheres().empty() || oneSphereHolds(grown, pts, 3)) {
    if (grown.spheres().empty()) st.gap = std::numeric_limits<double>::infinity();
    return st;
  }
  PointGap pa{a, gapToUnion(grown, a)}, pb{b}, pc{c};
  const Nearby near = nearbySpheres(grown, a, b, c, pa.gap);
  coverTriangle(near, &pa, &pb, &pc, 0, max_depth, &st);
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

// Protrusion of a sphere set from a solid: the largest distance from a point of the union of the
// balls to the solid (the one-sided Hausdorff distance from the union to the solid), with a
// guaranteed upper bound and a witness point (evaluate.hpp, sphereProtrusion).
//
// Reference: branch and bound over a Lipschitz function. d(x) = distance from x to the solid
// (0 inside) is 1-Lipschitz, so over a cube of half-diagonal h centred at q, d ≤ d(q) + h; when q
// is inside the solid at distance δ from its surface, d ≤ max(0, h - δ) (the cube's points
// within δ of q are inside). The union's protrusion is the largest of its balls', each found on
// its own: the cubes of an octree over the ball's bounding cube that meet the ball, the one of
// largest bound split first, until no bound exceeds the best value found at a cube centre in
// the ball by more than the tolerance. The maximum need not be on the sphere: a ball over a
// cavity protrudes most inside. A cube's centre takes its side of the surface (inside or out)
// from its parent's when it lies within the parent centre's distance to the surface (the ball of
// that radius misses the surface); only centres near the surface are classified by a ray: the
// same answers, for 0.62 of the time (spot.obj's curve, its 306 balls: 1.14 s against 1.83 s).
// When only the union's figure is wanted (ProtrusionOptions::union_only), every ball's seed
// directions are probed first and a ball is searched only while its bound exceeds the largest
// distance found on them, or `known` when larger: a bound below it cannot set the union's figure.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <queue>
#include <vector>

#include "cover/cover_cells.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {
namespace {

// sqrt(3): a cube of half-size s has half-diagonal s · kHalfDiagonal.
constexpr double kHalfDiagonal = 1.7320508075688772;
// Directions tried on the sphere before the search (axes, face diagonals, corners): a first
// witness, so that the search prunes from its start.
constexpr int kSeedDirections = 26;

// d at q, and the bound of d over the cube of half-diagonal h around q; q's distance to the
// surface and its side.
struct Probe {
  double d = 0.0, bound = 0.0, dist = 0.0;
  Containment where = Containment::kBoundary;
};

struct Cell {
  Vec3 centre;
  double half = 0.0;  // half the edge
  Probe probe;        // at the centre; probe.bound holds d over the cell
  bool operator<(const Cell& o) const { return probe.bound < o.probe.bound; }
};

// The probe at q, `gap` away from an earlier probe `near` (its side taken when the ball around it
// allows: detail::sideNear) or none.
Probe probe(const SolidIndex& solid, const Vec3& q, double h, const Probe* near = nullptr,
            double gap = 0.0) {
  Probe p;
  p.dist = solid.distance(q);
  p.where =
      near ? detail::sideNear(solid, q, p.dist, near->where, near->dist, gap) : solid.classify(q);
  if (p.where == Containment::kOutside) {
    p.d = p.dist;
    p.bound = p.dist + h;
  } else {
    p.bound = std::max(0.0, h - p.dist);
  }
  return p;
}

double cubeBallGap(const Vec3& centre, double half, const Sphere& s) {
  const Vec3 d = ((s.center - centre).cwiseAbs().array() - half).max(0.0).matrix();
  return d.norm() - s.radius;
}

// A ball's search before its octree: the centre's probe (kept as the root cell's) and the
// distances at its centre and kSeedDirections points of its sphere, a first witness.
struct Seeded {
  SphereProtrusionBound out;
  Probe root;
};

Seeded seedBall(const SolidIndex& solid, const Sphere& s) {
  Seeded r;
  SphereProtrusionBound& out = r.out;
  out.witness = s.center;
  r.root = probe(solid, s.center, s.radius * kHalfDiagonal);
  out.lower = r.root.d;  // 0 inside
  for (int i = 0; i < 27; ++i) {
    if (i == 13) continue;  // (0, 0, 0)
    const Vec3 u = Vec3(i % 3 - 1.0, (i / 3) % 3 - 1.0, i / 9 - 1.0).normalized();
    const Vec3 x = s.center + s.radius * u;
    const double d = probe(solid, x, 0.0, &r.root, s.radius).d;
    if (d > out.lower) out.lower = d, out.witness = x;
  }
  static_assert(kSeedDirections == 26);
  out.cells = 1;
  return r;
}

// The octree search of a seeded ball: cells are split while their bound exceeds both the best
// distance found by more than the tolerance and `settle` (ProtrusionOptions::union_only).
SphereProtrusionBound searchBall(const SolidIndex& solid, const Sphere& s, Seeded seeded,
                                 double tolerance, double settle, int64_t max_cells) {
  SphereProtrusionBound out = seeded.out;
  const auto enough = [&] { return std::max(out.lower + tolerance, settle); };
  std::priority_queue<Cell> open;
  double dropped = 0.0;  // the largest bound of a cell left unsplit because it was enough
  open.push({s.center, s.radius, seeded.root});
  while (!open.empty() && open.top().probe.bound > enough()) {
    if (out.cells >= max_cells) break;
    const Cell c = open.top();
    open.pop();
    const double half = 0.5 * c.half;
    for (int k = 0; k < 8; ++k) {
      const Vec3 q =
          c.centre + half * Vec3(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
      if (cubeBallGap(q, half, s) > 0.0) continue;  // no point of the ball
      const Probe p = probe(solid, q, half * kHalfDiagonal, &c.probe, half * kHalfDiagonal);
      ++out.cells;
      if ((q - s.center).norm() <= s.radius && p.d > out.lower) out.lower = p.d, out.witness = q;
      if (p.bound > enough())
        open.push({q, half, p});
      else
        dropped = std::max(dropped, p.bound);
    }
  }
  // Every cell is split, open, or dropped with its bound: the largest of these bounds holds d
  // over the whole ball.
  out.upper = std::max({out.lower, dropped, open.empty() ? 0.0 : open.top().probe.bound});
  out.converged = out.upper <= enough();
  return out;
}

}  // namespace

Expected<ProtrusionResult> sphereProtrusion(const SolidIndex& solid,
                                            const std::vector<Sphere>& spheres,
                                            const ProtrusionOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    return Error{ErrorCode::kInvalidArgument,
                 "protrusion tolerance must be a finite length above 0"};
  if (options.max_cells < 1)
    return Error{ErrorCode::kInvalidArgument, "protrusion cells must be at least 1"};
  if (!(options.known >= 0.0) || !std::isfinite(options.known))
    return Error{ErrorCode::kInvalidArgument,
                 "protrusion known: expected a finite length of at least 0"};
  for (size_t i = 0; i < spheres.size(); ++i)
    if (!spheres[i].center.allFinite() || !std::isfinite(spheres[i].radius) ||
        spheres[i].radius < 0.0)
      return Error{ErrorCode::kInvalidArgument,
                   "sphere " + std::to_string(i) + ": NaN, infinite or negative value"};
  std::vector<Seeded> seeded(spheres.size());
  tbb::parallel_for(size_t{0}, spheres.size(),
                    [&](size_t i) { seeded[i] = seedBall(solid, spheres[i]); });
  double settle = 0.0;
  if (options.union_only) {
    settle = options.known;
    for (const Seeded& b : seeded) settle = std::max(settle, b.out.lower);
  }
  ProtrusionResult r;
  r.spheres.resize(spheres.size());
  tbb::parallel_for(size_t{0}, spheres.size(), [&](size_t i) {
    r.spheres[i] =
        searchBall(solid, spheres[i], seeded[i], options.tolerance, settle, options.max_cells);
  });
  for (size_t i = 0; i < spheres.size(); ++i) {
    const SphereProtrusionBound& b = r.spheres[i];
    r.upper = std::max(r.upper, b.upper);
    if (r.sphere < 0 || b.lower > r.lower) {
      r.lower = b.lower;
      r.witness = b.witness;
      r.sphere = static_cast<int>(i);
    }
    r.cells += b.cells;
    r.converged = r.converged && b.converged;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace sphereset

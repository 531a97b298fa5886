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

SphereProtrusionBound oneSphere(const SolidIndex& solid, const Sphere& s, double tolerance,
                                int64_t max_cells) {
  SphereProtrusionBound out;
  out.witness = s.center;
  auto consider = [&](const Vec3& x, double d) {
    if (d > out.lower) {
      out.lower = d;
      out.witness = x;
    }
  };
  const double root_h = s.radius * kHalfDiagonal;
  const Probe root = probe(solid, s.center, root_h);
  consider(s.center, root.d);
  for (int i = 0; i < 27; ++i) {
    if (i == 13) continue;  // (0, 0, 0)
    const Vec3 u = Vec3(i % 3 - 1.0, (i / 3) % 3 - 1.0, i / 9 - 1.0).normalized();
    const Vec3 x = s.center + s.radius * u;
    consider(x, probe(solid, x, 0.0, &root, s.radius).d);
  }
  static_assert(kSeedDirections == 26);
  std::priority_queue<Cell> open;
  double dropped = 0.0;  // the largest bound of a cell left unsplit because of the tolerance
  open.push({s.center, s.radius, root});
  out.cells = 1;
  while (!open.empty() && open.top().probe.bound > out.lower + tolerance) {
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
      if ((q - s.center).norm() <= s.radius) consider(q, p.d);
      if (p.bound > out.lower + tolerance)
        open.push({q, half, p});
      else
        dropped = std::max(dropped, p.bound);
    }
  }
  // Every cell is split, open, or dropped with its bound: the largest of these bounds holds d
  // over the whole ball.
  out.upper = std::max({out.lower, dropped, open.empty() ? 0.0 : open.top().probe.bound});
  out.converged = out.upper <= out.lower + tolerance;
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
  for (size_t i = 0; i < spheres.size(); ++i)
    if (!spheres[i].center.allFinite() || !std::isfinite(spheres[i].radius) ||
        spheres[i].radius < 0.0)
      return Error{ErrorCode::kInvalidArgument,
                   "sphere " + std::to_string(i) + ": NaN, infinite or negative value"};
  ProtrusionResult r;
  r.spheres.resize(spheres.size());
  tbb::parallel_for(size_t{0}, spheres.size(), [&](size_t i) {
    r.spheres[i] = oneSphere(solid, spheres[i], options.tolerance, options.max_cells);
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

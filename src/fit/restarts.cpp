// Restarts (beyond the paper). Reference: Wang et al. 2006, Sec. 5 runs the clustering once
// from random seeds; its local minima vary a lot with the seed, so independent fits from
// derived seeds (sampling and seeding both change) buy quality for time. Either the best fit
// is kept, or n spheres are chosen among all the restarts' spheres (select.cpp) and end the fit
// as fit.cpp ends it: the surface bound, the shrinking passes, the interior bound.
#include "fit/restarts.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "fit/bound_refit.hpp"
#include "fit/fit_common.hpp"
#include "fit/optimal_radii.hpp"
#include "fit/samples.hpp"
#include "fit/select.hpp"
#include "fit/shrink.hpp"
#include "util/sampling.hpp"

namespace sphereset::detail {
namespace {

// Branch-and-bound nodes of the selection's ILP (a node limit, not a time limit, so that the
// result does not depend on the machine's load).
constexpr int kSelectionNodes = 2000;

// The selection among `pool` (the restarts' spheres; `start`: the best restart's, as indices)
// ended as a fit ends. Replaces best's spheres when the result has less outside volume than
// best->energy (before padding). Adds its queries and passes to *best. Returns the seconds of
// its optimal-radii program (FitOptions::optimal_radii), whether or not it replaced best's.
double selectAmongRestarts(const SolidIndex& index, const FitOptions& o,
                           const std::vector<Sphere>& pool, const std::vector<int32_t>& group_of,
                           const std::vector<int32_t>& start, FitResult* best) {
  const int n = o.num_spheres;
  const PointSet ps = samplePoints(index, fitTargetPoints(o), o.interior_share, o.seed);
  const double min_edge = boundMinEdge(index, ps);
  const std::vector<Vec3> interior(ps.points.begin(), ps.points.begin() + ps.interior);
  const CoverProblem problem = coverProblem(index, pool, group_of, interior, min_edge);
  const Selection sel = selectCover(problem, n, start, kSelectionNodes);
  if (sel.chosen.empty()) return 0.0;
  std::vector<Sphere> sp;
  for (int32_t c : sel.chosen) sp.push_back(pool[c]);
  FitResult res = *best;
  BoundStats bs = boundSurface(index, &sp, min_edge);
  res.bounding_queries += bs.queries;
  if (o.shrink_passes > 0) shrinkPasses(index, ps, min_edge, o, &sp, &bs, &res);
  res.radii = {};  // the restart's program does not apply to the selection
  const double radii_before = res.seconds.radii;
  if (o.optimal_radii) runOptimalRadii(index, interior, min_edge, &sp, &res);
  const double radii_seconds = res.seconds.radii - radii_before;
  res.bounding_enlarged = bs.enlarged;
  boundInteriorPasses(index, &sp, &res);
  if (o.original) boundSurface(index, &sp, min_edge, nullptr, o.original);
  const std::vector<double> sov = outsideVolumes(index, sp);
  if (!(totalOf(sov) < best->energy)) return radii_seconds;
  res.spheres = std::move(sp);
  res.outside_volume = sov;
  res.energy = totalOf(sov);
  *best = std::move(res);
  return radii_seconds;
}

}  // namespace

uint64_t restartSeed(uint64_t seed, int r) { return r == 0 ? seed : mixSeed(seed, 7000 + r); }

Expected<FitResult> fitWithRestarts(const SolidIndex& index, const FitOptions& o) {
  const auto t0 = FitClock::now();
  FitOptions one = o;
  one.restarts = 1;
  // Padding goes on after the selection, when there is one.
  if (o.select_among_restarts) one.padding = 0.0;
  Expected<FitResult> best = Error{ErrorCode::kInvalidArgument, "no restart ran"};
  FitTimings sum;
  int64_t queries = 0, culled = 0, optimizer = 0;
  std::vector<Sphere> pool;
  std::vector<int32_t> start, group_of;
  for (int r = 0; r < o.restarts; ++r) {
    one.seed = restartSeed(o.seed, r);
    auto f = fitSpheres(index, one);
    if (!f) return f;
    addTimings(f->seconds, &sum);
    queries += f->sov_queries;
    culled += f->sov_queries_culled;
    optimizer += f->optimizer_queries;
    if (o.select_among_restarts) {
      const int32_t first = static_cast<int32_t>(pool.size());
      if (!best || f->energy < best->energy) {
        start.resize(f->spheres.size());
        for (size_t i = 0; i < start.size(); ++i) start[i] = first + static_cast<int32_t>(i);
      }
      pool.insert(pool.end(), f->spheres.begin(), f->spheres.end());
      group_of.resize(pool.size(), r);
    }
    if (!best || f->energy < best->energy) {
      best = std::move(f);
      best->restart = r;
    }
  }
  if (o.select_among_restarts) {
    const auto ts = FitClock::now();
    sum.radii += selectAmongRestarts(index, o, pool, group_of, start, &*best);
    for (Sphere& s : best->spheres) s.radius += o.padding;
    best->outside_volume = outsideVolumes(index, best->spheres);
    best->energy = totalOf(best->outside_volume);
    sum.bounding += secondsSince(ts);
  }
  best->seconds = sum;
  best->seconds.total = secondsSince(t0);
  best->sov_queries = queries;
  best->sov_queries_culled = culled;
  best->optimizer_queries = optimizer;
  return best;
}

}  // namespace sphereset::detail

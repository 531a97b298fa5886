// Restarts (beyond the paper). Reference: Wang et al. 2006, Sec. 5 runs the clustering once
// from random seeds; its local minima vary a lot with the seed, so independent fits from
// derived seeds (sampling and seeding both change) buy quality for time.
#include "fit/restarts.hpp"

#include <utility>

#include "fit/fit_common.hpp"
#include "util/sampling.hpp"

namespace sphereset::detail {

uint64_t restartSeed(uint64_t seed, int r) { return r == 0 ? seed : mixSeed(seed, 7000 + r); }

Expected<FitResult> fitWithRestarts(const SolidIndex& index, const FitOptions& o) {
  const auto t0 = FitClock::now();
  FitOptions one = o;
  one.restarts = 1;
  Expected<FitResult> best = Error{ErrorCode::kInvalidArgument, "no restart ran"};
  FitTimings sum;
  int64_t queries = 0, culled = 0, optimizer = 0;
  for (int r = 0; r < o.restarts; ++r) {
    one.seed = restartSeed(o.seed, r);
    auto f = fitSpheres(index, one);
    if (!f) return f;
    sum.sampling += f->seconds.sampling;
    sum.assignment += f->seconds.assignment;
    sum.update += f->seconds.update;
    sum.teleport += f->seconds.teleport;
    sum.bounding += f->seconds.bounding;
    queries += f->sov_queries;
    culled += f->sov_queries_culled;
    optimizer += f->optimizer_queries;
    if (!best || f->energy < best->energy) {
      best = std::move(f);
      best->restart = r;
    }
  }
  best->seconds = sum;
  best->seconds.total = secondsSince(t0);
  best->sov_queries = queries;
  best->sov_queries_culled = culled;
  best->optimizer_queries = optimizer;
  return best;
}

}  // namespace sphereset::detail

// The variational sphere-set fit. Reference: Wang et al. 2006, Sec. 5 ("Minimizing Outside
// Volume"), minimising the energy of Sec. 3 (the sum over the spheres of their outside volume,
// Eq. 2). The pipeline, one file per phase:
//   samples.cpp        preprocessing: interior grid points and surface samples (Sec. 5)
//   seeding.cpp        initial centres (Sec. 5)
//   decimate.cpp       optional: more spheres first, the cheapest removed (beyond the paper)
//   lloyd.cpp          the clustering rounds (Sec. 5): point assignment (cluster_assign.cpp)
//                      and sphere update (sphere_update.cpp, Eq. 5), with teleports
//                      (teleport.cpp)
//   bound_refit.cpp    the guaranteed bound (bound.cpp; Sec. 5, footnote 1) with refits
//   shrink.cpp         shrinking passes after the bound (beyond the paper)
//   restarts.cpp       independent fits, the best kept (beyond the paper)
// The comparison methods (baselines.cpp) share the points and the bounding step.
//
// Deviations from the paper are explained in the file of their phase: farthest-point seeding
// by default; the best spheres of all rounds are kept, since an assignment round can raise the
// error; teleports are chosen by predicted gain instead of overlap ratio and outside volume,
// and judged after a few rounds instead of one; optional decimation; the bound covers the
// whole surface exactly instead of sampled points; after the bound, shrinking passes refit
// each sphere around what it alone covers and move spheres that cover nothing alone to split
// the largest ones, which recovers much of what the bounding step costs.
#include "sphereset/fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "fit/baselines.hpp"
#include "fit/decimate.hpp"
#include "fit/fit_common.hpp"
#include "fit/finish.hpp"
#include "fit/restarts.hpp"
#include "fit/samples.hpp"
#include "fit/seeding.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

// The comparison methods: their clusters and minimal balls (no cluster points are kept).
detail::Clustering baselineClusters(const SolidIndex& index, const detail::PointSet& ps, int n,
                                    const FitOptions& o, FitResult* res) {
  const auto ta = detail::FitClock::now();
  detail::BaselineResult b =
      o.method == FitMethod::kOctree
          ? detail::octreeSpheres(ps, n)
          : detail::kmeansSpheres(ps, detail::initialCentres(ps, n, o.init, o.seed),
                                  o.max_iterations);
  res->seconds.assignment += detail::secondsSince(ta);
  res->iterations = b.iterations;
  detail::Clustering c;
  c.converged = b.converged;
  c.spheres = std::move(b.spheres);
  c.energy = detail::totalOf(detail::outsideVolumes(index, c.spheres));
  res->energy_history.push_back(c.energy);
  c.members.assign(c.spheres.size(), {});
  return c;
}

}  // namespace

Expected<FitResult> fitSpheres(const SolidIndex& index, const FitOptions& o) {
  if (Status st = detail::checkFitOptions(index, o); !st) return st.error();
  if (o.restarts > 1) return detail::fitWithRestarts(index, o);
  const auto t0 = detail::FitClock::now();
  FitResult res;
  const int n = o.num_spheres;
  detail::ProgressScope scope(o, t0);
  auto report = [&](const std::string& phase, int it, double e) { scope.report(phase, it, e); };

  // Preprocessing (paper Sec. 5): the points to cluster.
  report("sampling", 0, 0.0);
  const detail::PointSet ps =
      detail::samplePoints(index, detail::fitTargetPoints(o), o.interior_share, o.seed);
  res.points = static_cast<int64_t>(ps.points.size());
  res.interior_points = ps.interior;
  res.seconds.sampling = detail::secondsSince(t0);
  if (res.points < n)
    return Error{ErrorCode::kInvalidArgument,
                 "asked for " + std::to_string(n) + " spheres but only " +
                     std::to_string(res.points) + " points were sampled (raise --points)"};

  // Clustering: the variational method (paper Sec. 5) or a baseline.
  const bool variational = o.method == FitMethod::kVariational;
  detail::Clustering best;
  if (variational) {
    const auto progress = [&](int it, double e) { report("clustering", it, e); };
    best = detail::clusterWithDecimation(index, ps, n, o, &res, progress);
  } else {
    report("clustering", 0, 0.0);
    best = baselineClusters(index, ps, n, o, &res);
  }
  res.converged = best.converged;
  if (best.spheres.empty())
    return Error{ErrorCode::kInvalidArgument,
                 "could not place " + std::to_string(n) + " non-empty clusters"};
  res.energy_before_bounding = best.energy;

  // Guaranteed bounding of the surface (paper Sec. 5, footnote 1). Interior and surface points
  // are already inside the sphere of their cluster (each radius encloses its points).
  report("bounding", res.iterations, best.energy);
  const auto tb = detail::FitClock::now();
  detail::finishFit(index, ps, o, &best, &res);
  res.seconds.bounding = detail::secondsSince(tb);
  res.seconds.total = detail::secondsSince(t0);
  report("done", res.iterations, res.energy);
  return res;
}

}  // namespace sphereset

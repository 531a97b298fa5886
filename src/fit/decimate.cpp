// Decimation (beyond the paper). Reference: Wang et al. 2006, Sec. 5 clusters n spheres from
// n seeds; teleportation (Sec. 5, "Sphere Teleportation") only moves spheres. Here, with
// o.decimation > 0, the clustering starts with n + extra spheres and removes the cheapest ones
// in kDecimationSteps batches, clustering again after each: a removal also lets the others
// settle around the gap, which finds lower minima when n is small. The cost of a removal is
// the upper bound of teleport.cpp (its points join the spheres they stick out of least).
#include "fit/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fit/fit_common.hpp"
#include "fit/seeding.hpp"
#include "fit/teleport.hpp"

namespace sphereset::detail {
namespace {

// Batches in which the extra spheres of the decimation are removed, and teleports in a row
// that may fail before the clustering of an intermediate count is taken as settled.
constexpr int kDecimationSteps = 8;
constexpr int kDecimationFailedTeleports = 1;

// Removes up to `batch` spheres of the clustering, cheapest removals first (ties: lower
// index); a sphere is skipped if it or a sphere that would take its points is already
// involved in a removal. Returns the centres of the spheres kept, in index order.
std::vector<Vec3> removeCheapest(const SolidIndex& index, const Clustering& c, int batch,
                                 FitResult* res) {
  const int m = static_cast<int>(c.spheres.size());
  const auto tt = FitClock::now();
  std::vector<int64_t> q(m, 0);
  std::vector<std::vector<int>> takers;
  const std::vector<double> cost =
      removalCosts(index, c.spheres, c.members, outsideVolumes(index, c.spheres), &q, &takers);
  res->optimizer_queries += std::accumulate(q.begin(), q.end(), int64_t{0}) + m;
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] < cost[b]; });
  std::vector<char> gone(m, 0), involved(m, 0);
  int removed = 0;
  for (int i : order) {
    if (removed == batch) break;
    bool free = !involved[i];
    for (int j : takers[i]) free = free && !involved[j];
    if (!free) continue;
    gone[i] = involved[i] = 1;
    for (int j : takers[i]) involved[j] = 1;
    ++removed;
  }
  std::vector<Vec3> centres;
  for (int i = 0; i < m; ++i)
    if (!gone[i]) centres.push_back(c.spheres[i].center);
  res->decimated += removed;
  res->seconds.teleport += secondsSince(tt);
  return centres;
}

}  // namespace

Clustering clusterWithDecimation(const SolidIndex& index, const PointSet& ps, int n,
                                 const FitOptions& o, FitResult* res,
                                 const std::function<void(int, double)>& progress) {
  const int64_t points = static_cast<int64_t>(ps.points.size());
  const int extra = static_cast<int>(
      std::min<int64_t>(std::llround(o.decimation * static_cast<double>(n)), points - n));
  const int batch = std::max(1, (extra + kDecimationSteps - 1) / kDecimationSteps);
  int m = n + extra;
  std::vector<Vec3> centres = initialCentres(ps, m, o.init, o.seed);
  for (;;) {
    Clustering c =
        clusterPoints(index, ps, centres, o,
                      m > n ? kDecimationFailedTeleports : o.max_failed_teleports, res, progress);
    if (m > n && c.spheres.empty()) {
      // No round gave every one of the m clusters a point: start over with n.
      m = n;
      centres = initialCentres(ps, n, o.init, o.seed);
      continue;
    }
    if (m == n) return c;
    centres = removeCheapest(index, c, std::min(batch, m - n), res);
    m = static_cast<int>(centres.size());
  }
}

}  // namespace sphereset::detail

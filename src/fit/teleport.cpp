// Sphere teleportation. Reference: Wang et al. 2006, Sec. 5, "Sphere Teleportation": when the
// error stops improving, a source sphere is deleted and a destination sphere split in two,
// starting from "the two points farthest from each other" in its cluster.
//
// Deviation in the choice of the move: the paper takes the sphere of largest overlap ratio as
// the source and the sphere of largest outside volume as the destination. Here every
// sphere's gain from being split is measured (its points split by 2-means from the farthest
// pair, both halves refitted as in the sphere update, Eq. 5) and every sphere's cost of removal
// is bounded from above (its points join the spheres they stick out of least, which grow about
// fixed centres); pairs are ranked by gain minus cost. The removal costs also rank the
// decimation's removals (decimate.cpp).
#include "fit/teleport.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "cover/sphere_grid.hpp"
#include "fit/fit_common.hpp"
#include "fit/sphere_update.hpp"

namespace sphereset::detail {
namespace {

// 2-means rounds when a cluster is split in two.
constexpr int kSplitRounds = 5;
// Spheres whose split is evaluated together when ranking teleports.
constexpr int kSplitBatch = 8;

}  // namespace

void splitTwoMeans(const std::vector<Vec3>& pts, std::vector<Vec3>* a, std::vector<Vec3>* b) {
  Vec3 ca = farthestFrom(pts, centroid(pts)), cb = farthestFrom(pts, ca);
  for (int it = 0; it < kSplitRounds; ++it) {
    a->clear();
    b->clear();
    for (const Vec3& p : pts)
      ((p - ca).squaredNorm() <= (p - cb).squaredNorm() ? a : b)->push_back(p);
    if (a->empty() || b->empty()) return;
    ca = centroid(*a);
    cb = centroid(*b);
  }
}

std::vector<double> removalCosts(const SolidIndex& index, const std::vector<Sphere>& sp,
                                 const std::vector<std::vector<Vec3>>& members,
                                 const std::vector<double>& sov, std::vector<int64_t>* q,
                                 std::vector<std::vector<int>>* receivers) {
  const int n = static_cast<int>(sp.size());
  std::vector<double> cost(n);
  if (receivers) receivers->assign(n, {});
  const SphereGrid grid(sp);
  tbb::parallel_for(0, n, [&](int i) {
    pollCancel();
    std::vector<double> grown(n, 0.0);
    for (const Vec3& p : members[i]) {
      std::pair<double, int32_t> least[2];
      const int m = leastGrowth(grid, &p, 1, 2, least);
      const int k = least[0].second == i ? 1 : 0;
      if (k < m) grown[least[k].second] = std::max(grown[least[k].second], least[k].first);
    }
    double c = -sov[i];
    for (int j = 0; j < n; ++j)
      if (grown[j] > 0.0) {
        c += index.outsideVolume({sp[j].center, sp[j].radius + grown[j]}).volume - sov[j];
        ++(*q)[i];
        if (receivers) (*receivers)[i].push_back(j);
      }
    cost[i] = c;
  });
  return cost;
}

std::optional<TeleportMove> bestTeleport(const SolidIndex& index, const std::vector<Sphere>& sp,
                                         const std::vector<std::vector<Vec3>>& members,
                                         const std::vector<double>& sov, SphereOptimizer optimizer,
                                         int evaluations,
                                         const std::vector<std::pair<int, int>>& tried,
                                         std::vector<SplitCache>* cache, int64_t* queries) {
  const int n = static_cast<int>(sp.size());
  std::vector<double> gain(n, -std::numeric_limits<double>::infinity());
  cache->resize(n);
  std::vector<int64_t> q(n, 0);
  const std::vector<double> cost = removalCosts(index, sp, members, sov, &q, nullptr);
  // Split gains, in decreasing order of outside volume (a sphere cannot gain more than its
  // own), in fixed batches until no remaining sphere can beat the (tried + 1) best gains.
  std::vector<int> by_sov(n);
  std::iota(by_sov.begin(), by_sov.end(), 0);
  std::stable_sort(by_sov.begin(), by_sov.end(), [&](int a, int b) { return sov[a] > sov[b]; });
  std::vector<double> found;
  for (int first = 0; first < n; first += kSplitBatch) {
    if (found.size() > tried.size()) {
      const auto kth = found.begin() + static_cast<ptrdiff_t>(tried.size());
      std::nth_element(found.begin(), kth, found.end(), std::greater<>());
      if (sov[by_sov[first]] <= *kth) break;
    }
    const int last = std::min(n, first + kSplitBatch);
    tbb::parallel_for(first, last, [&](int k) {
      pollCancel();
      const int i = by_sov[k];
      SplitCache& sc = (*cache)[i];
      if (sc.members != members[i]) {
        sc.members = members[i];
        sc.valid = false;
        // The paper's split (Sec. 5): two centres from the farthest pair of the cluster.
        std::vector<Vec3> a, b;
        if (members[i].size() >= 2) splitTwoMeans(members[i], &a, &b);
        if (!a.empty() && !b.empty()) {
          const SphereUpdate ua = updateSphere(index, a, centroid(a), optimizer, evaluations);
          const SphereUpdate ub = updateSphere(index, b, centroid(b), optimizer, evaluations);
          sc.valid = true;
          sc.halves_sov = ua.sov + ub.sov;
          sc.ca = ua.sphere.center;
          sc.cb = ub.sphere.center;
          q[i] += ua.queries + ub.queries;
        }
      }
      if (sc.valid) gain[i] = sov[i] - sc.halves_sov;
    });
    for (int k = first; k < last; ++k)
      if (std::isfinite(gain[by_sov[k]])) found.push_back(gain[by_sov[k]]);
  }
  for (int i = 0; i < n; ++i) *queries += q[i];
  std::optional<TeleportMove> best;
  for (int d = 0; d < n; ++d) {
    if (!std::isfinite(gain[d])) continue;
    for (int s = 0; s < n; ++s) {
      if (s == d || (best && gain[d] - cost[s] <= best->predicted)) continue;
      if (std::find(tried.begin(), tried.end(), std::make_pair(s, d)) != tried.end()) continue;
      best = TeleportMove{s, d, (*cache)[d].cb, (*cache)[d].ca, gain[d] - cost[s]};
    }
  }
  return best;
}

}  // namespace sphereset::detail

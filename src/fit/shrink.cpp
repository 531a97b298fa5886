// Shrinking after the bound (beyond the paper). Reference: Wang et al. 2006, Sec. 5: the
// paper's bounding post-process (footnote 1) only enlarges spheres, without looking at their
// neighbours. Here each sphere is refitted (the sphere update, Eq. 5) around what it alone
// covers (the surface pieces and interior points no other sphere holds), which keeps the bound
// except where two neighbours both let go of a shared piece; a bounding pass repairs that.
// Spheres that cover nothing alone are teleported (Sec. 5, "Sphere Teleportation") to split
// the spheres of largest outside volume. A pass is kept only if it lowers the total outside
// volume; it recovers much of what the bounding step costs.
#include "fit/shrink.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "fit/fit_common.hpp"
#include "fit/sphere_update.hpp"
#include "fit/teleport.hpp"

namespace sphereset::detail {
namespace {

// Each sphere that covers something alone, refitted around that.
std::vector<Sphere> refitOwned(const SolidIndex& index, const std::vector<Sphere>& sp,
                               const std::vector<std::vector<Vec3>>& owned, const FitOptions& o) {
  const int n = static_cast<int>(sp.size());
  std::vector<Sphere> shrunk = sp;
  tbb::parallel_for(0, n, [&](int i) {
    if (owned[i].empty()) return;
    const SphereUpdate u =
        updateSphere(index, owned[i], shrunk[i].center, o.optimizer, o.optimizer_evaluations);
    shrunk[i] = u.sphere;
  });
  return shrunk;
}

// The spheres `idle` (which cover nothing alone) moved to split the spheres of largest outside
// volume in `shrunk`, each in two along the points it alone covers (those with at least two).
std::vector<Sphere> moveIdle(const SolidIndex& index, const std::vector<Sphere>& shrunk,
                             const std::vector<std::vector<Vec3>>& owned,
                             const std::vector<int>& idle, const FitOptions& o) {
  const int n = static_cast<int>(shrunk.size());
  std::vector<int> by_sov(n);
  const std::vector<double> sov = outsideVolumes(index, shrunk);
  std::iota(by_sov.begin(), by_sov.end(), 0);
  std::stable_sort(by_sov.begin(), by_sov.end(), [&](int a, int b) { return sov[a] > sov[b]; });
  std::vector<std::pair<int, int>> moves;  // (idle sphere, split sphere)
  for (int k = 0, d = 0; k < static_cast<int>(idle.size()) && d < n; ++d)
    if (owned[by_sov[d]].size() >= 2) moves.emplace_back(idle[k++], by_sov[d]);
  std::vector<Sphere> moved = shrunk;
  tbb::parallel_for(size_t{0}, moves.size(), [&](size_t m) {
    const auto [i, j] = moves[m];
    std::vector<Vec3> a, b;
    splitTwoMeans(owned[j], &a, &b);
    if (a.empty() || b.empty()) return;
    moved[j] = updateSphere(index, a, centroid(a), o.optimizer, o.optimizer_evaluations).sphere;
    moved[i] = updateSphere(index, b, centroid(b), o.optimizer, o.optimizer_evaluations).sphere;
  });
  return moved;
}

}  // namespace

void shrinkPasses(const SolidIndex& index, const PointSet& ps, double min_edge, const FitOptions& o,
                  std::vector<Sphere>* sp, BoundStats* bs, FitResult* res) {
  const int n = static_cast<int>(sp->size());
  const std::vector<Vec3> interior(ps.points.begin(), ps.points.begin() + ps.interior);
  double current = totalOf(outsideVolumes(index, *sp));
  for (int pass = 0; pass < o.shrink_passes; ++pass) {
    const auto owned = soleCover(index, *sp, interior, min_edge);
    std::vector<std::vector<Sphere>> cands{refitOwned(index, *sp, owned, o)};
    std::vector<int> idle;
    for (int i = 0; i < n; ++i)
      if (owned[i].empty()) idle.push_back(i);
    if (!idle.empty()) cands.push_back(moveIdle(index, cands[0], owned, idle, o));
    // Repair the bound of each candidate and keep the best, if it beats the current set.
    int pick = -1;
    double e_pick = current;
    BoundStats b_pick;
    for (size_t c = 0; c < cands.size(); ++c) {
      const BoundStats b = boundSurface(index, &cands[c], min_edge, nullptr);
      res->bounding_queries += b.queries;
      const double e = totalOf(outsideVolumes(index, cands[c]));
      if (e < e_pick) {
        e_pick = e;
        pick = static_cast<int>(c);
        b_pick = b;
      }
    }
    if (pick < 0) break;
    ++res->shrink_passes;
    if (pick == 1) res->idle_teleports += static_cast<int>(idle.size());
    const bool small_gain = e_pick > current * (1.0 - o.tolerance);
    current = e_pick;
    *sp = std::move(cands[pick]);
    *bs = b_pick;
    if (small_gain && pick == 0) break;
  }
}

}  // namespace sphereset::detail

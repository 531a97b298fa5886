// Preparation of the point assignment's fill. Reference: Wang et al. 2006, Sec. 5, "Point
// Assignment": "we compute lower bounds on outside volume increase for assigning p to each
// cluster C_i" from its table of radius -> SOV, and clusters are examined in increasing order
// of that bound. Here the per-point scan over all clusters (distances, bounds, the short list
// of smallest bounds) is done for batches of queued points in parallel (beyond the paper); the
// decisions stay sequential (cluster_assign.cpp). Most points of a round are already inside
// some sphere when the fill reaches them, and the rule then wants the nearest such centre: a
// grid of the centres (centre_grid.hpp) finds it among the few centres near the point.
#include "fit/assign_prepare.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "fit/fit_common.hpp"

namespace sphereset::detail {
namespace {

// The first ball searched for a holder has at least this fraction of the largest radius.
constexpr double kFirstReachRel = 1.0 / 64.0;

// The nearest centre whose sphere holds x (ties: the lower index), or -1 if none does; no
// sphere is larger than max_radius. Once some sphere holds x, only centres at most that far
// can be nearer, and the grid lists those; the first holder is looked for among the clusters
// of x's labelled neighbours, then in balls of doubling size about x.
int32_t nearestHolder(const std::vector<Cluster>& cl, const CentreGrid& grid, const PointSet& ps,
                      const std::vector<int32_t>& labels, int64_t p, double max_radius,
                      double* dist) {
  const Vec3& x = ps.points[p];
  int32_t h = -1;
  double dh = std::numeric_limits<double>::infinity();
  auto consider = [&](int32_t ci) {
    const double d = (x - cl[ci].center).norm();
    if (d <= cl[ci].radius && (d < dh || (d == dh && ci < h))) {
      h = ci;
      dh = d;
    }
  };
  for (int32_t k = ps.adj_start[p]; k < ps.adj_start[p + 1]; ++k)
    if (labels[ps.adj[k]] >= 0) consider(labels[ps.adj[k]]);
  for (double reach = std::max(grid.cell(), kFirstReachRel * max_radius); h < 0; reach *= 2.0) {
    grid.forEachWithin(x, reach, consider);
    if (reach >= max_radius) break;
  }
  if (h < 0) return -1;
  grid.forEachWithin(x, dh, consider);
  *dist = dh;
  return h;
}

void prepare(const std::vector<Cluster>& cl, const CentreGrid* grid, double max_radius,
             const PointSet& ps, const std::vector<int32_t>& labels, int64_t p, Scratch* s,
             Prepared* pr) {
  if (grid) {
    pr->inside = nearestHolder(cl, *grid, ps, labels, p, max_radius, &pr->inside_dist);
    if (pr->inside >= 0) return;
  }
  const Vec3& x = ps.points[p];
  const int32_t nc = static_cast<int32_t>(cl.size());
  s->dist.resize(nc);
  for (int32_t ci = 0; ci < nc; ++ci) {
    s->dist[ci] = (x - cl[ci].center).norm();
    if (s->dist[ci] <= cl[ci].radius && (pr->inside < 0 || s->dist[ci] < s->dist[pr->inside]))
      pr->inside = ci;
  }
  if (pr->inside >= 0) {
    pr->inside_dist = s->dist[pr->inside];
    return;
  }
  // The kShortList first clusters in examination order (increasing bound, distance, index),
  // kept sorted in one pass; whatever is not kept lowers rest_bound.
  auto before = [](double b0, double d0, int32_t i0, double b1, double d1, int32_t i1) {
    return b0 < b1 || (b0 == b1 && (d0 < d1 || (d0 == d1 && i0 < i1)));
  };
  int& m = pr->count;
  for (int32_t ci = 0; ci < nc; ++ci) {
    const double b = increaseBound(cl[ci], s->dist[ci]), d = s->dist[ci];
    if (m == kShortList) {
      if (!before(b, d, ci, pr->bound[m - 1], pr->dist[m - 1], pr->cluster[m - 1])) {
        pr->rest_bound = std::min(pr->rest_bound, b);
        continue;
      }
      pr->rest_bound = std::min(pr->rest_bound, pr->bound[m - 1]);
      --m;
    }
    int k = m++;
    for (; k > 0 && before(b, d, ci, pr->bound[k - 1], pr->dist[k - 1], pr->cluster[k - 1]); --k) {
      pr->bound[k] = pr->bound[k - 1];
      pr->dist[k] = pr->dist[k - 1];
      pr->cluster[k] = pr->cluster[k - 1];
    }
    pr->bound[k] = b;
    pr->dist[k] = d;
    pr->cluster[k] = ci;
  }
}

}  // namespace

void prepareBatch(const std::vector<Cluster>& cl, const CentreGrid* grid, const PointSet& ps,
                  const std::vector<int32_t>& labels, const std::vector<int32_t>& batch,
                  std::vector<Prepared>* prepared, Scratch* serial) {
  prepared->assign(batch.size(), Prepared{});
  double max_radius = 0.0;
  if (grid)
    for (const Cluster& c : cl) max_radius = std::max(max_radius, c.radius);
  if (batch.size() == 1) {
    prepare(cl, grid, max_radius, ps, labels, batch[0], serial, &(*prepared)[0]);
  } else {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, batch.size()), [&](const tbb::blocked_range<size_t>& r) {
          Scratch local;
          for (size_t k = r.begin(); k < r.end(); ++k) {
            pollCancel();
            prepare(cl, grid, max_radius, ps, labels, batch[k], &local, &(*prepared)[k]);
          }
        });
  }
}

}  // namespace sphereset::detail

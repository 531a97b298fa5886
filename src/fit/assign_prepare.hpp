// Private: the preparation of the point assignment's fill (cluster_assign.cpp): the lower
// bounds of the outside-volume increase from each cluster's table (paper Sec. 5, the
// acceleration of "Point Assignment"), and batches of queued points scanned in parallel
// against the clusters.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

#include "fit/centre_grid.hpp"
#include "fit/cluster_assign.hpp"

namespace sphereset::detail {

// Lower bound of SOV(c.center, radius): the tabulated value at the largest radius not above
// `radius` (the outside volume never decreases with the radius).
inline double lowerBoundSov(const Cluster& c, double radius) {
  // Far points are usually beyond the table.
  if (!c.table.empty() && radius >= c.table.back().first) return c.table.back().second;
  auto it =
      std::upper_bound(c.table.begin(), c.table.end(), radius,
                       [](double r, const std::pair<double, double>& e) { return r < e.first; });
  return it == c.table.begin() ? 0.0 : std::prev(it)->second;
}

// Lower bound of the outside-volume increase when cluster c grows to `radius`.
inline double increaseBound(const Cluster& c, double radius) {
  return std::max(0.0, lowerBoundSov(c, radius) - c.sov);
}

// Points of the fill prepared together, in parallel, against the clusters as they were when
// the batch began: distances, whether a sphere already holds the point, and the clusters of
// smallest lower bound. The decisions are then made in queue order with the tables and radii
// of that moment, so the labels are the sequential fill's whatever the batch size; only the
// O(clusters) scan per point runs in parallel (outside-volume queries are made when a point is
// decided, where the latest tables cull best). A function of the cluster count only.
constexpr int32_t kParallelClusters = 64;
constexpr size_t kMaxBatch = 128;
constexpr int kShortList = 8;  // clusters of smallest lower bound kept per prepared point
inline size_t batchSize(int32_t nc) {
  return nc < kParallelClusters ? 1 : std::min<size_t>(kMaxBatch, static_cast<size_t>(nc) / 8);
}

struct Prepared {
  int32_t inside = -1;  // nearest cluster whose sphere held the point, or -1
  double inside_dist = 0.0;
  int count = 0;  // short list: clusters in examination order, their distances and bounds
  std::array<int32_t, kShortList> cluster;
  std::array<double, kShortList> dist, bound;
  double rest_bound = std::numeric_limits<double>::infinity();  // least bound of the others
};

struct Scratch {
  std::vector<double> dist;
};

// Prepares the points `batch` against the clusters `cl` (with the centre grid `grid` when
// there is one): prepared[k] for point batch[k]. `serial` is the scratch of a batch of one.
void prepareBatch(const std::vector<Cluster>& cl, const CentreGrid* grid, const PointSet& ps,
                  const std::vector<int32_t>& labels, const std::vector<int32_t>& batch,
                  std::vector<Prepared>* prepared, Scratch* serial);

}  // namespace sphereset::detail

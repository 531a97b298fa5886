// Point assignment of the variational fit. Reference: Wang et al. 2006, Sec. 5 "Point
// Assignment": each point goes to the cluster whose bounding sphere's outside volume grows
// least when enlarged to include it (ties: nearest centre), in flood-fill order from the
// cluster centres over adjacent points. Deviation: the paper's flood fill is stack-based
// (depth first); ours is first-in first-out (breadth first), which grows the clusters as even
// wavefronts. Measured with `sphereset fit -n 32` (summed E_r, depth first -> breadth first):
// spot 0.47 -> 0.37, armadillo (n = 64) 0.70 -> 0.64, fandisk 0.90 -> 0.95; it costs about
// 60% more SOV queries. Acceleration as in the paper: per cluster, a
// table of radius -> SOV computed so far gives a lower bound of the increase for any larger
// radius, and clusters are examined in increasing order of that bound, so most are dismissed
// without an SOV query.
//
// Parallel preparation (beyond the paper): with many clusters, the per-point scan over all
// clusters dominates, so batches of queued points are scanned in parallel against the
// clusters as they were when the batch began, and decided one by one in queue order against
// the clusters as they are then; see assign_prepare.hpp for why the labels are exactly
// those of the sequential fill. Measured (same labels, 2 cores): spot n = 1024,
// assignment 42.8 s -> 35.1 s; armadillo n = 512, 32.6 s -> 29.9 s, where the outside-volume
// queries, made in order so that the freshest tables cull them, are most of the time.
//
// Most points of a round are already inside some sphere when the fill reaches them (95% on
// spot, n = 1024), and the rule then wants the nearest such centre: a grid of the centres
// finds it among the few centres near the point instead of all of them, and a grid of the
// points finds each centre's seed point. Same labels; spot n = 1024, assignment 34.1 s ->
// 23.1 s; n = 2048, 133.7 s -> 67.5 s.
//
// This file is the fill: the clusters' reset, the seeds, the queue and the sequential decision
// of each point; assign_prepare.cpp prepares the batches.
#include "fit/cluster_assign.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <tuple>

#include "fit/assign_prepare.hpp"
#include "fit/centre_grid.hpp"
#include "fit/fit_common.hpp"

namespace sphereset::detail {
namespace {

// A table longer than this is dropped instead of grown (it is only a cache).
constexpr size_t kMaxTable = 1 << 14;

// Examination order of candidate clusters: increasing lower bound, then distance, then index.
bool examinedBefore(const std::vector<double>& bound, const std::vector<double>& dist, int32_t a,
                    int32_t b) {
  return bound[a] < bound[b] || (bound[a] == bound[b] && dist[a] < dist[b]) ||
         (bound[a] == bound[b] && dist[a] == dist[b] && a < b);
}

// First table entry whose radius is not below `radius`.
auto tableEntry(const Cluster& c, double radius) {
  return std::lower_bound(c.table.begin(), c.table.end(), radius,
                          [](const std::pair<double, double>& e, double r) { return e.first < r; });
}

// The tabulated SOV at exactly `radius`, or a negative number.
double tabulated(const Cluster& c, double radius) {
  const auto it = tableEntry(c, radius);
  return it != c.table.end() && it->first == radius ? it->second : -1.0;
}

void remember(Cluster* c, double radius, double sov) {
  if (c->table.size() >= kMaxTable) c->table.assign(1, {0.0, 0.0});
  const auto it = tableEntry(*c, radius);
  if (it != c->table.end() && it->first == radius) return;
  c->table.insert(it, {radius, sov});
}

// Radii start at zero; a cluster keeps its table only while its centre stays where it was.
void resetClusters(std::vector<Cluster>* clusters) {
  for (Cluster& c : *clusters) {
    c.radius = 0.0;
    c.sov = 0.0;
    if (c.table.empty() || c.table_center != c.center) {
      c.table.assign(1, {0.0, 0.0});
      c.table_center = c.center;
    }
  }
}

// The best cluster found so far for a point: least increase, ties to the nearest centre.
struct Candidate {
  int32_t cluster = -1;
  double inc = std::numeric_limits<double>::infinity(), sov = 0.0, dist = 0.0;
};

// The flood fill of one assignment (paper Sec. 5: "The algorithm starts from the cluster
// centers and progresses to adjacent points"), first in, first out.
class Fill {
 public:
  Fill(const SolidIndex& index, const PointSet& ps, std::vector<Cluster>* clusters,
       std::vector<int32_t>* labels, AssignStats* stats)
      : index_(index),
        ps_(ps),
        cl_(*clusters),
        labels_(*labels),
        stats_(stats),
        nc_(static_cast<int32_t>(cl_.size())),
        np_(static_cast<int64_t>(ps.points.size())) {}

  void seed();
  void run();

 private:
  void place(int64_t p, int32_t ci, double d, double sov);
  double query(int32_t ci, double radius);
  bool nextBatch();
  int32_t holder(const Vec3& x, const Prepared& pr, double* dist) const;
  void consider(int32_t ci, double d, Candidate* best, int64_t* looked);
  Candidate leastIncrease(const Vec3& x, const Prepared& pr);
  void decide(int32_t p, const Prepared& pr);

  const SolidIndex& index_;
  const PointSet& ps_;
  std::vector<Cluster>& cl_;
  std::vector<int32_t>& labels_;
  AssignStats* stats_;
  const int32_t nc_;
  const int64_t np_;
  std::deque<int32_t> queue_;
  std::unique_ptr<CentreGrid> grid_;
  std::vector<int32_t> batch_;
  std::vector<Prepared> prepared_;
  std::vector<char> queued_, changed_, examined_;
  std::vector<int32_t> changed_list_;  // clusters that grew since the batch was prepared
  Scratch serial_;
  std::vector<double> dist_, bound_;
  std::vector<int32_t> order_;
  std::vector<std::tuple<double, double, int32_t>> merged_;
  int64_t scan_ = 0;  // points before this one are all labelled
};

// Point p joins cluster ci at distance d (whose sphere then has outside volume `sov` if it
// grows), and its unlabelled neighbours join the queue (Sec. 5: "Once a point is assigned,
// the bounding sphere radius of its cluster is updated, and its adjacent points are pushed").
void Fill::place(int64_t p, int32_t ci, double d, double sov) {
  labels_[p] = ci;
  if (d > cl_[ci].radius) {
    cl_[ci].radius = d;
    cl_[ci].sov = sov;
  }
  for (int32_t k = ps_.adj_start[p]; k < ps_.adj_start[p + 1]; ++k)
    if (labels_[ps_.adj[k]] < 0) queue_.push_back(ps_.adj[k]);
}

// SOV of cluster ci's centre at `radius`, from its table if known (then recorded there).
double Fill::query(int32_t ci, double radius) {
  if (const double known = tabulated(cl_[ci], radius); known >= 0.0) {
    ++stats_->reused;
    return known;
  }
  const double v = index_.outsideVolume({cl_[ci].center, radius}).volume;
  ++stats_->queries;
  remember(&cl_[ci], radius, v);
  return v;
}

// Seeds: the point nearest each centre (clusters whose nearest point is taken keep none).
void Fill::seed() {
  std::vector<int64_t> nearest(nc_, -1);
  tbb::parallel_for(int32_t{0}, nc_, [&](int32_t ci) {
    nearest[ci] = ps_.grid.nearest(ps_.points, cl_[ci].center);
  });
  for (int32_t ci = 0; ci < nc_; ++ci) {
    const int64_t p = nearest[ci];
    if (p >= 0 && labels_[p] < 0) {
      const double d = (ps_.points[p] - cl_[ci].center).norm();
      place(p, ci, d, query(ci, d));
    }
  }
}

// The next points of the fill: the first unlabelled entries of the queue, or, when it runs
// dry, the first point of a part not reached from any centre. False when all are labelled.
bool Fill::nextBatch() {
  const size_t batch_size = batchSize(nc_);
  batch_.clear();
  while (!queue_.empty() && batch_.size() < batch_size) {
    const int32_t q = queue_.front();
    queue_.pop_front();
    if (labels_[q] < 0 && !queued_[q]) {
      queued_[q] = 1;
      batch_.push_back(q);
    }
  }
  if (batch_.empty()) {
    while (scan_ < np_ && labels_[scan_] >= 0) ++scan_;
    if (scan_ == np_) return false;
    batch_.push_back(static_cast<int32_t>(scan_));
  }
  return true;
}

// The nearest cluster whose sphere holds x (ties: lower index), or -1. Spheres only grow, so
// only those that grew since the preparation can newly hold the point.
int32_t Fill::holder(const Vec3& x, const Prepared& pr, double* dist) const {
  int32_t inside = pr.inside;
  double inside_dist = pr.inside_dist;
  for (const int32_t j : changed_list_) {
    const double dj = (x - cl_[j].center).norm();
    if (dj <= cl_[j].radius &&
        (inside < 0 || dj < inside_dist || (dj == inside_dist && j < inside))) {
      inside = j;
      inside_dist = dj;
    }
  }
  *dist = inside_dist;
  return inside;
}

// Examines cluster ci at distance d, unless its lower bound exceeds the best exact increase
// found: one SOV query (or a table entry).
void Fill::consider(int32_t ci, double d, Candidate* best, int64_t* looked) {
  examined_[ci] = 1;
  ++*looked;
  if (increaseBound(cl_[ci], d) > best->inc) return;
  const double v = query(ci, d);
  const double inc = v - cl_[ci].sov;
  if (inc < best->inc || (inc == best->inc && d < best->dist)) *best = {ci, inc, v, d};
}

// Least increase (paper Sec. 5: "p is assigned to that cluster whose outside volume increases
// least. In case of a tie, p is assigned to the cluster whose sphere center is closest"). A
// cluster is dismissed when its lower bound exceeds the best exact increase found; the result
// does not depend on the order in which clusters are examined. Unchanged clusters: the
// prepared bounds are still lower bounds (tables only gain entries), so the short list is
// examined in their order and the rest only if the least other bound does not exceed the best
// increase. Clusters that grew meanwhile (their bound can have dropped) are examined afresh.
Candidate Fill::leastIncrease(const Vec3& x, const Prepared& pr) {
  Candidate best;
  int64_t looked = 0;
  // The short list's unchanged clusters and the grown ones, merged by lower bound.
  merged_.clear();
  for (int i = 0; i < pr.count; ++i)
    if (!changed_[pr.cluster[i]]) merged_.push_back({pr.bound[i], pr.dist[i], pr.cluster[i]});
  for (const int32_t j : changed_list_) {
    const double dj = (x - cl_[j].center).norm();
    merged_.push_back({increaseBound(cl_[j], dj), dj, j});
  }
  std::sort(merged_.begin(), merged_.end());
  for (const auto& [b, d, ci] : merged_) {
    if (b > best.inc) break;
    consider(ci, d, &best, &looked);
  }
  for (const int32_t j : changed_list_) examined_[j] = 1;  // examined or dismissed
  if (pr.rest_bound <= best.inc) {
    // The short list did not settle it: every other cluster, in order of lower bound.
    order_.clear();
    for (int32_t ci = 0; ci < nc_; ++ci) {
      if (examined_[ci]) continue;
      dist_[ci] = (x - cl_[ci].center).norm();
      bound_[ci] = increaseBound(cl_[ci], dist_[ci]);
      if (bound_[ci] <= best.inc) order_.push_back(ci);
    }
    std::sort(order_.begin(), order_.end(),
              [&](int32_t a, int32_t b) { return examinedBefore(bound_, dist_, a, b); });
    for (const int32_t ci : order_) {
      if (bound_[ci] > best.inc) break;
      consider(ci, dist_[ci], &best, &looked);
    }
  }
  for (const int32_t j : changed_list_) examined_[j] = 0;
  for (int i = 0; i < pr.count; ++i) examined_[pr.cluster[i]] = 0;
  for (const int32_t ci : order_) examined_[ci] = 0;
  order_.clear();
  stats_->culled += nc_ - looked;
  return best;
}

// Assigns point p, prepared as `pr`, with the clusters as they are now.
void Fill::decide(int32_t p, const Prepared& pr) {
  queued_[p] = 0;
  const Vec3& x = ps_.points[p];
  // Already inside a sphere: no increase; the nearest such centre wins.
  double inside_dist = 0.0;
  if (const int32_t inside = holder(x, pr, &inside_dist); inside >= 0) {
    place(p, inside, inside_dist, cl_[inside].sov);
    return;
  }
  const Candidate best = leastIncrease(x, pr);
  const double before_radius = cl_[best.cluster].radius;
  place(p, best.cluster, best.dist, best.sov);
  if (cl_[best.cluster].radius != before_radius && !changed_[best.cluster]) {
    changed_[best.cluster] = 1;
    changed_list_.push_back(best.cluster);
  }
}

void Fill::run() {
  if (nc_ >= kParallelClusters) grid_ = std::make_unique<CentreGrid>(cl_);
  queued_.assign(np_, 0);
  changed_.assign(nc_, 0);
  examined_.assign(nc_, 0);
  dist_.resize(nc_);
  bound_.resize(nc_);
  while (nextBatch()) {
    pollCancel();
    prepareBatch(cl_, grid_.get(), ps_, labels_, batch_, &prepared_, &serial_);
    for (size_t k = 0; k < batch_.size(); ++k) decide(batch_[k], prepared_[k]);
    for (const int32_t j : changed_list_) changed_[j] = 0;
    changed_list_.clear();
  }
}

}  // namespace

void assignPoints(const SolidIndex& index, const PointSet& ps, std::vector<Cluster>* clusters,
                  std::vector<int32_t>* labels, AssignStats* stats) {
  labels->assign(ps.points.size(), -1);
  resetClusters(clusters);
  Fill fill(index, ps, clusters, labels, stats);
  fill.seed();
  fill.run();
}

}  // namespace sphereset::detail

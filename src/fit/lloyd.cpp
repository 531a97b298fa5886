// The clustering rounds of the variational fit. Reference: Wang et al. 2006, Sec. 5: "a variant
// of the Lloyd clustering algorithm" that minimises the total outside volume (Sec. 3, the sum
// of Eq. 2 over the spheres) by alternating point assignment (cluster_assign.cpp) and the
// update of each cluster's sphere (Eq. 5, sphere_update.cpp), with sphere teleportation
// (teleport.cpp) when the error stops improving.
//
// Deviations: the best complete state of all rounds is kept, since an assignment round can
// raise the error (the paper notes it "can not guarantee a decrease"); a teleport is judged
// after kTeleportRounds rounds instead of one, and the clustering stops after a number of
// teleports in a row that failed instead of the first; an empty cluster is restarted in the
// cluster of largest outside volume.
#include "fit/lloyd.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "fit/cluster_assign.hpp"
#include "fit/fit_common.hpp"
#include "fit/sphere_update.hpp"
#include "fit/teleport.hpp"

namespace sphereset::detail {
namespace {

// Rounds without enough improvement before a teleport is tried, and rounds a teleport gets
// before it is judged (the paper judges after one; the split spheres often need more).
constexpr int kStallRounds = 2;
constexpr int kTeleportRounds = 3;

// One round's clusters: the points of each, the updated spheres and their outside volumes.
struct Round {
  std::vector<Sphere> spheres;
  std::vector<std::vector<Vec3>> members;
  std::vector<double> sov;
  double energy = 0.0;
  bool complete = true;  // every cluster has a point
};

class LloydClustering {
 public:
  LloydClustering(const SolidIndex& index, const PointSet& ps, const std::vector<Vec3>& centres,
                  const FitOptions& o, int max_failed, FitResult* res)
      : index_(index),
        ps_(ps),
        o_(o),
        max_failed_(max_failed),
        res_(res),
        n_(static_cast<int>(centres.size())),
        clusters_(n_),
        upd_(n_) {
    for (int i = 0; i < n_; ++i) clusters_[i].center = centres[i];
  }

  Clustering run(const std::function<void(int, double)>& report);
  // A complete state to start from, the best so far.
  void setBest(Clustering start) { out_ = std::move(start); }

 private:
  Round lloydRound();
  void judgeTeleport();
  void restartEmpty(Round* rd);
  bool startTeleport();

  const SolidIndex& index_;
  const PointSet& ps_;
  const FitOptions& o_;
  const int max_failed_;
  FitResult* res_;
  const int n_;
  Clustering out_;
  std::vector<Cluster> clusters_;
  std::vector<int32_t> labels_;
  int stall_ = 0;  // rounds without enough improvement over the best
  int failed_teleports_ = 0;
  int teleport_rounds_left_ = 0;  // rounds a teleport gets to settle before it is judged
  double energy_before_teleport_ = 0.0;
  std::vector<std::pair<int, int>> tried_;  // (source, destination) since the last success
  std::vector<SplitCache> split_cache_;
  // A cluster whose centre is where its last update put it and whose points are the same
  // keeps that update (the update is a deterministic function of both); near convergence
  // and during teleports most clusters are such, so rounds cost little beyond the changes.
  std::vector<SphereUpdate> upd_;
  std::vector<int32_t> prev_labels_;
};

// One Lloyd round (paper Sec. 5, "Point Assignment" then "Sphere Fitting"): assignment by
// least outside-volume increase, then the sphere update of every cluster (Eq. 5; in parallel,
// deterministic per cluster).
Round LloydClustering::lloydRound() {
  const int n = n_;
  Round rd;
  const auto ta = FitClock::now();
  AssignStats as;
  assignPoints(index_, ps_, &clusters_, &labels_, &as);
  res_->sov_queries += as.queries;
  res_->sov_queries_culled += as.culled + as.reused;
  res_->seconds.assignment += secondsSince(ta);
  rd.members.assign(n, {});
  for (size_t p = 0; p < labels_.size(); ++p) rd.members[labels_[p]].push_back(ps_.points[p]);
  for (int i = 0; i < n; ++i) rd.complete = rd.complete && !rd.members[i].empty();
  std::vector<char> same(n, prev_labels_.size() == labels_.size() ? 1 : 0);
  for (size_t p = 0; p < labels_.size() && p < prev_labels_.size(); ++p)
    if (labels_[p] != prev_labels_[p]) same[labels_[p]] = same[prev_labels_[p]] = 0;
  prev_labels_ = labels_;
  const auto tu = FitClock::now();
  tbb::parallel_for(0, n, [&](int i) {
    pollCancel();
    if (same[i] && upd_[i].sphere.center == clusters_[i].center && !rd.members[i].empty()) {
      upd_[i].queries = 0;
      return;
    }
    if (rd.members[i].empty()) {
      upd_[i] = {};
      upd_[i].sphere = {clusters_[i].center, 0.0};
      return;
    }
    upd_[i] = updateSphere(index_, rd.members[i], clusters_[i].center, o_.optimizer,
                           o_.optimizer_evaluations);
  });
  res_->seconds.update += secondsSince(tu);
  rd.spheres.resize(n);
  rd.sov.resize(n);
  for (int i = 0; i < n; ++i) {
    rd.spheres[i] = upd_[i].sphere;
    rd.sov[i] = upd_[i].sov;
    clusters_[i].center = upd_[i].sphere.center;
    rd.energy += upd_[i].sov;
    res_->optimizer_queries += upd_[i].queries;
  }
  return rd;
}

// A teleport has had its rounds: it is kept if the best energy dropped enough (paper Sec. 5:
// "If the new error is less, the teleportation is accepted").
void LloydClustering::judgeTeleport() {
  ++res_->teleports;
  if (out_.energy < energy_before_teleport_ * (1.0 - o_.tolerance)) {
    ++res_->teleports_accepted;
    failed_teleports_ = 0;
    tried_.clear();
  } else {
    ++failed_teleports_;
  }
  stall_ = kStallRounds;  // judge the next move from the best state right away
}

// An empty cluster (its seed point was taken by another) restarts at the point farthest from
// its centre in the cluster of largest outside volume.
void LloydClustering::restartEmpty(Round* rd) {
  std::vector<std::vector<Vec3>>& members = rd->members;
  for (int i = 0; i < n_; ++i) {
    if (!members[i].empty()) continue;
    int worst = -1;
    for (int j = 0; j < n_; ++j)
      if (members[j].size() > 1 && (worst < 0 || rd->sov[j] > rd->sov[worst])) worst = j;
    if (worst < 0) break;
    clusters_[i].center = farthestFrom(members[worst], clusters_[worst].center);
    members[worst].clear();  // one restart per donor and round
  }
}

// Teleportation when the error stops improving (paper Sec. 5): from the best state, one
// sphere leaves its place and splits another's cluster. The paper takes the sphere of
// largest overlap ratio to the sphere of largest outside volume; ranking pairs by predicted
// gain (bestTeleport) keeps far more of the moves it tries. Measured on spot, n = 32, seeds
// 1-8, 30 rounds: mean E_r 0.382 with the paper's choice, 0.342 ranked. Returns false when
// the clustering has converged (too many failed teleports, or no move left to try).
bool LloydClustering::startTeleport() {
  if (failed_teleports_ >= max_failed_ || n_ < 2) return false;
  // The most promising move not tried since the state last changed.
  const auto tt = FitClock::now();
  const std::optional<TeleportMove> move = bestTeleport(
      index_, out_.spheres, out_.members, outsideVolumes(index_, out_.spheres), o_.optimizer,
      o_.optimizer_evaluations, tried_, &split_cache_, &res_->optimizer_queries);
  res_->seconds.teleport += secondsSince(tt);
  if (!move) return false;
  tried_.emplace_back(move->src, move->dst);
  for (int i = 0; i < n_; ++i) clusters_[i].center = out_.spheres[i].center;
  clusters_[move->dst].center = move->dst_centre;
  clusters_[move->src].center = move->src_centre;
  teleport_rounds_left_ = kTeleportRounds;
  energy_before_teleport_ = out_.energy;
  stall_ = 0;
  return true;
}

Clustering LloydClustering::run(const std::function<void(int, double)>& report) {
  for (int it = 0; it < std::max(1, o_.max_iterations); ++it) {
    Round rd = lloydRound();
    res_->energy_history.push_back(rd.energy);
    ++res_->iterations;
    report(res_->iterations, rd.energy);
    const bool improved = rd.complete && rd.energy < out_.energy * (1.0 - o_.tolerance);
    if (rd.complete && rd.energy < out_.energy) {
      out_.energy = rd.energy;
      out_.spheres = rd.spheres;
      out_.members = rd.members;
    }
    stall_ = improved ? 0 : stall_ + 1;
    if (teleport_rounds_left_ > 0 && --teleport_rounds_left_ == 0) judgeTeleport();
    if (teleport_rounds_left_ > 0) continue;
    if (!rd.complete) {
      restartEmpty(&rd);
      continue;
    }
    // "Teleportation is triggered when insufficient error improvement occurs" (Sec. 5).
    if (stall_ >= kStallRounds && !startTeleport()) {
      out_.converged = true;
      break;
    }
  }
  return std::move(out_);
}

}  // namespace

Clustering clusterPoints(const SolidIndex& index, const PointSet& ps,
                         const std::vector<Vec3>& centres, const FitOptions& o, int max_failed,
                         FitResult* res, const std::function<void(int, double)>& report) {
  return LloydClustering(index, ps, centres, o, max_failed, res).run(report);
}

Clustering clusterFrom(const SolidIndex& index, const PointSet& ps, Clustering start,
                       const FitOptions& o, int max_failed, FitResult* res,
                       const std::function<void(int, double)>& report) {
  std::vector<Vec3> centres;
  for (const Sphere& s : start.spheres) centres.push_back(s.center);
  LloydClustering lc(index, ps, centres, o, max_failed, res);
  lc.setBest(std::move(start));
  return lc.run(report);
}

}  // namespace sphereset::detail

// The variational sphere-set fit. Reference: Wang et al. 2006, Sec. 5: Lloyd-style
// alternation of point assignment by least outside-volume increase (cluster_assign.cpp) and
// per-cluster sphere update (sphere_update.cpp), on interior grid points and surface samples
// (samples.cpp), followed by a bounding step (bound.cpp) that here covers the whole surface
// exactly instead of sampled points only, and the interior cubes of the evaluation's test.
//
// Deviations from the paper, each explained where it happens: farthest-point seeding by
// default (the paper suggests better seeding for large n; random interior seeds remain an
// option); the best spheres of all rounds are kept, since an assignment round can raise the
// error; teleports are chosen by predicted gain instead of overlap ratio and outside volume,
// and judged after a few rounds instead of one; optionally (decimation) the clustering starts
// with extra spheres and removes the cheapest; and after the bound, shrinking passes refit
// each sphere around what it alone covers and move spheres that cover nothing alone to split
// the largest ones (teleportation applied to the bounded set), which recovers much of what
// the bounding step costs.
#include "sphereset/fit.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <random>

#include "cover/sphere_grid.hpp"
#include "fit/baselines.hpp"
#include "fit/bound.hpp"
#include "fit/cluster_assign.hpp"
#include "fit/samples.hpp"
#include "fit/sphere_update.hpp"
#include "sphereset/evaluate.hpp"
#include "util/sampling.hpp"

namespace sphereset {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Seeds: farthest-point sampling over the interior points (all points if there are none),
// starting from a seeded random one; or plain random distinct points.
std::vector<Vec3> initialCentres(const detail::PointSet& ps, int n, FitInit init, uint64_t seed) {
  const int64_t pool = ps.interior > 0 ? ps.interior : static_cast<int64_t>(ps.points.size());
  std::mt19937_64 rng(detail::mixSeed(seed, 11));
  std::vector<Vec3> out;
  if (init == FitInit::kRandom || pool <= n) {
    std::vector<int64_t> idx(pool);
    for (int64_t i = 0; i < pool; ++i) idx[i] = i;
    std::shuffle(idx.begin(), idx.end(), rng);
    for (int64_t i = 0; i < std::min<int64_t>(n, pool); ++i) out.push_back(ps.points[idx[i]]);
    return out;
  }
  std::vector<double> d2(pool, std::numeric_limits<double>::infinity());
  int64_t next = static_cast<int64_t>(detail::uniform01(rng) * pool) % pool;
  for (int k = 0; k < n; ++k) {
    out.push_back(ps.points[next]);
    int64_t far = 0;
    for (int64_t i = 0; i < pool; ++i) {
      d2[i] = std::min(d2[i], (ps.points[i] - out.back()).squaredNorm());
      if (d2[i] > d2[far]) far = i;
    }
    next = far;
  }
  return out;
}

// Outside volume of each sphere (in parallel), and their sum in a fixed order.
std::vector<double> outsideVolumes(const SolidIndex& index, const std::vector<Sphere>& sp) {
  std::vector<double> v(sp.size());
  tbb::parallel_for(size_t{0}, sp.size(),
                    [&](size_t i) { v[i] = index.outsideVolume(sp[i]).volume; });
  return v;
}
double total(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

Vec3 farthestFrom(const std::vector<Vec3>& pts, const Vec3& q) {
  Vec3 best = q;
  double bd = -1.0;
  for (const Vec3& p : pts)
    if ((p - q).squaredNorm() > bd) {
      bd = (p - q).squaredNorm();
      best = p;
    }
  return best;
}

// Rounds without enough improvement before a teleport is tried, and rounds a teleport gets
// before it is judged (the paper judges after one; the split spheres often need more).
constexpr int kStallRounds = 2;
constexpr int kTeleportRounds = 3;
// Refits of the spheres the bounding step enlarged, before the final bounding pass.
constexpr int kRefitPasses = 2;
// 2-means rounds when a sphere is split in two after the bound.
constexpr int kSplitRounds = 5;
// Spheres whose split is evaluated together when ranking teleports.
constexpr int kSplitBatch = 8;
// Batches in which the extra spheres of the decimation are removed, and teleports in a row
// that may fail before the clustering of an intermediate count is taken as settled.
constexpr int kDecimationSteps = 8;
constexpr int kDecimationFailedTeleports = 1;
// Passes of the interior bound (each settles the cubes it finds; one usually suffices).
constexpr int kInteriorPasses = 4;

Vec3 centroid(const std::vector<Vec3>& pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return c / static_cast<double>(pts.size());
}

// Splits points in two: 2-means from the farthest pair.
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

// A teleport candidate: sphere `src` leaves its place and, with `dst`, splits dst's cluster.
struct TeleportMove {
  int src = -1, dst = -1;
  Vec3 src_centre, dst_centre;  // where the two start
  double predicted = 0.0;       // predicted decrease of the energy
};

// A sphere's split, kept while its points stay the same.
struct SplitCache {
  std::vector<Vec3> members;
  bool valid = false;
  double halves_sov = 0.0;  // outside volume of the two refitted halves
  Vec3 ca, cb;
};

// For each sphere, an upper bound on the change of the energy if it is removed: each of its
// points joins the other sphere it sticks out of least (ties: lower index), and those spheres
// grow about fixed centres (one outside-volume query per grown sphere, counted in q[i]).
// If `receivers` is given, (*receivers)[i] lists the spheres that would grow.
std::vector<double> removalCosts(const SolidIndex& index, const std::vector<Sphere>& sp,
                                 const std::vector<std::vector<Vec3>>& members,
                                 const std::vector<double>& sov, std::vector<int64_t>* q,
                                 std::vector<std::vector<int>>* receivers) {
  const int n = static_cast<int>(sp.size());
  std::vector<double> cost(n);
  if (receivers) receivers->assign(n, {});
  const detail::SphereGrid grid(sp);
  tbb::parallel_for(0, n, [&](int i) {
    std::vector<double> grown(n, 0.0);
    for (const Vec3& p : members[i]) {
      std::pair<double, int32_t> least[2];
      const int m = detail::leastGrowth(grid, &p, 1, 2, least);
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

// The most promising teleport not in `tried` (deviation from the paper, which pairs the
// sphere of largest overlap ratio with the sphere of largest outside volume), or none. Each
// sphere's gain from being split is measured: its points split by 2-means, both halves
// refitted. Each sphere's cost of removal is bounded from above: its points join the sphere
// they stick out of least, those spheres grow about fixed centres. A pair is ranked by gain
// minus cost (ties: lower destination, then lower source).
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
      const int i = by_sov[k];
      SplitCache& sc = (*cache)[i];
      if (sc.members != members[i]) {
        sc.members = members[i];
        sc.valid = false;
        std::vector<Vec3> a, b;
        if (members[i].size() >= 2) splitTwoMeans(members[i], &a, &b);
        if (!a.empty() && !b.empty()) {
          const detail::SphereUpdate ua =
              detail::updateSphere(index, a, centroid(a), optimizer, evaluations);
          const detail::SphereUpdate ub =
              detail::updateSphere(index, b, centroid(b), optimizer, evaluations);
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

// The clustering (paper Sec. 5) from the given centres: Lloyd rounds of assignment and update,
// teleports when the error stops improving, until `max_failed` teleports in a row did not
// help or o.max_iterations rounds ran. The best complete state of all rounds is returned
// (none if no round gave every cluster a point). Counts and times add to *res.
struct Clustering {
  std::vector<Sphere> spheres;
  std::vector<std::vector<Vec3>> members;
  double energy = std::numeric_limits<double>::infinity();
  bool converged = false;  // stopped because neither rounds nor teleports improved
};
Clustering clusterPoints(const SolidIndex& index, const detail::PointSet& ps,
                         const std::vector<Vec3>& centres, const FitOptions& o, int max_failed,
                         FitResult* res, const std::function<void(int, double)>& report) {
  const int n = static_cast<int>(centres.size());
  Clustering out;
  std::vector<detail::Cluster> clusters(n);
  for (int i = 0; i < n; ++i) clusters[i].center = centres[i];
  std::vector<int32_t> labels;
  std::vector<Sphere>& best_spheres = out.spheres;
  std::vector<std::vector<Vec3>>& best_members = out.members;
  double& best_energy = out.energy;
  int stall = 0;  // rounds without enough improvement over the best
  int failed_teleports = 0;
  int teleport_rounds_left = 0;  // rounds a teleport gets to settle before it is judged
  double energy_before_teleport = 0.0;
  std::vector<std::pair<int, int>> tried;  // (source, destination) since the last success
  std::vector<SplitCache> split_cache;
  // One Lloyd round on a point set: assignment by least outside-volume increase, then the
  // sphere update of every cluster (in parallel; deterministic per cluster).
  struct Round {
    std::vector<Sphere> spheres;
    std::vector<std::vector<Vec3>> members;
    std::vector<double> sov;
    double energy = 0.0;
    bool complete = true;
  };
  // A cluster whose centre is where its last update put it and whose points are the same
  // keeps that update (the update is a deterministic function of both); near convergence
  // and during teleports most clusters are such, so rounds cost little beyond the changes.
  std::vector<detail::SphereUpdate> upd(n);
  std::vector<int32_t> prev_labels;
  auto lloydRound = [&](const detail::PointSet& points) {
    Round rd;
    const auto ta = Clock::now();
    detail::AssignStats as;
    detail::assignPoints(index, points, &clusters, &labels, &as);
    res->sov_queries += as.queries;
    res->sov_queries_culled += as.culled + as.reused;
    res->seconds.assignment += since(ta);
    rd.members.assign(n, {});
    for (size_t p = 0; p < labels.size(); ++p) rd.members[labels[p]].push_back(points.points[p]);
    for (int i = 0; i < n; ++i) rd.complete = rd.complete && !rd.members[i].empty();
    std::vector<char> same(n, prev_labels.size() == labels.size() ? 1 : 0);
    for (size_t p = 0; p < labels.size() && p < prev_labels.size(); ++p)
      if (labels[p] != prev_labels[p]) same[labels[p]] = same[prev_labels[p]] = 0;
    prev_labels = labels;
    const auto tu = Clock::now();
    tbb::parallel_for(0, n, [&](int i) {
      if (same[i] && upd[i].sphere.center == clusters[i].center && !rd.members[i].empty()) {
        upd[i].queries = 0;
        return;
      }
      if (rd.members[i].empty()) {
        upd[i] = {};
        upd[i].sphere = {clusters[i].center, 0.0};
        return;
      }
      upd[i] = detail::updateSphere(index, rd.members[i], clusters[i].center, o.optimizer,
                                    o.optimizer_evaluations);
    });
    res->seconds.update += since(tu);
    rd.spheres.resize(n);
    rd.sov.resize(n);
    for (int i = 0; i < n; ++i) {
      rd.spheres[i] = upd[i].sphere;
      rd.sov[i] = upd[i].sov;
      clusters[i].center = upd[i].sphere.center;
      rd.energy += upd[i].sov;
      res->optimizer_queries += upd[i].queries;
    }
    return rd;
  };
  for (int it = 0; it < std::max(1, o.max_iterations); ++it) {
    Round rd = lloydRound(ps);
    const double energy = rd.energy;
    const bool complete = rd.complete;
    std::vector<std::vector<Vec3>>& members = rd.members;
    const std::vector<Sphere>& spheres = rd.spheres;
    res->energy_history.push_back(energy);
    ++res->iterations;
    report(res->iterations, energy);
    const bool improved = complete && energy < best_energy * (1.0 - o.tolerance);
    if (complete && energy < best_energy) {
      best_energy = energy;
      best_spheres = spheres;
      best_members = members;
    }
    stall = improved ? 0 : stall + 1;
    if (teleport_rounds_left > 0 && --teleport_rounds_left == 0) {
      ++res->teleports;
      if (best_energy < energy_before_teleport * (1.0 - o.tolerance)) {
        ++res->teleports_accepted;
        failed_teleports = 0;
        tried.clear();
      } else {
        ++failed_teleports;
      }
      stall = kStallRounds;  // judge the next move from the best state right away
    }
    if (teleport_rounds_left > 0) continue;
    // An empty cluster (its seed point was taken by another) restarts at the point farthest
    // from its centre in the cluster of largest outside volume.
    if (!complete) {
      for (int i = 0; i < n; ++i) {
        if (!members[i].empty()) continue;
        int worst = -1;
        for (int j = 0; j < n; ++j)
          if (members[j].size() > 1 && (worst < 0 || rd.sov[j] > rd.sov[worst])) worst = j;
        if (worst < 0) break;
        clusters[i].center = farthestFrom(members[worst], clusters[worst].center);
        members[worst].clear();  // one restart per donor and round
      }
      continue;
    }
    // Teleportation when the error stops improving (paper Sec. 5): from the best state, one
    // sphere leaves its place and splits another's cluster. The paper takes the sphere of
    // largest overlap ratio to the sphere of largest outside volume; ranking pairs by
    // predicted gain (bestTeleport) keeps far more of the moves it tries. Measured on spot,
    // n = 32, seeds 1-8, 30 rounds: mean E_r 0.382 with the paper's choice, 0.342 ranked.
    if (stall >= kStallRounds) {
      if (failed_teleports >= max_failed || n < 2) {
        out.converged = true;
        break;
      }
      // The most promising move not tried since the state last changed.
      const auto tt = Clock::now();
      const std::optional<TeleportMove> move = bestTeleport(
          index, best_spheres, best_members, outsideVolumes(index, best_spheres), o.optimizer,
          o.optimizer_evaluations, tried, &split_cache, &res->optimizer_queries);
      res->seconds.teleport += since(tt);
      if (!move) {
        out.converged = true;
        break;
      }
      tried.emplace_back(move->src, move->dst);
      for (int i = 0; i < n; ++i) clusters[i].center = best_spheres[i].center;
      clusters[move->dst].center = move->dst_centre;
      clusters[move->src].center = move->src_centre;
      teleport_rounds_left = kTeleportRounds;
      energy_before_teleport = best_energy;
      stall = 0;
    }
  }
  return out;
}

}  // namespace

Expected<FitResult> fitSpheres(const SolidIndex& index, const FitOptions& o) {
  if (o.restarts < 1) return Error{ErrorCode::kInvalidArgument, "restarts must be at least 1"};
  if (o.restarts > 1) {
    // Independent fits from derived seeds (sampling and seeding both change); the lowest
    // final outside volume wins, ties to the earlier restart. Counts and times add up.
    const auto t0 = Clock::now();
    FitOptions one = o;
    one.restarts = 1;
    Expected<FitResult> best = Error{ErrorCode::kInvalidArgument, "no restart ran"};
    FitTimings sum;
    int64_t queries = 0, culled = 0, optimizer = 0;
    for (int r = 0; r < o.restarts; ++r) {
      one.seed = r == 0 ? o.seed : detail::mixSeed(o.seed, 7000 + r);
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
    best->seconds.total = since(t0);
    best->sov_queries = queries;
    best->sov_queries_culled = culled;
    best->optimizer_queries = optimizer;
    return best;
  }
  const auto t0 = Clock::now();
  FitResult res;
  if (o.num_spheres < 1)
    return Error{ErrorCode::kInvalidArgument, "the number of spheres must be at least 1"};
  if (!(o.interior_share >= 0.0 && o.interior_share <= 1.0))
    return Error{ErrorCode::kInvalidArgument, "interior share must be between 0 and 1"};
  if (o.max_iterations < 0 || o.optimizer_evaluations < 0 || !(o.padding >= 0.0) ||
      !std::isfinite(o.padding) || o.target_points < 0 || !(o.tolerance >= 0.0) ||
      o.shrink_passes < 0 || !(o.decimation >= 0.0 && o.decimation <= 16.0))
    return Error{ErrorCode::kInvalidArgument, "fit options out of range"};
  if (!(signedVolume(index.mesh()) > 0.0))
    return Error{ErrorCode::kNotSolid, "the mesh encloses no volume"};
  const int n = o.num_spheres;
  auto report = [&](const std::string& phase, int it, double e) {
    if (o.progress) o.progress({phase, it, e, n, since(t0)});
  };

  // Preprocessing: the points to cluster.
  report("sampling", 0, 0.0);
  const int64_t target =
      o.target_points > 0 ? o.target_points : std::max<int64_t>(5000, 100 * int64_t{n});
  const detail::PointSet ps = detail::samplePoints(index, target, o.interior_share, o.seed);
  res.points = static_cast<int64_t>(ps.points.size());
  res.interior_points = ps.interior;
  res.seconds.sampling = since(t0);
  if (res.points < n)
    return Error{ErrorCode::kInvalidArgument,
                 "asked for " + std::to_string(n) + " spheres but only " +
                     std::to_string(res.points) + " points were sampled (raise --points)"};

  const bool variational = o.method == FitMethod::kVariational;
  std::vector<Sphere> best_spheres;
  std::vector<std::vector<Vec3>> best_members;
  double best_energy = std::numeric_limits<double>::infinity();
  if (!variational) {
    // Baselines: their clusters and minimal balls, then the same bounding step.
    report("clustering", 0, 0.0);
    const auto ta = Clock::now();
    detail::BaselineResult b =
        o.method == FitMethod::kOctree
            ? detail::octreeSpheres(ps, n)
            : detail::kmeansSpheres(ps, initialCentres(ps, n, o.init, o.seed), o.max_iterations);
    res.seconds.assignment += since(ta);
    res.iterations = b.iterations;
    res.converged = b.converged;
    best_spheres = std::move(b.spheres);
    best_energy = total(outsideVolumes(index, best_spheres));
    res.energy_history.push_back(best_energy);
    best_members.assign(best_spheres.size(), {});
  } else {
    // Decimation (beyond the paper): with o.decimation > 0 the clustering starts with
    // n + extra spheres and removes the cheapest ones in kDecimationSteps batches, clustering
    // again after each; teleports only move spheres, a removal also lets the others settle
    // around the gap, which finds lower minima when n is small.
    const int extra = static_cast<int>(
        std::min<int64_t>(std::llround(o.decimation * static_cast<double>(n)), res.points - n));
    const int batch = std::max(1, (extra + kDecimationSteps - 1) / kDecimationSteps);
    int m = n + extra;
    std::vector<Vec3> centres = initialCentres(ps, m, o.init, o.seed);
    const auto progress = [&](int it, double e) { report("clustering", it, e); };
    for (;;) {
      Clustering c = clusterPoints(index, ps, centres, o,
                                   m > n ? kDecimationFailedTeleports : o.max_failed_teleports,
                                   &res, progress);
      if (m > n && c.spheres.empty()) {
        // No round gave every one of the m clusters a point: start over with n.
        m = n;
        centres = initialCentres(ps, n, o.init, o.seed);
        continue;
      }
      if (m == n) {
        best_spheres = std::move(c.spheres);
        best_members = std::move(c.members);
        best_energy = c.energy;
        res.converged = c.converged;
        break;
      }
      // The batch: cheapest removals first (ties: lower index); a sphere is skipped if it
      // or a sphere that would take its points is already involved in a removal.
      const auto tt = Clock::now();
      std::vector<int64_t> q(m, 0);
      std::vector<std::vector<int>> takers;
      const std::vector<double> cost =
          removalCosts(index, c.spheres, c.members, outsideVolumes(index, c.spheres), &q, &takers);
      res.optimizer_queries += std::accumulate(q.begin(), q.end(), int64_t{0}) + m;
      std::vector<int> order(m);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] < cost[b]; });
      std::vector<char> gone(m, 0), involved(m, 0);
      int removed = 0;
      for (int i : order) {
        if (removed == std::min(batch, m - n)) break;
        bool free = !involved[i];
        for (int j : takers[i]) free = free && !involved[j];
        if (!free) continue;
        gone[i] = involved[i] = 1;
        for (int j : takers[i]) involved[j] = 1;
        ++removed;
      }
      centres.clear();
      for (int i = 0; i < m; ++i)
        if (!gone[i]) centres.push_back(c.spheres[i].center);
      m -= removed;
      res.decimated += removed;
      res.seconds.teleport += since(tt);
    }
  }
  if (best_spheres.empty())
    return Error{ErrorCode::kInvalidArgument,
                 "could not place " + std::to_string(n) + " non-empty clusters"};
  res.energy_before_bounding = best_energy;

  // Guaranteed bounding of the surface. Interior and surface points are already inside the
  // sphere of their cluster (each radius encloses its points).
  report("bounding", res.iterations, best_energy);
  const auto tb = Clock::now();
  const double surface_spacing =
      std::sqrt(surfaceArea(index.mesh()) /
                std::max<double>(1.0, static_cast<double>(res.points - res.interior_points)));
  const double min_edge = 0.5 * std::min(surface_spacing, ps.spacing);
  // The bounding step grows spheres where the surface between samples pokes out. Spheres
  // that grew are refitted once with the pieces they had to take added to their points, so
  // that their centres can move instead of only their radii growing; a last pass then
  // guarantees the bound.
  // Bounds `sp` (the clusters' points in `mem`), refitting the spheres that grew; returns
  // the last pass's statistics.
  auto boundWithRefits = [&](std::vector<Sphere>* sp, std::vector<std::vector<Vec3>>* mem) {
    std::vector<std::vector<Vec3>> held;
    detail::BoundStats b = detail::boundSurface(index, sp, min_edge, &held);
    res.bounding_pieces += b.pieces;
    res.bounding_queries += b.queries;
    for (int pass = 0; variational && pass < kRefitPasses && b.enlarged > 0; ++pass) {
      tbb::parallel_for(0, n, [&](int i) {
        if (held[i].empty()) return;
        (*mem)[i].insert((*mem)[i].end(), held[i].begin(), held[i].end());
        (*sp)[i] = detail::updateSphere(index, (*mem)[i], (*sp)[i].center, o.optimizer,
                                        o.optimizer_evaluations)
                       .sphere;
      });
      b = detail::boundSurface(index, sp, min_edge, &held);
      res.bounding_pieces += b.pieces;
      res.bounding_queries += b.queries;
    }
    return b;
  };
  detail::BoundStats bs = boundWithRefits(&best_spheres, &best_members);
  // Shrinking (beyond the paper): each sphere is refitted around what it alone covers (the
  // surface pieces and interior points no other sphere holds), which keeps the bound except
  // where two neighbours both let go of a shared piece; a bounding pass repairs that. A pass
  // is kept only if it lowers the total outside volume. It removes part of the cost of the
  // bounding step, which grows spheres without looking at their neighbours.
  if (variational && o.shrink_passes > 0) {
    const std::vector<Vec3> interior(ps.points.begin(), ps.points.begin() + ps.interior);
    double current = total(outsideVolumes(index, best_spheres));
    for (int pass = 0; pass < o.shrink_passes; ++pass) {
      const auto owned = detail::soleCover(index, best_spheres, interior, min_edge);
      std::vector<Sphere> shrunk = best_spheres;
      tbb::parallel_for(0, n, [&](int i) {
        if (owned[i].empty()) return;
        const detail::SphereUpdate u = detail::updateSphere(index, owned[i], shrunk[i].center,
                                                            o.optimizer, o.optimizer_evaluations);
        shrunk[i] = u.sphere;
      });
      std::vector<std::vector<Sphere>> cands{shrunk};
      // Spheres that cover nothing alone are moved (teleported, paper Sec. 5) to split the
      // spheres of largest outside volume, each in two along its own points.
      std::vector<int> idle, by_sov(n);
      for (int i = 0; i < n; ++i)
        if (owned[i].empty()) idle.push_back(i);
      if (!idle.empty()) {
        const std::vector<double> sov = outsideVolumes(index, shrunk);
        std::iota(by_sov.begin(), by_sov.end(), 0);
        std::stable_sort(by_sov.begin(), by_sov.end(),
                         [&](int a, int b) { return sov[a] > sov[b]; });
        std::vector<std::pair<int, int>> moves;  // (idle sphere, split sphere)
        for (int k = 0, d = 0; k < static_cast<int>(idle.size()) && d < n; ++d)
          if (owned[by_sov[d]].size() >= 2) moves.emplace_back(idle[k++], by_sov[d]);
        std::vector<Sphere> moved = shrunk;
        tbb::parallel_for(size_t{0}, moves.size(), [&](size_t m) {
          const auto [i, j] = moves[m];
          std::vector<Vec3> a, b;
          splitTwoMeans(owned[j], &a, &b);
          if (a.empty() || b.empty()) return;
          moved[j] =
              detail::updateSphere(index, a, centroid(a), o.optimizer, o.optimizer_evaluations)
                  .sphere;
          moved[i] =
              detail::updateSphere(index, b, centroid(b), o.optimizer, o.optimizer_evaluations)
                  .sphere;
        });
        cands.push_back(std::move(moved));
      }
      // Repair the bound of each candidate and keep the best, if it beats the current set.
      int pick = -1;
      double e_pick = current;
      detail::BoundStats b_pick;
      for (size_t c = 0; c < cands.size(); ++c) {
        const detail::BoundStats b = detail::boundSurface(index, &cands[c], min_edge, nullptr);
        res.bounding_queries += b.queries;
        const double e = total(outsideVolumes(index, cands[c]));
        if (e < e_pick) {
          e_pick = e;
          pick = static_cast<int>(c);
          b_pick = b;
        }
      }
      if (pick < 0) break;
      ++res.shrink_passes;
      if (pick == 1) res.idle_teleports += static_cast<int>(idle.size());
      const bool small_gain = e_pick > current * (1.0 - o.tolerance);
      current = e_pick;
      best_spheres = std::move(cands[pick]);
      bs = b_pick;
      if (small_gain && pick == 0) break;
    }
  }
  res.bounding_enlarged = bs.enlarged;
  // Interior: the cubes of the evaluation's octree test whose centres lie inside the solid
  // must be covered too (between grid points the clusters' spheres can leave gaps, most of
  // all for the baselines). Radii only grow, so the surface stays covered.
  for (int pass = 0; pass < kInteriorPasses; ++pass) {
    const detail::BoundStats is =
        detail::boundInterior(index, &best_spheres, EvalOptions{}.interior_max_depth);
    res.bounding_queries += is.queries;
    res.bounding_interior_cells += is.pieces;
    if (is.enlarged == 0) break;
  }
  for (Sphere& s : best_spheres) s.radius += o.padding;
  res.spheres = std::move(best_spheres);
  res.outside_volume = outsideVolumes(index, res.spheres);
  res.energy = total(res.outside_volume);
  res.seconds.bounding = since(tb);
  res.seconds.total = since(t0);
  report("done", res.iterations, res.energy);
  return res;
}

}  // namespace sphereset

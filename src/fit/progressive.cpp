// Progressive fitting (beyond the paper). Reference: Wang et al. 2006, Sec. 5 fits one count
// from seeds; its teleportation (Sec. 5, "Sphere Teleportation") splits a cluster in two from
// "the two points farthest from each other". Here a fit at n + k starts from the clustering of
// a fit at n: the k splits that lower the outside volume most (each cluster split by 2-means
// from its farthest pair, both halves refitted as in the sphere update, Eq. 5) give the extra
// seeds, and the paper's rounds and teleports run again from there, the split state counting as
// the best so far. One point set, the one fitSpheres samples for the largest count, serves
// every count: a fit at a lower count clusters more points than fitSpheres would give it (above
// 50 spheres, where the default points grow with n). Each count ends as fitSpheres ends
// (finish.cpp), so every fit of the curve is bounded; its clustering, before the bound, is what a
// larger count starts from.
//
// Deviation from an independent fit at each count: a warm-started clustering gets fewer rounds
// (kWarmRounds): its clusters start settled, and the splits are the moves a teleport would try.
// Doubling, it keeps the options' teleports that may fail in a row (allowing 2 instead cost 1.5 %
// of E_r at 32 and 64 spheres on six of the shared meshes for no time saved; 100 rounds instead
// of 30 cost time and quality); from the count just below, fewer (kSettledFailedTeleports).
// docs/benchmarks.md, "Progressive fitting", compares both on the shared meshes. Warm-started,
// the largest counts end about 5 % above independent fits in outside volume (E_r at 64 over the 12
// shared closed meshes); ProgressiveOptions::top_from_seeds clusters the largest count from seeds
// instead, as fitSpheres does (a curve's last count: fitCurve).
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "fit/finish.hpp"
#include "fit/fit_common.hpp"
#include "fit/lloyd.hpp"
#include "fit/local_split.hpp"
#include "fit/samples.hpp"
#include "fit/seeding.hpp"
#include "sphereset/fit.hpp"

namespace sphereset {
namespace {

// A warm-started clustering: at most this many rounds (or the options' fewer; below half the
// largest count, ProgressiveOptions::warm_rounds_below_half may ask for fewer).
constexpr int kWarmRounds = 30;
// Started from the count just below (start_ratio 1: a few splits of a settled clustering), at
// most this many teleports in a row may fail (or the options' fewer): the robot's candidates
// took 14 % longer with the options' 6, for 0.3 % more outside volume (Kinova, budget 60).
constexpr int kSettledFailedTeleports = 2;
// ProgressiveOptions::start_ratio: from the count just below it, a few splits leave a clustering
// that the warm rounds barely move, and a chain of such steps stays in its minimum (spot.obj
// through 1, 2, 3, 4, 6, ... 64: E_r 0.83 at 64 against 0.16 through 8, 16, 32, 64; starting
// from at most half, 0.17; from a quarter, 0.157, but a doubling run would start from seeds).

// A cluster while the seeds of the next count are chosen: its points, its sphere's centre and
// outside volume, and (once known) its best split: the gain and the two halves.
struct Piece {
  std::vector<Vec3> points;
  Sphere sphere;  // encloses `points`
  double sov = 0.0;
  bool split_known = false;
  double gain = -std::numeric_limits<double>::infinity();
  detail::PointSplit split;
};

// The split of every piece not yet measured (in parallel, deterministic per piece).
void measureSplits(const SolidIndex& index, const FitOptions& o, std::vector<Piece>* pieces,
                   FitResult* res) {
  std::vector<int64_t> queries(pieces->size(), 0);
  tbb::parallel_for(size_t{0}, pieces->size(), [&](size_t i) {
    detail::pollCancel();
    Piece& p = (*pieces)[i];
    if (p.split_known) return;
    p.split_known = true;
    p.split = detail::splitPoints(index, p.points, o);
    if (!p.split.ok) return;
    p.gain = p.sov - (p.split.ua.sov + p.split.ub.sov);
    queries[i] = p.split.ua.queries + p.split.ub.queries;
  });
  res->optimizer_queries += std::accumulate(queries.begin(), queries.end(), int64_t{0});
}

// The clustering of `count` spheres made from clustering `c` (fewer spheres): the pieces whose
// split gains most are split, as many at once as are still missing, until there are `count` (a
// half can be split again in a later pass); in the first pass, with `first` (one value per
// sphere of c), those of the largest values instead. Fewer spheres only if no piece can be split.
detail::Clustering splitClusters(const SolidIndex& index, const detail::Clustering& c, int count,
                                 std::span<const double> first, const FitOptions& o,
                                 FitResult* res) {
  const auto tt = detail::FitClock::now();
  const std::vector<double> sov = detail::outsideVolumes(index, c.spheres);
  std::vector<Piece> pieces(c.spheres.size());
  for (size_t i = 0; i < pieces.size(); ++i) {
    pieces[i].points = c.members[i];
    pieces[i].sphere = c.spheres[i];
    pieces[i].sov = sov[i];
  }
  while (static_cast<int>(pieces.size()) < count) {
    measureSplits(index, o, &pieces, res);
    std::vector<size_t> order;
    for (size_t i = 0; i < pieces.size(); ++i)
      if (std::isfinite(pieces[i].gain)) order.push_back(i);
    if (order.empty()) break;
    const bool by_first = first.size() == c.spheres.size() && pieces.size() == first.size();
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) {
      return by_first ? first[x] > first[y] : pieces[x].gain > pieces[y].gain;
    });
    order.resize(std::min(order.size(), static_cast<size_t>(count) - pieces.size()));
    for (size_t i : order) {
      Piece& p = pieces[i];
      Piece half;
      half.points = std::move(p.split.b);
      half.sphere = p.split.ub.sphere;
      half.sov = p.split.ub.sov;
      p.points = std::move(p.split.a);
      p.sphere = p.split.ua.sphere;
      p.sov = p.split.ua.sov;
      p.split_known = false;
      p.gain = -std::numeric_limits<double>::infinity();
      pieces.push_back(std::move(half));
    }
  }
  detail::Clustering out;
  out.energy = 0.0;
  for (Piece& p : pieces) {
    out.spheres.push_back(p.sphere);
    out.members.push_back(std::move(p.points));
    out.energy += p.sov;
  }
  res->seconds.teleport += detail::secondsSince(tt);
  return out;
}

}  // namespace

namespace {

// A count's fit and the clustering it ended (the next counts start from the clustering).
struct CountFit {
  detail::Clustering clustering;
  FitResult fit;
};

// How a count is clustered warm from a smaller one: from the largest at most count / ratio
// (ProgressiveOptions::start_ratio), in at most `rounds` rounds.
struct WarmStart {
  int ratio = ProgressiveOptions{}.start_ratio;
  int rounds = kWarmRounds;
};

// The fit at o.num_spheres from the clustering of `from` (0: seeds), ended as fitSpheres ends
// one (its interior bound with the geometry kept in `cells`, or none); its seconds from here.
// Defined below, with the clustering it calls.
Expected<CountFit> fitCount(const SolidIndex& index, const detail::PointSet& ps,
                            const std::map<int, detail::Clustering>& done, int from,
                            std::span<const double> split_first, const FitOptions& o,
                            const WarmStart& warm, detail::GeometryForest* cells = nullptr);

}  // namespace

// The largest count's fit from seeds on a thread of its own (ProgressiveOptions::top_alongside),
// in a task arena of its own: the run's other fits on the calling thread never run its tasks
// (nor it theirs), so the caller's progress callback and cancelling stay on the caller's thread.
// Its own progress callback keeps its latest progress, which take() passes on to the caller's
// while it waits, and stops it once the run is destroyed. Two fits at once instead of one after
// the other: a curve 1 ... 64 (fitCurve) took 0.83 of the time on spot.obj on 2 cores, the same
// sets (docs/benchmarks.md, "Progressive fitting").
class TopAlongside {
 public:
  TopAlongside(const SolidIndex& index, const detail::PointSet& ps, const FitOptions& options,
               int threads)
      : options_(options), report_(options.progress) {
    options_.progress = [this](const FitProgress& p) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        latest_ = p;
      }
      if (abandoned_.load()) throw Abandoned{};
    };
    thread_ = std::thread([this, &index, &ps, threads] {
      try {
        tbb::task_arena arena(threads);
        arena.execute([&] { made_.emplace(fitCount(index, ps, {}, 0, {}, options_, {})); });
      } catch (...) {
        error_ = std::current_exception();
      }
      {
        std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
      }
      done_cv_.notify_all();
    });
  }
  TopAlongside(const TopAlongside&) = delete;
  TopAlongside& operator=(const TopAlongside&) = delete;
  ~TopAlongside() {
    abandoned_ = true;
    if (thread_.joinable()) thread_.join();
  }

  // Waits for the fit, calling the caller's progress callback with its latest progress about
  // every progress_interval (so that the callback may cancel the wait by throwing); rethrows
  // what stopped the fit.
  Expected<CountFit> take() {
    const auto interval =
        std::chrono::duration<double>(std::max(options_.progress_interval, kMinWaitSeconds));
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_cv_.wait_for(lock, interval, [&] { return done_; }))
      if (report_ && latest_) {
        const FitProgress p = *latest_;
        lock.unlock();
        report_(p);
        lock.lock();
      }
    lock.unlock();
    if (thread_.joinable()) thread_.join();
    if (error_) std::rethrow_exception(error_);
    return std::move(*made_);
  }

 private:
  // take() waits at least this long between calls of the caller's callback (seconds), whatever
  // FitOptions::progress_interval (0 allowed) says.
  static constexpr double kMinWaitSeconds = 0.01;
  struct Abandoned {};
  FitOptions options_;
  std::function<void(const FitProgress&)> report_;  // the caller's callback
  std::atomic<bool> abandoned_{false};
  std::mutex mutex_;  // guards latest_ and done_
  std::condition_variable done_cv_;
  std::optional<FitProgress> latest_;
  bool done_ = false;
  std::optional<Expected<CountFit>> made_;
  std::exception_ptr error_;
  std::thread thread_;
};

struct ProgressiveFit::Impl {
  const SolidIndex& index;
  FitOptions options;
  ProgressiveOptions progressive;
  detail::PointSet ps;                            // sampled for options.num_spheres spheres
  std::map<int, detail::Clustering> clusterings;  // by count: each fit's, before its bound
  std::map<int, FitResult> fits;                  // by count
  std::optional<detail::SplitChain> chain;        // the last count fitted or stepped
  std::optional<detail::SplitChain> fitted;       // the last count fitted
  std::unique_ptr<TopAlongside> top;              // the largest count, made beside the others
  // The interior cubes' geometry, kept from bound to bound of the fits and steps made on the
  // calling thread (boundInterior; the largest count beside them bounds without it).
  detail::GeometryForest cells;
};

ProgressiveFit::ProgressiveFit(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ProgressiveFit::ProgressiveFit(ProgressiveFit&&) noexcept = default;
ProgressiveFit& ProgressiveFit::operator=(ProgressiveFit&&) noexcept = default;
ProgressiveFit::~ProgressiveFit() = default;

const ProgressiveFit::Impl& ProgressiveFit::impl() const {
  assert(impl_ && "ProgressiveFit used after a move");
  return *impl_;
}

ProgressiveFit::Impl& ProgressiveFit::impl() {
  assert(impl_ && "ProgressiveFit used after a move");
  return *impl_;
}

bool ProgressiveFit::allows(const FitOptions& options) {
  return options.method == FitMethod::kVariational && options.restarts == 1 &&
         options.decimation == 0.0;
}

int ProgressiveFit::maxCount() const { return impl().options.num_spheres; }

Expected<ProgressiveFit> ProgressiveFit::start(const SolidIndex& index, const FitOptions& options,
                                               const ProgressiveFit* warm_from,
                                               const ProgressiveOptions& progressive) {
  if (Status st = detail::checkFitOptions(index, options); !st) return st.error();
  if (progressive.start_ratio < 1)
    return Error{ErrorCode::kInvalidArgument, "start_ratio must be at least 1"};
  if (progressive.warm_rounds_below_half < 0)
    return Error{ErrorCode::kInvalidArgument, "warm_rounds_below_half must be at least 0"};
  if (!allows(options))
    return Error{ErrorCode::kInvalidArgument,
                 "progressive fitting takes the variational method with one restart and no "
                 "decimation"};
  auto impl =
      std::unique_ptr<Impl>(new Impl{index, options, progressive, {}, {}, {}, {}, {}, {}, {}});
  impl->ps = detail::samplePoints(index, detail::fitTargetPoints(options), options.interior_share,
                                  options.seed);
  const int64_t points = static_cast<int64_t>(impl->ps.points.size());
  if (points < options.num_spheres)
    return Error{ErrorCode::kInvalidArgument,
                 "asked for up to " + std::to_string(options.num_spheres) + " spheres but only " +
                     std::to_string(points) + " points were sampled (raise --points)"};
  if (warm_from) {
    if (&warm_from->impl().index != &index)
      return Error{ErrorCode::kInvalidArgument,
                   "a progressive run can start only from a run on the same solid"};
    for (const auto& [count, c] : warm_from->impl().clusterings)
      if (count <= options.num_spheres) impl->clusterings.emplace(count, c);
  }
  ProgressiveFit run(std::move(impl));
  Impl& m = run.impl();
  // The caller's thread limit sizes the fit's arena: its arena's, under tbb::global_control's
  // (which this_task_arena::max_concurrency does not report: `sphereset --threads 1`).
  const int threads = std::min(tbb::this_task_arena::max_concurrency(),
                               static_cast<int>(tbb::global_control::active_value(
                                   tbb::global_control::max_allowed_parallelism)));
  if (progressive.top_alongside && progressive.top_from_seeds &&
      run.startCount(options.num_spheres) == 0 && threads > 1) {
    try {
      m.top = std::make_unique<TopAlongside>(m.index, m.ps, m.options, threads);
    } catch (const std::system_error&) {
      // No thread to spare: the largest count is made when asked for, as without the option.
    }
  }
  return run;
}

namespace {

// The count a fit at `count` starts from: `count` itself when clustered and `adopt`, else the
// largest clustered count below it and at most count / ratio, else 0 (from seeds).
int startFrom(const std::map<int, detail::Clustering>& done, int count, int ratio, bool adopt) {
  if (adopt && done.contains(count)) return count;
  auto above = done.upper_bound(ratio <= 1 ? count - 1 : count / ratio);
  return above == done.begin() ? 0 : std::prev(above)->first;
}

// The clustering of `count` spheres: the one another run (start's warm_from) made, taken as it
// is (ProgressiveOptions::adopt); else from seeds when no smaller count was clustered; else from
// the largest smaller count's, split (splitClusters) and clustered again.
detail::Clustering clusterCount(const SolidIndex& index, const detail::PointSet& ps,
                                const std::map<int, detail::Clustering>& done, int count, int from,
                                const WarmStart& warm_start, std::span<const double> split_first,
                                const FitOptions& o, FitResult* res, detail::ProgressScope* scope) {
  const auto progress = [&](int it, double e) { scope->report("clustering", it, e); };
  if (from == count) return done.at(count);  // adopted
  if (from == 0) {
    scope->report("clustering", 0, 0.0);
    return detail::clusterPoints(index, ps, detail::initialCentres(ps, count, o.init, o.seed), o,
                                 o.max_failed_teleports, res, progress);
  }
  const auto below = done.find(from);
  scope->report("splitting", 0, below->second.energy);
  detail::Clustering split = splitClusters(index, below->second, count, split_first, o, res);
  if (static_cast<int>(split.spheres.size()) != count) return {};
  FitOptions warm = o;
  warm.max_iterations = std::min(o.max_iterations, warm_start.rounds);
  const int teleports = warm_start.ratio <= 1
                            ? std::min(o.max_failed_teleports, kSettledFailedTeleports)
                            : o.max_failed_teleports;
  return detail::clusterFrom(index, ps, std::move(split), warm, teleports, res, progress);
}

}  // namespace

namespace {

Status countInRange(int count, int max_count) {
  if (count >= 1 && count <= max_count) return {};
  return Error{ErrorCode::kInvalidArgument,
               "count " + std::to_string(count) + " is outside 1 to " + std::to_string(max_count)};
}

// A count's result before it is made: the run's points.
FitResult pointsOf(const detail::PointSet& ps) {
  FitResult res;
  res.points = static_cast<int64_t>(ps.points.size());
  res.interior_points = ps.interior;
  return res;
}

}  // namespace

int ProgressiveFit::startCount(int count) const {
  const Impl& m = impl();
  if (m.fits.contains(count)) return count;  // clustered by this run
  const bool adopted = m.progressive.adopt && m.clusterings.contains(count);
  if (!adopted && ((m.progressive.top_from_seeds && count == m.options.num_spheres) ||
                   std::ranges::find(m.progressive.seeded, count) != m.progressive.seeded.end()))
    return 0;
  return startFrom(m.clusterings, count, m.progressive.start_ratio, m.progressive.adopt);
}

namespace {

Expected<CountFit> fitCount(const SolidIndex& index, const detail::PointSet& ps,
                            const std::map<int, detail::Clustering>& done, int from,
                            std::span<const double> split_first, const FitOptions& o,
                            const WarmStart& warm, detail::GeometryForest* cells) {
  const int count = o.num_spheres;
  const auto t0 = detail::FitClock::now();
  CountFit out;
  FitResult& res = out.fit;
  res = pointsOf(ps);
  detail::ProgressScope scope(o, t0);
  detail::Clustering c =
      clusterCount(index, ps, done, count, from, warm, split_first, o, &res, &scope);
  res.converged = c.converged;
  if (c.spheres.empty())
    return Error{ErrorCode::kInvalidArgument,
                 "could not place " + std::to_string(count) + " non-empty clusters"};
  res.energy_before_bounding = c.energy;
  out.clustering = c;
  scope.report("bounding", res.iterations, c.energy);
  const auto tb = detail::FitClock::now();
  detail::finishFit(index, ps, o, &c, &res, cells);
  res.seconds.bounding = detail::secondsSince(tb);
  res.seconds.total = detail::secondsSince(t0);
  scope.report("done", res.iterations, res.energy);
  return out;
}

// How `count` is clustered warm in a run up to `max_count`.
WarmStart warmStart(const ProgressiveOptions& p, int count, int max_count) {
  WarmStart w{.ratio = p.start_ratio};
  if (p.warm_rounds_below_half > 0 && 2 * count < max_count) w.rounds = p.warm_rounds_below_half;
  return w;
}

}  // namespace

Expected<FitResult> ProgressiveFit::fit(int count, std::span<const double> split_first) {
  Impl& m = impl();
  if (Status st = countInRange(count, m.options.num_spheres); !st) return st.error();
  if (auto it = m.fits.find(count); it != m.fits.end()) {
    m.chain = m.fitted = detail::startChain(it->second.spheres, it->second.outside_volume);
    return it->second;
  }
  FitOptions o = m.options;
  o.num_spheres = count;
  const int from = startCount(count);
  if (!split_first.empty() &&
      (from == 0 || from == count || split_first.size() != m.clusterings.at(from).spheres.size()))
    return Error{ErrorCode::kInvalidArgument,
                 "split_first needs one value per sphere of the count the fit starts from (" +
                     std::to_string(from) + ")"};
  std::unique_ptr<TopAlongside> top = count == m.options.num_spheres ? std::move(m.top) : nullptr;
  if (from != 0) top.reset();  // not from seeds after all (adopted): stopped, not taken
  Expected<CountFit> made =
      top ? top->take()
          : fitCount(m.index, m.ps, m.clusterings, from, split_first, o,
                     warmStart(m.progressive, count, m.options.num_spheres), &m.cells);
  if (!made) return made.error();
  m.clusterings[count] = std::move(made->clustering);
  const FitResult& res = made->fit;
  m.chain = m.fitted = detail::startChain(res.spheres, res.outside_volume);
  return m.fits[count] = res;
}

void ProgressiveFit::forgetAnswers() { impl().cells = detail::GeometryForest{}; }

Expected<FitResult> ProgressiveFit::step(int count) {
  Impl& m = impl();
  if (Status st = countInRange(count, m.options.num_spheres); !st) return st.error();
  const auto next_to = [&](const std::optional<detail::SplitChain>& c) {
    return c && (c->count == count - 1 || c->count == count + 1);
  };
  if (!next_to(m.chain) && next_to(m.fitted)) m.chain = m.fitted;
  if (!next_to(m.chain))
    return Error{ErrorCode::kInvalidArgument,
                 "a step to " + std::to_string(count) + " spheres needs the run's last fit at " +
                     std::to_string(count - 1) + " or " + std::to_string(count + 1)};
  const auto t0 = detail::FitClock::now();
  FitOptions o = m.options;
  o.num_spheres = count;
  FitResult res = pointsOf(m.ps);
  detail::ProgressScope scope(o, t0);
  const bool up = m.chain->count == count - 1;
  const double energy_before = detail::totalOf(m.chain->sov);
  scope.report(up ? "splitting" : "removing", 0, energy_before);
  detail::SplitChain next = *m.chain;
  if (up ? !detail::splitLocally(m.index, m.ps, o, &next, &res, &m.cells)
         : !detail::removeLocally(m.index, m.ps, o, &next, &res, &m.cells))
    return Error{ErrorCode::kInvalidArgument, "no sphere of the fit at " +
                                                  std::to_string(m.chain->count) + " can be " +
                                                  (up ? "split" : "removed")};
  m.chain = std::move(next);
  res.energy_before_bounding = energy_before;  // the count it came from
  res.seconds.total = detail::secondsSince(t0);
  scope.report("done", 0, res.energy);
  return res;
}

}  // namespace sphereset

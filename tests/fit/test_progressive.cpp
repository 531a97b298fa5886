// Progressive fitting (ProgressiveFit, src/fit/progressive.cpp): every count's fit bounds the
// solid (brute force), a first count (and the largest, asked to) is exactly fitSpheres' fit,
// warm-started counts stay close to independent fits, and the same calls give the same spheres
// for any thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "coverage_oracle.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

FitOptions seededOptions(int max_count, FitQuality quality) {
  FitOptions o = fitPreset(max_count, quality);
  o.seed = 3;
  return o;
}
FitOptions quickOptions(int max_count) { return seededOptions(max_count, FitQuality::kFast); }
// A generous bound on how long a run takes to stop a fit it no longer needs (seconds; the fit
// polls about every FitOptions::progress_interval, 0.25 s).
constexpr double kStopSeconds = 5.0;

TEST(ProgressiveFit, EveryCountBoundsTheSolidWithItsCount) {
  const Mesh torus = test::makeTorus(1.0, 0.3, 24, 12);
  const SolidIndex idx(torus);
  auto run = ProgressiveFit::start(idx, quickOptions(16));
  ASSERT_TRUE(run.ok()) << run.error().message;
  for (int n : {1, 2, 3, 5, 8, 16}) {
    auto f = run->fit(n);
    ASSERT_TRUE(f.ok()) << f.error().message;
    ASSERT_EQ(f->spheres.size(), static_cast<size_t>(n));
    EXPECT_EQ(test::uncoveredSurfacePoints(torus, f->spheres, 30), 0) << "n = " << n;
    EXPECT_NEAR(f->energy, test::totalSov(idx, f->spheres), 1e-12 * f->energy) << "n = " << n;
  }
}

TEST(ProgressiveFit, AFirstCountIsTheFitFromSeeds) {
  // With no smaller count fitted, the clustering starts from seeds as fitSpheres does; with the
  // same points (both counts take 5000 below 50 spheres), the same spheres, bit for bit.
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = quickOptions(12);
  auto run = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok());
  auto p = run->fit(6);
  o.num_spheres = 6;
  auto f = fitSpheres(idx, o);
  ASSERT_TRUE(p.ok() && f.ok());
  ASSERT_EQ(p->spheres.size(), f->spheres.size());
  for (size_t i = 0; i < f->spheres.size(); ++i) {
    EXPECT_EQ(p->spheres[i].center, f->spheres[i].center);
    EXPECT_EQ(p->spheres[i].radius, f->spheres[i].radius);
  }
}

TEST(ProgressiveFit, TheLargestCountFromSeedsIsTheIndependentFit) {
  // With top_from_seeds the largest count is clustered from seeds though smaller counts were
  // clustered before it: fitSpheres's fit at that count, bit for bit. Without it, the same
  // count starts from half its count and differs.
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  const FitOptions o = quickOptions(8);
  ProgressiveOptions seeded;
  seeded.top_from_seeds = true;
  auto run = ProgressiveFit::start(idx, o, nullptr, seeded);
  auto warm = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok() && warm.ok());
  for (int n : {2, 4}) ASSERT_TRUE(run->fit(n).ok() && warm->fit(n).ok());
  EXPECT_EQ(run->startCount(8), 0);
  EXPECT_EQ(warm->startCount(8), 4);
  EXPECT_EQ(run->startCount(6), 2);  // below the largest, as start_ratio says
  auto top = run->fit(8);
  auto independent = fitSpheres(idx, o);
  auto warm_top = warm->fit(8);
  ASSERT_TRUE(top.ok() && independent.ok() && warm_top.ok());
  ASSERT_EQ(top->spheres.size(), independent->spheres.size());
  bool differs = false;
  for (size_t i = 0; i < top->spheres.size(); ++i) {
    EXPECT_EQ(top->spheres[i].center, independent->spheres[i].center) << i;
    EXPECT_EQ(top->spheres[i].radius, independent->spheres[i].radius) << i;
    differs = differs || warm_top->spheres[i].center != top->spheres[i].center;
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(run->startCount(8), 8);  // fitted now: asked again, the same fit
  // A largest count another run clustered is adopted before it would be clustered from seeds,
  // unless the run does not adopt.
  ProgressiveOptions adopting = seeded, own = seeded;
  own.adopt = false;
  auto quick = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(quick.ok() && quick->fit(8).ok());
  auto with_adopt = ProgressiveFit::start(idx, o, &*quick, adopting);
  auto without = ProgressiveFit::start(idx, o, &*quick, own);
  ASSERT_TRUE(with_adopt.ok() && without.ok());
  EXPECT_EQ(with_adopt->startCount(8), 8);
  EXPECT_EQ(without->startCount(8), 0);
  // The seeded counts start from seeds too, the others from half their count.
  ProgressiveOptions low;
  low.seeded = {4};
  auto chain = ProgressiveFit::start(idx, o, nullptr, low);
  ASSERT_TRUE(chain.ok());
  ASSERT_TRUE(chain->fit(1).ok());
  EXPECT_EQ(chain->startCount(2), 1);
  ASSERT_TRUE(chain->fit(2).ok());
  EXPECT_EQ(chain->startCount(4), 0);
  ASSERT_TRUE(chain->fit(4).ok());
  EXPECT_EQ(chain->startCount(8), 4);
}

TEST(ProgressiveFit, TheLargestCountMadeAlongsideIsTheSameFit) {
  // top_alongside makes the largest count on a thread of its own while the smaller ones are
  // fitted: every count the same spheres as without it, the largest fitSpheres's own, and the
  // caller's progress callback is called only from the caller's thread.
  tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = quickOptions(8);
  const std::thread::id caller = std::this_thread::get_id();
  int elsewhere = 0, calls = 0;
  o.progress = [&](const FitProgress&) {
    ++calls;
    elsewhere += std::this_thread::get_id() != caller;
  };
  ProgressiveOptions seeded, alongside;
  seeded.top_from_seeds = alongside.top_from_seeds = true;
  alongside.top_alongside = true;
  auto a = ProgressiveFit::start(idx, o, nullptr, alongside);
  auto b = ProgressiveFit::start(idx, o, nullptr, seeded);
  ASSERT_TRUE(a.ok() && b.ok());
  for (int n : {2, 4, 8}) {
    auto fa = a->fit(n);
    auto fb = b->fit(n);
    ASSERT_TRUE(fa.ok() && fb.ok());
    ASSERT_EQ(fa->spheres.size(), fb->spheres.size());
    for (size_t i = 0; i < fa->spheres.size(); ++i) {
      EXPECT_EQ(fa->spheres[i].center, fb->spheres[i].center) << n << " " << i;
      EXPECT_EQ(fa->spheres[i].radius, fb->spheres[i].radius) << n << " " << i;
    }
    EXPECT_EQ(fa->energy, fb->energy) << n;
  }
  EXPECT_GT(calls, 0);
  EXPECT_EQ(elsewhere, 0);
  EXPECT_EQ(a->startCount(8), 8);  // taken: asked again, the same fit
}

TEST(ProgressiveFit, WaitingForTheLargestCountReportsAndCancelsOnTheCallersThread) {
  // fit() at the largest count, made alongside, waits for it calling the caller's callback with
  // its progress (that count's), on the caller's thread; a callback that throws cancels the wait.
  tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = quickOptions(8);
  o.progress_interval = 0.0;
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0, elsewhere = 0, other_count = 0;
  o.progress = [&](const FitProgress& p) {
    ++calls;
    elsewhere += std::this_thread::get_id() != caller;
    other_count += p.spheres != 8;
  };
  ProgressiveOptions alongside;
  alongside.top_from_seeds = alongside.top_alongside = true;
  auto run = ProgressiveFit::start(idx, o, nullptr, alongside);
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->fit(8).ok());
  EXPECT_GT(calls, 0);
  EXPECT_EQ(elsewhere, 0);
  EXPECT_EQ(other_count, 0);
  o.progress = [&](const FitProgress&) { throw std::runtime_error("stop"); };
  auto cancelled = ProgressiveFit::start(idx, o, nullptr, alongside);
  ASSERT_TRUE(cancelled.ok());
  EXPECT_THROW((void)cancelled->fit(8), std::runtime_error);
}

// The process's threads (Linux: the Threads line of /proc/self/status; -1 where it is absent).
int processThreads() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
  return -1;
}

TEST(ProgressiveFit, TheLargestCountIsMadeAlongsideOnlyWhenThreadsAllowIt) {
  // Under a limit of one thread (tbb::global_control, as `sphereset --threads 1` sets it, which
  // the calling arena's max_concurrency does not report) start() starts no thread of its own;
  // under two it does, while the largest count is being made.
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  const FitOptions o = fitPreset(128);
  ProgressiveOptions alongside;
  alongside.top_from_seeds = alongside.top_alongside = true;
  const auto startedThreads = [&](int limit) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, limit);
    // A run without the option first, so that the pool's workers exist before the count.
    auto warm = ProgressiveFit::start(idx, o);
    EXPECT_TRUE(warm.ok());
    const int before = processThreads();
    auto run = ProgressiveFit::start(idx, o, nullptr, alongside);
    EXPECT_TRUE(run.ok());
    return processThreads() - before;
  };
  if (processThreads() < 0) GTEST_SKIP() << "no /proc/self/status";
  if (tbb::this_task_arena::max_concurrency() < 2) GTEST_SKIP() << "one core: never alongside";
  EXPECT_EQ(startedThreads(1), 0);
  EXPECT_GE(startedThreads(2), 1);
}

TEST(ProgressiveFit, ARunLeftWithItsLargestCountInFlightStopsIt) {
  // Destroyed before the largest count is taken (an error or a cancel in a smaller count), the
  // run stops that fit and returns; a cancel on the caller's thread still reaches the caller.
  // The largest count here (a fit at 256 from seeds) takes far longer than the bound below.
  tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = fitPreset(256);
  ProgressiveOptions alongside;
  alongside.top_from_seeds = alongside.top_alongside = true;
  {
    auto started = ProgressiveFit::start(idx, o, nullptr, alongside);
    ASSERT_TRUE(started.ok());
    std::optional<ProgressiveFit> run(std::move(started).value());
    ASSERT_TRUE(run->fit(1).ok());
    const auto t0 = std::chrono::steady_clock::now();
    run.reset();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
              kStopSeconds);
  }
  o = fitPreset(64);
  int calls = 0;
  o.progress = [&](const FitProgress&) {
    if (++calls == 3) throw std::runtime_error("stop");
  };
  auto run = ProgressiveFit::start(idx, o, nullptr, alongside);
  ASSERT_TRUE(run.ok());
  EXPECT_THROW((void)run->fit(4), std::runtime_error);
}

TEST(ProgressiveFit, WarmStartedCountsAreCloseToIndependentFits) {
  // A deterministic guard of the warm start's quality on one solid (docs/benchmarks.md measures
  // it over the shared meshes): within 15 % of a fit from seeds at each count.
  const Mesh torus = test::makeTorus(1.0, 0.3, 32, 16);
  const SolidIndex idx(torus);
  FitOptions o = fitPreset(16);
  o.seed = 5;
  auto run = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok());
  for (int n : {4, 8, 16}) {
    auto p = run->fit(n);
    FitOptions one = o;
    one.num_spheres = n;
    auto f = fitSpheres(idx, one);
    ASSERT_TRUE(p.ok() && f.ok());
    EXPECT_LT(p->energy, 1.15 * f->energy) << "n = " << n;
    if (n > 4) {
      EXPECT_GT(p->iterations, 0);  // it clustered again
    }
  }
}

TEST(ProgressiveFit, SameCallsSameSpheresForAnyThreadCount) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  auto curve = [&] {
    auto run = ProgressiveFit::start(idx, quickOptions(10));
    std::vector<Sphere> all;
    for (int n : {2, 7, 4, 10}) {
      auto f = run->fit(n);
      EXPECT_TRUE(f.ok());
      all.insert(all.end(), f->spheres.begin(), f->spheres.end());
    }
    return all;
  };
  const std::vector<Sphere> parallel = curve();
  std::vector<Sphere> single;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    single = curve();
  }
  ASSERT_EQ(parallel.size(), single.size());
  for (size_t i = 0; i < parallel.size(); ++i) {
    EXPECT_EQ(parallel[i].center, single[i].center);
    EXPECT_EQ(parallel[i].radius, single[i].radius);
  }
}

TEST(ProgressiveFit, ACountAskedAgainIsTheSameFit) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  auto run = ProgressiveFit::start(idx, quickOptions(8));
  auto a = run->fit(5);
  auto b = run->fit(8);
  auto c = run->fit(5);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a->spheres.size(), c->spheres.size());
  for (size_t i = 0; i < a->spheres.size(); ++i)
    EXPECT_EQ(a->spheres[i].center, c->spheres[i].center);
}

TEST(ProgressiveFit, EveryCountClustersThePointsOfTheLargest) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o;  // target_points 0: max(5000, 100 n)
  o.num_spheres = 80;
  o.max_iterations = 2;
  o.refine = false;
  auto run = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok());
  auto a = run->fit(3);
  ASSERT_TRUE(a.ok());
  EXPECT_NEAR(static_cast<double>(a->points), 8000.0, 800.0);
  auto b = run->fit(80);
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(a->points, b->points);
  EXPECT_EQ(b->spheres.size(), 80u);
}

TEST(ProgressiveFit, ACountStartsFromAtMostHalfOrFromTheCountBelow) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  auto half = ProgressiveFit::start(idx, quickOptions(16));
  auto below = ProgressiveFit::start(idx, quickOptions(16), nullptr, {.start_ratio = 1});
  ASSERT_TRUE(half.ok() && below.ok());
  for (ProgressiveFit* run : {&*half, &*below}) {
    EXPECT_EQ(run->startCount(5), 0);  // nothing clustered: from seeds
    ASSERT_TRUE(run->fit(2).ok());
    ASSERT_TRUE(run->fit(8).ok());
    EXPECT_EQ(run->startCount(8), 8);  // clustered: only ended again
  }
  EXPECT_EQ(half->startCount(12), 2);  // at most 6
  EXPECT_EQ(below->startCount(12), 8);
  EXPECT_EQ(half->startCount(3), 0);  // at most 1: none
  EXPECT_EQ(below->startCount(3), 2);
  EXPECT_FALSE(ProgressiveFit::start(idx, quickOptions(4), nullptr, {.start_ratio = 0}).ok());
}

TEST(ProgressiveFit, WarmCountsBelowHalfTheLargestTakeTheirOwnRounds) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  const FitOptions o = seededOptions(16, FitQuality::kDefault);
  // 1, 2 and 4 from seeds in both runs, so that both start 7 and 8 from the same sets.
  auto few =
      ProgressiveFit::start(idx, o, nullptr, {.seeded = {1, 2, 4}, .warm_rounds_below_half = 2});
  auto all = ProgressiveFit::start(idx, o, nullptr, {.seeded = {1, 2, 4}});
  ASSERT_TRUE(few.ok() && all.ok());
  for (int n : {1, 2, 4}) ASSERT_TRUE(few->fit(n).ok() && all->fit(n).ok());
  EXPECT_EQ(few->startCount(7), 2);
  EXPECT_EQ(few->startCount(8), 4);
  auto few7 = few->fit(7), all7 = all->fit(7);  // 7 of 16: below half, from 2
  auto few8 = few->fit(8), all8 = all->fit(8);  // 8: half, from 4 as well
  ASSERT_TRUE(few7.ok() && all7.ok() && few8.ok() && all8.ok());
  EXPECT_LE(few7->iterations, 2);
  EXPECT_GT(all7->iterations, 2);
  EXPECT_EQ(few8->iterations, all8->iterations);
  EXPECT_EQ(few8->energy, all8->energy);
  auto bad = ProgressiveFit::start(idx, o, nullptr, {.warm_rounds_below_half = -1});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.error().message.find("warm_rounds_below_half"), std::string::npos);
}

TEST(ProgressiveFit, WarmFromAdoptsAnotherRunsClusterings) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  auto quick = ProgressiveFit::start(idx, quickOptions(8));
  ASSERT_TRUE(quick.ok());
  ASSERT_TRUE(quick->fit(4).ok());
  const FitOptions full = seededOptions(8, FitQuality::kDefault);
  auto run = ProgressiveFit::start(idx, full, &*quick);
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(run->startCount(4), 4);  // adopted: only ended with this run's options
  EXPECT_EQ(run->startCount(8), 4);
  auto f = run->fit(8);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f->spheres.size(), 8u);
  EXPECT_EQ(test::uncoveredSurfacePoints(link, f->spheres, 20), 0);
  const Mesh box = test::makeBox(Vec3::Zero(), Vec3::Ones());
  const SolidIndex other(box);
  EXPECT_FALSE(ProgressiveFit::start(other, quickOptions(8), &*quick).ok());  // another solid
}

TEST(ProgressiveFit, WithoutAdoptingACountIsClusteredAgainFromTheOneBelow) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  auto quick = ProgressiveFit::start(idx, quickOptions(8));
  ASSERT_TRUE(quick.ok());
  ASSERT_TRUE(quick->fit(2).ok());
  auto quick4 = quick->fit(4);
  ASSERT_TRUE(quick4.ok());
  const FitOptions full = seededOptions(8, FitQuality::kDefault);
  auto adopting = ProgressiveFit::start(idx, full, &*quick, {.start_ratio = 1});
  auto own = ProgressiveFit::start(idx, full, &*quick, {.start_ratio = 1, .adopt = false});
  ASSERT_TRUE(adopting.ok() && own.ok());
  EXPECT_EQ(adopting->startCount(4), 4);
  EXPECT_EQ(own->startCount(4), 2);  // the quick run's 4 is a start for 5 and up only
  auto taken = adopting->fit(4);
  auto clustered = own->fit(4);
  ASSERT_TRUE(taken.ok() && clustered.ok());
  EXPECT_EQ(taken->iterations, 0);  // only ended
  EXPECT_GT(clustered->iterations, 0);
  EXPECT_EQ(test::uncoveredSurfacePoints(link, clustered->spheres, 20), 0);
  EXPECT_EQ(own->startCount(4), 4);  // its own now
  EXPECT_EQ(own->startCount(6), 4);
}

TEST(ProgressiveFit, SplitFirstSplitsTheSpheresGiven) {
  // From 4 to 5 spheres, each of the four singled out in turn: the split goes where it is told,
  // so the fits differ (ignored, all four would be the same fit), and each bounds the solid.
  const Mesh torus = test::makeTorus(1.0, 0.3, 24, 12);
  const SolidIndex idx(torus);
  const FitOptions o = quickOptions(8);
  const ProgressiveOptions below{.start_ratio = 1};
  auto run = ProgressiveFit::start(idx, o, nullptr, below);
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->fit(4).ok());
  const std::vector<double> wrong(3, 1.0);
  EXPECT_FALSE(run->fit(5, wrong).ok());  // one value per sphere of the count it starts from
  std::vector<std::vector<Sphere>> fits;
  for (int chosen = 0; chosen < 4; ++chosen) {
    auto again = ProgressiveFit::start(idx, o, nullptr, below);
    ASSERT_TRUE(again->fit(4).ok());
    std::vector<double> first(4, 0.0);
    first[chosen] = 1.0;
    auto five = again->fit(5, first);
    ASSERT_TRUE(five.ok()) << five.error().message;
    ASSERT_EQ(five->spheres.size(), 5u);
    EXPECT_EQ(test::uncoveredSurfacePoints(torus, five->spheres, 20), 0);
    fits.push_back(five->spheres);
  }
  int distinct = 0;
  for (size_t a = 0; a < fits.size(); ++a) {
    bool same_as_earlier = false;
    for (size_t b = 0; b < a; ++b) {
      bool same = true;
      for (size_t k = 0; k < 5; ++k) same = same && fits[a][k].center == fits[b][k].center;
      same_as_earlier = same_as_earlier || same;
    }
    distinct += same_as_earlier ? 0 : 1;
  }
  EXPECT_GE(distinct, 2);
}

TEST(ProgressiveFit, RefusesWhatItCannotHonour) {
  const Mesh box = test::makeBox(Vec3::Zero(), Vec3::Ones());
  const SolidIndex idx(box);
  for (auto change : std::vector<void (*)(FitOptions*)>{
           [](FitOptions* o) { o->restarts = 2; }, [](FitOptions* o) { o->decimation = 0.5; },
           [](FitOptions* o) { o->method = FitMethod::kKMeans; }}) {
    FitOptions o = quickOptions(4);
    change(&o);
    auto run = ProgressiveFit::start(idx, o);
    ASSERT_FALSE(run.ok());
    EXPECT_NE(run.error().message.find("progressive fitting takes"), std::string::npos);
  }
  FitOptions bad = quickOptions(4);
  bad.num_spheres = 0;
  EXPECT_FALSE(ProgressiveFit::start(idx, bad).ok());
  auto run = ProgressiveFit::start(idx, quickOptions(4));
  ASSERT_TRUE(run.ok());
  for (int n : {0, -1, 5}) {
    auto f = run->fit(n);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(f.error().message.find("outside 1 to 4"), std::string::npos);
  }
}

TEST(ProgressiveFit, AProgressCallbackThatThrowsCancels) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = quickOptions(8);
  int calls = 0;
  o.progress = [&](const FitProgress& p) {
    EXPECT_LE(p.spheres, 8);
    if (++calls == 3) throw std::runtime_error("stop");
  };
  auto run = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok());
  EXPECT_THROW((void)run->fit(8), std::runtime_error);
}

}  // namespace
}  // namespace sphereset

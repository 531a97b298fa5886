// One local split (ProgressiveFit::step, src/fit/local_split.cpp): a step adds one sphere and
// keeps the set bounded (the evaluation's certificate and a brute-force surface check), its
// figures are those of its spheres, a chain of steps lowers the outside volume, the same calls
// give the same spheres for any thread count, and steps that have no count before them are
// refused; a chain keeps only the split measures a step cannot have changed.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <string>
#include <vector>

#include "coverage_oracle.hpp"
#include "fit/fit_common.hpp"
#include "fit/local_split.hpp"
#include "fit/samples.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

FitOptions stepOptions(int max_count) {
  FitOptions o = fitPreset(max_count, FitQuality::kFast);
  o.seed = 3;
  return o;
}

// The fit at `from`, then steps up to `to`: each step's spheres.
std::vector<std::vector<Sphere>> stepsUpFrom(const SolidIndex& idx, const FitOptions& o, int from,
                                             int to) {
  auto run = ProgressiveFit::start(idx, o);
  EXPECT_TRUE(run.ok());
  std::vector<std::vector<Sphere>> sets;
  auto f = run->fit(from);
  EXPECT_TRUE(f.ok());
  sets.push_back(f->spheres);
  for (int n = from + 1; n <= to; ++n) {
    auto s = run->step(n);
    EXPECT_TRUE(s.ok()) << s.error().message;
    if (!s.ok()) break;
    sets.push_back(s->spheres);
  }
  return sets;
}

TEST(LocalSplit, EachStepAddsOneSphereAndKeepsTheBound) {
  const Mesh torus = test::makeTorus(1.0, 0.3, 24, 12);
  const SolidIndex idx(torus);
  auto run = ProgressiveFit::start(idx, stepOptions(12));
  ASSERT_TRUE(run.ok());
  auto f = run->fit(4);
  ASSERT_TRUE(f.ok());
  double previous = f->energy;
  for (int n = 5; n <= 12; ++n) {
    auto s = run->step(n);
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ(s->spheres.size(), static_cast<size_t>(n));
    EXPECT_EQ(test::uncoveredSurfacePoints(torus, s->spheres, 30), 0) << "n = " << n;
    auto ev = evaluateSpheres(idx, s->spheres, fitCheckEvalOptions(1));
    ASSERT_TRUE(ev.ok());
    EXPECT_TRUE(ev->surface_covered && ev->interior_covered) << "n = " << n;
    EXPECT_NEAR(s->energy, test::totalSov(idx, s->spheres), 1e-12 * s->energy) << "n = " << n;
    ASSERT_EQ(s->outside_volume.size(), s->spheres.size());
    EXPECT_EQ(s->energy_before_bounding, previous) << "n = " << n;  // the count it came from
    previous = s->energy;
  }
  // Eight splits, each chosen for the outside volume it saves, end below the fit they started
  // from (on this torus each saves some).
  EXPECT_LT(previous, f->energy);
  // Down from there: one sphere fewer, still bounded.
  auto down = run->step(11);
  ASSERT_TRUE(down.ok()) << down.error().message;
  ASSERT_EQ(down->spheres.size(), 11u);
  EXPECT_EQ(test::uncoveredSurfacePoints(torus, down->spheres, 30), 0);
  auto ev = evaluateSpheres(idx, down->spheres, fitCheckEvalOptions(1));
  ASSERT_TRUE(ev.ok());
  EXPECT_TRUE(ev->surface_covered && ev->interior_covered);
}

// A chain keeps a sphere's split measure across a step only where the step cannot have changed
// it (takeIntoChain: its ball meets no changed one): before every split, each measure the chain
// kept equals the one a chain started afresh from the same set measures, so the split makes the
// same set, with fewer measures; removal steps (whose own measures are a heuristic) in between,
// and padding on the spheres.
TEST(LocalSplit, AKeptSplitMeasureIsTheOneMeasuredAfresh) {
  const SolidIndex idx(test::makeTorus(1.0, 0.3, 24, 12));
  FitOptions o = stepOptions(4);
  o.padding = 0.01;
  auto fit = fitSpheres(idx, o);
  ASSERT_TRUE(fit.ok()) << fit.error().message;
  const detail::PointSet ps =
      detail::samplePoints(idx, detail::fitTargetPoints(o), o.interior_share, o.seed);
  detail::SplitChain kept = detail::startChain(fit->spheres, fit->outside_volume);
  int64_t kept_queries = 0, fresh_queries = 0, compared = 0;
  for (int step = 0; step < 10; ++step) {
    SCOPED_TRACE("step " + std::to_string(step));
    if (step % 4 == 3) {  // one sphere fewer, then splits from there
      FitResult r;
      ASSERT_TRUE(detail::removeLocally(idx, ps, o, &kept, &r));
      continue;
    }
    const std::vector<bool> measured = kept.split_measured;  // kept from the steps before
    detail::SplitChain fresh = detail::startChain(kept.spheres, kept.sov);
    FitResult rk, rf;
    ASSERT_TRUE(detail::splitLocally(idx, ps, o, &kept, &rk));
    ASSERT_TRUE(detail::splitLocally(idx, ps, o, &fresh, &rf));
    // Every measure the split chose among, the kept ones included, as measured afresh.
    for (size_t i = 0; i < measured.size(); ++i) {
      EXPECT_EQ(kept.gain[i], fresh.gain[i]) << "sphere " << i;
      compared += measured[i];
    }
    ASSERT_EQ(kept.spheres.size(), fresh.spheres.size());
    for (size_t i = 0; i < kept.spheres.size(); ++i) {
      EXPECT_EQ(kept.spheres[i].center, fresh.spheres[i].center);
      EXPECT_EQ(kept.spheres[i].radius, fresh.spheres[i].radius);
    }
    if (step > 0) kept_queries += rk.optimizer_queries, fresh_queries += rf.optimizer_queries;
  }
  EXPECT_GT(compared, 0);                  // measures were kept across steps
  EXPECT_LT(kept_queries, fresh_queries);  // and not made again
}

TEST(LocalSplit, PaddingStaysOnEverySphere) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  FitOptions o = stepOptions(6);
  o.padding = 0.01;
  auto run = ProgressiveFit::start(idx, o);
  ASSERT_TRUE(run.ok());
  ASSERT_TRUE(run->fit(4).ok());
  auto s = run->step(5);
  ASSERT_TRUE(s.ok()) << s.error().message;
  // Unpadded, the step's set still bounds the solid: the padding is on top of the bound; the
  // same for a step down from the fit at 6.
  const auto bare = [&](std::vector<Sphere> sp) {
    for (Sphere& b : sp) b.radius -= o.padding;
    return sp;
  };
  EXPECT_EQ(test::uncoveredSurfacePoints(link, bare(s->spheres), 20), 0);
  ASSERT_TRUE(run->fit(6).ok());
  auto down = run->step(5);
  ASSERT_TRUE(down.ok()) << down.error().message;
  ASSERT_EQ(down->spheres.size(), 5u);
  EXPECT_EQ(test::uncoveredSurfacePoints(link, bare(down->spheres), 20), 0);
  auto ev = evaluateSpheres(idx, bare(down->spheres), fitCheckEvalOptions(1));
  ASSERT_TRUE(ev.ok());
  EXPECT_TRUE(ev->surface_covered && ev->interior_covered);
}

TEST(LocalSplit, SameCallsSameSpheresForAnyThreadCount) {
  const Mesh link = test::robotLink();
  const SolidIndex idx(link);
  std::vector<std::vector<Sphere>> one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = stepsUpFrom(idx, stepOptions(9), 4, 7);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = stepsUpFrom(idx, stepOptions(9), 4, 7);
  }
  ASSERT_EQ(one.size(), 4u);
  ASSERT_EQ(one.size(), two.size());
  for (size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one[k].size(), two[k].size());
    for (size_t i = 0; i < one[k].size(); ++i) {
      EXPECT_EQ(one[k][i].center, two[k][i].center);
      EXPECT_EQ(one[k][i].radius, two[k][i].radius);
    }
  }
}

TEST(LocalSplit, AStepNeedsTheCountBelowAsTheRunsLast) {
  const SolidIndex idx(test::robotLink());
  auto run = ProgressiveFit::start(idx, stepOptions(8));
  ASSERT_TRUE(run.ok());
  const auto refused = [&](int n, const char* words) {
    auto s = run->step(n);
    ASSERT_FALSE(s.ok()) << n;
    EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(s.error().message.find(words), std::string::npos) << s.error().message;
  };
  refused(3, "needs the run's last fit at 2 or 4");  // nothing fitted yet
  ASSERT_TRUE(run->fit(4).ok());
  refused(6, "needs the run's last fit at 5 or 7");
  refused(0, "outside 1 to 8");
  refused(9, "outside 1 to 8");
  EXPECT_TRUE(run->step(5).ok());
  EXPECT_TRUE(run->step(6).ok());
}

}  // namespace
}  // namespace sphereset

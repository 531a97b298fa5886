// The fewest spheres that meet a tolerance (fitToTolerance): the count found meets it with a
// certified protrusion, no smaller count tried met it, the doubling and the bisection are in the
// curve, a tolerance no count meets gives the best count tried, and bad requests are refused.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

FitRequest fastRequest() {
  FitRequest r;
  r.quality = FitQuality::kFast;
  return r;
}

TEST(ToleranceFit, TheCountFoundMeetsItAndNoSmallerCountTriedDid) {
  const SolidIndex index(test::robotLink());
  ToleranceOptions t;
  t.max_protrusion_fraction = 0.06;
  t.max_spheres = 64;
  auto r = fitToTolerance(index, fastRequest(), t);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r->met);
  const double limit = 0.06 * index.bounds().diagonal();
  EXPECT_DOUBLE_EQ(r->protrusion_limit, limit);
  EXPECT_LE(r->eval.protrusion, limit);
  EXPECT_EQ(static_cast<int>(r->fit.spheres.size()), r->n);
  EXPECT_TRUE(r->eval.surface_covered && r->eval.interior_covered);
  // The protrusion reported is the certified one of the set returned.
  ProtrusionOptions po;
  po.tolerance = 1e-3 * index.bounds().diagonal();
  auto p = sphereProtrusion(index, r->fit.spheres, po);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p->upper, r->eval.protrusion);
  std::set<int> tried;
  for (const CurvePoint& c : r->curve) {
    EXPECT_TRUE(tried.insert(c.n).second) << "count " << c.n << " tried twice";
    EXPECT_EQ(c.meets, c.covered && c.protrusion <= limit) << c.n;
    if (c.n < r->n) {
      EXPECT_FALSE(c.meets) << c.n;
    }
  }
  // Doubling from 1 up to the first count that met it, then bisection below it.
  for (int n = 1; n < r->n; n *= 2) EXPECT_EQ(tried.count(n), 1u) << n;
  // The bisection ends next to it: the count below it was tried and did not meet it.
  EXPECT_TRUE(r->n == 1 || tried.count(r->n - 1) == 1);
}

TEST(ToleranceFit, AToleranceNoCountMeetsGivesTheBestTried) {
  const SolidIndex index(test::makeBox(Vec3::Zero(), Vec3(1.0, 0.2, 0.1)));
  ToleranceOptions t;
  t.max_protrusion = 1e-6;  // a thin box: never that tight with 4 spheres
  t.max_spheres = 4;
  auto r = fitToTolerance(index, fastRequest(), t);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->met);
  ASSERT_EQ(r->curve.size(), 3u);  // 1, 2, 4
  double best = r->curve[0].protrusion;
  for (const CurvePoint& c : r->curve) best = std::min(best, c.protrusion);
  EXPECT_EQ(r->eval.protrusion, best);
}

TEST(ToleranceFit, BothLimitsTogether) {
  const SolidIndex index(test::makeTorus(1.0, 0.3, 24, 12));
  ToleranceOptions t;
  t.max_er = 0.8;
  t.max_protrusion_fraction = 0.1;
  t.max_spheres = 64;
  auto r = fitToTolerance(index, fastRequest(), t);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r->met);
  EXPECT_LE(r->eval.er_sum, 0.8);
  EXPECT_LE(r->eval.protrusion, 0.1 * index.bounds().diagonal());
}

TEST(ToleranceFit, CountsAreOneProgressiveRunWhenTheRequestAllowsIt) {
  const SolidIndex index(test::makeTorus(1.0, 0.3, 24, 12));
  ToleranceOptions t;
  t.max_er = 0.8;
  t.max_spheres = 64;
  auto r = fitToTolerance(index, fastRequest(), t);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r->progressive);
  // The same counts in the same order through a ProgressiveFit give the same set.
  FitRequest top = fastRequest();
  top.num_spheres = 64;
  auto run = ProgressiveFit::start(index, fitOptionsFor(top));
  ASSERT_TRUE(run.ok());
  Expected<FitResult> last = Error{ErrorCode::kInvalidArgument, "none"};
  for (const CurvePoint& c : r->curve) {
    auto f = run->fit(c.n);
    ASSERT_TRUE(f.ok());
    if (c.n == r->n) last = std::move(f);
  }
  ASSERT_TRUE(last.ok());
  ASSERT_EQ(last->spheres.size(), r->fit.spheres.size());
  for (size_t i = 0; i < last->spheres.size(); ++i)
    EXPECT_EQ(last->spheres[i].center, r->fit.spheres[i].center);
  // Restarts are not a progressive run's: independent fits.
  FitRequest restarts = fastRequest();
  restarts.restarts = 2;
  t.max_spheres = 4;
  auto ind = fitToTolerance(index, restarts, t);
  ASSERT_TRUE(ind.ok());
  EXPECT_FALSE(ind->progressive);
}

TEST(ToleranceFit, FewPointsBoundTheRunsWindow) {
  // A progressive run cannot hold more spheres than points: with 40 points the search still
  // runs (its first run holds 40 spheres at most, not 64).
  const SolidIndex index(test::robotLink());
  FitRequest r = fastRequest();
  r.points = 40;
  ToleranceOptions t;
  t.max_er = 50.0;
  auto found = fitToTolerance(index, r, t);
  ASSERT_TRUE(found.ok()) << found.error().message;
  EXPECT_TRUE(found->met);
  EXPECT_TRUE(found->progressive);
  FitRequest given = fastRequest();
  ASSERT_TRUE(setFitRequestOption(&given, "n", "8").ok());
  auto both = fitToTolerance(index, given, t);
  ASSERT_FALSE(both.ok());
  EXPECT_NE(both.error().message.find("n and a tolerance"), std::string::npos);
}

// fit_progress reports each count's fit from inside it (FitProgress::spheres is the count being
// fitted, in the order the counts are tried), and a throw from it ends the search mid-fit: the
// count running never reaches `progress`.
TEST(ToleranceFit, FitProgressReportsInsideEachCountAndMayCancel) {
  const SolidIndex index(test::robotLink());
  ToleranceOptions t;
  t.max_protrusion_fraction = 0.06;
  t.max_spheres = 64;
  std::vector<int> fitted, finished;
  t.fit_progress = [&](const FitProgress& p) {
    if (fitted.empty() || fitted.back() != p.spheres) fitted.push_back(p.spheres);
  };
  t.progress = [&](const CurvePoint& c) { finished.push_back(c.n); };
  auto r = fitToTolerance(index, fastRequest(), t);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(fitted, finished);  // every count's fit reported, in the order tried
  struct Stop {};
  finished.clear();
  t.fit_progress = [&](const FitProgress& p) {
    if (p.spheres == 2) throw Stop{};
  };
  EXPECT_THROW(fitToTolerance(index, fastRequest(), t), Stop);
  EXPECT_EQ(finished, std::vector<int>{1});
}

TEST(ToleranceFit, BadRequestsAreRefused) {
  const SolidIndex index(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  ToleranceOptions t;
  EXPECT_EQ(fitToTolerance(index, fastRequest(), t).error().code, ErrorCode::kInvalidArgument);
  t.max_er = 0.5;
  t.max_spheres = 0;
  auto capped = fitToTolerance(index, fastRequest(), t);
  ASSERT_FALSE(capped.ok());
  EXPECT_NE(capped.error().message.find("max_spheres '0': expected an integer from 1"),
            std::string::npos);
  // A limit set in the struct is checked as its option's text: a negative one is not ignored.
  t.max_spheres = 4;
  t.max_protrusion = -1.0;
  auto negative = fitToTolerance(index, fastRequest(), t);
  ASSERT_FALSE(negative.ok());
  EXPECT_EQ(
      negative.error().message,
      "max_protrusion '-1': expected a number above 0 and at most 1e+30, optionally followed by %");
  t.max_protrusion = 0.0;
  t.max_protrusion_fraction = -0.05;  // checked as the percentage a user would type
  auto fraction = fitToTolerance(index, fastRequest(), t);
  ASSERT_FALSE(fraction.ok());
  EXPECT_EQ(fraction.error().message,
            "max_protrusion '-5%': expected a number above 0 and at most 1e+30, optionally "
            "followed by %");
  t.max_protrusion_fraction = 0.0;
  ToleranceOptions o;
  EXPECT_TRUE(setToleranceOption(&o, "max_protrusion", "5%").ok());
  EXPECT_DOUBLE_EQ(o.max_protrusion_fraction, 0.05);
  EXPECT_EQ(o.max_protrusion, 0.0);
  EXPECT_TRUE(setToleranceOption(&o, "max_protrusion", "0.01").ok());
  EXPECT_DOUBLE_EQ(o.max_protrusion, 0.01);
  EXPECT_EQ(o.max_protrusion_fraction, 0.0);
  for (const char* bad : {"nan", "-1", "5%%", "%", "inf", "1e40", "0", "0%"})
    EXPECT_FALSE(setToleranceOption(&o, "max_protrusion", bad).ok()) << bad;
  EXPECT_FALSE(setToleranceOption(&o, "max_er", "-0.1").ok());
  auto zero = setToleranceOption(&o, "max_er", "0");
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.error().message, "max_er '0': expected a number above 0 and at most 1000000");
  auto zero_percent = setToleranceOption(&o, "max_protrusion", "0%");
  ASSERT_FALSE(zero_percent.ok());
  EXPECT_EQ(
      zero_percent.error().message,
      "max_protrusion '0%': expected a number above 0 and at most 1e+30, optionally followed by %");
  EXPECT_FALSE(setToleranceOption(&o, "max_spheres", "0").ok());
}

// A cap given is marked, and one without a limit is refused (it would cap nothing); the
// library's default cap, not given, is not; with a limit the cap is taken.
TEST(ToleranceFit, ACapGoesWithALimit) {
  ToleranceOptions t;
  EXPECT_FALSE(t.max_spheres_given);
  EXPECT_TRUE(checkToleranceRequest(fastRequest(), t).ok());
  ASSERT_TRUE(setToleranceOption(&t, "max_spheres", "8").ok());
  EXPECT_TRUE(t.max_spheres_given);
  const Status alone = checkToleranceRequest(fastRequest(), t);
  ASSERT_FALSE(alone.ok());
  EXPECT_EQ(alone.error().code, ErrorCode::kInvalidArgument);
  EXPECT_EQ(alone.error().message,
            "max_spheres goes with a tolerance (max_protrusion, max_er): alone it caps nothing");
  ASSERT_TRUE(setToleranceOption(&t, "max_er", "2").ok());
  EXPECT_TRUE(checkToleranceRequest(fastRequest(), t).ok());
  EXPECT_EQ(t.max_spheres, 8);
}

// Best effort (the best set written when no count meets the limit) needs a limit too.
TEST(ToleranceFit, BestEffortGoesWithALimit) {
  ToleranceOptions t;
  EXPECT_TRUE(checkBestEffort(false, t).ok());
  const Status alone = checkBestEffort(true, t);
  ASSERT_FALSE(alone.ok());
  EXPECT_EQ(alone.error().code, ErrorCode::kInvalidArgument);
  EXPECT_EQ(alone.error().message,
            "best_effort goes with a tolerance (max_protrusion, max_er): alone it writes nothing "
            "more");
  ASSERT_TRUE(setToleranceOption(&t, "max_protrusion", "5%").ok());
  EXPECT_TRUE(checkBestEffort(true, t).ok());
}

}  // namespace
}  // namespace sphereset

// The curve of a run (fitCurve): one point per count, each the certified check of the set it
// returns (re-evaluated here), the fits those of one progressive run whose last count is the
// independent fit (or of independent fits when the request does not allow one), every count
// 1 ... max_spheres by default, progress per count that may cancel, and bad counts refused.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <optional>
#include <stdexcept>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

FitRequest quick() {
  FitRequest r;
  r.quality = FitQuality::kFast;
  return r;
}

void expectSameSpheres(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].center, b[i].center) << i;
    EXPECT_EQ(a[i].radius, b[i].radius) << i;
  }
}

// The run a curve makes: its last count and 1, 2 and 8 clustered from seeds.
ProgressiveOptions seededTop() {
  ProgressiveOptions p;
  p.top_from_seeds = true;
  p.seeded = {1, 2, 8};
  return p;
}

TEST(FitCurve, EachPointIsTheCheckOfItsSetFromOneProgressiveRun) {
  const SolidIndex index(test::robotLink());
  CurveOptions o;
  o.counts = {1, 2, 4, 8};
  std::vector<int> reported;
  o.progress = [&](const CurvePoint& p) { reported.push_back(p.n); };
  auto c = fitCurve(index, quick(), o);
  ASSERT_TRUE(c.ok()) << c.error().message;
  EXPECT_TRUE(c->progressive);
  EXPECT_EQ(reported, o.counts);
  ASSERT_EQ(c->points.size(), 4u);
  ASSERT_EQ(c->spheres.size(), 4u);
  // The run's fits, count by count: a ProgressiveFit for the largest count asked the same.
  FitRequest top = quick();
  top.num_spheres = 8;
  auto run = ProgressiveFit::start(index, fitOptionsFor(top), nullptr, seededTop());
  ASSERT_TRUE(run.ok());
  // The last count is fitted from seeds: fitSpheres's own fit at 8, as `sphereset fit -n 8`.
  auto independent = fitSpheres(index, fitOptionsFor(top));
  ASSERT_TRUE(independent.ok());
  expectSameSpheres(c->spheres.back(), independent->spheres);
  for (size_t i = 0; i < 4; ++i) {
    const CurvePoint& p = c->points[i];
    EXPECT_EQ(p.n, o.counts[i]);
    EXPECT_EQ(static_cast<int>(c->spheres[i].size()), p.n);
    EXPECT_FALSE(p.meets);
    auto fit = run->fit(p.n);
    ASSERT_TRUE(fit.ok());
    expectSameSpheres(c->spheres[i], fit->spheres);
    // Its figures are the check of that set.
    auto ev = evaluateSpheres(index, c->spheres[i], fitCheckEvalOptions(1, nullptr, nullptr));
    ASSERT_TRUE(ev.ok());
    EXPECT_EQ(p.er_sum, ev->er_sum) << p.n;
    EXPECT_EQ(p.protrusion, ev->protrusion) << p.n;
    EXPECT_TRUE(p.covered) << p.n;
  }
}

double totalEnergy(const SolidIndex& index, const std::vector<Sphere>& spheres) {
  double e = 0.0;
  for (const Sphere& s : spheres) e += index.outsideVolume(s).volume;
  return e;
}

TEST(FitCurve, CountsBetweenPowersOfTwoAreStepsCheckedAsAFullEvaluationChecks) {
  // Every count 1 ... 7: 1, 2, 4 and the last, 7, are the run's fits; 3, 5 and 6 are steps
  // (ProgressiveFit::step), up from the fit below and down from the fit above, the better
  // crossover taken. Each point is the full check of its set (the protrusion within its
  // tolerance), though the steps' are made by the certificate kept up to date and the changed
  // spheres' protrusion.
  const SolidIndex index(test::robotLink());
  CurveOptions o;
  o.max_spheres = 7;
  std::vector<int> reported;
  o.progress = [&](const CurvePoint& p) { reported.push_back(p.n); };
  auto c = fitCurve(index, quick(), o);
  ASSERT_TRUE(c.ok()) << c.error().message;
  ASSERT_EQ(c->points.size(), 7u);
  EXPECT_EQ(reported, (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
  FitRequest top = quick();
  top.num_spheres = 7;
  auto run = ProgressiveFit::start(index, fitOptionsFor(top), nullptr, seededTop());
  ASSERT_TRUE(run.ok());
  for (int n : {1, 2, 4, 7}) {
    auto fit = run->fit(n);
    ASSERT_TRUE(fit.ok());
    expectSameSpheres(c->spheres[n - 1], fit->spheres);
  }
  // The steps of 5 and 6: up from 4, down from 7; the curve's two sets are the crossover of
  // least total outside volume among (up, up), (up, down) and, when the downward 6 is no looser
  // than the upward one (the downward steps stop at the first looser set), (down, down).
  ASSERT_TRUE(run->fit(4).ok());
  auto up5 = run->step(5), up6 = run->step(6);
  ASSERT_TRUE(run->fit(7).ok());
  auto down6 = run->step(6), down5 = run->step(5);
  ASSERT_TRUE(up5.ok() && up6.ok() && down6.ok() && down5.ok());
  const double chosen = totalEnergy(index, c->spheres[4]) + totalEnergy(index, c->spheres[5]);
  EXPECT_LE(chosen, up5->energy + up6->energy);
  EXPECT_LE(chosen, up5->energy + down6->energy);
  if (down6->energy <= up6->energy)
    EXPECT_LE(chosen, down5->energy + down6->energy);
  else  // the downward 5 was never made: the 5 is the upward one
    expectSameSpheres(c->spheres[4], up5->spheres);
  for (int n = 1; n <= 7; ++n) {
    ASSERT_EQ(static_cast<int>(c->spheres[n - 1].size()), n);
    const CurvePoint& p = c->points[n - 1];
    EXPECT_EQ(p.n, n);
    auto ev = evaluateSpheres(index, c->spheres[n - 1], fitCheckEvalOptions(1, nullptr, nullptr));
    ASSERT_TRUE(ev.ok());
    EXPECT_EQ(p.er_sum, ev->er_sum) << n;
    // Both bound the same union: at least the full check's witness, and the curve's (searched
    // only as far as the union's figure needs) at most the full bound plus the tolerance.
    const double tolerance = EvalOptions{}.protrusion_tolerance * index.bounds().diagonal();
    EXPECT_GE(p.protrusion, ev->protrusion_witness_distance) << n;
    EXPECT_LE(p.protrusion, ev->protrusion + tolerance) << n;
    EXPECT_EQ(p.covered, ev->surface_covered && ev->interior_covered) << n;
    EXPECT_TRUE(p.covered) << n;
  }
}

TEST(FitCurve, ASteppedCurveIsTheSameForAnyThreadCount) {
  const SolidIndex index(test::robotLink());
  CurveOptions o;
  o.max_spheres = 7;
  std::optional<CurveResult> one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    auto r = fitCurve(index, quick(), o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    one = std::move(r).value();
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    auto r = fitCurve(index, quick(), o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    two = std::move(r).value();
  }
  for (size_t k = 0; k < 7; ++k) {
    expectSameSpheres(one->spheres[k], two->spheres[k]);
    EXPECT_EQ(one->points[k].er_sum, two->points[k].er_sum);
    EXPECT_EQ(one->points[k].protrusion, two->points[k].protrusion);
  }
}

TEST(FitCurve, EveryCountByDefaultAndIndependentFitsWhenTheRequestAsks) {
  const SolidIndex index(test::robotLink());
  CurveOptions o;
  o.max_spheres = 3;
  FitRequest r = quick();
  r.restarts = 2;  // not a progressive run's
  auto c = fitCurve(index, r, o);
  ASSERT_TRUE(c.ok()) << c.error().message;
  EXPECT_FALSE(c->progressive);
  ASSERT_EQ(c->points.size(), 3u);
  for (int n = 1; n <= 3; ++n) {
    EXPECT_EQ(c->points[n - 1].n, n);
    FitRequest at = r;
    at.num_spheres = n;
    auto fit = fitSpheres(index, fitOptionsFor(at));
    ASSERT_TRUE(fit.ok());
    expectSameSpheres(c->spheres[n - 1], fit->spheres);
  }
}

TEST(FitCurve, ProgressMayCancelAndBadCountsAreRefused) {
  const SolidIndex index(test::robotLink());
  CurveOptions o;
  o.counts = {1, 2, 3};
  o.progress = [](const CurvePoint& p) {
    if (p.n == 2) throw std::runtime_error("stop");
  };
  EXPECT_THROW(fitCurve(index, quick(), o), std::runtime_error);
  const auto refused = [&](CurveOptions bad, const FitRequest& r, const char* words) {
    auto c = fitCurve(index, r, bad);
    ASSERT_FALSE(c.ok()) << words;
    EXPECT_EQ(c.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(c.error().message.find(words), std::string::npos) << c.error().message;
  };
  CurveOptions bad;
  bad.counts = {2, 2};
  refused(bad, quick(), "expected increasing counts");
  bad.counts = {0, 1};
  refused(bad, quick(), "counts: 0 is not from 1");
  bad.counts = {limits::kMaxCurveCount + 1};
  refused(bad, quick(), "is not from 1");
  bad.counts.clear();
  bad.max_spheres = 0;
  refused(bad, quick(), "max_spheres 0");
  FitRequest with_n = quick();
  ASSERT_TRUE(setFitRequestOption(&with_n, "n", "4").ok());
  refused(CurveOptions{}, with_n, "n and a curve's counts exclude each other");
}

}  // namespace
}  // namespace sphereset

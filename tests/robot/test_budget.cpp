// Splitting a sphere budget over links by marginal gain (robot_fit.hpp), against hand-worked
// allocations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sphereset/robot_fit.hpp"

namespace sphereset {
namespace {

LinkFitCurve powerLaw(double a, double b) {
  LinkFitCurve c;
  for (int k : {1, 2, 4, 8}) {
    c.counts.push_back(k);
    c.outside_volume.push_back(a * std::pow(k, -b));
  }
  return c;
}

TEST(RobotBudget, CurveInterpolatesAndExtrapolatesAPowerLaw) {
  const LinkFitCurve c = powerLaw(3.0, 1.5);
  for (int k : {1, 3, 5, 8, 16, 40})
    EXPECT_NEAR(*curveVolume(c, k), 3.0 * std::pow(k, -1.5), 1e-12);
  LinkFitCurve one;
  one.counts = {4};
  one.outside_volume = {2.0};
  EXPECT_EQ(*curveVolume(one, 1), 2.0);
  EXPECT_EQ(*curveVolume(one, 9), 2.0);
}

// k = -1 used to give NaN (the log of a negative count): refused, as are curves no fit makes.
TEST(RobotBudget, CurveVolumeRefusesWhatItCannotAnswer) {
  const LinkFitCurve c = powerLaw(3.0, 1.5);
  for (int k : {0, -1}) {
    const auto v = curveVolume(c, k);
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(v.error().message.find("k must be at least 1"), std::string::npos);
  }
  EXPECT_FALSE(curveVolume(LinkFitCurve{}, 1));
  LinkFitCurve bad = c;
  bad.outside_volume[1] = std::nan("");
  EXPECT_FALSE(curveVolume(bad, 2));
  bad = c;
  bad.counts[1] = bad.counts[0];
  EXPECT_FALSE(curveVolume(bad, 2));
}

TEST(RobotBudget, GreedySplitFollowsTheLargestGain) {
  // Link 0 loses 10 -> 5 -> 2.5 ... (halving), link 1 loses 1 -> 0.5 ...: with 5 spheres the
  // gains are 5, 2.5, 1.25 for link 0 before link 1's first 0.5 is worth it.
  const std::vector<LinkFitCurve> curves = {powerLaw(10.0, 1.0), powerLaw(1.0, 1.0)};
  // Gains of k -> k+1 under 1/k: a (1/k - 1/(k+1)): link 0: 5, 1.67, 0.83, 0.5, 0.33...;
  // link 1: 0.5, 0.167, ...
  auto s = splitBudget(curves, {-1, -1}, 5);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ((*s)[0] + (*s)[1], 5);
  EXPECT_EQ((*s)[0], 4);  // 1 + three gains (5, 1.67, 0.83) above link 1's 0.5
  EXPECT_EQ((*s)[1], 1);
  // The split never has a larger total outside volume than an even one.
  auto total = [&](const std::vector<int>& n) {
    return *curveVolume(curves[0], n[0]) + *curveVolume(curves[1], n[1]);
  };
  auto s10 = splitBudget(curves, {-1, -1}, 10);
  ASSERT_TRUE(s10.ok());
  EXPECT_LT(total(*s10), total({5, 5}));
}

TEST(RobotBudget, FixedLinksKeepTheirCountsAndTheBudgetMustAllowThem) {
  const std::vector<LinkFitCurve> curves = {powerLaw(1.0, 1.0), powerLaw(1.0, 1.0),
                                            powerLaw(1.0, 1.0)};
  auto s = splitBudget(curves, {3, -1, 0}, 9);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ((*s)[0], 3);
  EXPECT_EQ((*s)[1], 6);
  EXPECT_EQ((*s)[2], 0);
  auto bad = splitBudget(curves, {3, -1, 0}, 3);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.error().message.find("budget of 3"), std::string::npos);
}

// The parallel arrays are checked instead of read past: one curve per link, one volume per count.
TEST(RobotBudget, SplitChecksItsArrays) {
  const std::vector<LinkFitCurve> curves = {powerLaw(1.0, 1.0), powerLaw(1.0, 1.0)};
  auto fewer = splitBudget(curves, {-1, -1, -1}, 9);
  ASSERT_FALSE(fewer.ok());
  EXPECT_EQ(fewer.error().message, "2 curves for 3 links");
  LinkFitCurve ragged = powerLaw(1.0, 1.0);
  ragged.outside_volume.pop_back();
  auto r = splitBudget({ragged, powerLaw(1.0, 1.0)}, {-1, -1}, 9);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
  LinkFitCurve nan = powerLaw(1.0, 1.0);
  nan.outside_volume[0] = std::nan("");
  EXPECT_FALSE(splitBudget({nan, powerLaw(1.0, 1.0)}, {-1, -1}, 9).ok());
}

TEST(RobotBudget, EnvelopeIsDecreasingConvexAndBelowEveryMeasurement) {
  // The Kinova base link's quick fits: 8 spheres measured worse than 4.
  LinkFitCurve c;
  c.counts = {1, 2, 4, 8, 16, 32};
  c.outside_volume = {3.0e-3, 1.17e-3, 0.85e-3, 1.29e-3, 1.0e-3, 0.72e-3};
  const LinkFitCurve e = curveEnvelope(c);
  ASSERT_GE(e.counts.size(), 2u);
  EXPECT_EQ(e.counts.front(), 1);
  EXPECT_EQ(e.counts.back(), 32);
  // Every measurement lies on or above the envelope; the envelope never rises.
  for (size_t i = 0; i < c.counts.size(); ++i)
    EXPECT_LE(*curveVolume(e, c.counts[i]), c.outside_volume[i] * (1 + 1e-12)) << c.counts[i];
  double prev_gain = 1e300;
  for (int k = 1; k < 40; ++k) {
    const double gain = *curveVolume(e, k) - *curveVolume(e, k + 1);
    EXPECT_GE(gain, 0.0) << k;
    EXPECT_LE(gain, prev_gain * (1 + 1e-9)) << k;  // diminishing returns: convex
    prev_gain = gain;
  }
  // 8 is dropped (above the 4 before it); 2 lies above the chord from 1 to 4, so it goes too.
  EXPECT_EQ(std::count(e.counts.begin(), e.counts.end(), 8), 0);
  // A power law is its own envelope (collinear points in log-log may be dropped).
  const LinkFitCurve p = powerLaw(3.0, 1.5);
  const LinkFitCurve pe = curveEnvelope(p);
  for (int k : {1, 3, 8, 20}) EXPECT_NEAR(*curveVolume(pe, k), *curveVolume(p, k), 1e-12) << k;
  // A link bounded exactly stops at its 0.
  LinkFitCurve z;
  z.counts = {1, 2, 4};
  z.outside_volume = {1.0, 0.0, 0.5};
  const LinkFitCurve ze = curveEnvelope(z);
  EXPECT_EQ(ze.counts, (std::vector<int>{1, 2}));
  EXPECT_EQ(*curveVolume(ze, 7), 0.0);
}

TEST(RobotBudget, SplitUsesTheEnvelopeNotTheNoise) {
  // Link 0's measurement at 2 is noise above its trend; without the envelope the greedy split
  // would see a loss in going from 1 to 2 spheres and starve it.
  LinkFitCurve noisy;
  noisy.counts = {1, 2, 4, 8};
  noisy.outside_volume = {10.0, 12.0, 2.5, 1.25};
  const std::vector<LinkFitCurve> curves = {noisy, powerLaw(1.0, 1.0)};
  auto s = splitBudget(curves, {-1, -1}, 6);
  ASSERT_TRUE(s.ok());
  EXPECT_GE((*s)[0], 4);
}

// Brute force over every combination: the least total outside volume within the budget.
double bestByEnumeration(const std::vector<std::vector<LinkCandidate>>& cand, int budget) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<size_t> idx(cand.size(), 0);
  while (true) {
    int total = 0;
    double v = 0.0;
    for (size_t i = 0; i < cand.size(); ++i) {
      total += cand[i][idx[i]].count;
      v += cand[i][idx[i]].outside_volume;
    }
    if (total <= budget) best = std::min(best, v);
    size_t i = 0;
    while (i < cand.size() && ++idx[i] == cand[i].size()) idx[i++] = 0;
    if (i == cand.size()) break;
  }
  return best;
}

TEST(RobotBudget, PickCandidatesMatchesEnumeration) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::vector<LinkCandidate>> cand(2 + trial % 5);
    int min_total = 0;
    for (auto& list : cand) {
      const int m = 1 + static_cast<int>(rng() % 3);
      int lowest = 1000;
      for (int c = 0; c < m; ++c) {
        const int k = 1 + static_cast<int>(rng() % 12);
        list.push_back({k, std::uniform_real_distribution<double>(0.1, 2.0)(rng) / k});
        lowest = std::min(lowest, k);
      }
      min_total += lowest;
    }
    const int budget = min_total + static_cast<int>(rng() % 20);
    auto pick = pickCandidates(cand, budget);
    ASSERT_TRUE(pick.ok()) << pick.error().message;
    int total = 0;
    double v = 0.0;
    for (size_t i = 0; i < cand.size(); ++i) {
      total += cand[i][(*pick)[i]].count;
      v += cand[i][(*pick)[i]].outside_volume;
    }
    EXPECT_LE(total, budget);
    EXPECT_NEAR(v, bestByEnumeration(cand, budget), 1e-12) << trial;
  }
  // Nothing fits: an error, not a guess.
  EXPECT_FALSE(pickCandidates({{{5, 1.0}}, {{5, 1.0}}}, 9).ok());
  EXPECT_FALSE(pickCandidates({{}}, 9).ok());
}

}  // namespace
}  // namespace sphereset

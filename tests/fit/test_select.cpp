// The selection among candidate spheres (select.cpp): the ILP's choice against enumeration of
// every n-subset, the units against the candidates that hold them, and the best preset's
// selection among its restarts independent of the thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "fit/select.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using detail::CoverProblem;
using detail::Selection;

// A random instance: m candidates of random cost, classes of 1 to 4 random holders, and one
// planted n-subset that covers every class (each class gets one of its members), so that the
// instance is feasible.
CoverProblem randomProblem(int m, int n, int classes, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.1, 1.0);
  CoverProblem p;
  for (int c = 0; c < m; ++c) p.cost.push_back(u(rng));
  std::vector<int32_t> all(m);
  for (int c = 0; c < m; ++c) all[c] = c;
  std::shuffle(all.begin(), all.end(), rng);
  const std::vector<int32_t> planted(all.begin(), all.begin() + n);
  for (int k = 0; k < classes; ++k) {
    std::vector<int32_t> h{planted[rng() % n]};
    const int extra = static_cast<int>(rng() % 4);
    for (int e = 0; e < extra; ++e) h.push_back(static_cast<int32_t>(rng() % m));
    std::sort(h.begin(), h.end());
    h.erase(std::unique(h.begin(), h.end()), h.end());
    p.classes.push_back(h);
  }
  std::sort(p.classes.begin(), p.classes.end());
  p.classes.erase(std::unique(p.classes.begin(), p.classes.end()), p.classes.end());
  return p;
}

// The cheapest n-subset covering every class, by enumeration (ascending indices).
std::vector<int32_t> bruteForce(const CoverProblem& p, int n, double* best_cost) {
  const int m = static_cast<int>(p.cost.size());
  std::vector<int32_t> best;
  *best_cost = std::numeric_limits<double>::infinity();
  std::vector<char> pick(m, 0);
  std::fill(pick.begin(), pick.begin() + n, 1);
  do {
    std::vector<int32_t> s;
    double cost = 0.0;
    for (int c = 0; c < m; ++c)
      if (pick[c]) s.push_back(c), cost += p.cost[c];
    const bool covers = std::all_of(p.classes.begin(), p.classes.end(), [&](const auto& cls) {
      return std::any_of(cls.begin(), cls.end(), [&](int32_t c) { return pick[c] != 0; });
    });
    if (covers && cost < *best_cost) *best_cost = cost, best = s;
  } while (std::prev_permutation(pick.begin(), pick.end()));
  return best;
}

TEST(Select, IlpMatchesEnumerationOnRandomInstances) {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const int m = 8 + static_cast<int>(seed % 6), n = 2 + static_cast<int>(seed % 4);
    const CoverProblem p = randomProblem(m, n, 6 + static_cast<int>(seed % 20), seed);
    double brute_cost = 0.0;
    const std::vector<int32_t> brute = bruteForce(p, n, &brute_cost);
    ASSERT_FALSE(brute.empty());
    // From the greedy start, and from a start that is not a cover (the greedy takes over).
    for (const std::vector<int32_t>& start : {std::vector<int32_t>{}, std::vector<int32_t>{0}}) {
      const Selection s = detail::selectCover(p, n, start, 1000);
      EXPECT_EQ(s.chosen, brute) << "seed " << seed;
      EXPECT_NEAR(s.cost, brute_cost, 1e-12) << "seed " << seed;
      EXPECT_TRUE(s.proven) << "seed " << seed;
    }
  }
}

TEST(Select, SwapSearchAloneKeepsAFeasibleCoverNoWorseThanItsStart) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const int m = 12, n = 4;
    const CoverProblem p = randomProblem(m, n, 15, seed);
    double brute_cost = 0.0;
    bruteForce(p, n, &brute_cost);
    const Selection s = detail::selectCover(p, n, {}, -1);  // no ILP
    if (s.chosen.empty()) continue;                         // the greedy may need more than n
    EXPECT_EQ(s.chosen.size(), static_cast<size_t>(n));
    EXPECT_FALSE(s.proven);
    EXPECT_GE(s.cost, brute_cost - 1e-12);
    for (const auto& cls : p.classes)
      EXPECT_TRUE(std::any_of(cls.begin(), cls.end(), [&](int32_t c) {
        return std::binary_search(s.chosen.begin(), s.chosen.end(), c);
      }));
  }
}

TEST(Select, InfeasibleCardinalityGivesNoChoice) {
  CoverProblem p;
  p.cost = {1.0, 1.0, 1.0};
  p.classes = {{0}, {1}, {2}};
  EXPECT_TRUE(detail::selectCover(p, 2, {}, 100).chosen.empty());
  EXPECT_EQ(detail::selectCover(p, 3, {}, 100).chosen, (std::vector<int32_t>{0, 1, 2}));
}

// Two groups (two fits' spheres): every class is held by its listed candidates and by a member
// of each group, and each group alone covers every class.
TEST(Select, UnitsAreHeldByEveryGroup) {
  const Mesh mesh = test::robotLink();
  const SolidIndex idx(mesh);
  std::vector<Sphere> pool;
  std::vector<int32_t> group_of;
  for (int g = 0; g < 2; ++g) {
    FitOptions o;
    o.num_spheres = 6;
    o.target_points = 2000;
    o.seed = 11 + g;
    auto r = fitSpheres(idx, o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    pool.insert(pool.end(), r->spheres.begin(), r->spheres.end());
    group_of.resize(pool.size(), g);
  }
  const std::vector<Vec3> interior;
  const CoverProblem p = detail::coverProblem(idx, pool, group_of, interior, 1e-3);
  EXPECT_EQ(p.unheld, 0);
  EXPECT_GE(p.units, static_cast<int64_t>(mesh.triangles.size()));
  ASSERT_EQ(p.cost.size(), pool.size());
  for (const auto& cls : p.classes) {
    ASSERT_FALSE(cls.empty());
    EXPECT_TRUE(std::is_sorted(cls.begin(), cls.end()));
    bool g0 = false, g1 = false;
    for (int32_t c : cls) (group_of[c] == 0 ? g0 : g1) = true;
    EXPECT_TRUE(g0 && g1);
  }
  for (int g = 0; g < 2; ++g) {
    std::vector<int32_t> start;
    for (size_t c = 0; c < pool.size(); ++c)
      if (group_of[c] == g) start.push_back(static_cast<int32_t>(c));
    const Selection s = detail::selectCover(p, 6, start, 0);
    ASSERT_EQ(s.chosen.size(), 6u);
    double group_cost = 0.0;
    for (int32_t c : start) group_cost += p.cost[c];
    EXPECT_LE(s.cost, group_cost);
  }
}

TEST(Select, BestPresetSelectionIsIndependentOfThreadCount) {
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 32, 16));
  FitOptions o = fitPreset(8, FitQuality::kBest);
  ASSERT_TRUE(o.select_among_restarts);
  o.target_points = 1500;
  o.restarts = 2;
  auto a = fitSpheres(idx, o);
  Expected<FitResult> b = Error{ErrorCode::kInvalidArgument, ""};
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    b = fitSpheres(idx, o);
  }
  Expected<FitResult> c = Error{ErrorCode::kInvalidArgument, ""};
  {
    tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    c = fitSpheres(idx, o);
  }
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a->spheres.size(), 8u);
  for (const auto* r : {&*b, &*c}) {
    ASSERT_EQ(r->spheres.size(), a->spheres.size());
    for (size_t i = 0; i < a->spheres.size(); ++i) {
      EXPECT_EQ(a->spheres[i].center, r->spheres[i].center);
      EXPECT_EQ(a->spheres[i].radius, r->spheres[i].radius);
    }
  }
  // Never worse than keeping the best restart.
  o.select_among_restarts = false;
  auto kept = fitSpheres(idx, o);
  ASSERT_TRUE(kept.ok());
  EXPECT_LE(a->energy, kept->energy);
}

}  // namespace
}  // namespace sphereset

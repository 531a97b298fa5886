// The sphere grid's coverage queries against scans of all spheres.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <random>

#include "cover/sphere_grid.hpp"

namespace sphereset::detail {
namespace {

// Many small spheres, a few large ones and some of radius 0, in a flat box.
std::vector<Sphere> randomSpheres(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Sphere> out;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(4.0 * u(rng), 2.0 * u(rng), 0.5 * u(rng));
    const double r = i % 50 == 0 ? 1.5 * u(rng) : (i % 17 == 0 ? 0.0 : 0.05 + 0.2 * u(rng));
    out.push_back({c, r});
  }
  return out;
}

TEST(SphereGrid, QueriesMatchScansOfAllSpheres) {
  const std::vector<Sphere> sp = randomSpheres(600, 4);
  const SphereGrid grid(sp);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-0.5, 1.0);
  int held = 0, shared = 0;
  for (int q = 0; q < 3000; ++q) {
    // Small triangles near the spheres, and some far outside.
    const Vec3 a = q % 100 == 0 ? Vec3(30.0, -5.0, 2.0) : Vec3(5 * u(rng), 3 * u(rng), u(rng));
    const double s = 0.1 * (u(rng) + 0.5);
    const std::array<Vec3, 3> t{a, a + Vec3(s, 0, 0), a + Vec3(0, s, 0.3 * s)};
    for (int n : {1, 3}) {
      int count = 0;
      int32_t last = -1;
      for (int32_t i = 0; i < static_cast<int32_t>(sp.size()) && count < 2; ++i) {
        bool all = true;
        for (int k = 0; k < n; ++k) all = all && sp[i].contains(t[k]);
        if (all) {
          ++count;
          last = i;
        }
      }
      int32_t holder = -1;
      EXPECT_EQ(holders(grid, t.data(), n, &holder), count);
      if (count > 0) {
        EXPECT_EQ(holder, last);
      }
      EXPECT_EQ(oneSphereHolds(grid, t.data(), n), count > 0);
      held += count > 0;
      shared += count > 1;

      std::vector<std::pair<double, int32_t>> all;
      for (int32_t i = 0; i < static_cast<int32_t>(sp.size()); ++i) {
        double need = 0.0;
        for (int k = 0; k < n; ++k) need = std::max(need, (t[k] - sp[i].center).norm());
        all.push_back({need - sp[i].radius, i});
      }
      std::sort(all.begin(), all.end());
      std::array<std::pair<double, int32_t>, 5> least;
      ASSERT_EQ(leastGrowth(grid, t.data(), n, 5, least.data()), 5);
      for (int k = 0; k < 5; ++k) EXPECT_EQ(least[k], all[k]);
    }
    double gap = std::numeric_limits<double>::infinity();
    for (const Sphere& sph : sp) gap = std::min(gap, (a - sph.center).norm() - sph.radius);
    EXPECT_EQ(gapToUnion(grid, a), std::max(gap, 0.0));
  }
  // Both cases occur often enough for the comparison to mean something.
  EXPECT_GT(held, 1000);
  EXPECT_GT(shared, 300);
  EXPECT_LT(held, 5800);
}

TEST(SphereGrid, FewerSpheresThanAskedAndNone) {
  const std::vector<Sphere> two{{Vec3(0, 0, 0), 1.0}, {Vec3(5, 0, 0), 0.5}};
  const SphereGrid grid(two);
  const Vec3 p(2.0, 0.0, 0.0);
  std::array<std::pair<double, int32_t>, 3> least;
  ASSERT_EQ(leastGrowth(grid, &p, 1, 3, least.data()), 2);
  EXPECT_EQ(least[0].second, 0);
  EXPECT_DOUBLE_EQ(least[0].first, 1.0);
  EXPECT_EQ(least[1].second, 1);
  EXPECT_DOUBLE_EQ(least[1].first, 2.5);
  EXPECT_DOUBLE_EQ(gapToUnion(grid, p), 1.0);

  const std::vector<Sphere> none;
  const SphereGrid empty(none);
  int32_t holder = -1;
  EXPECT_EQ(holders(empty, &p, 1, &holder), 0);
  EXPECT_FALSE(oneSphereHolds(empty, &p, 1));
  EXPECT_EQ(leastGrowth(empty, &p, 1, 3, least.data()), 0);
}

}  // namespace
}  // namespace sphereset::detail

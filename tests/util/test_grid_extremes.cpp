// The grids built on cell_key.hpp with coordinates at the ends of the double range: no
// undefined conversions, and the same answers as scans of all points or spheres.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "cover/sphere_grid.hpp"
#include "fit/centre_grid.hpp"
#include "fit/samples.hpp"

namespace sphereset::detail {
namespace {

int64_t nearestByScan(const std::vector<Vec3>& pts, const Vec3& q) {
  int64_t best = 0;
  for (int64_t i = 1; i < static_cast<int64_t>(pts.size()); ++i)
    if ((pts[i] - q).squaredNorm() < (pts[best] - q).squaredNorm()) best = i;
  return best;
}

// Points near the origin and far out (1e300 cells of 1e-3 away): far keys saturate.
TEST(GridExtremes, PointGridNearestWithHugeCoordinates) {
  std::vector<Vec3> pts = {{1e300, 0.0, 0.0},  {0.0, 0.0, 0.0},     {1.0, 0.0, 0.0},
                           {-1e300, 2.0, 0.0}, {1e300, 1e300, 1.0}, {0.5, -1e250, 0.0}};
  const PointGrid grid(pts, 1e-3);
  // Queries whose nearest point is at a finite squared distance (the scan's answer is then
  // unique).
  for (const Vec3& q : {Vec3(1e300, 0.0, 0.0), Vec3(0.9, 0.0, 0.0), Vec3(-1e300, 2.5, 0.0),
                        Vec3(1e300, 1e300, 0.0), Vec3(0.5, -1e250, 0.1), Vec3(0.2, 0.0, 0.0)})
    EXPECT_EQ(grid.nearest(pts, q), nearestByScan(pts, q)) << q.transpose();
}

// Centres within 1e-110 or 1e-150 of each other (the box volume underflows), or 1e150 (it
// overflows).
TEST(GridExtremes, CentreGridListsEveryCentreWithinReachAtAnyScale) {
  for (const double scale : {1e-150, 1e-110, 1.0, 1e150}) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Cluster> cl(100);
    for (Cluster& c : cl) c.center = scale * Vec3(u(rng), u(rng), u(rng));
    const CentreGrid grid(cl);
    for (int k = 0; k < 50; ++k) {
      const Vec3 q = scale * Vec3(u(rng), u(rng), u(rng));
      const double reach = 0.3 * scale;
      std::vector<char> listed(cl.size(), 0);
      grid.forEachWithin(q, reach, [&](int32_t i) { listed[i] = 1; });
      for (size_t i = 0; i < cl.size(); ++i)
        if ((cl[i].center - q).norm() <= reach) {
          EXPECT_TRUE(listed[i]) << scale << " " << i;
        }
    }
  }
}

// Spheres near both ends of the double range: the box's extent overflows to infinity.
TEST(GridExtremes, SphereGridHoldersWithExtentsBeyondTheDoubleRange) {
  const std::vector<Sphere> sp = {
      {{-1.7e308, 0.0, 0.0}, 1.0}, {{1.7e308, 0.0, 0.0}, 1.0}, {{0.0, 0.0, 0.0}, 2.0}};
  const SphereGrid grid(sp);
  for (int i = 0; i < 3; ++i) {
    int32_t holder = -1;
    EXPECT_EQ(holders(grid, &sp[i].center, 1, &holder), 1) << i;
    EXPECT_EQ(holder, i);
    std::pair<double, int32_t> least[1];
    ASSERT_EQ(leastGrowth(grid, &sp[i].center, 1, 1, least), 1);
    EXPECT_EQ(least[0].second, i);
    EXPECT_EQ(gapToUnion(grid, sp[i].center), 0.0);
  }
}

}  // namespace
}  // namespace sphereset::detail

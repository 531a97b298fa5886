// Grid cell coordinates: the checked conversion, keys, neighbour iteration.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "util/cell_key.hpp"

namespace sphereset::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(CellKey, FloorAndCeilAreExactInRange) {
  for (const double x : {0.0, -0.0, 0.25, -0.25, 1.0, -1.0, 2.5, -2.5, 1e15 + 0.5, -1e15 - 0.5,
                         0x1.0p59, -0x1.0p59}) {
    EXPECT_EQ(floorCell(x), static_cast<int64_t>(std::floor(x))) << x;
    EXPECT_EQ(ceilCells(x), static_cast<int64_t>(std::ceil(x))) << x;
  }
}

TEST(CellKey, OutOfRangeValuesSaturateAndNaNGivesZero) {
  for (const double x : {0x1.0p60, 1e19, 1e300, kInf}) {
    EXPECT_EQ(floorCell(x), kMaxCellCoord) << x;
    EXPECT_EQ(floorCell(-x), -kMaxCellCoord) << x;
    EXPECT_EQ(ceilCells(x), kMaxCellCoord) << x;
    EXPECT_EQ(ceilCells(-x), -kMaxCellCoord) << x;
  }
  EXPECT_EQ(floorCell(std::nan("")), 0);
  EXPECT_EQ(ceilCells(std::nan("")), 0);
  // Neighbour offsets of saturated coordinates stay far from overflow.
  EXPECT_LT(kMaxCellCoord, std::numeric_limits<int64_t>::max() / 2);
}

// Saturation never separates neighbours: points within one cell of each other (per axis) have
// keys at most one apart, whatever their magnitude.
TEST(CellKey, PointsWithinACellGetAdjacentKeysAtAnyMagnitude) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), e(-320.0, 308.0);
  int tested = 0;
  for (int i = 0; i < 20000; ++i) {
    const double cell = std::pow(10.0, 0.5 * e(rng));
    const Vec3 p = Vec3(u(rng), u(rng), u(rng)) * std::pow(10.0, e(rng));
    const Vec3 q = p + cell * Vec3(u(rng), u(rng), u(rng));
    if (!q.allFinite() || ((q - p).cwiseAbs().array() > cell).any()) continue;
    ++tested;
    const CellKey a = cellKey(p, cell), b = cellKey(q, cell);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(a[k] - b[k]), 1) << p.transpose() << " / " << cell;
      EXPECT_LE(std::abs(a[k]), kMaxCellCoord);
    }
  }
  EXPECT_GT(tested, 10000);
}

TEST(CellKey, NeighbourCellsInOrderUntilFound) {
  std::vector<CellKey> seen;
  EXPECT_FALSE(anyCellAround(CellKey{5, -7, kMaxCellCoord}, 1, [&](const CellKey& c) {
    seen.push_back(c);
    return false;
  }));
  ASSERT_EQ(seen.size(), 27u);
  EXPECT_EQ(seen.front(), (CellKey{4, -8, kMaxCellCoord - 1}));
  EXPECT_EQ(seen[1], (CellKey{4, -8, kMaxCellCoord}));  // z fastest
  EXPECT_EQ(seen.back(), (CellKey{6, -6, kMaxCellCoord + 1}));
  int calls = 0;
  EXPECT_TRUE(anyCellAround(CellKey{0, 0, 0}, 2, [&](const CellKey& c) {
    ++calls;
    return c == CellKey{-2, -2, 0};
  }));
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace sphereset::detail

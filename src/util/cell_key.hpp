// Private: integer cell coordinates of uniform grids, the checked conversion that computes
// them, neighbour iteration and the hash of a cell key. Used by
//   - the hash grids keyed by floor(p / cell) over all of space (cubes with a corner at the
//     origin): vertex welding (mesh/weld.cpp), the fit's point grid and point adjacency
//     (fit/samples.cpp); they share cellKey, the neighbour iteration and CellKeyHash;
//   - the dense grids over a box, whose coordinates are clamped to the box: the assignment's
//     centre grid (fit/centre_grid.hpp) and the sphere grid (cover/sphere_grid.hpp); they
//     share the checked conversion only (their cells are array indices, not hashed keys).
// CellKeyHash also hashes the sorted vertex triples of triangles (mesh/clean.cpp: duplicates).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sphereset/mesh.hpp"

namespace sphereset::detail {

using CellKey = std::array<int64_t, 3>;

// Cell coordinates are saturated to [-kMaxCellCoord, kMaxCellCoord]: far enough inside the
// int64 range that neighbour offsets and differences of coordinates cannot overflow, and far
// beyond any grid that fits in memory. Saturation keeps the grids exact: it never increases
// the difference of two coordinates, so points in the same or adjacent cells stay so, and a
// point k cells away in the saturated grid is at least k cells away in space. Only points more
// than 2^60 cells from the origin (huge coordinates or tiny cells) share the outermost cells,
// which makes those searches slower, never wrong.
inline constexpr int64_t kMaxCellCoord = int64_t{1} << 60;

// floor(x) as an integer cell coordinate, saturated as above; 0 for NaN. The checked
// double -> int64 conversion of every grid: a plain cast of a value outside the int64 range
// (coordinates of untrusted data divided by a small cell) is undefined behaviour.
inline int64_t floorCell(double x) {
  constexpr double kMax = static_cast<double>(kMaxCellCoord);  // exact: a power of two
  const double f = std::floor(x);
  if (f >= kMax) return kMaxCellCoord;
  if (f <= -kMax) return -kMaxCellCoord;
  if (std::isnan(f)) return 0;
  return static_cast<int64_t>(f);
}

// ceil(x) as an integer cell count, saturated like floorCell; 0 for NaN.
inline int64_t ceilCells(double x) { return -floorCell(-x); }

// The cell of p among the cubes of side `cell` with a corner at the origin.
inline CellKey cellKey(const Vec3& p, double cell) {
  return {floorCell(p.x() / cell), floorCell(p.y() / cell), floorCell(p.z() / cell)};
}

// Calls f(key) for the cells at most `reach` cells from k along each axis (x slowest, z
// fastest) until f returns true; returns whether it did.
template <class F>
bool anyCellAround(const CellKey& k, int reach, F&& f) {
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dz = -reach; dz <= reach; ++dz)
        if (f(CellKey{k[0] + dx, k[1] + dy, k[2] + dz})) return true;
  return false;
}

// FNV-1a over the three coordinates.
struct CellKeyHash {
  size_t operator()(const CellKey& k) const {
    size_t h = 1469598103934665603ull;
    for (int64_t v : k) h = (h ^ static_cast<size_t>(v)) * 1099511628211ull;
    return h;
  }
};

}  // namespace sphereset::detail

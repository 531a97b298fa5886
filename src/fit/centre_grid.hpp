// Private: the cluster centres of a point assignment bucketed in a dense grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fit/cluster_assign.hpp"
#include "util/cell_key.hpp"

namespace sphereset::detail {

// The cluster centres (fixed during an assignment) bucketed in a dense grid of about one
// centre per cell, to find the centres within a distance of a point without scanning all.
// A dense grid over the centres' box, indexed by clamped coordinates: it shares the checked
// conversion of cell_key.hpp with the hash grids, not their keys or hash.
class CentreGrid {
 public:
  explicit CentreGrid(const std::vector<Cluster>& cl);

  // Calls f(cluster) for every centre within `reach` of q (and some a little farther).
  template <class F>
  void forEachWithin(const Vec3& q, double reach, F&& f) const {
    const double pad = reach + kPadRel * cell_;
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = coord(q - Vec3::Constant(pad), a);
      hi[a] = coord(q + Vec3::Constant(pad), a);
    }
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
      for (int64_t y = lo[1]; y <= hi[1]; ++y) {
        const int64_t row = index(lo[0], y, z);
        for (int32_t k = start_[row]; k < start_[row + hi[0] - lo[0] + 1]; ++k) f(members_[k]);
      }
  }

  double cell() const { return cell_; }

 private:
  // Extents below this fraction of the diagonal are widened (flat or collinear centres).
  static constexpr double kMinExtentRel = 1e-3;
  // Query boxes are widened by this fraction of a cell, against rounding.
  static constexpr double kPadRel = 1e-6;
  // Cells are never below this fraction of the largest extent. Extents are at least
  // kMinExtentRel of the diagonal, so the cell (the cube root of the box volume per centre) is
  // at least 1e-2 / cbrt(centres) >= 7.7e-6 of the largest extent for up to 2^31 centres; a
  // smaller one means the volume underflowed, and would make the grid astronomically large.
  static constexpr double kMinCellRel = 1e-6;
  // The cell coordinate along axis a, clamped to the grid (checked conversion, cell_key.hpp).
  int64_t coord(const Vec3& p, int a) const {
    return std::clamp<int64_t>(floorCell((p[a] - origin_[a]) / cell_), 0, dims_[a] - 1);
  }
  int64_t index(int64_t x, int64_t y, int64_t z) const { return x + dims_[0] * (y + dims_[1] * z); }
  Vec3 origin_;
  double cell_ = 1.0;
  int64_t dims_[3] = {1, 1, 1};
  std::vector<int32_t> start_, members_;
};

}  // namespace sphereset::detail

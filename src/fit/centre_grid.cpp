// The cluster centres of a point assignment in a dense grid (centre_grid.hpp): an acceleration
// of the nearest-holder search of cluster_assign.cpp that does not change its answers.
#include "fit/centre_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace sphereset::detail {

CentreGrid::CentreGrid(const std::vector<Cluster>& cl) {
  Aabb box;
  for (const Cluster& c : cl) box.extend(c.center);
  const double nc = static_cast<double>(cl.size());
  const Vec3 ext = (box.max - box.min).cwiseMax(Vec3::Constant(kMinExtentRel * box.diagonal()));
  double cell = std::cbrt(ext.prod() / nc);
  if (!(cell >= kMinCellRel * ext.maxCoeff())) {
    // ext.prod() underflowed (extents of about 1e-100 and below): the same cell from the
    // extents relative to the largest.
    cell = ext.maxCoeff() * std::cbrt((ext / ext.maxCoeff()).prod() / nc);
  }
  cell_ = std::max(std::numeric_limits<double>::min(), cell);  // NaN (NaN centres): min
  origin_ = box.min;
  for (int a = 0; a < 3; ++a) dims_[a] = std::max<int64_t>(1, ceilCells(ext[a] / cell_) + 1);
  std::vector<int64_t> cell_of(cl.size());
  start_.assign(dims_[0] * dims_[1] * dims_[2] + 1, 0);
  for (size_t i = 0; i < cl.size(); ++i) {
    cell_of[i] = index(coord(cl[i].center, 0), coord(cl[i].center, 1), coord(cl[i].center, 2));
    ++start_[cell_of[i] + 1];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  members_.resize(cl.size());
  std::vector<int32_t> fill(start_.begin(), start_.end() - 1);
  for (size_t i = 0; i < cl.size(); ++i) members_[fill[cell_of[i]]++] = static_cast<int32_t>(i);
}

}  // namespace sphereset::detail

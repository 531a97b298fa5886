// Spheres bucketed in a uniform grid (sphere_grid.hpp). Every query gives exactly the answer
// of a scan over all spheres in index order; the grid only skips spheres that cannot matter.
#include "cover/sphere_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/cell_key.hpp"

namespace sphereset::detail {
namespace {

// Sphere boxes are widened by this fraction of the largest coordinate magnitude, so that a
// point a sphere contains (tested in floating point) always lies in a cell that lists it.
constexpr double kWidenRel = 1e-9;
// Cells are about the median radius; the cell grows by this factor while the spheres would be
// listed in more than kMaxListedPerSphere cells on average (a few very large spheres).
constexpr double kCellGrowth = 1.5;
constexpr int64_t kMaxListedPerSphere = 64;
// At most this many cells per sphere (and kMinCells in all), however small the spheres.
constexpr int64_t kMaxCellsPerSphere = 8;
constexpr int64_t kMinCells = 4096;

}  // namespace

SphereGrid::SphereGrid(const std::vector<Sphere>& spheres) : spheres_(&spheres) {
  const int64_t n = static_cast<int64_t>(spheres.size());
  start_.assign(2, 0);
  if (n == 0) return;
  double magnitude = 0.0;
  std::vector<double> radii(n);
  for (int64_t i = 0; i < n; ++i) {
    magnitude = std::max(magnitude, spheres[i].center.cwiseAbs().maxCoeff() + spheres[i].radius);
    radii[i] = spheres[i].radius;
  }
  const double widen = kWidenRel * magnitude + std::numeric_limits<double>::min();
  Aabb box;
  for (const Sphere& s : spheres) {
    box.extend(s.center - Vec3::Constant(s.radius + widen));
    box.extend(s.center + Vec3::Constant(s.radius + widen));
  }
  origin_ = box.min;
  const Vec3 ext = box.max - box.min;
  std::nth_element(radii.begin(), radii.begin() + n / 2, radii.end());
  const double max_cells = static_cast<double>(std::max(kMinCells, kMaxCellsPerSphere * n));
  cell_ = std::max({radii[n / 2], std::cbrt(ext.prod() / max_cells), ext.maxCoeff() / 1024.0,
                    std::numeric_limits<double>::min()});
  while (true) {
    for (int a = 0; a < 3; ++a) dims_[a] = std::max<int64_t>(1, ceilCells(ext[a] / cell_));
    int64_t listed = 0;
    for (const Sphere& s : spheres) {
      int64_t count = 1;
      for (int a = 0; a < 3; ++a)
        count *= clampedCell(s.center[a] + s.radius + widen, a) -
                 clampedCell(s.center[a] - s.radius - widen, a) + 1;
      listed += count;
    }
    if (listed <= kMaxListedPerSphere * n) break;
    cell_ *= kCellGrowth;
  }
  // Counting sort by cell; spheres enter each list in increasing index order.
  const int64_t cells = dims_[0] * dims_[1] * dims_[2];
  start_.assign(cells + 1, 0);
  auto forCells = [&](const Sphere& s, auto&& f) {
    int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = clampedCell(s.center[a] - s.radius - widen, a);
      hi[a] = clampedCell(s.center[a] + s.radius + widen, a);
    }
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t x = lo[0]; x <= hi[0]; ++x) f(x + dims_[0] * (y + dims_[1] * z));
  };
  first_cell_.resize(n);
  for (int64_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      first_cell_[i][a] =
          static_cast<int32_t>(clampedCell(spheres[i].center[a] - spheres[i].radius - widen, a));
  for (const Sphere& s : spheres) forCells(s, [&](int64_t id) { ++start_[id + 1]; });
  for (int64_t id = 0; id < cells; ++id) start_[id + 1] += start_[id];
  members_.resize(start_[cells]);
  std::vector<int32_t> fill(start_.begin(), start_.end() - 1);
  for (int64_t i = 0; i < n; ++i)
    forCells(spheres[i], [&](int64_t id) { members_[fill[id]++] = static_cast<int32_t>(i); });
}

bool SphereGrid::cellOf(const Vec3& p, int64_t* c) const {
  if (std::isinf(cell_)) {
    // Extents beyond the double range (spheres near +-1.8e308) make one infinite cell, where
    // p - origin can overflow: every point is in it.
    c[0] = c[1] = c[2] = 0;
    return true;
  }
  for (int a = 0; a < 3; ++a) {
    // Range-checked before the conversion (NaN fails the test): outside the grid, no cell.
    const double f = std::floor((p[a] - origin_[a]) / cell_);
    if (!(f >= 0.0 && f < static_cast<double>(dims_[a]))) return false;
    c[a] = static_cast<int64_t>(f);
  }
  return true;
}

int64_t SphereGrid::clampedCell(double x, int axis) const {
  return std::clamp<int64_t>(floorCell((x - origin_[axis]) / cell_), 0, dims_[axis] - 1);
}

bool SphereGrid::coveredBy(const Vec3& p, double reach) const {
  for (int a = 0; a < 3; ++a)
    if (p[a] - reach > origin_[a] || p[a] + reach < origin_[a] + dims_[a] * cell_) return false;
  return true;
}

bool oneSphereHolds(const SphereGrid& grid, const Vec3* pts, int n) {
  bool found = false;
  grid.forEachNear(pts[0], [&](int32_t i) {
    if (found) return;
    const Sphere& s = grid.spheres()[i];
    bool all = true;
    for (int k = 0; k < n && all; ++k) all = s.contains(pts[k]);
    found = all;
  });
  return found;
}

int holders(const SphereGrid& grid, const Vec3* pts, int n, int32_t* holder) {
  int count = 0;
  grid.forEachNear(pts[0], [&](int32_t i) {
    if (count >= 2) return;
    const Sphere& s = grid.spheres()[i];
    bool all = true;
    for (int k = 0; k < n && all; ++k) all = s.contains(pts[k]);
    if (all) {
      ++count;
      *holder = i;
    }
  });
  return count;
}

double gapToUnion(const SphereGrid& grid, const Vec3& p) {
  // Inside a sphere near p: no gap. Otherwise the exact distance over all spheres: the least
  // of |p - c| - r over the spheres met within a growing reach of p. A sphere at distance d
  // from p has its box within d of p, so once the least distance found is at most the reach
  // (or the reach holds the whole grid), no sphere left out can be nearer; the minimum is the
  // one a scan over all spheres gives, to the last bit.
  bool inside = false;
  grid.forEachNear(p, [&](int32_t i) {
    const Sphere& s = grid.spheres()[i];
    inside = inside || (p - s.center).norm() - s.radius <= 0.0;
  });
  if (inside) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  if (grid.spheres().empty()) return best;
  for (double reach = grid.cell();; reach *= 2.0) {
    grid.forEachWithin(p, reach, [&](int32_t i) {
      const Sphere& s = grid.spheres()[i];
      best = std::min(best, (p - s.center).norm() - s.radius);
    });
    if (best <= reach || grid.coveredBy(p, reach)) break;
  }
  return std::max(best, 0.0);
}

int leastGrowth(const SphereGrid& grid, const Vec3* pts, int n, int count,
                std::pair<double, int32_t>* out, double reach) {
  count = std::min(count, static_cast<int>(grid.spheres().size()));
  int m = 0;
  auto consider = [&](int32_t i) {
    for (int k = 0; k < m; ++k)
      if (out[k].second == i) return;  // seen at a smaller reach
    const Sphere& s = grid.spheres()[i];
    double need = 0.0;
    for (int k = 0; k < n; ++k) need = std::max(need, (pts[k] - s.center).norm());
    const std::pair<double, int32_t> c{need - s.radius, i};
    if (m == count && !(c < out[m - 1])) return;
    int k = m < count ? m++ : m - 1;
    for (; k > 0 && c < out[k - 1]; --k) out[k] = out[k - 1];
    out[k] = c;
  };
  // A sphere not met within `reach` of pts[0] needs more than `reach` of growth.
  if (!(reach > 0.0)) reach = grid.cell();
  for (; count > 0; reach *= 2.0) {
    grid.forEachWithin(pts[0], reach, consider);
    if ((m == count && out[m - 1].first <= reach) || grid.coveredBy(pts[0], reach)) break;
  }
  return m;
}

}  // namespace sphereset::detail

// Sampling the solid for clustering. Reference: Wang et al. 2006, Sec. 5 "Preprocessing":
// inner points from a voxelisation with the outside points removed, surface points in
// proportion to triangle area (Turk 1990). Deviation: the grid spacing is chosen from a target
// point count instead of by hand, and refined until the solid holds enough interior points.
#include "fit/samples.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "fit/fit_common.hpp"
#include "util/cell_key.hpp"
#include "util/sampling.hpp"

namespace sphereset::detail {
namespace {

// Fewest interior points accepted before the grid is refined (thin parts, small targets).
constexpr double kMinInteriorShare = 0.5;
constexpr int kMaxRefinements = 4;
// The interior grid classifies every cell of the bounding box, so a solid that fills a tiny
// part of its box (a thin rod along the box's diagonal) would ask for billions of cells and
// run for hours. Past this many cells the spacing is widened instead and the interior is
// represented by fewer points; the surface samples and the guaranteed bound do not depend on
// it. Benchmark meshes need at most a few hundred thousand cells.
constexpr double kMaxGridCells = 16777216.0;  // 2^24

double gridCells(const Aabb& b, double h) {
  const Vec3 ext = b.max - b.min;
  double cells = 1.0;
  for (int k = 0; k < 3; ++k) cells *= std::max(1.0, std::ceil(ext[k] / h));
  return cells;
}

// h, or the smallest spacing tried above it that keeps the grid within kMaxGridCells.
double cappedSpacing(const Aabb& b, double h) {
  while (gridCells(b, h) > kMaxGridCells) h *= 1.01 * std::cbrt(gridCells(b, h) / kMaxGridCells);
  return h;
}

std::vector<Vec3> interiorGrid(const SolidIndex& index, double h) {
  const Aabb& b = index.bounds();
  const Vec3 ext = b.max - b.min;
  const int64_t nx = std::max<int64_t>(1, ceilCells(ext.x() / h));
  const int64_t ny = std::max<int64_t>(1, ceilCells(ext.y() / h));
  const int64_t nz = std::max<int64_t>(1, ceilCells(ext.z() / h));
  // Centre the grid in the box.
  const Vec3 origin = b.center() - 0.5 * h * Vec3(nx - 1, ny - 1, nz - 1);
  std::vector<std::vector<Vec3>> slabs(nz);
  tbb::parallel_for(int64_t{0}, nz, [&](int64_t k) {
    pollCancel();
    for (int64_t j = 0; j < ny; ++j)
      for (int64_t i = 0; i < nx; ++i) {
        const Vec3 p = origin + h * Vec3(i, j, k);
        if (index.classify(p) == Containment::kInside) slabs[k].push_back(p);
      }
  });
  std::vector<Vec3> out;
  for (auto& s : slabs) out.insert(out.end(), s.begin(), s.end());
  return out;
}

// Rings of cells searched around a query before the nearest-point search gives up on the
// grid and scans every point (a query far from all points).
constexpr int64_t kMaxRings = 8;

}  // namespace

PointGrid::PointGrid(const std::vector<Vec3>& points, double cell) : cell_(cell) {
  const int32_t n = static_cast<int32_t>(points.size());
  std::vector<std::pair<CellKey, int32_t>> keyed(n);
  for (int32_t i = 0; i < n; ++i) keyed[i] = {cellKey(points[i], cell_), i};
  std::sort(keyed.begin(), keyed.end());
  sorted_.resize(n);
  lo_.fill(std::numeric_limits<int64_t>::max());
  hi_.fill(std::numeric_limits<int64_t>::min());
  for (int32_t i = 0; i < n; ++i) {
    sorted_[i] = keyed[i].second;
    auto [it, fresh] = cells_.try_emplace(keyed[i].first, i, i);
    it->second.second = i + 1;
    for (int a = 0; a < 3; ++a) {
      lo_[a] = std::min(lo_[a], keyed[i].first[a]);
      hi_[a] = std::max(hi_[a], keyed[i].first[a]);
    }
  }
}

int64_t PointGrid::nearest(const std::vector<Vec3>& pts, const Vec3& q) const {
  if (pts.empty() || sorted_.empty()) return -1;
  int64_t best = -1;
  double bd = std::numeric_limits<double>::infinity();
  auto consider = [&](int64_t i) {
    const double d = (pts[i] - q).squaredNorm();
    if (d < bd || (d == bd && i < best)) {
      bd = d;
      best = i;
    }
  };
  const CellKey k = cellKey(q, cell_);
  for (int64_t ring = 0; ring <= kMaxRings; ++ring) {
    // Cells of Chebyshev distance `ring` from the query's cell, within the occupied range.
    for (int64_t x = std::max(k[0] - ring, lo_[0]); x <= std::min(k[0] + ring, hi_[0]); ++x)
      for (int64_t y = std::max(k[1] - ring, lo_[1]); y <= std::min(k[1] + ring, hi_[1]); ++y)
        for (int64_t z = std::max(k[2] - ring, lo_[2]); z <= std::min(k[2] + ring, hi_[2]); ++z) {
          if (std::max({std::abs(x - k[0]), std::abs(y - k[1]), std::abs(z - k[2])}) != ring)
            continue;
          const auto it = cells_.find({x, y, z});
          if (it == cells_.end()) continue;
          for (int32_t s = it->second.first; s < it->second.second; ++s) consider(sorted_[s]);
        }
    // Points of farther rings lie at least `ring` whole cells away.
    const double reach = static_cast<double>(ring) * cell_;
    if (best >= 0 && bd < reach * reach) return best;
  }
  // Far from every point: scan them all.
  for (int64_t i = 0; i < static_cast<int64_t>(pts.size()); ++i) consider(i);
  return best;
}

void buildAdjacency(PointSet* ps, double cell) {
  const int64_t n = static_cast<int64_t>(ps->points.size());
  ps->cell = cell;
  const double reach2 = (1.8 * cell) * (1.8 * cell);
  std::unordered_map<CellKey, std::vector<int32_t>, CellKeyHash> grid;
  for (int64_t i = 0; i < n; ++i)
    grid[cellKey(ps->points[i], cell)].push_back(static_cast<int32_t>(i));
  std::vector<std::vector<int32_t>> nb(n);
  tbb::parallel_for(int64_t{0}, n, [&](int64_t i) {
    pollCancel();
    // Neighbours are closer than 1.8 cells: in the 5 x 5 x 5 cells about the point's.
    anyCellAround(cellKey(ps->points[i], cell), 2, [&](const CellKey& c) {
      const auto it = grid.find(c);
      if (it == grid.end()) return false;
      for (int32_t j : it->second)
        if (j != i && (ps->points[j] - ps->points[i]).squaredNorm() <= reach2) nb[i].push_back(j);
      return false;
    });
    std::sort(nb[i].begin(), nb[i].end());
  });
  ps->adj_start.assign(n + 1, 0);
  for (int64_t i = 0; i < n; ++i)
    ps->adj_start[i + 1] = ps->adj_start[i] + static_cast<int32_t>(nb[i].size());
  ps->adj.clear();
  ps->adj.reserve(ps->adj_start[n]);
  for (auto& v : nb) ps->adj.insert(ps->adj.end(), v.begin(), v.end());
  ps->grid = PointGrid(ps->points, cell);
}

PointSet samplePoints(const SolidIndex& index, int64_t target, double interior_share,
                      uint64_t seed) {
  PointSet ps;
  const Mesh& mesh = index.mesh();
  const double volume = std::max(signedVolume(mesh), 1e-300);
  const int64_t want_inside = std::max<int64_t>(1, std::llround(target * interior_share));
  double h = cappedSpacing(index.bounds(), std::cbrt(volume / static_cast<double>(want_inside)));
  std::vector<Vec3> inside;
  for (int refine = 0; refine <= kMaxRefinements; ++refine) {
    inside = interiorGrid(index, h);
    if (static_cast<double>(inside.size()) >= kMinInteriorShare * want_inside) break;
    if (gridCells(index.bounds(), 0.5 * h) > kMaxGridCells) break;
    h *= 0.5;
  }
  ps.spacing = h;
  ps.interior = static_cast<int64_t>(inside.size());
  ps.points = std::move(inside);

  const int64_t want_surface = std::max<int64_t>(0, target - want_inside);
  const SurfaceSampler sampler(mesh);
  std::mt19937_64 rng(mixSeed(seed, 77));
  for (int64_t k = 0; k < want_surface; ++k) ps.points.push_back(sampler.sample(rng));

  // Adjacency through a hash grid, over cells of about the larger point spacing.
  const double surface_spacing =
      want_surface > 0 ? std::sqrt(surfaceArea(mesh) / static_cast<double>(want_surface)) : h;
  buildAdjacency(&ps, 1.01 * std::max(h, surface_spacing));
  return ps;
}

}  // namespace sphereset::detail

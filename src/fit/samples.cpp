// Sampling the solid for clustering. Reference: Wang et al. 2006, Sec. 5 "Preprocessing":
// inner points from a voxelisation with the outside points removed, surface points in
// proportion to triangle area (Turk 1990). Deviation: the grid spacing is chosen from a target
// point count instead of by hand, and refined until the solid holds enough interior points.
#include "fit/samples.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
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

// Blocks of at most this many cells are classified cell by cell.
constexpr int64_t kLeafBlockCells = 8;
// Edge, in cells, of the blocks the grid is cut into for the parallel loop.
constexpr int64_t kTopBlockEdge = 32;
// Margin by which a block's cells must clear the surface (beyond the index's boundary
// tolerance) for one classification to stand for all of them, as a fraction of the box's
// diagonal plus its largest coordinate: rounding in the cells' coordinates grows with both (a
// small part far from the origin).
constexpr double kBlockClearance = 1e-9;

// The interior grid: cell (i, j, k) is the point origin + h (i, j, k).
struct Grid {
  Vec3 origin;
  double h = 0.0;
  std::array<int64_t, 3> n{};
  Vec3 point(int64_t i, int64_t j, int64_t k) const { return origin + h * Vec3(i, j, k); }
  int64_t flat(int64_t i, int64_t j, int64_t k) const { return (k * n[1] + j) * n[0] + i; }
};

// Marks the inside cells of the block [lo, hi). A block whose cells all lie in a ball that
// clears the surface has one containment, that of its centre, as a per-cell classification
// would find; other blocks are split in eight. The marks are those of classifying every cell,
// at the cost of one distance per block on the way down.
void classifyBlock(const SolidIndex& index, const Grid& g, double clearance,
                   std::array<int64_t, 3> lo, std::array<int64_t, 3> hi, std::vector<char>* in) {
  const Vec3 size(static_cast<double>(hi[0] - lo[0]), static_cast<double>(hi[1] - lo[1]),
                  static_cast<double>(hi[2] - lo[2]));
  auto fill = [&](auto&& inside_at) {
    for (int64_t k = lo[2]; k < hi[2]; ++k)
      for (int64_t j = lo[1]; j < hi[1]; ++j)
        for (int64_t i = lo[0]; i < hi[0]; ++i) (*in)[g.flat(i, j, k)] = inside_at(i, j, k);
  };
  if (size.prod() <= static_cast<double>(kLeafBlockCells)) {
    fill([&](int64_t i, int64_t j, int64_t k) {
      return index.classify(g.point(i, j, k)) == Containment::kInside;
    });
    return;
  }
  const Vec3 centre =
      g.origin + g.h * 0.5 * (Vec3(lo[0] + hi[0] - 1, lo[1] + hi[1] - 1, lo[2] + hi[2] - 1));
  const double radius = 0.5 * g.h * (size - Vec3::Ones()).norm();
  if (index.distance(centre) > radius + clearance) {
    const bool inside = index.classify(centre) == Containment::kInside;
    fill([&](int64_t, int64_t, int64_t) { return inside; });
    return;
  }
  const std::array<int64_t, 3> mid{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  for (int c = 0; c < 8; ++c) {
    std::array<int64_t, 3> a = lo, b = hi;
    for (int axis = 0; axis < 3; ++axis) (c >> axis & 1 ? a : b)[axis] = mid[axis];
    if (a[0] < b[0] && a[1] < b[1] && a[2] < b[2]) classifyBlock(index, g, clearance, a, b, in);
  }
}

std::vector<Vec3> interiorGrid(const SolidIndex& index, double h) {
  const Aabb& b = index.bounds();
  const Vec3 ext = b.max - b.min;
  Grid g;
  g.h = h;
  g.n = {std::max<int64_t>(1, ceilCells(ext.x() / h)), std::max<int64_t>(1, ceilCells(ext.y() / h)),
         std::max<int64_t>(1, ceilCells(ext.z() / h))};
  // Centre the grid in the box.
  g.origin = b.center() - 0.5 * h * Vec3(g.n[0] - 1, g.n[1] - 1, g.n[2] - 1);
  const double magnitude = std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
  const double clearance = index.boundaryTolerance() + kBlockClearance * (b.diagonal() + magnitude);
  std::array<int64_t, 3> blocks{};
  for (int axis = 0; axis < 3; ++axis)
    blocks[axis] = (g.n[axis] + kTopBlockEdge - 1) / kTopBlockEdge;
  std::vector<char> in(static_cast<size_t>(g.n[0] * g.n[1] * g.n[2]), 0);
  tbb::parallel_for(int64_t{0}, blocks[0] * blocks[1] * blocks[2], [&](int64_t t) {
    pollCancel();
    const std::array<int64_t, 3> at{t % blocks[0], t / blocks[0] % blocks[1],
                                    t / (blocks[0] * blocks[1])};
    std::array<int64_t, 3> lo{}, hi{};
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = at[axis] * kTopBlockEdge;
      hi[axis] = std::min(g.n[axis], lo[axis] + kTopBlockEdge);
    }
    classifyBlock(index, g, clearance, lo, hi, &in);
  });
  std::vector<Vec3> out;
  for (int64_t k = 0; k < g.n[2]; ++k)
    for (int64_t j = 0; j < g.n[1]; ++j)
      for (int64_t i = 0; i < g.n[0]; ++i)
        if (in[g.flat(i, j, k)]) out.push_back(g.point(i, j, k));
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

double surfaceSpacing(const SolidIndex& index, const PointSet& ps) {
  const double surface = static_cast<double>(ps.points.size()) - static_cast<double>(ps.interior);
  return std::sqrt(surfaceArea(index.mesh()) / std::max(1.0, surface));
}

double boundMinEdge(const SolidIndex& index, const PointSet& ps) {
  return 0.5 * std::min(surfaceSpacing(index, ps), ps.spacing);
}

}  // namespace sphereset::detail

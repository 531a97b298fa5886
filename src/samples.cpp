// Sampling the solid for clustering. Reference: Wang et al. 2006, Sec. 5 "Preprocessing":
// inner points from a voxelisation with the outside points removed, surface points in
// proportion to triangle area (Turk 1990). Deviation: the grid spacing is chosen from a target
// point count instead of by hand, and refined until the solid holds enough interior points.
#include "samples.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "sampling.hpp"

namespace sphereset::detail {
namespace {

// Fewest interior points accepted before the grid is refined (thin parts, small targets).
constexpr double kMinInteriorShare = 0.5;
constexpr int kMaxRefinements = 4;

std::vector<Vec3> interiorGrid(const SolidIndex& index, double h) {
  const Aabb& b = index.bounds();
  const Vec3 ext = b.max - b.min;
  const int64_t nx = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(ext.x() / h)));
  const int64_t ny = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(ext.y() / h)));
  const int64_t nz = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(ext.z() / h)));
  // Centre the grid in the box.
  const Vec3 origin = b.center() - 0.5 * h * Vec3(nx - 1, ny - 1, nz - 1);
  std::vector<std::vector<Vec3>> slabs(nz);
  tbb::parallel_for(int64_t{0}, nz, [&](int64_t k) {
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

struct CellHash {
  size_t operator()(const std::array<int64_t, 3>& k) const {
    return static_cast<size_t>(k[0] * 73856093 ^ k[1] * 19349663 ^ k[2] * 83492791);
  }
};

}  // namespace

void buildAdjacency(PointSet* ps, double cell) {
  const int64_t n = static_cast<int64_t>(ps->points.size());
  ps->cell = cell;
  const double reach2 = (1.8 * cell) * (1.8 * cell);
  std::unordered_map<std::array<int64_t, 3>, std::vector<int32_t>, CellHash> grid;
  auto key = [&](const Vec3& p) {
    return std::array<int64_t, 3>{static_cast<int64_t>(std::floor(p.x() / cell)),
                                  static_cast<int64_t>(std::floor(p.y() / cell)),
                                  static_cast<int64_t>(std::floor(p.z() / cell))};
  };
  for (int64_t i = 0; i < n; ++i) grid[key(ps->points[i])].push_back(static_cast<int32_t>(i));
  std::vector<std::vector<int32_t>> nb(n);
  tbb::parallel_for(int64_t{0}, n, [&](int64_t i) {
    const auto k = key(ps->points[i]);
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dz = -2; dz <= 2; ++dz) {
          auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (int32_t j : it->second)
            if (j != i && (ps->points[j] - ps->points[i]).squaredNorm() <= reach2)
              nb[i].push_back(j);
        }
    std::sort(nb[i].begin(), nb[i].end());
  });
  ps->adj_start.assign(n + 1, 0);
  for (int64_t i = 0; i < n; ++i)
    ps->adj_start[i + 1] = ps->adj_start[i] + static_cast<int32_t>(nb[i].size());
  ps->adj.clear();
  ps->adj.reserve(ps->adj_start[n]);
  for (auto& v : nb) ps->adj.insert(ps->adj.end(), v.begin(), v.end());
}

PointSet samplePoints(const SolidIndex& index, int64_t target, double interior_share,
                      uint64_t seed) {
  PointSet ps;
  const Mesh& mesh = index.mesh();
  const double volume = std::max(signedVolume(mesh), 1e-300);
  const int64_t want_inside = std::max<int64_t>(1, std::llround(target * interior_share));
  double h = std::cbrt(volume / static_cast<double>(want_inside));
  std::vector<Vec3> inside;
  for (int refine = 0; refine <= kMaxRefinements; ++refine) {
    inside = interiorGrid(index, h);
    if (static_cast<double>(inside.size()) >= kMinInteriorShare * want_inside) break;
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

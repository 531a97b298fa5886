// Evaluation of a sphere set (paper Sec. 7 metrics, plus certified coverage).
//
// - E_r summed: Σ SOV(S_i) / vol, exact (paper eq. 4 divided by the mesh volume).
// - E_r of the union: Monte Carlo. A sphere is picked in proportion to its volume and a point
//   drawn uniformly in it; the estimator ΣV · [outside] / (number of spheres containing the
//   point) is unbiased for the union's outside volume and samples only where spheres are.
// - Surface coverage: each triangle is certified when it lies in one sphere (convexity: its
//   three vertices do), otherwise split in four, down to a depth limit. Any vertex or centroid
//   found outside every sphere refutes coverage and gives a gap (eval/coverage_pieces.hpp, the
//   rule the incremental certificate of certificate.hpp shares).
// - Interior coverage: the same on octree cells: a cell is certified when its corners share a
//   sphere or it is free of surface and outside the solid (cover/cover_cells.hpp).
// - Proximity (paper Sec. 7, Fig. 14): outside length of random surface-to-surface segments
//   against the mesh and against the union of spheres. The paper draws segments between two
//   copies of the model; we draw both end points on the one mesh.
// Work is split into fixed blocks with their own seeded generators, so results do not depend
// on the number of threads.
#include "sphereset/evaluate.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>

#include "cover/cover_cells.hpp"
#include "cover/segment_cover.hpp"
#include "eval/coverage_pieces.hpp"
#include "util/poll.hpp"
#include "util/sampling.hpp"

namespace sphereset {
namespace {

using detail::mixSeed;
using detail::uniform01;

// E_r of the union by Monte Carlo: sets er_union and its standard error.
void unionOutsideVolume(const SolidIndex& index, const std::vector<Sphere>& spheres,
                        const EvalOptions& options, double vol, EvalResult* res) {
  const size_t n = spheres.size();
  std::vector<double> cum(n);
  double vsum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    vsum += 4.0 / 3.0 * std::numbers::pi * std::pow(spheres[i].radius, 3);
    cum[i] = vsum;
  }
  if (n == 0 || !(vsum > 0.0) || options.union_samples <= 0) return;
  constexpr int64_t kBlock = 4096;
  const int64_t blocks = (options.union_samples + kBlock - 1) / kBlock;
  std::vector<std::pair<double, double>> part(blocks);  // (Σ x, Σ x²)
  tbb::parallel_for(int64_t{0}, blocks, [&](int64_t blk) {
    detail::pollCancel();
    std::mt19937_64 rng(mixSeed(options.seed, 1000 + blk));
    const int64_t count = std::min(kBlock, options.union_samples - blk * kBlock);
    double sx = 0.0, sxx = 0.0;
    for (int64_t k = 0; k < count; ++k) {
      const double pick = uniform01(rng) * vsum;
      const size_t i =
          std::min<size_t>(std::upper_bound(cum.begin(), cum.end(), pick) - cum.begin(), n - 1);
      Vec3 u;
      do {
        u = Vec3(2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1);
      } while (u.squaredNorm() > 1.0);
      const Vec3 p = spheres[i].center + spheres[i].radius * u;
      double x = 0.0;
      if (index.classify(p) == Containment::kOutside) {
        int cover = 0;
        for (const Sphere& s : spheres) cover += s.contains(p) ? 1 : 0;
        x = vsum / std::max(cover, 1);
      }
      sx += x;
      sxx += x * x;
    }
    part[blk] = {sx, sxx};
  });
  double sx = 0.0, sxx = 0.0;
  for (const auto& [a, b] : part) {
    sx += a;
    sxx += b;
  }
  const double m = static_cast<double>(options.union_samples);
  const double mean = sx / m;
  const double var = std::max(0.0, sxx / m - mean * mean);
  res->er_union = mean / vol;
  res->er_union_stderr = std::sqrt(var / m) / vol;
}

// Surface coverage of a mesh's triangles, certified per triangle.
detail::SurfaceCover surfaceCoverage(const Mesh& mesh, const detail::SphereGrid& grown_grid,
                                     size_t n, const EvalOptions& options, double diag) {
  std::vector<detail::PieceCover> st(mesh.triangles.size());
  tbb::parallel_for(size_t{0}, st.size(), [&](size_t t) {
    detail::pollCancel();
    st[t] = detail::certifyTriangle(grown_grid, mesh, t, options.surface_max_depth);
  });
  return detail::summarizeSurface(st, n, diag);
}

// Interior coverage on an octree below an 8³ grid of cubes covering the bounds: the walk
// stops at a gap (the cube is refuted).
void interiorCoverage(const SolidIndex& index, const detail::SphereGrid& grown_grid, size_t n,
                      const EvalOptions& options, double diag, EvalResult* res) {
  std::vector<detail::PieceCover> st(detail::kRootCells);
  tbb::parallel_for(0, detail::kRootCells, [&](int k) {
    double size = 0.0;
    const Vec3 mn = detail::rootCell(index.bounds(), k, &size);
    detail::walkSolidCells(
        index, grown_grid, mn, size, 0, options.interior_max_depth,
        [&](const Vec3&, double, int, double gap) {
          st[k].gap = std::max(st[k].gap, gap);
          return false;  // refuted
        },
        [&](const Vec3&, double) { st[k].uncertified += 1.0; });
  });
  const detail::InteriorCover c = detail::summarizeInterior(st, n, diag, res->surface_covered);
  res->max_interior_gap = c.max_gap;
  res->interior_uncertified_cells = c.uncertified_cells;
  res->interior_covered = c.covered;
}

// Mean proximity error over random surface-to-surface segments, / diag.
double proximityError(const SolidIndex& index, const std::vector<Sphere>& spheres,
                      const EvalOptions& options, double diag) {
  const detail::SurfaceSampler sampler(index.mesh());
  const int segs = options.proximity_segments;
  std::vector<double> err(segs);
  tbb::parallel_for(0, segs, [&](int k) {
    detail::pollCancel();
    std::mt19937_64 rng(mixSeed(options.seed, 5000000 + k));
    const Vec3 a = sampler.sample(rng), bb = sampler.sample(rng);
    err[k] = std::abs(index.outsideLength(a, bb) - detail::segmentOutsideSpheres(spheres, a, bb));
  });
  double s = 0.0;
  for (double e : err) s += e;
  return s / segs / diag;
}

}  // namespace

Expected<EvalResult> evaluateSpheres(const SolidIndex& index, const std::vector<Sphere>& spheres,
                                     const EvalOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkEvalOptions(options); !st) return st.error();
  // Cancellation from inside the long loops (util/poll.hpp).
  const detail::PollScope poll(options.poll, options.poll_interval);
  if (Status st = detail::checkSpheres(spheres); !st) return st.error();
  EvalResult res;
  const Mesh& mesh = index.mesh();
  res.mesh_volume = signedVolume(mesh);
  res.bbox_diagonal = index.bounds().diagonal();
  const double diag = res.bbox_diagonal > 0.0 ? res.bbox_diagonal : 1.0;
  const double vol = res.mesh_volume > 0.0 ? res.mesh_volume : 1.0;
  const size_t n = spheres.size();

  // Exact summed outside volume.
  res.outside_volume.assign(n, 0.0);
  tbb::parallel_for(size_t{0}, n, [&](size_t i) {
    detail::pollCancel();
    res.outside_volume[i] = index.outsideVolume(spheres[i]).volume;
  });
  double total = 0.0;
  for (double v : res.outside_volume) total += v;
  res.er_sum = total / vol;
  if (options.walls) {
    // E_r against the walls of an envelope (repair.hpp): the same spheres, the walls' volume.
    const SolidIndex walls(*options.walls);
    std::vector<double> walls_outside(n, 0.0);
    tbb::parallel_for(size_t{0}, n, [&](size_t i) {
      detail::pollCancel();
      walls_outside[i] = walls.outsideVolume(spheres[i]).volume;
    });
    double walls_total = 0.0;
    for (double v : walls_outside) walls_total += v;
    res.walls_volume = signedVolume(*options.walls);
    res.er_walls = res.walls_volume > 0.0 ? walls_total / res.walls_volume : 0.0;
  } else {
    res.walls_volume = res.mesh_volume;
    res.er_walls = res.er_sum;
  }

  unionOutsideVolume(index, spheres, options, vol, &res);

  // Coverage: spheres grown by the rounding tolerance.
  const std::vector<Sphere> grown = detail::grownSpheres(spheres, diag);
  const detail::SphereGrid grown_grid(grown);
  const detail::SurfaceCover sc = surfaceCoverage(mesh, grown_grid, n, options, diag);
  res.surface_covered = sc.covered;
  res.max_surface_gap = sc.max_gap;
  res.surface_uncertified_area = sc.uncertified;
  res.uncovered_triangles = sc.uncovered;
  if (options.original) {
    const detail::SurfaceCover oc =
        surfaceCoverage(*options.original, grown_grid, n, options, diag);
    res.original_covered = oc.covered;
    res.max_original_gap = oc.max_gap;
    res.original_uncovered_triangles = oc.uncovered;
  }
  interiorCoverage(index, grown_grid, n, options, diag, &res);

  if (options.proximity_segments > 0 && n > 0)
    res.proximity_error = proximityError(index, spheres, options, diag);

  if (options.protrusion_tolerance > 0.0 && n > 0) {
    ProtrusionOptions po;
    po.tolerance = options.protrusion_tolerance * diag;
    auto p = sphereProtrusion(index, spheres, po);
    if (!p) return p.error();
    res.protrusion = p->upper;
    res.protrusion_witness_distance = p->lower;
    res.protrusion_witness = p->witness;
    res.protrusion_sphere = p->sphere;
    res.protrusion_converged = p->converged;
    for (const SphereProtrusionBound& b : p->spheres) res.sphere_protrusion.push_back(b.upper);
  }

  if (options.shadow_resolution > 0 && n > 0) {
    const ShadowResult sh = compareShadows(index, spheres, options.up_axis,
                                           options.shadow_resolution, options.shadow_lights);
    res.shadow_error_sky = sh.sky_rms;
    res.shadow_error_lights = sh.lights_rms;
  }

  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace sphereset

// The bounding step of the fit. Reference: Wang et al. 2006, Sec. 5, footnote 1: "to ensure
// that the sphere set bounds the triangle mesh, each sphere is enlarged as a post-process to
// bound the edge mid-points and triangle centers". Deviation: bound.cpp covers the whole
// surface exactly (triangles split until one sphere holds each piece) and the interior cubes
// of the evaluation's test, instead of sampled points only. The bounding step grows spheres
// where the surface between samples pokes out; spheres that grew are refitted (the sphere
// update, Eq. 5) with the pieces they had to take added to their points, so that their centres
// can move instead of only their radii growing; a last pass then guarantees the bound.
#include "fit/bound_refit.hpp"

#include <tbb/parallel_for.h>

#include "fit/sphere_update.hpp"
#include "sphereset/cover.hpp"

namespace sphereset::detail {
namespace {

// Refits of the spheres the bounding step enlarged, before the final bounding pass.
constexpr int kRefitPasses = 2;
// Passes of the interior bound (each settles the cubes it finds; one usually suffices).
constexpr int kInteriorPasses = 4;

}  // namespace

BoundStats boundWithRefits(const SolidIndex& index, std::vector<Sphere>* sp,
                           std::vector<std::vector<Vec3>>* mem, double min_edge, bool refit,
                           const FitOptions& o, FitResult* res, const Mesh* surface,
                           const std::vector<bool>* refittable) {
  const int n = static_cast<int>(sp->size());
  // The pieces a sphere grew for are kept only for the spheres that are refitted: a local step's
  // bound held millions of pieces for none (a removal) or all but two (a split).
  std::vector<std::vector<Vec3>> held;
  SurfaceBoundOptions bo;
  bo.min_edge = min_edge;
  bo.held = refit ? &held : nullptr;
  bo.held_for = refittable;
  bo.surface = surface;
  BoundStats b = boundSurface(index, sp, bo);
  res->bounding_pieces += b.pieces;
  res->bounding_queries += b.queries;
  for (int pass = 0; refit && pass < kRefitPasses && b.enlarged > 0; ++pass) {
    tbb::parallel_for(0, n, [&](int i) {
      if (held[i].empty() || (refittable && !(*refittable)[i])) return;
      (*mem)[i].insert((*mem)[i].end(), held[i].begin(), held[i].end());
      (*sp)[i] =
          updateSphere(index, (*mem)[i], (*sp)[i].center, o.optimizer, o.optimizer_evaluations)
              .sphere;
    });
    b = boundSurface(index, sp, bo);
    res->bounding_pieces += b.pieces;
    res->bounding_queries += b.queries;
  }
  return b;
}

void boundInteriorPasses(const SolidIndex& index, std::vector<Sphere>* sp, FitResult* res,
                         const Aabb* region, GeometryForest* cells) {
  // Between grid points the clusters' spheres can leave gaps (most of all for the baselines).
  // Radii only grow, so the surface stays covered.
  for (int pass = 0; pass < kInteriorPasses; ++pass) {
    const BoundStats is = boundInterior(index, sp, kInteriorSplitDepth, region, cells);
    res->bounding_queries += is.queries;
    res->bounding_interior_cells += is.pieces;
    if (is.enlarged == 0) break;
  }
}

}  // namespace sphereset::detail

// Private: the bounding step as the fit runs it: the surface bound of bound.cpp with refits of
// the spheres it enlarged, and the interior passes.
#pragma once

#include <vector>

#include "fit/bound.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::detail {

// Bounds the surface with the spheres `sp` (the points of their clusters in `mem`). If
// `refit`, the spheres that grew are refitted up to kRefitPasses times with the pieces they had
// to take added to their points, each followed by a bounding pass. Returns the statistics of
// the last pass; pieces and queries add to *res. A local bound (local_split.cpp) gives the
// triangles to cover (`surface`, else the solid's) and which spheres may be refitted
// (`refittable`, else all): a refit moves a sphere off what it covered.
BoundStats boundWithRefits(const SolidIndex& index, std::vector<Sphere>* sp,
                           std::vector<std::vector<Vec3>>* mem, double min_edge, bool refit,
                           const FitOptions& o, FitResult* res, const Mesh* surface = nullptr,
                           const std::vector<bool>* refittable = nullptr);

// Interior bound passes (until one enlarges nothing, at most kInteriorPasses): the cubes of
// the evaluation's octree test whose centres lie inside the solid are covered too; with
// `region`, only its cubes that meet the region; with `cells`, the cubes' geometry kept there
// (boundInterior).
void boundInteriorPasses(const SolidIndex& index, std::vector<Sphere>* sp, FitResult* res,
                         const Aabb* region = nullptr, GeometryForest* cells = nullptr);

}  // namespace sphereset::detail

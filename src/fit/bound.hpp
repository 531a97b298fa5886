// Private: the guaranteed-bounding step of the fit.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

struct BoundStats {
  int64_t enlarged = 0;  // spheres whose radius grew
  int64_t pieces = 0;    // triangle pieces that needed an enlargement
  int64_t queries = 0;   // outside-volume evaluations
};

// Enlarges spheres until every point of every triangle lies in some sphere: each triangle is
// split in four until each piece has its three vertices in one sphere (then the piece is
// inside it, by convexity) or is shorter than `min_edge`; such a small piece is given to the
// sphere whose outside volume grows least when enlarged to hold its vertices.
// If `held` is given, (*held)[i] receives the vertices of the pieces sphere i was enlarged for.
// The triangles are those of `surface`, or of the index's mesh when it is null.
BoundStats boundSurface(const SolidIndex& index, std::vector<Sphere>* spheres, double min_edge,
                        std::vector<std::vector<Vec3>>* held = nullptr,
                        const Mesh* surface = nullptr);

// Interior coverage on the octree of cover_cells.hpp (the same test `evaluateSpheres` runs):
// cubes down to `max_depth` whose centre lies inside the solid but in no sphere are handed
// whole to the sphere whose outside volume grows least. One pass; radii only grow.
BoundStats boundInterior(const SolidIndex& index, std::vector<Sphere>* spheres, int max_depth);

// For each sphere, what it alone covers: the vertices of the surface pieces (triangles split
// until one sphere holds each piece, as in boundSurface) that no other sphere holds, and the
// given interior points no other sphere contains. A sphere refitted around these keeps
// everything covered that only it covered.
std::vector<std::vector<Vec3>> soleCover(const SolidIndex& index, const std::vector<Sphere>& sp,
                                         const std::vector<Vec3>& interior, double min_edge);

}  // namespace sphereset::detail

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
BoundStats boundSurface(const SolidIndex& index, std::vector<Sphere>* spheres, double min_edge,
                        std::vector<std::vector<Vec3>>* held = nullptr);

// Interior coverage on the octree of cover_cells.hpp (the same test `evaluateSpheres` runs):
// cubes down to `max_depth` whose centre lies inside the solid but in no sphere are handed
// whole to the sphere whose outside volume grows least. One pass; radii only grow.
BoundStats boundInterior(const SolidIndex& index, std::vector<Sphere>* spheres, int max_depth);

}  // namespace sphereset::detail

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

}  // namespace sphereset::detail

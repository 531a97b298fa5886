// Private: the index's queries done the slow, obvious way, the oracles of the tests and the
// baselines of the benchmarks; no production code uses them. The per-triangle kernels they
// share with the accelerated queries are in sphere_triangle.hpp and winding.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "index/sphere_triangle.hpp"
#include "index/winding.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {

// SolidIndex::outsideVolume summed over every triangle, with no hierarchy.
OutsideVolume outsideVolumeBruteForce(const SolidIndex& index, const Sphere& ball);

// Original indices of the triangles whose bounding boxes overlap the ball, sorted.
std::vector<int32_t> trianglesNearBall(const SolidIndex& index, const Sphere& ball);

}  // namespace sphereset

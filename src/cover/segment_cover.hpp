// Private: the length of a segment outside a set of spheres, from the union of the parameter
// intervals inside each sphere (Wang et al. 2006, Sec. 7 "Proximity Application"). The
// evaluation's proximity error uses it over a plain set; the tree queries over a tree's leaves.
#pragma once

#include <utility>
#include <vector>

#include "sphereset/sphere.hpp"

namespace sphereset::detail {

// Parameter interval [t0, t1] ⊂ [0, 1] of a + t d inside the sphere, if not empty.
bool segmentInterval(const Sphere& s, const Vec3& a, const Vec3& d, double* t0, double* t1);

// Length of [0, len] left outside the union of the intervals (sorted in place).
double uncoveredLength(std::vector<std::pair<double, double>>* in, double len);

// Length of segment [a, b] outside every sphere of the set: one interval per sphere.
double segmentOutsideSpheres(const std::vector<Sphere>& spheres, const Vec3& a, const Vec3& b);

}  // namespace sphereset::detail

// Private: the comparison methods of the fit (paper Sec. 2 and 5): an octree of occupied
// cells (Hubbard) and L2 Lloyd (k-means) clusters, each cluster bounded by its minimal
// enclosing ball. fit.cpp runs them on the same points and through the same bounding step.
#pragma once

#include <cstdint>
#include <vector>

#include "fit/samples.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset::detail {

struct BaselineResult {
  std::vector<Sphere> spheres;  // each the minimal ball of its cluster's points
  int iterations = 0;           // k-means rounds, or octree splits
  bool converged = false;       // k-means: the assignment stopped changing
};

// Octree: starting from the bounding cube of the points, the occupied leaf with the largest
// ball is split into its occupied octants while the count stays within n; a split that would
// overshoot keeps the largest octants and merges the rest into one leaf. At most n spheres
// (fewer only when the points cannot be split further).
BaselineResult octreeSpheres(const PointSet& ps, int n);

// k-means with farthest-point seeds from `seeds`, at most max_iterations rounds.
BaselineResult kmeansSpheres(const PointSet& ps, const std::vector<Vec3>& seeds,
                             int max_iterations);

}  // namespace sphereset::detail

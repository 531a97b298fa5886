// Private: the clustering rounds of the variational fit (paper Sec. 5): Lloyd-style
// alternation of point assignment and sphere update, with teleports.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "fit/samples.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// The best complete state (every cluster has a point) of a clustering.
struct Clustering {
  std::vector<Sphere> spheres;             // empty if no round gave every cluster a point
  std::vector<std::vector<Vec3>> members;  // the points of each sphere's cluster
  double energy = std::numeric_limits<double>::infinity();
  bool converged = false;  // stopped because neither rounds nor teleports improved
};

// The clustering from the given centres (one cluster each): rounds of assignment and update,
// teleports when the error stops improving, until `max_failed` teleports in a row did not
// help or o.max_iterations rounds ran. The best complete state of all rounds is returned.
// Rounds, teleports, counts and times add to *res; report(round, energy) after each round.
Clustering clusterPoints(const SolidIndex& index, const PointSet& ps,
                         const std::vector<Vec3>& centres, const FitOptions& o, int max_failed,
                         FitResult* res, const std::function<void(int, double)>& report);

// The same from a complete state (`start`: spheres, their clusters' points and energy), which
// counts as the best state so far: the rounds start from its centres, and it is returned if no
// round or teleport beats it.
Clustering clusterFrom(const SolidIndex& index, const PointSet& ps, Clustering start,
                       const FitOptions& o, int max_failed, FitResult* res,
                       const std::function<void(int, double)>& report);

}  // namespace sphereset::detail

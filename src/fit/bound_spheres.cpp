// The guaranteed bound of a given set (fit.hpp, boundSpheres): the fit's bounding step without
// the clustering before it, for sets that moved (animate --rebound) or were edited (the view).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "fit/bound.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {

Expected<std::vector<Sphere>> boundSpheres(const SolidIndex& index, std::vector<Sphere> spheres,
                                           const BoundOptions& options) {
  if (Status st = checkSphereSet(spheres, "bound"); !st) return st.error();
  if (Status st = limits::checkRange("min_edge", options.min_edge, 0.0, limits::kMaxCoordinate);
      !st)
    return st.error();
  if (Status st = limits::checkRange("interior_max_depth", options.interior_max_depth, 0,
                                     limits::kMaxInteriorDepth);
      !st)
    return st.error();
  double min_edge = options.min_edge;
  if (min_edge == 0.0) {
    const double samples =
        std::max(kBoundMinSamples, kBoundSamplesPerSphere * static_cast<double>(spheres.size()));
    min_edge = 0.5 * std::sqrt(surfaceArea(index.mesh()) / samples);
  }
  detail::boundSurface(index, &spheres, min_edge);
  for (int pass = 0; pass < kBoundInteriorPasses; ++pass)
    if (detail::boundInterior(index, &spheres, options.interior_max_depth).enlarged == 0) break;
  if (options.original) detail::boundSurface(index, &spheres, min_edge, nullptr, options.original);
  return spheres;
}

}  // namespace sphereset

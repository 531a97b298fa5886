// The end of a fit, after its clustering. Reference: Wang et al. 2006, Sec. 5, footnote 1 (the
// spheres enlarged to bound the surface); everything else here goes beyond the paper and is
// explained in the file of its step: bound_refit.cpp (the exact bound with refits), shrink.cpp,
// refine.cpp, optimal_radii.cpp, bound.cpp (the original triangles).
#include "fit/finish.hpp"

#include <utility>
#include <vector>

#include "fit/bound.hpp"
#include "fit/bound_refit.hpp"
#include "fit/fit_common.hpp"
#include "fit/optimal_radii.hpp"
#include "fit/refine.hpp"
#include "fit/shrink.hpp"

namespace sphereset::detail {

void finishFit(const SolidIndex& index, const PointSet& ps, const FitOptions& o, Clustering* best,
               FitResult* res, GeometryForest* cells) {
  const bool variational = o.method == FitMethod::kVariational;
  const double surface_spacing = surfaceSpacing(index, ps);
  const double min_edge = boundMinEdge(index, ps);
  auto t = FitClock::now();
  BoundStats bs =
      boundWithRefits(index, &best->spheres, &best->members, min_edge, variational, o, res);
  res->seconds.bound += secondsSince(t);
  if (variational && o.shrink_passes > 0) {
    t = FitClock::now();
    shrinkPasses(index, ps, min_edge, o, &best->spheres, &bs, res);
    res->seconds.shrink += secondsSince(t);
  }
  const std::vector<Vec3> interior(ps.points.begin(), ps.points.begin() + ps.interior);
  if (variational && o.refine) {
    t = FitClock::now();
    const RefineStats rs = refineCoverage(index, interior, kRefineSpacing * surface_spacing,
                                          min_edge, res->points, &best->spheres);
    res->bounding_queries += rs.queries;
    if (rs.kept) res->refine_points = rs.points;
    res->seconds.refine += secondsSince(t);
  }
  if (variational && o.optimal_radii)
    runOptimalRadii(index, interior, min_edge, &best->spheres, res);
  res->bounding_enlarged = bs.enlarged;
  t = FitClock::now();
  boundInteriorPasses(index, &best->spheres, res, nullptr, cells);
  if (o.original) {
    // A repaired solid's input triangles: the wrap holds them strictly inside and a union or
    // capped solid holds them on or inside its boundary, so this pass rarely grows a sphere;
    // it makes their coverage exact rather than implied.
    const BoundStats ob = boundSurface(index, &best->spheres, min_edge, nullptr, o.original);
    res->bounding_enlarged += ob.enlarged;
    res->bounding_pieces += ob.pieces;
    res->bounding_queries += ob.queries;
  }
  res->seconds.bound += secondsSince(t);
  for (Sphere& s : best->spheres) s.radius += o.padding;
  res->spheres = std::move(best->spheres);
  res->outside_volume = outsideVolumes(index, res->spheres);
  res->energy = totalOf(res->outside_volume);
}

}  // namespace sphereset::detail

// Private: everything a fit does after its clustering (fit.cpp, progressive.cpp).
#pragma once

#include "cover/cover_cells.hpp"
#include "fit/lloyd.hpp"
#include "fit/samples.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::detail {

// The clustering's spheres bounded and improved as every fit ends them: the exact bound with
// refits, the shrinking passes, the refinement, the optimal radii, the interior passes and the
// original triangles (the variational steps only for FitMethod::kVariational), each part timed
// in res->seconds; then the padding. Sets res->spheres, outside_volume and energy; `c` is
// left without its spheres. `cells`: the interior cubes' geometry kept between the bounds of one
// solid (boundInterior), or none.
void finishFit(const SolidIndex& index, const PointSet& ps, const FitOptions& o, Clustering* c,
               FitResult* res, GeometryForest* cells = nullptr);

}  // namespace sphereset::detail

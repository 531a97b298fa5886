// Private: the variational clustering with optional decimation (more spheres first, the
// cheapest removed in batches).
#pragma once

#include <functional>

#include "fit/lloyd.hpp"

namespace sphereset::detail {

// The clustering of the variational fit for n spheres. With o.decimation == 0 this is one
// clusterPoints run from n seeds (as in the paper); otherwise it starts with
// round(o.decimation * n) extra spheres (at most as many as there are points beyond n) and
// removes the cheapest in batches, clustering again after each. Counts and times add to *res.
Clustering clusterWithDecimation(const SolidIndex& index, const PointSet& ps, int n,
                                 const FitOptions& o, FitResult* res,
                                 const std::function<void(int, double)>& progress);

}  // namespace sphereset::detail

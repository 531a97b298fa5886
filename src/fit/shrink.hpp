// Private: shrinking passes of the variational fit after the bounding step.
#pragma once

#include <vector>

#include "fit/bound.hpp"
#include "fit/samples.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::detail {

// Up to o.shrink_passes passes over the bounded set `sp` (bounding pieces no shorter than
// `min_edge`), each kept only if it lowers the total outside volume; a kept pass replaces *sp
// and the last bounding statistics *bs. Stops early when a pass gains less than o.tolerance.
void shrinkPasses(const SolidIndex& index, const PointSet& ps, double min_edge, const FitOptions& o,
                  std::vector<Sphere>* sp, BoundStats* bs, FitResult* res);

}  // namespace sphereset::detail

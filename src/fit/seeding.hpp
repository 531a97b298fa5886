// Private: the initial cluster centres of the fit (paper Sec. 5, initialisation).
#pragma once

#include <cstdint>
#include <vector>

#include "fit/samples.hpp"
#include "sphereset/fit.hpp"

namespace sphereset::detail {

// n seeds among the points: farthest-point sampling from a seeded random start, or random
// distinct points (FitInit::kRandom, as in the paper), over the interior points, or over all
// points if there are fewer than n interior points. Fewer than n seeds only if there are fewer
// than n points.
std::vector<Vec3> initialCentres(const PointSet& ps, int n, FitInit init, uint64_t seed);

}  // namespace sphereset::detail

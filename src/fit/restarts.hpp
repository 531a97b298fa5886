// Private: independent restarts of the fit.
#pragma once

#include <cstdint>

#include "sphereset/fit.hpp"

namespace sphereset::detail {

// o.restarts independent fits (fitSpheres with one restart each) from derived seeds; the
// lowest final outside volume wins, ties to the earlier restart. Counts and times add up.
Expected<FitResult> fitWithRestarts(const SolidIndex& index, const FitOptions& o);

// The seed of restart r: the given seed for the first, seeds derived from it for the others
// (sampling and seeding both change).
uint64_t restartSeed(uint64_t seed, int r);

}  // namespace sphereset::detail

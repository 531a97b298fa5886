// Private: independent restarts of the fit.
#pragma once

#include "sphereset/fit.hpp"

namespace sphereset::detail {

// o.restarts independent fits (fitSpheres with one restart each) from derived seeds; the
// lowest final outside volume wins, ties to the earlier restart. Counts and times add up.
Expected<FitResult> fitWithRestarts(const SolidIndex& index, const FitOptions& o);

}  // namespace sphereset::detail

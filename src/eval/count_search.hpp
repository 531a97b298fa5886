// Private: the count search of the tolerances (tolerance_fit.cpp, and the robot's protrusion
// limits, src/robot/protrusion_split.cpp): counts 1, 2, 4, ... until one meets the tolerance
// (or the cap), then bisection between the last count that did not and the first that did.
#pragma once

#include <algorithm>

#include "sphereset/status.hpp"

namespace sphereset::detail {

// Calls meets(n) (Expected<bool>: whether the count n meets the tolerance) in the search's order;
// stops at the first error and returns it. Fits are not monotone in their count, so the caller
// keeps the best count tried.
template <class Meets>
Status searchFewestCount(int cap, Meets&& meets) {
  int lo = 0, hi = 0;
  for (int n = 1;; n = std::min(2 * n, cap)) {
    auto met = meets(n);
    if (!met) return met.error();
    if (*met) {
      hi = n;
      break;
    }
    lo = n;
    if (n == cap) break;
  }
  while (hi > 0 && hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    auto met = meets(mid);
    if (!met) return met.error();
    (*met ? hi : lo) = mid;
  }
  return {};
}

}  // namespace sphereset::detail

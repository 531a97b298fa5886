// Private: the count search of the tolerances (tolerance_fit.cpp, and the robot's protrusion
// limits, src/robot/protrusion_split.cpp): counts 1, 2, 4, ... until one meets the tolerance
// (or the cap), then bisection between the last count that did not and the first that did.
#pragma once

#include <algorithm>

#include "sphereset/status.hpp"

namespace sphereset::detail {

// The progressive runs of a search: the first for up to kFirstWindow spheres, each next one for
// up to kWindowGrowth times the count that passed the last (the cap at most), started from the
// last one's clusterings. A run samples the points of its largest count, so a small count does
// not cluster the points of the cap.
inline constexpr int kFirstWindow = 64;
inline constexpr int kWindowGrowth = 4;

// The largest count of the run that fits `count` when the last run ended below it.
inline int searchWindow(int count, int cap) {
  return std::min(cap, std::max(kFirstWindow, kWindowGrowth * count));
}

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

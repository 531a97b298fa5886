// Private: the sphere counts of a robot's links chosen by a protrusion limit per link
// (RobotFitOptions::max_protrusion, link_max_protrusion; fit_robot.cpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// One link held to a protrusion limit: its solid, its fit options for a largest count (a
// progressive run's, ProgressiveFit, or an independent fit's when they forbid a run), the most
// spheres it may get, and what eval checks it against.
struct ProtrusionLink {
  std::string name;
  const SolidIndex* index = nullptr;
  std::function<FitOptions(int max_count)> options_for;
  int cap = 1;
  const Mesh* original = nullptr;
  const Mesh* walls = nullptr;
  double limit = 0.0;  // the certified protrusion allowed before the padding (length, > 0)
};

// A link's fit and its check.
struct ProtrusionPick {
  int count = 0;
  FitResult fit;
  EvalResult eval;
  bool met = false;  // covered, and the certified protrusion at most the limit
  double seconds = 0.0;
};

// Without a budget (budget 0): each link's fewest spheres that meet its limit (counts 1, 2, 4,
// ... then a bisection, as fitToTolerance searches; at most the link's cap), the links in
// parallel. With one: every link starts at 1
// sphere, then the budget goes one sphere at a time to the link furthest over its limit (the
// largest protrusion / limit; an uncovered fit first), so that the worst link's ratio is as
// small as the greedy split makes it (in steps of a quarter of the link's count); each link
// keeps its best fit of the counts it was given (covered first, then the smaller protrusion).
// `done(link, units)` after each link's search (no budget: 1 unit) or each fit (a budget: the
// spheres it was given; `budget` units in all). Errors: the fits' and checks' (prefixed by the
// link's name).
inline constexpr int kLinkToleranceCap = 256;
Expected<std::vector<ProtrusionPick>> fitToProtrusion(
    const std::vector<ProtrusionLink>& links, int budget,
    const std::function<void(const std::string&, int)>& done);

}  // namespace sphereset::detail

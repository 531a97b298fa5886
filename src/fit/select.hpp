// Private: n spheres chosen among candidates by a weighted set cover of the surface pieces and
// the interior points, at least total outside volume.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// The set-cover instance: candidates with their costs, and the units they must cover grouped
// into classes of units held by the same candidates (one constraint per class).
struct CoverProblem {
  std::vector<double> cost;                   // per candidate: its outside volume
  std::vector<std::vector<int32_t>> classes;  // per class: the candidates holding it, ascending
  int64_t units = 0;                          // surface pieces and interior points held
  int64_t unheld = 0;                         // units no candidate holds (left to the bound)
};

// The units of `candidates`: each triangle of the index's mesh split in four (as the bound
// splits) until a candidate holds each piece (its three vertices), down to pieces of edge
// `min_edge` or the bound's depth; and the `interior` points. With groups (`group_of`: a group
// index per candidate, each group a set that covers the solid, such as one fit's spheres), a
// piece is split until a candidate of every group holds it, and only units every group holds
// are kept, so that each group is a feasible choice; the others count as unheld (the bound
// that follows covers them). Units held by the same candidates form one class; classes ascend
// lexicographically. Independent of the number of threads.
CoverProblem coverProblem(const SolidIndex& index, const std::vector<Sphere>& candidates,
                          const std::vector<int32_t>& group_of, const std::vector<Vec3>& interior,
                          double min_edge);

struct Selection {
  std::vector<int32_t> chosen;  // ascending; empty when no n candidates cover every class
  double cost = 0.0;            // sum of the chosen candidates' costs
  bool proven = false;          // the ILP proved it optimal
  int64_t nodes = 0;            // branch-and-bound nodes of the ILP
  double ilp_seconds = 0.0;     // time in the ILP solver
};

// Exactly n candidates covering every class at least total cost. A start (`start` when it is
// n candidates covering every class, else a greedy cover padded with the cheapest candidates)
// is improved by swapping one chosen candidate for another while that lowers the cost; then
// the ILP (min Σ cost x, Σ x = n, Σ_{c holds k} x_c ≥ 1 for each class k, x binary) is solved
// by CBC from that start, up to `max_nodes` branch-and-bound nodes (deterministic: no time
// limit). The better of the two is returned.
Selection selectCover(const CoverProblem& problem, int n, const std::vector<int32_t>& start,
                      int max_nodes);

}  // namespace sphereset::detail

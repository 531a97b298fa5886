// Splitting a budget of spheres over the links of a robot: by what lowers the robot's total
// outside volume most, from each link's outside volume measured at a few sphere counts.
#pragma once

#include <vector>

#include "sphereset/status.hpp"

namespace sphereset {

// A link's outside volume (absolute units) after fits with a few sphere counts.
struct LinkFitCurve {
  std::vector<int> counts;             // increasing, at least one, all >= 1
  std::vector<double> outside_volume;  // one per count, > 0 where measured
};

// The outside volume at k spheres on the curve: piecewise linear in log k and log volume
// between the measured counts, and the last piece's power law beyond them (the first piece's
// below them); a single measured count gives a constant. A volume of 0 (a link bounded
// exactly) stays 0 from there on.
double curveVolume(const LinkFitCurve& curve, int k);

// The lower envelope the budget split uses: measured volumes made non-increasing (k + 1
// spheres can always do what k do: a repeated sphere adds nothing), then the lower convex
// hull of the points in log k / log volume, so that the interpolated curve is convex and
// decreasing and the greedy split is optimal on it. Quick fits at a few counts are noisy (a
// fit can land in a worse local minimum with more spheres); the envelope keeps the best
// measured at or below each count. Points after the first volume of 0 are dropped.
LinkFitCurve curveEnvelope(const LinkFitCurve& curve);

// Counts per link, from the envelopes of the curves (curveEnvelope). `fixed[i]` >= 0 fixes link i's
// count (0 skips it); -1 leaves it to the budget. Every free link gets one sphere, then each
// further sphere goes to the free link whose curve drops most with one more (ties to the lower
// index), until the budget is spent. Errors (kInvalidArgument): the budget below the fixed counts
// plus one per free link.
Expected<std::vector<int>> splitBudget(const std::vector<LinkFitCurve>& curves,
                                       const std::vector<int>& fixed, int budget);

// The counts of an even split: `budget` spread over the free links (fixed[i] < 0) as evenly as
// possible, the remainder one each to the first free links; fixed links keep theirs. Errors as
// splitBudget's.
Expected<std::vector<int>> evenSplit(const std::vector<int>& fixed, int budget);

// One fitted candidate for a link: its sphere count and the outside volume the fit measured.
struct LinkCandidate {
  int count = 0;
  double outside_volume = 0.0;
};

// Picks one candidate per link (every list non-empty) so that the counts add up to at most
// `budget` and the total outside volume is least (exact, by dynamic programming over the
// totals reachable; ties go to the smaller total count, then to earlier candidates). Returns
// the index chosen per link. The robot command fits each link at the count of the curve split
// and of the even split and picks between them, so its total is never worse than either.
// Errors (kInvalidArgument): an empty list, or no choice within the budget.
Expected<std::vector<int>> pickCandidates(const std::vector<std::vector<LinkCandidate>>& candidates,
                                          int budget);

}  // namespace sphereset

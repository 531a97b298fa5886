// Splitting a sphere budget over a robot's links by marginal gain: a greedy allocation on
// each link's outside volume against its sphere count, measured at a few counts and
// interpolated as a power law between them (the outside volume of a variational fit falls
// roughly as a power of n; see docs/benchmarks.md, "E_r against the number of spheres").
// Greedy allocation is optimal when each curve is convex (diminishing returns), which a
// piecewise power law with decreasing slopes is; measured curves are close to that.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "sphereset/robot_fit.hpp"

namespace sphereset {

namespace {

// A curve as splitBudget and curveVolume take it (`what` names it).
Status checkCurve(const LinkFitCurve& c, const std::string& what) {
  bool ok = c.counts.size() == c.outside_volume.size();
  for (size_t k = 0; ok && k < c.counts.size(); ++k)
    ok = c.counts[k] >= 1 && (k == 0 || c.counts[k] > c.counts[k - 1]) &&
         c.outside_volume[k] >= 0.0 && std::isfinite(c.outside_volume[k]);
  if (!ok)
    return Error{ErrorCode::kInvalidArgument,
                 what + ": expected increasing counts from 1 and one finite volume >= 0 each"};
  return {};
}

// curveVolume on a checked curve and k >= 1.
double interpolate(const LinkFitCurve& c, int k) {
  const size_t m = c.counts.size();
  if (m == 0) return 0.0;
  if (m == 1) return c.outside_volume[0];
  // The piece [i, i+1] that holds k, or the first or last piece outside the measured range.
  size_t i = 0;
  while (i + 2 < m && k > c.counts[i + 1]) ++i;
  const double v0 = c.outside_volume[i], v1 = c.outside_volume[i + 1];
  if (!(v0 > 0.0) || !(v1 > 0.0)) return k >= c.counts[i + 1] ? v1 : v0;
  const double x0 = std::log(static_cast<double>(c.counts[i]));
  const double x1 = std::log(static_cast<double>(c.counts[i + 1]));
  const double slope = (std::log(v1) - std::log(v0)) / (x1 - x0);
  return std::exp(std::log(v0) + slope * (std::log(static_cast<double>(k)) - x0));
}

}  // namespace

Expected<double> curveVolume(const LinkFitCurve& c, int k) {
  if (c.counts.empty()) return Error{ErrorCode::kInvalidArgument, "the curve has no counts"};
  if (Status st = checkCurve(c, "the curve"); !st) return st.error();
  if (k < 1)
    return Error{ErrorCode::kInvalidArgument,
                 "k must be at least 1 (got " + std::to_string(k) + ")"};
  return interpolate(c, k);
}

LinkFitCurve curveEnvelope(const LinkFitCurve& c) {
  // Non-increasing: the best volume measured at or below each count; nothing after a 0.
  LinkFitCurve mono;
  for (size_t i = 0; i < c.counts.size(); ++i) {
    double v = c.outside_volume[i];
    if (!mono.counts.empty()) v = std::min(v, mono.outside_volume.back());
    mono.counts.push_back(c.counts[i]);
    mono.outside_volume.push_back(v);
    if (!(v > 0.0)) break;
  }
  // Lower convex hull in (log k, log v) of the positive points (monotone chain); a final 0 is
  // kept as it is (interpolate steps to it).
  LinkFitCurve hull;
  auto x = [](int k) { return std::log(static_cast<double>(k)); };
  for (size_t i = 0; i < mono.counts.size(); ++i) {
    const double v = mono.outside_volume[i];
    if (v > 0.0) {
      while (hull.counts.size() >= 2) {
        const size_t m = hull.counts.size();
        const double ax = x(hull.counts[m - 2]), ay = std::log(hull.outside_volume[m - 2]);
        const double bx = x(hull.counts[m - 1]), by = std::log(hull.outside_volume[m - 1]);
        const double cx = x(mono.counts[i]), cy = std::log(v);
        // b lies on or above the chord a-c: not on the lower hull.
        if ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) <= 0.0) {
          hull.counts.pop_back();
          hull.outside_volume.pop_back();
        } else {
          break;
        }
      }
    }
    hull.counts.push_back(mono.counts[i]);
    hull.outside_volume.push_back(v);
  }
  return hull;
}

namespace {

Error budgetError(int budget, int used) {
  return {ErrorCode::kInvalidArgument, "a budget of " + std::to_string(budget) +
                                           " spheres is below the " + std::to_string(used) +
                                           " the fixed links and one per other link need"};
}

// The curves of splitBudget: one per link, counts increasing from 1, one volume per count (an
// empty curve, a link whose quick fits all failed, counts as volume 0).
Status checkCurves(const std::vector<LinkFitCurve>& curves, const std::vector<int>& fixed) {
  if (curves.size() != fixed.size())
    return Error{ErrorCode::kInvalidArgument, std::to_string(curves.size()) + " curves for " +
                                                  std::to_string(fixed.size()) + " links"};
  for (size_t i = 0; i < curves.size(); ++i)
    if (Status st = checkCurve(curves[i], "curve " + std::to_string(i)); !st) return st;
  return {};
}

}  // namespace

Expected<std::vector<int>> splitBudget(const std::vector<LinkFitCurve>& measured,
                                       const std::vector<int>& fixed, int budget) {
  if (Status st = checkCurves(measured, fixed); !st) return st.error();
  const size_t n = measured.size();
  std::vector<LinkFitCurve> curves;
  for (const LinkFitCurve& c : measured) curves.push_back(curveEnvelope(c));
  std::vector<int> count(n, 0);
  int used = 0;
  for (size_t i = 0; i < n; ++i) {
    count[i] = fixed[i] >= 0 ? fixed[i] : 1;
    used += count[i];
  }
  if (used > budget) return budgetError(budget, used);
  for (; used < budget; ++used) {
    size_t best = n;
    double best_gain = -1.0;
    for (size_t i = 0; i < n; ++i) {
      if (fixed[i] >= 0) continue;
      const double gain = interpolate(curves[i], count[i]) - interpolate(curves[i], count[i] + 1);
      if (gain > best_gain) {
        best_gain = gain;
        best = i;
      }
    }
    if (best == n) break;  // every link fixed: the rest of the budget is not needed
    ++count[best];
  }
  return count;
}

Expected<std::vector<int>> pickCandidates(const std::vector<std::vector<LinkCandidate>>& cand,
                                          int budget) {
  // Layer i maps each total count reachable with links [0, i) to the least outside volume
  // reaching it and how (the previous total and the candidate taken).
  struct State {
    double volume;
    int previous;
    int choice;
  };
  std::vector<std::map<int, State>> layer(cand.size() + 1);
  layer[0][0] = {0.0, 0, -1};
  for (size_t i = 0; i < cand.size(); ++i) {
    if (cand[i].empty())
      return Error{ErrorCode::kInvalidArgument, "a link has no candidate sphere count"};
    for (const auto& [total, st] : layer[i])
      for (size_t c = 0; c < cand[i].size(); ++c) {
        const int t = total + cand[i][c].count;
        if (t > budget) continue;
        const double v = st.volume + cand[i][c].outside_volume;
        auto it = layer[i + 1].find(t);
        if (it == layer[i + 1].end() || v < it->second.volume)
          layer[i + 1][t] = {v, total, static_cast<int>(c)};
      }
  }
  const auto& last = layer.back();
  if (last.empty())
    return Error{ErrorCode::kInvalidArgument,
                 "no choice of sphere counts fits a budget of " + std::to_string(budget)};
  int best = last.begin()->first;
  for (const auto& [total, st] : last)
    if (st.volume < last.at(best).volume) best = total;
  std::vector<int> pick(cand.size());
  for (size_t i = cand.size(); i-- > 0;) {
    const State& st = layer[i + 1].at(best);
    pick[i] = st.choice;
    best = st.previous;
  }
  return pick;
}

}  // namespace sphereset

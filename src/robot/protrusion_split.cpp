// A robot's sphere counts chosen by protrusion limits (beyond the paper; the limit is the
// certified one-sided Hausdorff bound of src/eval/protrusion.cpp). Without a budget each link
// gets the fewest spheres that meet its limit (the tolerance search of tolerance_fit.cpp). With
// a budget the worst link's protrusion relative to its limit is made small greedily: the next
// spheres always go to the link furthest over its limit. Fits are not monotone in their count,
// so a link keeps the best fit among its counts; the greedy split is then a heuristic for the
// min-max allocation, not its optimum. A link's counts are fits of progressive runs
// (ProgressiveFit: each clustering warm-started from a smaller count's, its most protruding
// spheres split first), in windows as tolerance_fit.cpp's (LinkFits); independent fits when the
// options forbid a run (--quality best).
#include "robot/protrusion_split.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "eval/count_search.hpp"

namespace sphereset::detail {
namespace {

// The budget's greedy split gives the worst link given / kStepFraction more spheres at a time
// (at least 1): one at a time, each fit started from the one below it kept most of its clusters
// and with them its protrusion (on the Kinova's half_arm_1_link it stayed within 0.038 to
// 0.043 m from 4 to 31 spheres one by one, while the search without a budget, doubling,
// reached 0.014 m).
constexpr int kStepFraction = 4;

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// How far a pick is over its link's limit: protrusion / limit, infinite when not covered.
double overLimit(const ProtrusionPick& p, double limit) {
  const bool covered = p.eval.surface_covered && p.eval.interior_covered && p.eval.original_covered;
  return covered ? p.eval.protrusion / limit : std::numeric_limits<double>::infinity();
}

// Each sphere's certified protrusion in the checks so far, by count: what a larger count
// splits first (ProgressiveFit::fit's split_first), so that the spheres furthest out are split.
using ProtrusionsByCount = std::map<int, std::vector<double>>;

// The progressive runs of a link, in the windows of the tolerance search (searchWindow, at most
// the link's cap). Independent fits when the options forbid a run.
class LinkFits {
 public:
  explicit LinkFits(const ProtrusionLink& link) : link_(link) {}
  Expected<FitResult> fit(int count, const ProtrusionsByCount& seen) {
    FitOptions o = link_.options_for(detail::searchWindow(count, link_.cap));
    if (!ProgressiveFit::allows(o)) {
      FitOptions one = link_.options_for(count);
      return fitSpheres(*link_.index, one);
    }
    if (!run_ || count > run_->maxCount()) {
      auto r = ProgressiveFit::start(*link_.index, o, run_.get());
      if (!r) return r.error();
      run_ = std::make_unique<ProgressiveFit>(std::move(r).value());
    }
    const int from = run_->startCount(count);
    auto it = seen.find(from);
    return from > 0 && from < count && it != seen.end() ? run_->fit(count, it->second)
                                                        : run_->fit(count);
  }

 private:
  const ProtrusionLink& link_;
  std::unique_ptr<ProgressiveFit> run_;
};

// The fit of `link` at `count` and its check.
Expected<ProtrusionPick> pickAt(const ProtrusionLink& link, LinkFits* fits, int count,
                                ProtrusionsByCount* seen) {
  const auto t0 = std::chrono::steady_clock::now();
  ProtrusionPick p;
  p.count = count;
  auto f = fits->fit(count, *seen);
  if (!f) return f.error();
  p.fit = std::move(f).value();
  auto e =
      evaluateSpheres(*link.index, p.fit.spheres,
                      fitCheckEvalOptions(link.options_for(count).seed, link.original, link.walls));
  if (!e) return e.error();
  p.eval = std::move(e).value();
  (*seen)[count] = p.eval.sphere_protrusion;
  p.met = overLimit(p, link.limit) <= 1.0;
  p.seconds = secondsSince(t0);
  return p;
}

Error linkError(const ProtrusionLink& link, const Error& e) {
  return {e.code, "link '" + link.name + "': " + e.message};
}

// Each link alone: the fewest spheres that meet its limit.
Expected<std::vector<ProtrusionPick>> fewestPerLink(
    const std::vector<ProtrusionLink>& links,
    const std::function<void(const std::string&, int)>& done) {
  std::vector<ProtrusionPick> picks(links.size());
  std::vector<std::optional<Error>> errors(links.size());
  tbb::parallel_for(size_t{0}, links.size(), [&](size_t i) {
    const ProtrusionLink& link = links[i];
    const auto t0 = std::chrono::steady_clock::now();
    LinkFits fits(link);
    // Doubling until a count meets the limit, then bisection (count_search.hpp).
    std::optional<ProtrusionPick> best;
    ProtrusionsByCount seen;
    auto tryCount = [&](int n) -> Expected<bool> {
      auto p = pickAt(link, &fits, n, &seen);
      if (!p) return p.error();
      const bool met = p->met;
      if (!best || (met && (!best->met || n < best->count)) ||
          (!best->met && !met && overLimit(*p, link.limit) < overLimit(*best, link.limit)))
        best = std::move(p).value();
      return met;
    };
    if (Status st = searchFewestCount(link.cap, tryCount); !st) {
      errors[i] = linkError(link, st.error());
      return;
    }
    picks[i] = std::move(*best);
    picks[i].seconds = secondsSince(t0);
    link.index->forgetAnswers();
    if (done) done(link.name, 1);
  });
  for (const auto& e : errors)
    if (e) return *e;
  return picks;
}

// The budget's greedy split: one sphere at a time to the link furthest over its limit.
Expected<std::vector<ProtrusionPick>> greedySplit(
    const std::vector<ProtrusionLink>& links, int budget,
    const std::function<void(const std::string&, int)>& done) {
  const size_t n = links.size();
  std::vector<std::unique_ptr<LinkFits>> runs(n);
  std::vector<ProtrusionPick> best(n);
  std::vector<int> given(n, 1);
  std::vector<ProtrusionsByCount> seen(n);
  std::vector<std::optional<Error>> errors(n);
  tbb::parallel_for(size_t{0}, n, [&](size_t i) {
    runs[i] = std::make_unique<LinkFits>(links[i]);
    auto p = pickAt(links[i], runs[i].get(), 1, &seen[i]);
    if (!p) {
      errors[i] = linkError(links[i], p.error());
      return;
    }
    best[i] = std::move(p).value();
    if (done) done(links[i].name, 1);
  });
  for (const auto& e : errors)
    if (e) return *e;
  for (int left = budget - static_cast<int>(n); left > 0;) {
    size_t worst = n;
    for (size_t i = 0; i < n; ++i)
      if (given[i] < links[i].cap && (worst == n || overLimit(best[i], links[i].limit) >
                                                        overLimit(best[worst], links[worst].limit)))
        worst = i;
    if (worst == n) break;  // every link at its largest count
    const int step = std::min(
        {left, links[worst].cap - given[worst], std::max(1, given[worst] / kStepFraction)});
    given[worst] += step;
    left -= step;
    auto p = pickAt(links[worst], runs[worst].get(), given[worst], &seen[worst]);
    if (!p) return linkError(links[worst], p.error());
    best[worst].seconds += p->seconds;
    if (overLimit(*p, links[worst].limit) < overLimit(best[worst], links[worst].limit)) {
      p->seconds = best[worst].seconds;
      best[worst] = std::move(p).value();
    }
    if (done) done(links[worst].name, step);
  }
  for (const ProtrusionLink& link : links) link.index->forgetAnswers();
  return best;
}

}  // namespace

Expected<std::vector<ProtrusionPick>> fitToProtrusion(
    const std::vector<ProtrusionLink>& links, int budget,
    const std::function<void(const std::string&, int)>& done) {
  if (budget <= 0) return fewestPerLink(links, done);
  return greedySplit(links, budget, done);
}

}  // namespace sphereset::detail

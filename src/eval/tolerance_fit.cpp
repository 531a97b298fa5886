// The fewest spheres that meet a tolerance (evaluate.hpp, fitToTolerance): a protrusion bound
// (certified, sphereProtrusion) and/or an E_r, found by fitting at 1, 2, 4, ... spheres until a
// count meets it (or the cap), then bisecting between the last count that did not and the first
// that did. The counts are fits of one progressive run (fit.hpp, ProgressiveFit: each clustering
// warm-started from the largest count below it) when the request allows one (the variational
// method, one restart, no decimation), else independent fits (fitSpheres with the request's
// options at that count); each is checked as `sphereset fit` checks its result
// (fitCheckEvalOptions). Fits are not monotone in their count, so the count found is the
// smallest of those tried that meets the tolerance, with every count tried in the curve.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "eval/checked_count.hpp"
#include "eval/count_search.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/options.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {
namespace {

constexpr OptionSpec kToleranceOptions[] = {
    {"max_protrusion",
     "--max-protrusion",
     OptionType::kReal,
     0,
     limits::kMaxCoordinate,
     {},
     "none",
     "Of the counts tried (1, 2, 4, ..., then a bisection), the fewest spheres whose certified "
     "protrusion is at most this (a length above 0; with a trailing %, a percentage of the "
     "bounding-box diagonal)",
     nullptr,
     nullptr,
     true,
     true},
    {"max_er",
     "--max-er",
     OptionType::kReal,
     0,
     1e6,
     {},
     "none",
     "Of the counts tried, the fewest spheres whose E_r (summed outside volume / volume) is at "
     "most this (above 0)",
     nullptr,
     nullptr,
     true},
    {"max_spheres",
     "--max-spheres",
     OptionType::kInteger,
     1,
     limits::kMaxSpheres,
     {},
     "256",
     "The most spheres a tolerance search tries"},
};

// One count: the fit at n and its check.
using Trial = detail::CheckedCount;

}  // namespace

std::span<const OptionSpec> toleranceOptionTable() { return kToleranceOptions; }

Status setToleranceOption(ToleranceOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kToleranceOptions, "tolerance", name, text);
  if (!parsed) return parsed.error();
  const std::string_view n = parsed->spec->name;
  if (n == "max_protrusion") {  // a length, or a percentage of the diagonal
    o->max_protrusion = parsed->value.length();
    o->max_protrusion_fraction = parsed->value.fraction();
  }
  if (n == "max_er") o->max_er = parsed->value.real;
  if (n == "max_spheres") {
    o->max_spheres = static_cast<int>(parsed->value.integer);
    o->max_spheres_given = true;
  }
  return {};
}

bool ToleranceOptions::active() const {
  return max_protrusion > 0.0 || max_protrusion_fraction > 0.0 || max_er > 0.0;
}

bool ToleranceOptions::capSet() const {
  return max_spheres_given || max_spheres != ToleranceOptions{}.max_spheres;
}

Status checkToleranceRequest(const FitRequest& request, const ToleranceOptions& tolerance) {
  if (request.count_given && tolerance.active())
    return Error{ErrorCode::kInvalidArgument,
                 "n and a tolerance (max_protrusion, max_er) exclude each other: the tolerance "
                 "chooses the count"};
  if (tolerance.max_spheres_given && !tolerance.active())
    return Error{ErrorCode::kInvalidArgument,
                 "max_spheres goes with a tolerance (max_protrusion, max_er): alone it caps "
                 "nothing"};
  return {};
}

Status checkBestEffort(bool best_effort, bool limited, std::string_view limits) {
  if (best_effort && !limited)
    return Error{ErrorCode::kInvalidArgument, "best_effort goes with a tolerance (" +
                                                  std::string(limits) +
                                                  "): alone it writes nothing more"};
  return {};
}

Status checkBestEffort(bool best_effort, const ToleranceOptions& tolerance) {
  return checkBestEffort(best_effort, tolerance.active(), "max_protrusion, max_er");
}

Status checkToleranceOptions(const ToleranceOptions& t) {
  // The cap and each limit that is set (0: none), checked by its row as a door's text would be
  // (checkTableValue); the fraction as the percentage a user types ("5%").
  if (Status st = checkTableValue(kToleranceOptions, "tolerance", "max_spheres", t.max_spheres);
      !st)
    return st;
  for (const auto& [name, value] :
       {std::pair<const char*, double>{"max_protrusion", t.max_protrusion},
        std::pair<const char*, double>{"max_er", t.max_er}})
    if (value != 0.0)
      if (Status st = checkTableValue(kToleranceOptions, "tolerance", name, value); !st) return st;
  if (t.max_protrusion_fraction != 0.0)
    if (Status st = checkTableValue(kToleranceOptions, "tolerance", "max_protrusion",
                                    100.0 * t.max_protrusion_fraction, {}, true);
        !st)
      return st;
  if (!t.active())
    return Error{ErrorCode::kInvalidArgument,
                 "a tolerance search needs max_protrusion or max_er above 0"};
  return {};
}

Expected<ToleranceFitResult> fitToTolerance(const SolidIndex& index, const FitRequest& request,
                                            const ToleranceOptions& t) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkToleranceOptions(t); !st) return st.error();
  if (Status st = checkFitRequest(request); !st) return st.error();
  if (Status st = checkToleranceRequest(request, t); !st) return st.error();
  const double diag = index.bounds().diagonal();
  double limit = t.max_protrusion > 0.0 ? t.max_protrusion : 0.0;
  if (t.max_protrusion_fraction > 0.0) {
    const double relative = t.max_protrusion_fraction * diag;
    limit = limit > 0.0 ? std::min(limit, relative) : relative;
  }
  ToleranceFitResult out;
  out.protrusion_limit = limit;
  Trial best;
  bool have_best = false;
  // Whether b is a better fallback than a (when nothing meets the tolerance): covered first,
  // then the smaller protrusion (or E_r, with no protrusion limit).
  auto better = [&](const Trial& a, const Trial& b) {
    if (a.point.covered != b.point.covered) return b.point.covered;
    return limit > 0.0 ? b.point.protrusion < a.point.protrusion : b.point.er_sum < a.point.er_sum;
  };
  // Progressive runs when the request allows them: a run samples the points of its largest
  // count, so the first is for up to kFirstWindow spheres and, when the doubling passes it, the
  // next for up to kWindowGrowth times the count (its first count starts from seeds).
  FitOptions any = fitOptionsFor(request);
  const bool allowed = ProgressiveFit::allows(any);
  std::optional<ProgressiveFit> progressive;
  auto fitAt = [&](int n, const FitOptions& fo) -> Expected<FitResult> {
    if (!allowed) return fitSpheres(index, fo);
    if (!progressive || n > progressive->maxCount()) {
      // A run cannot hold more spheres than points: an explicit point count bounds the window.
      int top = detail::searchWindow(n, t.max_spheres);
      if (request.points > 0)
        top = static_cast<int>(std::max<int64_t>(n, std::min<int64_t>(top, request.points)));
      const FitOptions top_options = detail::countOptions(request, top, t.original, t.fit_progress);
      auto p = ProgressiveFit::start(index, top_options, progressive ? &*progressive : nullptr);
      if (!p) return p.error();
      progressive.emplace(std::move(p).value());
    }
    return progressive->fit(n);
  };
  out.progressive = allowed;
  auto run = [&](int n) -> Expected<Trial> {
    const auto s0 = std::chrono::steady_clock::now();
    const FitOptions fo = detail::countOptions(request, n, t.original, t.fit_progress);
    auto fit = fitAt(n, fo);
    if (!fit) return fit.error();
    auto trial = detail::checkCount(index, std::move(fit).value(), fo, t.walls, n, s0);
    if (!trial) return trial.error();
    CurvePoint& p = trial->point;
    p.meets = p.covered && (limit <= 0.0 || p.protrusion <= limit) &&
              (t.max_er <= 0.0 || p.er_sum <= t.max_er);
    out.curve.push_back(p);
    if (t.progress) t.progress(p);
    return trial;
  };
  auto keep = [&](Trial&& trial) {
    if (!have_best || (trial.point.meets && (!best.point.meets || trial.point.n < best.point.n)) ||
        (!best.point.meets && !trial.point.meets && better(best, trial))) {
      best = std::move(trial);
      have_best = true;
    }
  };
  // Doubling, then bisection (count_search.hpp).
  if (Status st = detail::searchFewestCount(t.max_spheres,
                                            [&](int n) -> Expected<bool> {
                                              auto trial = run(n);
                                              if (!trial) return trial.error();
                                              const bool meets = trial->point.meets;
                                              keep(std::move(trial).value());
                                              return meets;
                                            });
      !st)
    return st.error();
  out.met = best.point.meets;
  out.n = best.point.n;
  out.fit = std::move(best.fit);
  out.eval = std::move(best.eval);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace sphereset

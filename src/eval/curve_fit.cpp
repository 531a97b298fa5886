// The curve of a run (evaluate.hpp, fitCurve): E_r and the certified protrusion against the
// sphere count, the fits of one progressive run (fit.hpp, ProgressiveFit; beyond the paper, which
// fits one count at a time, Section 4) checked as `sphereset fit` checks its result. A count that
// follows the one before it is one local change of a neighbouring count's set
// (ProgressiveFit::step: a split up from the count below, or a removal down from the count
// above; runOrder), except the powers of two and the last count, which are fitted; the stepped
// counts are checked by the certificate of the last set kept up to date (certificate.hpp) and the
// certified protrusion of the spheres that changed (searched only as far as the union's figure
// needs: ProtrusionOptions::union_only), which give the figures a full evaluation gives, the
// protrusion within its tolerance (docs/benchmarks.md, "Progressive fitting": the costs and the
// looseness of the steps).
#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "eval/checked_count.hpp"
#include "sphereset/certificate.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

// The counts clustered from seeds, where the warm starts begin (ProgressiveOptions::seeded):
// started from one sphere, the run's fits at 32 ended 3.8 % above independent fits in E_r, from
// 8 0.5 % (12 shared meshes, seeds 1 and 2). The 4 warm-started from 2 ended 0.981 times the 4
// clustered from seeds in E_r, for 0.95 of the curve's time (docs/benchmarks.md).
constexpr std::array kSeededCounts = {1, 2, 8};
// The rounds of a warm-started count below half the last (ProgressiveOptions::
// warm_rounds_below_half: the 4 and the 16 of a curve to 64; the 32 keeps 30).
constexpr int kWarmRoundsBelowHalf = 20;

// A stretch's downward steps stop at the first count whose downward set has more outside volume
// than the upward one: a step down is good for a few counts below its fit and then worse than the
// step up, so the crossover of least total lies at or above it. A heuristic: a crossover below
// such a count would be missed. On the curves 1 ... 64 of the 12 shared closed meshes, stopping
// after 3 such counts in a row gave the same sets as every downward step made (seed 1), and after 2
// or 1 the same as after 3 (seeds 1 and 3); on spot.obj all downward steps took 1.80 s of the
// calling thread, 0.65 s of them for the sets kept (docs/benchmarks.md, "Progressive fitting").
constexpr int kDownBehind = 1;

// Whether counts[k] is a step from counts[k - 1] (ProgressiveFit::step): one more sphere, not a
// power of two (those are fitted, each from at most half its count) and not the last count.
bool isStep(const std::vector<int>& counts, size_t k) {
  const int n = counts[k];
  return k > 0 && k + 1 < counts.size() && n == counts[k - 1] + 1 && (n & (n - 1)) != 0;
}

// The points of a run whose sets change a few spheres at a time: the coverage certificate of the
// last set, updated where spheres changed, and each sphere's certified protrusion bounds (each
// ball's are found on its own, evaluate.hpp), computed again for the changed ones (protrude).
// The figures of fitCheckEvalOptions's evaluation: E_r summed and coverage equal, the largest
// protrusion bound within the tolerance of the union's witness as there.
class StepChecker {
 public:
  StepChecker(const SolidIndex& index, const Mesh* original) : index_(index) {
    options_.original = original;
    protrusion_.tolerance = EvalOptions{}.protrusion_tolerance * index.bounds().diagonal();
    protrusion_.union_only = true;
  }

  Expected<CurvePoint> check(const std::vector<Sphere>& spheres, int n) {
    std::vector<size_t> changed;
    for (size_t i = 0; i < spheres.size(); ++i)
      if (i >= last_.size() || spheres[i].center != last_[i].center ||
          spheres[i].radius != last_[i].radius)
        changed.push_back(i);
    if (Status st = update(spheres); !st) return st.error();
    if (Status st = protrude(spheres, changed); !st) return st.error();
    last_ = spheres;
    const CertificateSummary& s = cert_->summary();
    CurvePoint point;
    point.n = n;
    point.er_sum = s.er_sum;
    point.covered = s.covered;
    point.protrusion = *std::max_element(upper_.begin(), upper_.end());
    return point;
  }

 private:
  // The certificate brought to `spheres`: near the spheres that changed when few did, else in
  // full (CoverageCertificate::updateSpheres).
  Status update(const std::vector<Sphere>& spheres) {
    if (cert_) return cert_->updateSpheres(spheres);
    auto made = makeCoverageCertificate(index_, spheres, options_);
    if (!made) return made.error();
    cert_.emplace(std::move(made).value());
    return {};
  }

  // Each ball's protrusion bounds brought to `spheres`: only the union's figure is reported, so
  // the changed balls are searched with the largest distance the others reach as known
  // (ProtrusionOptions::union_only), and an unchanged ball whose bound was left above the
  // union's new lower bound plus the tolerance (its search stopped at the figure of a ball since
  // changed) is searched again, unless its search ran out of cells (it would end the same). The
  // union's bound is then within the tolerance of its witness, or as loose as such a ball's.
  Status protrude(const std::vector<Sphere>& spheres, const std::vector<size_t>& changed) {
    std::vector<bool> fresh(spheres.size(), false);
    for (size_t i : changed) fresh[i] = true;
    lower_.resize(spheres.size());
    upper_.resize(spheres.size());
    converged_.resize(spheres.size());
    double known = 0.0;
    for (size_t i = 0; i < spheres.size(); ++i)
      if (!fresh[i]) known = std::max(known, lower_[i]);
    if (Status st = search(spheres, changed, known); !st) return st;
    known = *std::max_element(lower_.begin(), lower_.end());
    std::vector<size_t> loose;
    for (size_t i = 0; i < spheres.size(); ++i)
      if (!fresh[i] && converged_[i] && upper_[i] > known + protrusion_.tolerance)
        loose.push_back(i);
    return search(spheres, loose, known);
  }

  Status search(const std::vector<Sphere>& spheres, const std::vector<size_t>& which,
                double known) {
    if (which.empty()) return {};
    std::vector<Sphere> balls;
    for (size_t i : which) balls.push_back(spheres[i]);
    ProtrusionOptions o = protrusion_;
    o.known = known;
    auto p = sphereProtrusion(index_, balls, o);
    if (!p) return p.error();
    for (size_t k = 0; k < which.size(); ++k) {
      lower_[which[k]] = p->spheres[k].lower;
      upper_[which[k]] = p->spheres[k].upper;
      converged_[which[k]] = p->spheres[k].converged;
    }
    return {};
  }

  const SolidIndex& index_;
  CertificateOptions options_;
  ProtrusionOptions protrusion_;
  std::optional<CoverageCertificate> cert_;
  std::vector<Sphere> last_;
  std::vector<double> lower_, upper_;  // each ball's protrusion bounds
  std::vector<bool> converged_;        // each ball's search ended before its cells ran out
};

}  // namespace

Status checkCurveOptions(const FitRequest& request, const CurveOptions& o) {
  const auto bad = [](const std::string& m) { return Error{ErrorCode::kInvalidArgument, m}; };
  if (request.count_given) return bad("n and a curve's counts exclude each other: give counts");
  const std::string range = "from 1 to " + std::to_string(limits::kMaxCurveCount);
  if (o.max_spheres < 1 || o.max_spheres > limits::kMaxCurveCount)
    return bad("max_spheres " + std::to_string(o.max_spheres) + ": expected an integer " + range);
  for (size_t i = 0; i < o.counts.size(); ++i) {
    const int n = o.counts[i];
    if (n < 1 || n > limits::kMaxCurveCount)
      return bad("counts: " + std::to_string(n) + " is not " + range);
    if (i > 0 && n <= o.counts[i - 1])
      return bad("counts: " + std::to_string(n) + " after " + std::to_string(o.counts[i - 1]) +
                 ": expected increasing counts");
  }
  return {};
}

namespace {

// One curve's making: each count fitted (a run's fit, else an independent fit) or stepped, then
// checked; the points reported in increasing order of count as soon as they and the ones before
// them are made.
class CurveMaker {
 public:
  CurveMaker(const SolidIndex& index, const FitRequest& request, const CurveOptions& o,
             std::vector<int> counts, ProgressiveFit* run, CurveResult* out)
      : index_(index),
        request_(request),
        o_(o),
        counts_(std::move(counts)),
        run_(run),
        out_(out),
        checker_(index, o.original),
        made_(counts_.size(), false) {
    for (size_t k = 0; k < counts_.size(); ++k) steps_ = steps_ || (run && isStep(counts_, k));
    out->points.resize(counts_.size());
    out->spheres.resize(counts_.size());
  }

  Status make() {
    size_t k = 0;
    while (k < counts_.size()) {
      if (!steps_ || !isStep(counts_, k)) {
        if (Status st = fitted(k); !st) return st;
        ++k;
        continue;
      }
      size_t e = k;
      while (isStep(counts_, e)) ++e;  // the last count is never a step
      if (Status st = stretch(k, e); !st) return st;
      k = made_[e] ? e + 1 : e;
    }
    return {};
  }

 private:
  Expected<FitResult> fitAt(size_t k) {
    const FitOptions fo = detail::countOptions(request_, counts_[k], o_.original, o_.fit_progress);
    return run_ ? run_->fit(counts_[k]) : fitSpheres(index_, fo);
  }

  // A step, or the fit at that count when the step cannot be made. The stretch's order keeps the
  // run's last count next to counts_[k], so the one error a step can meet here is a set with no
  // sphere that can be split or removed.
  Expected<FitResult> stepAt(size_t k) {
    auto s = run_->step(counts_[k]);
    return s ? s : run_->fit(counts_[k]);
  }

  Status fitted(size_t k) {
    const auto s0 = std::chrono::steady_clock::now();
    auto fit = fitAt(k);
    if (!fit) return fit.error();
    return check(k, std::move(fit).value(), secondsSince(s0));
  }

  // The stepped counts k ... e - 1 between the fitted counts k - 1 and e: every one stepped up
  // from the count below and, when count e follows them directly, down from e too (fitted
  // first) until kDownBehind downward sets in a row are looser than the upward ones; the counts
  // up to the crossover of least total outside volume take the upward sets, the others the
  // downward ones (a step leaves a set close to the one it came from, so each direction is best
  // near its own fit). Each set is checked in the order of its chain.
  Status stretch(size_t k, size_t e) {
    std::vector<FitResult> up, down(e - k);
    std::vector<double> seconds_up, seconds_down(e - k);
    for (size_t i = k; i < e; ++i) {
      const auto s0 = std::chrono::steady_clock::now();
      auto s = stepAt(i);
      if (!s) return s.error();
      up.push_back(std::move(s).value());
      seconds_up.push_back(secondsSince(s0));
    }
    size_t cross = e - k;  // how many take the upward sets
    std::optional<FitResult> top;
    double seconds_top = 0.0;
    if (counts_[e] == counts_[e - 1] + 1) {
      auto s0 = std::chrono::steady_clock::now();
      auto f = fitAt(e);
      if (!f) return f.error();
      top = std::move(f).value();
      seconds_top = secondsSince(s0);
      size_t low = e - k;  // down[j] is made for j >= low
      for (int worse = 0; low > 0 && worse < kDownBehind;) {
        const size_t i = k + --low;
        s0 = std::chrono::steady_clock::now();
        auto s = stepAt(i);
        if (!s) return s.error();
        down[low] = std::move(s).value();
        seconds_down[low] = secondsSince(s0);
        worse = down[low].energy > up[low].energy ? worse + 1 : 0;
      }
      double best = std::numeric_limits<double>::infinity();
      for (size_t c = low; c <= e - k; ++c) {
        double total = 0.0;
        for (size_t j = 0; j < e - k; ++j) total += j < c ? up[j].energy : down[j].energy;
        if (total < best) best = total, cross = c;
      }
    }
    for (size_t j = 0; j < cross; ++j)
      if (Status st = check(k + j, std::move(up[j]), seconds_up[j]); !st) return st;
    if (!top) return {};
    if (Status st = check(e, std::move(*top), seconds_top); !st) return st;
    for (size_t j = e - k; j-- > cross;)
      if (Status st = check(k + j, std::move(down[j]), seconds_down[j]); !st) return st;
    return {};
  }

  static double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  // Checks count k's set (CurvePoint::seconds: `seconds` of making it, plus the check's).
  Status check(size_t k, FitResult fit, double seconds) {
    const auto s0 = std::chrono::steady_clock::now();
    const int n = counts_[k];
    if (steps_) {
      auto checked = checker_.check(fit.spheres, n);
      if (!checked) return checked.error();
      out_->points[k] = *checked;
    } else {
      const FitOptions fo = detail::countOptions(request_, n, o_.original, o_.fit_progress);
      auto checked = detail::checkCount(index_, std::move(fit), fo, o_.walls, n, s0);
      if (!checked) return checked.error();
      out_->points[k] = checked->point;
      fit.spheres = std::move(checked->fit.spheres);
    }
    out_->points[k].seconds = seconds + secondsSince(s0);
    out_->spheres[k] = std::move(fit.spheres);
    made_[k] = true;
    for (; reported_ < counts_.size() && made_[reported_]; ++reported_)
      if (o_.progress) o_.progress(out_->points[reported_]);
    return {};
  }

  const SolidIndex& index_;
  const FitRequest& request_;
  const CurveOptions& o_;
  std::vector<int> counts_;
  ProgressiveFit* run_;
  CurveResult* out_;
  StepChecker checker_;
  std::vector<bool> made_;
  size_t reported_ = 0;
  bool steps_ = false;
};

}  // namespace

Expected<CurveResult> fitCurve(const SolidIndex& index, const FitRequest& request,
                               const CurveOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkFitRequest(request); !st) return st.error();
  if (Status st = checkCurveOptions(request, o); !st) return st.error();
  std::vector<int> counts = o.counts;
  if (counts.empty())
    for (int n = 1; n <= o.max_spheres; ++n) counts.push_back(n);
  CurveResult out;
  const FitOptions top_options =
      detail::countOptions(request, counts.back(), o.original, o.fit_progress);
  out.progressive = ProgressiveFit::allows(top_options);
  std::optional<ProgressiveFit> run;
  if (out.progressive) {
    ProgressiveOptions progressive;
    progressive.top_from_seeds = true;  // the last count is fitSpheres's own fit
    progressive.top_alongside = true;   // made beside the counts below it
    progressive.seeded.assign(kSeededCounts.begin(), kSeededCounts.end());
    progressive.warm_rounds_below_half = kWarmRoundsBelowHalf;
    auto started = ProgressiveFit::start(index, top_options, nullptr, progressive);
    if (!started) return started.error();
    run.emplace(std::move(started).value());
  }
  CurveMaker maker(index, request, o, std::move(counts), run ? &*run : nullptr, &out);
  if (Status st = maker.make(); !st) return st.error();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace sphereset

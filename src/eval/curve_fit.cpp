// The curve of a run (evaluate.hpp, fitCurve): E_r and the certified protrusion against the
// sphere count, the fits of one progressive run (fit.hpp, ProgressiveFit; beyond the paper, which
// fits one count at a time, Section 4) checked as `sphereset fit` checks its result. A count that
// follows the one before it is one local split of that count's set (ProgressiveFit::step),
// except the powers of two and the last count, which are fitted; the stepped counts are checked
// by the certificate of the last set kept up to date (certificate.hpp) and the certified
// protrusion of the spheres that changed, which give the figures a full evaluation gives
// (docs/benchmarks.md, "Progressive fitting": the costs and the looseness of the steps).
#include <algorithm>
#include <chrono>
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

// Whether counts[k] is a step from counts[k - 1] (ProgressiveFit::step): one more sphere, not a
// power of two (those are fitted, each from at most half its count) and not the last count.
bool isStep(const std::vector<int>& counts, size_t k) {
  const int n = counts[k];
  return k > 0 && k + 1 < counts.size() && n == counts[k - 1] + 1 && (n & (n - 1)) != 0;
}

// The points of a run whose sets change a few spheres at a time: the coverage certificate of the
// last set, updated where spheres changed, and each sphere's certified protrusion (each ball's is
// found on its own, evaluate.hpp), computed again for the changed ones. Equal to the figures of
// fitCheckEvalOptions's evaluation: E_r summed, coverage and the largest protrusion bound.
class StepChecker {
 public:
  StepChecker(const SolidIndex& index, const Mesh* original) : index_(index) {
    options_.original = original;
    protrusion_.tolerance = EvalOptions{}.protrusion_tolerance * index.bounds().diagonal();
  }

  Expected<CurvePoint> check(const std::vector<Sphere>& spheres, int n) {
    std::vector<size_t> changed;
    for (size_t i = 0; i < spheres.size(); ++i)
      if (i >= last_.size() || spheres[i].center != last_[i].center ||
          spheres[i].radius != last_[i].radius)
        changed.push_back(i);
    if (Status st = update(spheres, changed); !st) return st.error();
    std::vector<Sphere> moved;
    for (size_t i : changed) moved.push_back(spheres[i]);
    auto p = sphereProtrusion(index_, moved, protrusion_);
    if (!p) return p.error();
    sphere_protrusion_.resize(spheres.size());
    for (size_t k = 0; k < changed.size(); ++k)
      sphere_protrusion_[changed[k]] = p->spheres[k].upper;
    last_ = spheres;
    const CertificateSummary& s = cert_->summary();
    CurvePoint point;
    point.n = n;
    point.er_sum = s.er_sum;
    point.covered = s.covered;
    point.protrusion = *std::max_element(sphere_protrusion_.begin(), sphere_protrusion_.end());
    return point;
  }

 private:
  // The certificate brought to `spheres`: sphere by sphere when few changed, else in full.
  Status update(const std::vector<Sphere>& spheres, const std::vector<size_t>& changed) {
    if (!cert_ || spheres.size() < last_.size() || 2 * changed.size() > spheres.size()) {
      if (cert_) return cert_->setSpheres(spheres);
      auto made = makeCoverageCertificate(index_, spheres, options_);
      if (!made) return made.error();
      cert_.emplace(std::move(made).value());
      return {};
    }
    for (size_t i : changed) {
      Status st = i < last_.size() ? cert_->setSphere(static_cast<int>(i), spheres[i])
                                   : cert_->addSphere(spheres[i]);
      if (!st) return st;
    }
    return {};
  }

  const SolidIndex& index_;
  CertificateOptions options_;
  ProtrusionOptions protrusion_;
  std::optional<CoverageCertificate> cert_;
  std::vector<Sphere> last_;
  std::vector<double> sphere_protrusion_;
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
    auto started = ProgressiveFit::start(index, top_options);
    if (!started) return started.error();
    run.emplace(std::move(started).value());
  }
  bool steps = false;
  for (size_t k = 0; k < counts.size(); ++k) steps = steps || (run && isStep(counts, k));
  StepChecker checker(index, o.original);
  for (size_t k = 0; k < counts.size(); ++k) {
    const int n = counts[k];
    const auto s0 = std::chrono::steady_clock::now();
    const FitOptions fo = detail::countOptions(request, n, o.original, o.fit_progress);
    auto fit = !run ? fitSpheres(index, fo) : isStep(counts, k) ? run->step(n) : run->fit(n);
    if (!fit) return fit.error();
    CurvePoint point;
    if (steps) {
      auto checked = checker.check(fit->spheres, n);
      if (!checked) return checked.error();
      point = *checked;
      point.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    } else {
      auto checked = detail::checkCount(index, std::move(fit).value(), fo, o.walls, n, s0);
      if (!checked) return checked.error();
      point = checked->point;
      fit->spheres = std::move(checked->fit.spheres);
    }
    out.points.push_back(point);
    out.spheres.push_back(std::move(fit->spheres));
    if (o.progress) o.progress(out.points.back());
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace sphereset

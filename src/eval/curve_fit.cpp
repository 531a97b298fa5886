// The curve of a run (evaluate.hpp, fitCurve): E_r and the certified protrusion against the
// sphere count, the fits of one progressive run (fit.hpp, ProgressiveFit; beyond the paper, which
// fits one count at a time, Section 4) checked as `sphereset fit` checks its result. A full
// curve 1 ... N costs about one warm fit per count: docs/benchmarks.md, "Progressive fitting".
#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "eval/checked_count.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {

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
  for (const int n : counts) {
    const auto s0 = std::chrono::steady_clock::now();
    const FitOptions fo = detail::countOptions(request, n, o.original, o.fit_progress);
    auto fit = run ? run->fit(n) : fitSpheres(index, fo);
    if (!fit) return fit.error();
    auto checked = detail::checkCount(index, std::move(fit).value(), fo, o.walls, n, s0);
    if (!checked) return checked.error();
    out.points.push_back(checked->point);
    out.spheres.push_back(std::move(checked->fit.spheres));
    if (o.progress) o.progress(out.points.back());
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace sphereset

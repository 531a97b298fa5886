// Private: one count's fit checked as `sphereset fit` checks its result (fitCheckEvalOptions),
// shared by the tolerance search (tolerance_fit.cpp) and the curve of a run (curve_fit.cpp).
#pragma once

#include <chrono>
#include <functional>
#include <utility>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// The fit at one count, its check and its point of the curve (`meets` left false: the caller's
// tolerance decides it).
struct CheckedCount {
  FitResult fit;
  EvalResult eval;
  CurvePoint point;
};

// The options of the fit at n for `request` (fitOptionsFor), its original triangles and its
// progress: each count of a search or a curve, and a run's largest.
inline FitOptions countOptions(const FitRequest& request, int n, const Mesh* original,
                               const std::function<void(const FitProgress&)>& progress) {
  FitRequest r = request;
  r.num_spheres = n;
  FitOptions fo = fitOptionsFor(r);
  fo.original = original;
  fo.progress = progress;
  return fo;
}

// Checks `fit` (the fit at n with options `fo`) and fills the point; CurvePoint::seconds is the
// time since `start` (the tolerance search passes its fit's start: the fit and its check).
inline Expected<CheckedCount> checkCount(const SolidIndex& index, FitResult fit,
                                         const FitOptions& fo, const Mesh* walls, int n,
                                         std::chrono::steady_clock::time_point start) {
  auto ev = evaluateSpheres(index, fit.spheres, fitCheckEvalOptions(fo.seed, fo.original, walls));
  if (!ev) return ev.error();
  CheckedCount c{std::move(fit), std::move(ev).value(), {}};
  c.point.n = n;
  c.point.er_sum = c.eval.er_sum;
  c.point.protrusion = c.eval.protrusion;
  c.point.covered = c.eval.surface_covered && c.eval.interior_covered && c.eval.original_covered;
  c.point.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

}  // namespace sphereset::detail

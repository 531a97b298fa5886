// Private: small pieces shared by the phases of the fit: timing, the energy of a sphere set
// (paper Sec. 3: the sum over the spheres of their outside volume, Eq. 2 per sphere), and the
// centroid and farthest point of a point list.
#pragma once

#include <chrono>
#include <numeric>
#include <string>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "util/poll.hpp"

namespace sphereset::detail {

using FitClock = std::chrono::steady_clock;
inline double secondsSince(FitClock::time_point t) {
  return std::chrono::duration<double>(FitClock::now() - t).count();
}

// Adds the phases' seconds of `t` to *sum (all but total).
inline void addTimings(const FitTimings& t, FitTimings* sum) {
  sum->sampling += t.sampling;
  sum->assignment += t.assignment;
  sum->update += t.update;
  sum->teleport += t.teleport;
  sum->bounding += t.bounding;
  sum->bound += t.bound;
  sum->shrink += t.shrink;
  sum->refine += t.refine;
  sum->radii += t.radii;
}

// Progress, and with it cancellation, from inside long steps. fitSpheres holds one
// ProgressScope on its calling thread; report() calls FitOptions::progress at each phase and
// round, and the fit's long loops (sampling, seeding, assignment, updates, the bound) call
// pollCancel() (util/poll.hpp), which reports the current phase again once
// FitOptions::progress_interval seconds have passed since the last report. So a callback that
// throws (Python's Ctrl-C) stops a fit within about that time whatever n is (it used to wait for
// the end of a round or of the bound: 96 s at n = 10^6).
class ProgressScope {
 public:
  ProgressScope(const FitOptions& options, FitClock::time_point start);
  void report(const std::string& phase, int iteration, double energy);

 private:
  void call();
  const FitOptions& options_;
  FitClock::time_point start_;
  FitProgress current_;
  PollScope poll_;
};

// The options of fitSpheres within their limits, and a solid of positive volume.
Status checkFitOptions(const SolidIndex& index, const FitOptions& o);

// The default points of a fit at n spheres: max(kMinDefaultPoints, kDefaultPointsPerSphere n)
// (the quality presets scale it).
inline constexpr int64_t kMinDefaultPoints = 5000;
inline constexpr int64_t kDefaultPointsPerSphere = 100;
int64_t defaultPoints(int num_spheres);

// Points the fit clusters: o.target_points, or defaultPoints(o.num_spheres) when it is 0.
int64_t fitTargetPoints(const FitOptions& o);

// Outside volume of each sphere (in parallel).
std::vector<double> outsideVolumes(const SolidIndex& index, const std::vector<Sphere>& sp);

// Sum of the values in a fixed order (the energy, from outsideVolumes).
inline double totalOf(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

// Mean of the points (not empty).
Vec3 centroid(const std::vector<Vec3>& pts);

// The first of the points farthest from q; q itself if there are none.
Vec3 farthestFrom(const std::vector<Vec3>& pts, const Vec3& q);

}  // namespace sphereset::detail

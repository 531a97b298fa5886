// Small pieces shared by the phases of the fit (fit_common.hpp).
#include "fit/fit_common.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "sphereset/limits.hpp"

namespace sphereset::detail {

ProgressScope::ProgressScope(const FitOptions& options, FitClock::time_point start)
    : options_(options),
      start_(start),
      poll_(options.progress ? std::function<void()>([this] { call(); }) : nullptr,
            options.progress_interval) {
  current_.spheres = options.num_spheres;
}

void ProgressScope::call() {
  current_.seconds = secondsSince(start_);
  options_.progress(current_);
}

void ProgressScope::report(const std::string& phase, int iteration, double energy) {
  current_.phase = phase;
  current_.iteration = iteration;
  current_.energy = energy;
  poll_.restart();
  if (options_.progress) call();
}

std::vector<double> outsideVolumes(const SolidIndex& index, const std::vector<Sphere>& sp) {
  std::vector<double> v(sp.size());
  tbb::parallel_for(size_t{0}, sp.size(), [&](size_t i) {
    pollCancel();
    v[i] = index.outsideVolume(sp[i]).volume;
  });
  return v;
}

Vec3 centroid(const std::vector<Vec3>& pts) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : pts) c += p;
  return c / static_cast<double>(pts.size());
}

Vec3 farthestFrom(const std::vector<Vec3>& pts, const Vec3& q) {
  Vec3 best = q;
  double bd = -1.0;
  for (const Vec3& p : pts)
    if ((p - q).squaredNorm() > bd) {
      bd = (p - q).squaredNorm();
      best = p;
    }
  return best;
}

Status checkFitOptions(const SolidIndex& index, const FitOptions& o) {
  using limits::checkRange;
  for (Status st :
       {checkRange("num_spheres", o.num_spheres, 1, limits::kMaxSpheres),
        checkRange("target_points", static_cast<double>(o.target_points), 0,
                   static_cast<double>(limits::kMaxPoints)),
        checkRange("interior_share", o.interior_share, 0.0, 1.0),
        checkRange("max_iterations", o.max_iterations, 0, limits::kMaxIterations),
        checkRange("tolerance", o.tolerance, 0.0, 1.0),
        checkRange("max_failed_teleports", o.max_failed_teleports, 0, limits::kMaxIterations),
        checkRange("optimizer_evaluations", o.optimizer_evaluations, 0,
                   limits::kMaxOptimizerEvaluations),
        checkRange("padding", o.padding, 0.0, limits::kMaxCoordinate),
        checkRange("shrink_passes", o.shrink_passes, 0, limits::kMaxIterations),
        checkRange("decimation", o.decimation, 0.0, limits::kMaxDecimation),
        checkRange("restarts", o.restarts, 1, limits::kMaxRestarts),
        checkRange("progress_interval", o.progress_interval, 0.0, 3600.0)})
    if (!st) return st;
  if (!(signedVolume(index.mesh()) > 0.0))
    return Error{ErrorCode::kNotSolid, "the mesh encloses no volume"};
  return {};
}

int64_t defaultPoints(int num_spheres) {
  return std::max(kMinDefaultPoints, kDefaultPointsPerSphere * int64_t{num_spheres});
}

int64_t fitTargetPoints(const FitOptions& o) {
  return o.target_points > 0 ? o.target_points : defaultPoints(o.num_spheres);
}

}  // namespace sphereset::detail

// Small pieces shared by the phases of the fit (fit_common.hpp).
#include "fit/fit_common.hpp"

#include <tbb/parallel_for.h>

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

}  // namespace sphereset::detail

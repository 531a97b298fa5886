// Small pieces shared by the phases of the fit (fit_common.hpp).
#include "fit/fit_common.hpp"

#include <tbb/parallel_for.h>

namespace sphereset::detail {

namespace {
thread_local ProgressScope* current_scope = nullptr;
}  // namespace

ProgressScope::ProgressScope(const FitOptions& options, FitClock::time_point start)
    : options_(options), start_(start), last_(start), outer_(current_scope) {
  current_.spheres = options.num_spheres;
  current_scope = this;
}

ProgressScope::~ProgressScope() { current_scope = outer_; }

void ProgressScope::report(const std::string& phase, int iteration, double energy) {
  current_.phase = phase;
  current_.iteration = iteration;
  current_.energy = energy;
  current_.seconds = secondsSince(start_);
  last_ = FitClock::now();
  if (options_.progress) options_.progress(current_);
}

void ProgressScope::poll() {
  if (!options_.progress) return;
  const auto now = FitClock::now();
  if (std::chrono::duration<double>(now - last_).count() < options_.progress_interval) return;
  last_ = now;
  current_.seconds = secondsSince(start_);
  options_.progress(current_);
}

void pollProgress() {
  if (current_scope) current_scope->poll();
}

std::vector<double> outsideVolumes(const SolidIndex& index, const std::vector<Sphere>& sp) {
  std::vector<double> v(sp.size());
  tbb::parallel_for(size_t{0}, sp.size(), [&](size_t i) {
    pollProgress();
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

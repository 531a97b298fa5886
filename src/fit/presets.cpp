// Quality presets and fit requests (fit.hpp): the options of `sphereset fit --quality`, shared by
// the CLI, the batch and the Python module. Not from the paper: the presets trade the number of
// points, rounds and optimiser effort of the clustering (Wang et al. 2006, Sec. 5) for time.
#include <algorithm>
#include <cstdint>
#include <string>

#include "sphereset/fit.hpp"

namespace sphereset {
namespace {

// One preset: the factor on the default points max(5000, 100 n), assignment/update rounds,
// optimiser evaluations per sphere and round, failed teleports before stopping, restarts,
// decimation.
struct Preset {
  double points_factor;
  int rounds, evaluations, failed_teleports, restarts;
  double decimation;
};

constexpr int64_t kMinDefaultPoints = 5000;
constexpr int64_t kDefaultPointsPerSphere = 100;

Preset presetOf(FitQuality q) {
  switch (q) {
    case FitQuality::kFast:
      return {0.4, 30, 30, 2, 1, 0.0};
    case FitQuality::kBest:
      return {1.0, 100, 60, 6, 4, 0.5};
    case FitQuality::kDefault:
      break;
  }
  return {1.0, 100, 60, 6, 1, 0.0};
}

// The name of `value` among `names` (parallel to `values`), or an error listing them.
template <class T, size_t N>
Expected<T> fromName(const std::string& text, const char* what, const char* const (&names)[N],
                     const T (&values)[N]) {
  std::string valid;
  for (size_t i = 0; i < N; ++i) {
    if (text == names[i]) return values[i];
    valid += (i == 0 ? "" : (i + 1 == N ? " or " : ", ")) + std::string(names[i]);
  }
  return Error{ErrorCode::kInvalidArgument,
               std::string(what) + " '" + text + "': expected " + valid};
}

constexpr const char* kQualityNames[] = {"fast", "default", "best"};
constexpr FitQuality kQualities[] = {FitQuality::kFast, FitQuality::kDefault, FitQuality::kBest};
constexpr const char* kInitNames[] = {"fps", "random"};
constexpr FitInit kInits[] = {FitInit::kFarthestPoint, FitInit::kRandom};
constexpr const char* kOptimizerNames[] = {"powell", "gradient"};
constexpr SphereOptimizer kOptimizers[] = {SphereOptimizer::kPowell, SphereOptimizer::kGradient};
constexpr const char* kMethodNames[] = {"variational", "kmeans", "octree"};
constexpr FitMethod kMethods[] = {FitMethod::kVariational, FitMethod::kKMeans, FitMethod::kOctree};

}  // namespace

const char* fitQualityName(FitQuality quality) { return kQualityNames[static_cast<int>(quality)]; }
const char* fitInitName(FitInit init) { return kInitNames[static_cast<int>(init)]; }
const char* sphereOptimizerName(SphereOptimizer optimizer) {
  return kOptimizerNames[static_cast<int>(optimizer)];
}
const char* fitMethodName(FitMethod method) { return kMethodNames[static_cast<int>(method)]; }

Expected<FitQuality> fitQualityFromName(const std::string& name) {
  return fromName(name, "quality", kQualityNames, kQualities);
}
Expected<FitInit> fitInitFromName(const std::string& name) {
  return fromName(name, "init", kInitNames, kInits);
}
Expected<SphereOptimizer> sphereOptimizerFromName(const std::string& name) {
  return fromName(name, "optimizer", kOptimizerNames, kOptimizers);
}
Expected<FitMethod> fitMethodFromName(const std::string& name) {
  return fromName(name, "method", kMethodNames, kMethods);
}

FitOptions fitPreset(int num_spheres, FitQuality quality) {
  const Preset p = presetOf(quality);
  FitOptions fo;
  fo.num_spheres = num_spheres;
  fo.max_iterations = p.rounds;
  fo.optimizer_evaluations = p.evaluations;
  fo.max_failed_teleports = p.failed_teleports;
  fo.restarts = p.restarts;
  fo.decimation = p.decimation;
  fo.target_points = static_cast<int64_t>(
      p.points_factor * static_cast<double>(std::max<int64_t>(
                            kMinDefaultPoints, kDefaultPointsPerSphere * int64_t{num_spheres})));
  return fo;
}

FitOptions fitOptionsFor(const FitRequest& request) {
  FitOptions fo = fitPreset(request.num_spheres, request.quality);
  fo.seed = request.seed;
  fo.padding = request.padding;
  if (request.points > 0) fo.target_points = request.points;
  if (request.iterations) fo.max_iterations = *request.iterations;
  if (request.restarts) fo.restarts = *request.restarts;
  if (request.decimation) fo.decimation = *request.decimation;
  fo.optimizer = request.optimizer;
  fo.init = request.init;
  fo.method = request.method;
  return fo;
}

}  // namespace sphereset

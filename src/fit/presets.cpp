// Quality presets and fit requests (fit.hpp): the options of `sphereset fit --quality`, shared by
// the CLI, the batch and the Python module. Not from the paper: the presets trade the number of
// points, rounds and optimiser effort of the clustering (Wang et al. 2006, Sec. 5) for time.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

#include "fit/fit_common.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/options.hpp"

namespace sphereset {
namespace {

// One preset: the factor on the default points max(5000, 100 n), assignment/update rounds,
// optimiser evaluations per sphere and round, failed teleports before stopping, restarts,
// decimation, and whether the restarts' spheres are selected among (FitOptions::
// select_among_restarts) instead of the best restart kept.
struct Preset {
  double points_factor;
  int rounds, evaluations, failed_teleports, restarts;
  double decimation;
  bool select = false;
  bool radii = false;  // FitOptions::optimal_radii
};

Preset presetOf(FitQuality q) {
  switch (q) {
    case FitQuality::kFast:
      // Against the default preset of b6d6b7d (bench/tightness.sh, 6 meshes at n = 16, 32,
      // 64): E_r 0.959 in 0.43 of its time; 0.3 of the points, 30 evaluations and 2 failed
      // teleports gave 0.956 in 0.45; 0.4 of the points and 30 rounds 0.903 in 0.56.
      return {0.25, 20, 20, 1, 1, 0.0};
    case FitQuality::kBest:
      return {1.0, 100, 60, 6, 4, 0.5, true, true};
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

// The options of a fit request (fit.hpp), the one table every front door is made from.
constexpr double kRealMax = std::numeric_limits<double>::max();
constexpr OptionSpec kFitRequestOptions[] = {
    {"n",
     "-n,--spheres",
     OptionType::kInteger,
     1,
     limits::kMaxSpheres,
     {},
     "32",
     "Number of spheres"},
    {"quality", "--quality", OptionType::kChoice, 0, 0, kQualityNames, "default",
     "Preset of points, rounds, optimiser effort, restarts and decimation (best also proves the "
     "radii optimal for the centres, radii.gap in --json): fast, default or best"},
    {"seed",
     "--seed",
     OptionType::kUnsigned,
     0,
     0,
     {},
     "1",
     "Seed for sampling and initialisation"},
    {"points",
     "--points",
     OptionType::kInteger,
     0,
     static_cast<double>(limits::kMaxPoints),
     {},
     "0",
     "Points to cluster (0: max(5000, 100 n), scaled by the quality)"},
    {"iterations",
     "--iterations",
     OptionType::kInteger,
     0,
     limits::kMaxIterations,
     {},
     "100; quality fast: 20",
     "Cap on assignment/update rounds"},
    {"restarts",
     "--restarts",
     OptionType::kInteger,
     1,
     limits::kMaxRestarts,
     {},
     "1; quality best: 4",
     "Independent fits from derived seeds, the best kept"},
    {"decimation",
     "--decimation",
     OptionType::kReal,
     0.0,
     limits::kMaxDecimation,
     {},
     "0; quality best: 0.5",
     "Extra spheres to start with, as a fraction of n, removed cheapest first"},
    {"padding",
     "--padding",
     OptionType::kReal,
     0.0,
     limits::kMaxCoordinate,
     {},
     "0",
     "Distance added to every radius (absolute units)"},
    {"optimizer", "--optimizer", OptionType::kChoice, 0, 0, kOptimizerNames, "powell",
     "Sphere update: powell (derivative-free BOBYQA) or gradient (MMA with exact derivatives)"},
    {"init", "--init", OptionType::kChoice, 0, 0, kInitNames, "fps",
     "Seeding: fps (farthest point) or random (as in the paper)"},
    {"method", "--method", OptionType::kChoice, 0, 0, kMethodNames, "variational",
     "variational (the paper's), or the baselines kmeans (L2 Lloyd clusters) and octree "
     "(occupied octree leaves); all end with the same guaranteed bound"},
};

}  // namespace

std::span<const OptionSpec> fitRequestOptions() { return kFitRequestOptions; }

Status setFitRequestOption(FitRequest* r, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kFitRequestOptions, "fit", name, text);
  if (!parsed) return parsed.error();
  const OptionValue* v = &parsed->value;
  const std::string_view n = parsed->spec->name;
  const auto integer = static_cast<int>(v->integer);  // within the row's int bounds
  if (n == "n") {
    r->num_spheres = integer;
    r->count_given = true;
  }
  if (n == "quality") r->quality = fitQualityFromName(v->choice).value();
  if (n == "seed") r->seed = v->unsigned_integer;
  if (n == "points") r->points = v->integer;
  if (n == "iterations") r->iterations = integer;
  if (n == "restarts") r->restarts = integer;
  if (n == "decimation") r->decimation = v->real;
  if (n == "padding") r->padding = v->real;
  if (n == "optimizer") r->optimizer = sphereOptimizerFromName(v->choice).value();
  if (n == "init") r->init = fitInitFromName(v->choice).value();
  if (n == "method") r->method = fitMethodFromName(v->choice).value();
  return {};
}

Status checkFitRequest(const FitRequest& r) {
  // Each number as its text, through the same parser as every front door's.
  auto check = [](const char* name, const std::string& text) -> Status {
    auto v = parseTableOption(kFitRequestOptions, "fit", name, text);
    if (!v) return v.error();
    return {};
  };
  auto real = [](double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return std::string(buf);
  };
  Status st = check("n", std::to_string(r.num_spheres));
  if (st) st = check("points", std::to_string(r.points));
  if (st && r.iterations) st = check("iterations", std::to_string(*r.iterations));
  if (st && r.restarts) st = check("restarts", std::to_string(*r.restarts));
  if (st && r.decimation) st = check("decimation", real(*r.decimation));
  if (st) st = check("padding", real(r.padding));
  return st;
}

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
  fo.select_among_restarts = p.select;
  fo.optimal_radii = p.radii;
  fo.target_points = static_cast<int64_t>(p.points_factor *
                                          static_cast<double>(detail::defaultPoints(num_spheres)));
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

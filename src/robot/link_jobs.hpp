// Private: one link of a robot's fit (fit_robot.cpp) as its stages share it: its solid, its
// counts and results, the options of its fits, and the links held to a protrusion limit
// (link_limits.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset::detail {

// The curve fits are quick ones: fewer points and rounds than the final fit (each count of the
// curve's progressive run starts from the one below it, so few rounds settle it).
constexpr int64_t kCurvePoints = 3000;
constexpr int kCurveRounds = 10;

// One link to fit: its solid (repaired), its exact sphere primitives, and the results.
struct Job {
  const RobotLink* link = nullptr;
  std::vector<std::string> files;
  std::unique_ptr<SolidIndex> index;
  RepairResult repair;
  std::vector<Sphere> primitives;
  int fixed = -1;        // -1: from the budget
  bool decided = false;  // fitted by its protrusion limit (applyProtrusionLimits)
  double limit = 0.0;    // its protrusion limit (0: none)
  bool limit_met = true;
  bool skipped = false;  // fixed at 0: not fitted
  double padding = 0.0;
  LinkFitCurve curve;
  // Under a budget: the curve's progressive run, whose clusterings the link's fits start from.
  std::unique_ptr<ProgressiveFit> curve_run;
  int count = 0;         // the count chosen
  int split_count = -1;  // under a budget: the curve split's count
  std::vector<Sphere> spheres;
  EvalResult eval;
  double outside_volume = 0.0;  // of the chosen fit (Σ over its spheres, before padding)
  double split_volume = 0.0;    // of the fit at split_count
  double seconds = 0.0;
};

// The options of a link's fit at `n` spheres: the quality preset's, or with `quick` a curve fit's.
FitOptions linkFitOptions(const RobotFitOptions& o, const Job& j, int n, bool quick);

// Links with a protrusion limit (RobotFitOptions::max_protrusion, link_max_protrusion): fitted
// by the tolerance search (protrusion_split.cpp) and marked decided; the others are left to the
// budget or their counts. Under a budget every free link needs a limit and shares what the fixed
// counts and the sphere primitives leave. The limit holds the padded spheres: the fit's protrusion
// is held to the limit minus the link's padding.
Status applyProtrusionLimits(const RobotFitOptions& o, std::vector<Job>* jobs);

}  // namespace sphereset::detail

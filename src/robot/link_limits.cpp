// The options of a link's fits and the links held to a protrusion limit (link_jobs.hpp): the
// parts of a robot's fit (fit_robot.cpp) that choose a link's count by its protrusion, through
// the tolerance search of protrusion_split.cpp.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "robot/link_jobs.hpp"
#include "robot/link_tasks.hpp"
#include "robot/protrusion_split.hpp"
#include "sphereset/options.hpp"

namespace sphereset::detail {

FitOptions linkFitOptions(const RobotFitOptions& o, const Job& j, int n, bool quick) {
  // The quality presets of `fit` (fit.hpp); the curve fits are quick ones: the fast preset
  // with fewer points and rounds, and without the coverage-aware refinement (refine.cpp): the
  // curves only rank the links' gains. On the Kinova at a budget of 60, refining them made the
  // robot's fit 1.2 times as long and did not lower its outside volume (docs/benchmarks.md).
  FitOptions fo = fitPreset(n, quick ? FitQuality::kFast : o.quality);
  if (quick) {
    fo.target_points = kCurvePoints;
    fo.max_iterations = kCurveRounds;
    fo.refine = false;
  }
  fo.seed = o.seed;
  fo.original = originalTriangles(j.repair);
  if (o.progress)
    fo.progress = [&o, &link = j.link->name](const FitProgress& p) { o.progress(link, p); };
  return fo;
}

namespace {

// The link's protrusion limit as a length: its own (a length, or a fraction of its solid's
// diagonal), else the robot's (either form); 0 when none applies.
double linkProtrusionLimit(const RobotFitOptions& o, const Job& j) {
  const double diagonal = j.index->bounds().diagonal();
  if (auto it = o.link_max_protrusion.find(j.link->name); it != o.link_max_protrusion.end())
    return it->second;
  if (auto it = o.link_max_protrusion_fraction.find(j.link->name);
      it != o.link_max_protrusion_fraction.end())
    return it->second * diagonal;
  return o.max_protrusion > 0.0 ? o.max_protrusion : o.max_protrusion_fraction * diagonal;
}

}  // namespace

Status applyProtrusionLimits(const RobotFitOptions& o, std::vector<Job>* jobs) {
  if (!o.toleranceActive()) return {};
  std::vector<ProtrusionLink> links;
  std::vector<Job*> limited;
  int rest = o.budget;
  for (Job& j : *jobs) {
    rest -= static_cast<int>(j.primitives.size());
    if (!j.index || j.fixed >= 0) {
      rest -= std::max(0, j.fixed);
      continue;
    }
    j.limit = linkProtrusionLimit(o, j);
    if (!(j.limit > 0.0)) {
      if (o.budget > 0)
        return Error{ErrorCode::kInvalidArgument,
                     o.name + ": link '" + j.link->name +
                         "' has no protrusion limit: with a budget, give max_protrusion for "
                         "every link (or link_spheres for it)"};
      continue;
    }
    if (!(j.limit > j.padding))
      return Error{ErrorCode::kInvalidArgument,
                   o.name + ": link '" + j.link->name + "': its padding " + optionText(j.padding) +
                       " leaves nothing of its protrusion limit " + optionText(j.limit)};
    ProtrusionLink l;
    l.name = j.link->name;
    l.index = j.index.get();
    l.original = originalTriangles(j.repair);
    l.walls = envelopeWalls(j.repair);
    l.limit = j.limit - j.padding;
    links.push_back(std::move(l));
    limited.push_back(&j);
  }
  if (links.empty()) return {};
  if (o.budget > 0 && rest < static_cast<int>(links.size()))
    return Error{ErrorCode::kInvalidArgument,
                 o.name + ": budget " + std::to_string(o.budget) + " leaves " +
                     std::to_string(std::max(0, rest)) + " spheres for the " +
                     std::to_string(links.size()) + " links with a protrusion limit"};
  const int cap =
      std::min(kLinkToleranceCap,
               o.budget > 0 ? rest - static_cast<int>(links.size()) + 1 : kLinkToleranceCap);
  for (size_t i = 0; i < links.size(); ++i) {
    links[i].cap = cap;
    links[i].options_for = [&o, job = limited[i]](int n) {
      return linkFitOptions(o, *job, n, false);
    };
  }
  StepReporter steps(o, "link tolerance", o.budget > 0 ? rest : static_cast<int64_t>(links.size()));
  auto picks =
      fitToProtrusion(links, o.budget > 0 ? rest : 0, [&](const std::string& link, int units) {
        for (int u = 0; u < units; ++u) steps.done(link);
      });
  if (!picks) return Error{picks.error().code, o.name + ": " + picks.error().message};
  for (size_t i = 0; i < links.size(); ++i) {
    Job& j = *limited[i];
    ProtrusionPick& p = (*picks)[i];
    j.decided = true;
    j.limit_met = p.met;
    j.count = p.count;
    j.spheres = j.primitives;
    j.spheres.insert(j.spheres.end(), p.fit.spheres.begin(), p.fit.spheres.end());
    for (Sphere& sp : j.spheres) sp.radius += j.padding;
    j.eval = std::move(p.eval);
    j.outside_volume = p.fit.energy;
    j.seconds = p.seconds;
  }
  return {};
}

}  // namespace sphereset::detail

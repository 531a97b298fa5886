// Fits started from the page (view.hpp, startViewFit): the library's fitSpheres on one solid, or
// fitRobot's budget split over a robot's links, in a thread of the job's own, reporting how far
// it is from the fits' progress and stopping when asked (a progress callback that throws, as
// fit.hpp allows). The scene is only touched under the server's lock, by viewFitStatus, which
// applies a finished fit once.
#include "view/view_fit.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <utility>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot_fit.hpp"

namespace sphereset {
namespace {

// The share of a fit's work its clustering takes, the rest being sampling and bounding: what
// the progress bar shows of its rounds (an estimate; the bound's length varies).
constexpr double kClusteringShare = 0.8;
constexpr double kSamplingShare = 0.05;

struct Cancelled {};

double fitFraction(const FitProgress& p, int max_rounds) {
  if (p.phase == "sampling") return 0.0;
  if (p.phase == "clustering")
    return kSamplingShare +
           kClusteringShare *
               std::min(1.0, p.iteration / static_cast<double>(std::max(1, max_rounds)));
  if (p.phase == "done") return 1.0;
  return kSamplingShare + kClusteringShare;  // bounding
}

// Checks for a cancel; moves the fraction on (never back) and names the stage (empty: kept).
void report(ViewFitJob* job, double fraction, std::string stage) {
  if (job->cancel.load()) throw Cancelled{};
  std::lock_guard<std::mutex> g(job->mutex);
  job->status.fraction = std::max(job->status.fraction, std::min(1.0, fraction));
  if (!stage.empty()) job->status.stage = std::move(stage);
}

// Whether the job will still change the scene: running, or done and not yet applied.
bool pending(const ViewFitJob& job) {
  return job.status.state == "running" || (job.status.state == "done" && !job.applied);
}

void finish(ViewFitJob* job, std::vector<std::vector<Sphere>> sets,
            std::map<std::string, int> counts, bool tolerance = false, bool met = true) {
  std::lock_guard<std::mutex> g(job->mutex);
  job->sets = std::move(sets);
  job->status.counts = std::move(counts);
  job->status.tolerance = tolerance;
  job->status.tolerance_met = met;
  job->status.fraction = 1.0;
  job->status.stage = "done";
  job->status.state = "done";
}

void fail(ViewFitJob* job, const std::string& state, const std::string& error) {
  std::lock_guard<std::mutex> g(job->mutex);
  job->status.state = state;
  job->status.error = error;
}

// One solid: its link's sphere primitives (a robot's), then the fitted spheres.
void runSolidFit(ViewFitJob* job, std::shared_ptr<const SolidIndex> index,
                 std::shared_ptr<const SolidInput> input, std::vector<Sphere> primitives,
                 const ViewFitRequest& request) {
  FitOptions o = fitPreset(request.spheres, request.quality);
  o.original = input->original();
  const int rounds = o.max_iterations;
  o.progress = [job, rounds](const FitProgress& p) {
    report(job, fitFraction(p, rounds),
           p.phase + (p.phase == "clustering" ? " round " + std::to_string(p.iteration) : ""));
  };
  auto fit = fitSpheres(*index, o);
  if (!fit) return fail(job, "failed", fit.error().message);
  std::vector<Sphere> set = std::move(primitives);
  set.insert(set.end(), fit->spheres.begin(), fit->spheres.end());
  finish(job, {std::move(set)}, {});
}

// One solid, the fewest spheres that meet the tolerance (fitToTolerance): each count tried moves
// the bar on (a doubling then a bisection: about twice the cap's bits of counts), its fits report
// their rounds as the stage and check for a cancel; the best count found is applied when none
// meets it.
void runToleranceFit(ViewFitJob* job, std::shared_ptr<const SolidIndex> index,
                     std::shared_ptr<const SolidInput> input, std::vector<Sphere> primitives,
                     const ViewFitRequest& request, const std::string& name) {
  ToleranceOptions t = request.tolerance;
  t.original = input->original();
  t.walls = input->walls();
  const double expected = 2.0 * std::log2(static_cast<double>(std::max(2, t.max_spheres))) + 1.0;
  int tried = 0;
  t.progress = [job, &tried, expected](const CurvePoint& p) {
    ++tried;
    report(job, tried / expected,
           "n " + std::to_string(p.n) + (p.meets ? " meets it" : " does not meet it"));
  };
  t.fit_progress = [job](const FitProgress& p) {
    report(job, 0.0, "n " + std::to_string(p.spheres) + ": " + p.phase);
  };
  FitRequest fr;
  fr.quality = request.quality;
  auto found = fitToTolerance(*index, fr, t);
  if (!found) return fail(job, "failed", found.error().message);
  std::vector<Sphere> set = std::move(primitives);
  set.insert(set.end(), found->fit.spheres.begin(), found->fit.spheres.end());
  const int count = static_cast<int>(set.size());  // a link's primitives included
  finish(job, {std::move(set)}, {{name, count}}, true, found->met);
}

// A robot's budget: fitRobot with the scene's solids' options; each solid gets its link's set.
void runBudgetFit(ViewFitJob* job, std::shared_ptr<const Robot> robot, RobotFitOptions o,
                  std::vector<std::string> links) {
  o.progress = [job](const std::string&, const FitProgress&) { report(job, 0.0, ""); };
  o.steps = [job](const RobotProgress& p) {
    // The curves are the first third of the work, the fits the rest.
    const double part = p.total > 0 ? static_cast<double>(p.done) / p.total : 0.0;
    const bool curves = p.stage == "link curves";
    report(job, curves ? part / 3.0 : 1.0 / 3.0 + 2.0 * part / 3.0,
           p.stage + " " + std::to_string(p.done) + " of " + std::to_string(p.total) +
               (p.link.empty() ? "" : " (" + p.link + ")"));
  };
  auto fit = fitRobot(*robot, o);
  if (!fit) return fail(job, "failed", fit.error().message);
  std::vector<std::vector<Sphere>> sets(links.size());
  std::map<std::string, int> counts;
  for (const RobotLinkFit& l : fit->links) {
    counts[l.link] = static_cast<int>(l.spheres.size());
    const auto at = std::find(links.begin(), links.end(), l.link);
    if (at != links.end()) sets[static_cast<size_t>(at - links.begin())] = l.spheres;
  }
  finish(job, std::move(sets), std::move(counts), fit->tolerance, fit->tolerance_met);
}

// Runs `body` on the job's thread: a cancellation or an exception ends the job, never the
// server.
template <class Body>
void launch(const std::shared_ptr<ViewFitJob>& job, Body body) {
  ViewFitJob* j = job.get();
  j->thread = std::thread([j, body = std::move(body)]() mutable {
    try {
      body(j);
    } catch (const Cancelled&) {
      fail(j, "cancelled", "");
    } catch (const std::exception& e) {
      fail(j, "failed", e.what());
    }
  });
}

// The robot fit a request asks for: the scene's link solids and repair, the budget, and the
// tolerance's protrusion limit (either form; a fraction is of each link's own diagonal) as every
// link's.
RobotFitOptions robotOptions(const ViewScene& scene, const ViewFitRequest& request) {
  RobotFitOptions o;
  o.budget = request.budget;
  o.quality = request.quality;
  o.repair = scene.repair;
  o.link_solid = scene.link_solid;
  o.link_solid_for = scene.link_solid_for;
  o.name = scene.urdf_path;
  o.max_protrusion = request.tolerance.max_protrusion;
  o.max_protrusion_fraction = request.tolerance.max_protrusion_fraction;
  return o;
}

Status checkRequest(const ViewScene& scene, const ViewFitRequest& r) {
  const auto bad = [](const std::string& m) { return Error{ErrorCode::kInvalidArgument, m}; };
  if (scene.fit) {
    std::lock_guard<std::mutex> g(scene.fit->mutex);
    if (scene.fit->status.state == "running")
      return bad("a fit is running: wait for it or cancel it");
    if (pending(*scene.fit))
      return bad("a fit has finished and is not applied yet: ask for its status");
  }
  const bool tolerance = r.tolerance.active();
  if (tolerance)
    if (Status st = checkToleranceOptions(r.tolerance); !st) return st;
  if (r.budget != 0 || r.robot) {
    if (scene.kind != ViewKind::kRobot || !scene.robot)
      return bad(r.budget != 0 ? "fit: a budget is for robots" : "fit: the scene is no robot");
    if (r.tolerance.max_er > 0.0 || r.tolerance.capSet())
      return bad(
          "fit: a robot takes max_protrusion as every link's limit, not max_er or "
          "max_spheres (each link's cap is its own)");
    if (r.budget == 0 && !tolerance)
      return bad("fit: a robot fit needs a budget or max_protrusion");
    if (Status st = checkRobotFitOptions(robotOptions(scene, r)); !st) return st;
    if (r.budget == 0) return {};
    const auto least = static_cast<int64_t>(std::count_if(
        scene.solids.begin(), scene.solids.end(), [](const ViewSolid& s) { return s.set == 0; }));
    if (r.budget < least || r.budget > limits::kMaxSpheres)
      return bad("fit: the budget must be from " + std::to_string(least) + " (one per link) to " +
                 std::to_string(limits::kMaxSpheres));
    return {};
  }
  if (r.solid < 0 || r.solid >= static_cast<int64_t>(scene.solids.size()))
    return bad("fit: no solid " + std::to_string(r.solid) + " (the scene has " +
               std::to_string(scene.solids.size()) + ")");
  if (scene.solids[static_cast<size_t>(r.solid)].set != 0)
    return bad("fit: solid " + std::to_string(r.solid) + " is the compared set: it is not fitted");
  if (scene.solids[static_cast<size_t>(r.solid)].tree)
    return bad("fit: a tree's levels are fitted by `sphereset tree`, not one at a time");
  FitRequest fr;
  fr.quality = r.quality;
  if (tolerance) {
    // The count is the tolerance's to choose: spheres given with one is refused in the library's
    // words (checkToleranceRequest).
    fr.count_given = r.spheres != 0;
    if (fr.count_given) fr.num_spheres = r.spheres;
    return checkToleranceRequest(fr, r.tolerance);
  }
  fr.num_spheres = r.spheres;
  if (Status st = checkToleranceRequest(fr, r.tolerance); !st) return st;  // a cap with no limit
  if (Status st = checkFitRequest(fr); !st) return st;
  if (r.spheres < 1) return bad("fit: the sphere count must be at least 1");
  return {};
}

}  // namespace

ViewFitJob::~ViewFitJob() {
  cancel = true;
  if (thread.joinable()) thread.join();
}

Status checkNotFitting(const ViewScene& scene, int64_t solid) {
  if (!scene.fit) return {};
  std::lock_guard<std::mutex> g(scene.fit->mutex);
  // A finished fit not yet applied would replace what an edit does now.
  if (!pending(*scene.fit)) return {};
  if (std::find(scene.fit->status.solids.begin(), scene.fit->status.solids.end(), solid) ==
      scene.fit->status.solids.end())
    return {};
  return Error{ErrorCode::kInvalidArgument, "solid " + std::to_string(solid) +
                                                " is being fitted: wait for the fit or cancel it"};
}

Status startViewFit(ViewScene* scene, const ViewFitRequest& request) {
  if (Status st = checkRequest(*scene, request); !st) return st;
  auto job = std::make_shared<ViewFitJob>();
  if (request.budget != 0 || request.robot) {
    std::vector<std::string> links;
    for (size_t k = 0; k < scene->solids.size(); ++k) {
      if (scene->solids[k].set != 0) continue;
      job->status.solids.push_back(static_cast<int64_t>(k));
      links.push_back(scene->solids[k].link);
    }
    const RobotFitOptions o = robotOptions(*scene, request);
    launch(job,
           [robot = scene->robot, o, links](ViewFitJob* j) { runBudgetFit(j, robot, o, links); });
  } else {
    const ViewSolid& s = scene->solids[static_cast<size_t>(request.solid)];
    job->status.solids.push_back(request.solid);
    std::vector<Sphere> primitives;
    if (scene->robot) {
      for (const RobotLink& l : scene->robot->links)
        if (l.name == s.link) primitives = linkSpheres(l);
    }
    const std::string name = s.link.empty() ? "mesh" : s.link;
    launch(job, [index = s.index, input = s.input, primitives, request, name](ViewFitJob* j) {
      if (request.tolerance.active())
        runToleranceFit(j, index, input, primitives, request, name);
      else
        runSolidFit(j, index, input, primitives, request);
    });
  }
  scene->fit = std::move(job);
  return {};
}

ViewFitStatus viewFitStatus(ViewScene* scene) {
  ViewFitStatus out;
  if (!scene->fit) return out;
  ViewFitJob& job = *scene->fit;
  std::lock_guard<std::mutex> g(job.mutex);
  out = job.status;
  if (job.status.state == "done" && !job.applied) {
    job.applied = true;
    out.applied = true;
    for (size_t i = 0; i < job.status.solids.size(); ++i) {
      if (job.sets[i].empty()) continue;  // a link the budget skipped keeps its set
      replaceViewSet(&scene->solids[static_cast<size_t>(job.status.solids[i])],
                     std::move(job.sets[i]));
    }
    ++scene->version;
  }
  return out;
}

void cancelViewFit(ViewScene* scene) {
  if (scene->fit) scene->fit->cancel = true;
}

}  // namespace sphereset

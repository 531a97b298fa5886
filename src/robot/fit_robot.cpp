// fitRobot: collision spheres for every link of a robot (robot_fit.hpp). Each link's collision
// geometry (visual when it has none) is one solid (linkSolid), fitted like a mesh file; sphere
// primitives stay exact spheres. Counts: fixed per link, or a budget split over the links by
// marginal gain on quick fits at a few counts (budget.cpp), then each link fitted at the split's
// count and counts either side of it, the best combination kept (pickCandidates). Links are
// prepared and fitted in parallel; every fit gives the same spheres for any thread count, and so
// does the whole.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "robot/link_jobs.hpp"
#include "robot/link_keys.hpp"
#include "robot/link_tasks.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"

namespace sphereset {
namespace {

using detail::applyProtrusionLimits;
using detail::Job;
using detail::linkFitOptions;

// Under a budget, each free link is also fitted at counts within this many of the split's, every
// kCandidateStep-th, and the exact pick (pickCandidates) chooses among all of them: a fit's
// outside volume is not monotone in its count (a fit with more spheres can end in a worse local
// minimum: the Kinova's base link envelope gives E_r 0.54 at 6 spheres and 0.74 at 8), so a link
// may do better with fewer and leave its spheres to another. A link's candidates are one
// progressive run (each warm-started from the count below it). On the Kinova at a budget of 60,
// seeds 1 to 3: spread 1 (step 1) lost 4 % of outside volume to spread 2; spread 2 with step 2
// (the split's count and 2 either side) took 0.86 of the time of step 1 for 1.3 % more outside
// volume. The count of an even split (the budget shared alike) is no candidate: it took 8 % of
// the time for 0.8 % less outside volume (docs/benchmarks.md, "The robot budget with progressive
// curves").
constexpr int kCandidateSpread = 2;
constexpr int kCandidateStep = 2;
// Sphere counts at which each free link is fitted to measure its curve for the budget split: up
// to the first at or above kCurveReach times the even share (the budget over the free links;
// beyond it the split extrapolates the last piece of the curve, budget.cpp), and never above the
// budget.
constexpr int kCurveCounts[] = {1, 2, 4, 8, 16, 32};
constexpr double kCurveReach = 2.0;

// One fit of a link at one count (the budget fits each free link at two counts and keeps one).
struct LinkFit {
  int count = 0;
  std::vector<Sphere> spheres;
  EvalResult eval;
  double outside_volume = 0.0;
  double seconds = 0.0;
  std::string error;
};

// Whether a link has geometry to fit (anything but sphere primitives).
bool hasFittedGeometry(const RobotLink& link) {
  for (const LinkGeometry& g : link.geometry)
    if (g.kind != LinkGeometry::Kind::kSphere) return true;
  return false;
}
// A free link's curve for the budget split: one progressive run of quick fits through the
// curve's counts up to `reach` (each clustering warm-started from the count before it; the fast
// preset has one restart and no decimation), kept in j->curve_run for the link's fits to start
// from.
void measureCurve(const RobotFitOptions& o, Job* j, double reach) {
  int top = 0;
  for (int k : kCurveCounts)
    if (k <= o.budget && top < reach) top = k;
  auto run = ProgressiveFit::start(*j->index, linkFitOptions(o, *j, top, true));
  for (int k : kCurveCounts) {
    if (!run || k > top) break;
    auto f = run->fit(k);
    if (!f) break;
    j->curve.counts.push_back(k);
    j->curve.outside_volume.push_back(f->energy);
  }
  if (run) {
    run->forgetAnswers();
    j->curve_run = std::make_unique<ProgressiveFit>(std::move(run).value());
  }
  j->index->forgetAnswers();  // memory per link in flight, not per link (a 1000-link chain)
}
// Loads, repairs and indexes every link with geometry, the links in parallel (the wrap is
// single-threaded), and under a budget measures each free link's curve as soon as it is ready
// (each fit is parallel too, and gives the same spheres for any thread count); the first error
// in link order is reported.
Expected<std::vector<Job>> prepareLinks(const RobotFitOptions& o, const Robot& robot) {
  std::vector<Job> jobs;
  int64_t free_links = 0;
  for (const RobotLink& link : robot.links)
    if (!link.geometry.empty()) {
      jobs.emplace_back();
      jobs.back().link = &link;
      free_links += hasFittedGeometry(link) && !o.link_spheres.contains(link.name);
    }
  const bool curves = o.budget > 0 && free_links > 0 && !o.toleranceActive();
  const double reach = curves ? kCurveReach * o.budget / static_cast<double>(free_links) : 0.0;
  detail::StepReporter steps(o, "link curves", free_links);
  std::vector<Status> status(jobs.size());
  // The largest mesh files first (their repairs are single-threaded).
  std::vector<double> bytes(jobs.size(), 0.0);
  for (size_t i = 0; i < jobs.size(); ++i)
    for (const LinkGeometry& g : jobs[i].link->geometry) {
      if (g.kind != LinkGeometry::Kind::kMesh) continue;
      std::error_code ec;
      const auto size = std::filesystem::file_size(g.mesh_path, ec);
      if (!ec) bytes[i] += static_cast<double>(size);
    }
  detail::forEachLargestFirst(bytes, [&](size_t i) {
    Job& j = jobs[i];
    const RobotLink& link = *j.link;
    const std::string name = o.name + ": link '" + link.name + "'";
    j.primitives = linkSpheres(link);
    for (const LinkGeometry& g : link.geometry)
      if (g.kind == LinkGeometry::Kind::kMesh) j.files.push_back(g.mesh_path);
    if (!hasFittedGeometry(link)) return;  // sphere primitives only
    if (auto it = o.link_spheres.find(link.name); it != o.link_spheres.end() && it->second == 0)
      return;  // skipped: not worth repairing
    // The options were checked by fitRobot (checkRobotFitOptions).
    auto solid = linkSolid(
        link, linkRepairOptions(o.repair, o.link_solid, o.link_solid_for, link.name), name);
    if (!solid) {
      status[i] = solid.error();
      return;
    }
    j.repair = std::move(solid->repair);
    j.index = std::make_unique<SolidIndex>(j.repair.solid);
    if (curves && !o.link_spheres.contains(link.name)) {
      measureCurve(o, &j, reach);
      steps.done(link.name);
    }
  });
  for (const Status& st : status)
    if (!st) return st.error();
  return jobs;
}
// The sphere counts: fixed links, then, under a budget, the split by measured curves
// (split_count); the fits decide around it (fitLinks).
Status chooseCounts(const RobotFitOptions& o, std::vector<Job>* jobs) {
  bool any_free = false;
  for (Job& j : *jobs) {
    if (!j.index) j.fixed = 0;  // only sphere primitives: nothing to fit
    if (j.decided) j.fixed = j.count;
    any_free = any_free || j.fixed < 0;
  }
  if (o.budget <= 0 || !any_free) {
    int total = 0;
    for (Job& j : *jobs) {
      j.count = j.fixed >= 0 ? j.fixed : o.default_link_spheres;
      total += j.count + static_cast<int>(j.primitives.size());
    }
    if (o.budget > 0 && total > o.budget)
      return Error{ErrorCode::kInvalidArgument, o.name + ": budget " + std::to_string(o.budget) +
                                                    ": the links' fixed counts "
                                                    "and sphere primitives already come to " +
                                                    std::to_string(total)};
    return {};
  }
  std::vector<LinkFitCurve> curves;
  std::vector<int> fixed;
  int primitives = 0;
  for (const Job& j : *jobs) {
    curves.push_back(j.curve);
    fixed.push_back(j.fixed);
    primitives += static_cast<int>(j.primitives.size());
  }
  // The budget counts the sphere primitives, which are not fitted.
  auto budgetError = [&](const Error& e) {
    return Error{e.code, o.name + ": budget " + std::to_string(o.budget) + ": " + e.message +
                             (primitives > 0 ? " (after the URDF's " + std::to_string(primitives) +
                                                   " sphere primitives)"
                                             : "")};
  };
  auto split = splitBudget(curves, fixed, o.budget - primitives);
  if (!split) return budgetError(split.error());
  for (size_t i = 0; i < jobs->size(); ++i) {
    Job& j = (*jobs)[i];
    j.count = (*split)[i];
    if (j.fixed < 0) j.split_count = (*split)[i];
  }
  return {};
}
// One fit of the link at `count` spheres, by the link's progressive run if it has one (its
// certificates come later: evaluateLink).
LinkFit fitLinkAt(const RobotFitOptions& o, const Job& j, int count, ProgressiveFit* run) {
  const auto t0 = std::chrono::steady_clock::now();
  LinkFit out;
  out.count = count;
  if (j.index && count > 0) {
    auto f = run ? run->fit(count) : fitSpheres(*j.index, linkFitOptions(o, j, count, false));
    if (!f) {
      out.error = f.error().message;
      return out;
    }
    out.spheres = f->spheres;
    out.outside_volume = f->energy;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}
// eval's certificates of the fit kept for a link (an empty fit has none); "" or the error.
std::string evaluateLink(const RobotFitOptions& o, const Job& j, LinkFit* f) {
  if (!j.index || f->count == 0) return {};
  const auto t0 = std::chrono::steady_clock::now();
  EvalOptions eo;
  eo.seed = o.seed;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = originalTriangles(j.repair);
  eo.walls = envelopeWalls(j.repair);
  auto e = evaluateSpheres(*j.index, f->spheres, eo);
  if (!e) return e.error().message;
  f->eval = std::move(e).value();
  f->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {};
}
// The fits of each link at its tasks' counts: per link, the counts in increasing order through
// one progressive run when the options allow it (each clustering warm-started from the count
// before, the first from the link's curve run), else independent fits; the links in parallel.
// A link's index forgets its remembered answers after its last fit, so that memory follows the
// links being fitted, not all of them (about 6.5 MB each, SolidIndex).
std::vector<LinkFit> fitCandidates(const RobotFitOptions& o, const std::vector<Job>& jobs,
                                   const std::vector<std::pair<size_t, int>>& tasks) {
  std::vector<LinkFit> fits(tasks.size());
  std::vector<std::vector<size_t>> of_link(jobs.size());
  for (size_t t = 0; t < tasks.size(); ++t) of_link[tasks[t].first].push_back(t);
  detail::StepReporter steps(o, "link fits", static_cast<int64_t>(tasks.size()));
  // The costliest links first: triangles times the spheres of all their fits.
  std::vector<double> cost(jobs.size(), 0.0);
  for (size_t t = 0; t < tasks.size(); ++t) {
    const Job& j = jobs[tasks[t].first];
    if (j.index)
      cost[tasks[t].first] +=
          static_cast<double>(j.index->mesh().triangles.size()) * tasks[t].second;
  }
  detail::forEachLargestFirst(cost, [&](size_t i) {
    const Job& j = jobs[i];
    std::vector<size_t>& mine = of_link[i];
    std::unique_ptr<ProgressiveFit> run;
    std::stable_sort(mine.begin(), mine.end(),
                     [&](size_t a, size_t b) { return tasks[a].second < tasks[b].second; });
    if (j.index && !mine.empty() && tasks[mine.back()].second > 0) {
      const FitOptions top = linkFitOptions(o, j, tasks[mine.back()].second, false);
      if (ProgressiveFit::allows(top))
        // Counts next to each other from the curve's settled clustering: each from the one
        // below it (on the Kinova at 60, seeds 1-3: 3.5 % less outside volume than from at
        // most half, in 0.87 times the time). A count of the curve is clustered again, not
        // taken as the quick fit's clustering (adopt): at a budget of 30, 3.5 % less outside
        // volume in 1.11 times the time (docs/benchmarks.md).
        if (auto r = ProgressiveFit::start(*j.index, top, j.curve_run.get(),
                                           {.start_ratio = 1, .adopt = false}))
          run = std::make_unique<ProgressiveFit>(std::move(r).value());
    }
    for (size_t t : mine) {
      fits[t] = fitLinkAt(o, j, tasks[t].second, run.get());
      steps.done(j.link->name);
    }
    if (j.index) j.index->forgetAnswers();
  });
  return fits;
}
// Fits every link at its count, and free links under a budget at the curve split's count and
// those kCandidateStep apart within kCandidateSpread of it (fitCandidates); then keeps, per link,
// the fit of whichever count gives the least total outside volume within the budget
// (pickCandidates), so the result is never worse than the split's. Fails with the first error in
// link order.
Status fitLinks(const RobotFitOptions& o, std::vector<Job>* jobs) {
  std::vector<std::pair<size_t, int>> tasks;  // (link, count)
  for (size_t i = 0; i < jobs->size(); ++i) {
    const Job& j = (*jobs)[i];
    if (j.decided) continue;
    tasks.emplace_back(i, j.count);
    if (j.split_count < 0) continue;
    for (int k = j.count - kCandidateSpread; k <= j.count + kCandidateSpread; k += kCandidateStep)
      if (k >= 1 && k != j.count) tasks.emplace_back(i, k);
  }
  std::vector<LinkFit> fits = fitCandidates(o, *jobs, tasks);
  for (size_t t = 0; t < tasks.size(); ++t)
    if (!fits[t].error.empty())
      return Error{
          ErrorCode::kInvalidArgument,
          o.name + ": link '" + (*jobs)[tasks[t].first].link->name + "': " + fits[t].error};
  // Candidates per link, in task order; links with one fit have one candidate. Links fitted by
  // their protrusion limit have none: their single "candidate" is what they have.
  std::vector<std::vector<LinkCandidate>> cand(jobs->size());
  std::vector<std::vector<size_t>> fit_of(jobs->size());
  int budget = 0;
  for (size_t t = 0; t < tasks.size(); ++t) {
    cand[tasks[t].first].push_back({fits[t].count, fits[t].outside_volume});
    fit_of[tasks[t].first].push_back(t);
  }
  for (size_t i = 0; i < jobs->size(); ++i)
    if ((*jobs)[i].decided) cand[i].push_back({0, 0.0});  // counted outside this budget
  for (const Job& j : *jobs) budget += j.decided ? 0 : j.count;
  auto pick = pickCandidates(cand, budget);
  if (!pick) return pick.error();
  // What the split would have cost, for the report.
  for (size_t i = 0; i < jobs->size(); ++i)
    for (size_t t : fit_of[i])
      if (fits[t].count == (*jobs)[i].split_count) (*jobs)[i].split_volume = fits[t].outside_volume;
  // eval's certificates of the fits kept only, the links in parallel.
  std::vector<std::string> error(jobs->size());
  tbb::parallel_for(size_t{0}, jobs->size(), [&](size_t i) {
    const Job& j = (*jobs)[i];
    if (j.decided) return;
    LinkFit& f = fits[fit_of[i][(*pick)[i]]];
    error[i] = evaluateLink(o, j, &f);
    if (j.index) j.index->forgetAnswers();
  });
  for (size_t i = 0; i < jobs->size(); ++i)
    if (!error[i].empty())
      return Error{ErrorCode::kInvalidArgument,
                   o.name + ": link '" + (*jobs)[i].link->name + "': " + error[i]};
  for (size_t i = 0; i < jobs->size(); ++i) {
    Job& j = (*jobs)[i];
    if (j.decided) continue;
    const LinkFit& f = fits[fit_of[i][(*pick)[i]]];
    j.count = f.count;
    j.spheres = j.primitives;
    j.spheres.insert(j.spheres.end(), f.spheres.begin(), f.spheres.end());
    for (Sphere& sp : j.spheres) sp.radius += j.padding;
    j.eval = f.eval;
    j.outside_volume = f.outside_volume;
    j.seconds = 0.0;
    for (size_t t : fit_of[i]) j.seconds += fits[t].seconds;
    j.curve_run.reset();
  }
  return {};
}

}  // namespace

Expected<RobotFitResult> fitRobot(const Robot& robot, const RobotFitOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (Status st = checkRobotFitOptions(o); !st) return st.error();
  if (Status st = detail::checkLinkKeys(robot, o.link_spheres, "link_spheres", o.name); !st)
    return st.error();
  if (Status st = detail::checkLinkKeys(robot, o.link_padding, "link_padding", o.name); !st)
    return st.error();
  if (Status st = checkLinkSolids(robot, o.repair, o.link_solid, o.link_solid_for, o.name); !st)
    return st.error();
  for (const auto* limits : {&o.link_max_protrusion, &o.link_max_protrusion_fraction})
    if (Status st = detail::checkLinkKeys(robot, *limits, "link_max_protrusion", o.name); !st)
      return st.error();
  auto jobs = prepareLinks(o, robot);
  if (!jobs) return jobs.error();
  for (Job& j : *jobs) {
    if (auto it = o.link_spheres.find(j.link->name); it != o.link_spheres.end())
      j.fixed = it->second;
    if (j.fixed == 0) {
      j.skipped = true;
      j.primitives.clear();
    }
    auto p = o.link_padding.find(j.link->name);
    j.padding = p != o.link_padding.end() ? p->second : o.padding;
  }
  if (Status s = applyProtrusionLimits(o, &*jobs); !s) return s.error();
  if (Status s = chooseCounts(o, &*jobs); !s) return s.error();
  if (Status s = fitLinks(o, &*jobs); !s) return s.error();
  RobotFitResult res;
  for (Job& j : *jobs) {
    RobotLinkFit l;
    l.link = j.link->name;
    l.spheres = std::move(j.spheres);
    l.primitives = static_cast<int>(j.primitives.size());
    l.skipped = j.skipped;
    l.from_visual = j.link->from_visual;
    l.fitted = j.index != nullptr && j.count > 0;
    l.covered =
        !l.fitted || (j.eval.surface_covered && j.eval.interior_covered && j.eval.original_covered);
    l.files = std::move(j.files);
    l.repair = std::move(j.repair);
    l.eval = j.eval;
    l.outside_volume = j.outside_volume;
    l.padding = j.padding;
    l.curve = std::move(j.curve);
    l.split_count = j.split_count;
    l.split_volume = j.split_volume;
    l.seconds = j.seconds;
    l.protrusion_limit = j.limit;
    l.limit_met = j.limit_met;
    if (j.limit > 0.0) {
      res.tolerance = true;
      res.tolerance_met = res.tolerance_met && j.limit_met;
    }
    if (l.split_count >= 0) {
      res.budget_split = true;
      res.outside_volume += l.outside_volume;
      res.split_outside_volume += l.split_volume;
    }
    res.links.push_back(std::move(l));
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace sphereset

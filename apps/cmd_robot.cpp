// sphereset robot: collision spheres for every link of a robot described by a URDF, in the link
// frames. Each link's collision geometry (visual when it has none) becomes one mesh, repaired
// like fit's meshes; sphere primitives are kept as exact spheres. Counts come from --budget
// (split by marginal gain, robot_fit.hpp) and --link-spheres. Outputs: cuRobo's YAML with the
// self-collision ignore list, the URDF with sphere collisions, or a JSON report.
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

// Sphere counts at which each free link is fitted to measure its curve for the budget split.
constexpr int kCurveCounts[] = {1, 2, 4, 8, 16, 32};
// The curve fits are quick ones: fewer points and rounds than the final fit.
constexpr int64_t kCurvePoints = 3000;
constexpr int kCurveRounds = 20;
// Spheres per link when neither --budget nor --link-spheres says.
constexpr int kDefaultLinkSpheres = 8;

struct RobotArgs {
  std::string urdf, out_path, quality = "default", joint_positions;
  std::vector<std::string> package_paths, link_spheres, link_padding;
  MeshArgs repair;  // repair options only (no mesh path)
  int budget = 0;
  double padding = 0.0;
  uint64_t seed = 1;
  bool quiet = false, json = false;
};

// One link to fit: its solid (repaired), its exact sphere primitives, and the results.
struct LinkJob {
  const RobotLink* link = nullptr;
  std::vector<std::string> files;
  std::unique_ptr<SolidIndex> index;
  RepairResult repair;
  std::vector<Sphere> primitives;
  int fixed = -1;        // -1: from the budget
  bool skipped = false;  // --link-spheres LINK=0: not fitted, not written (keeps its collisions)
  double padding = 0.0;
  LinkFitCurve curve;
  int count = 0;         // the count chosen
  int split_count = -1;  // with --budget: the curve split's count and the even split's
  int even_count = -1;
  std::vector<Sphere> spheres;
  EvalResult eval;
  double outside_volume = 0.0;  // of the chosen fit (Σ over its spheres, before padding)
  double split_volume = 0.0, even_volume = 0.0;  // of the fits at split_count and even_count
  double seconds = 0.0;
};

// One fit of a link at one count (the budget fits each free link at two counts and keeps one).
struct LinkFit {
  int count = 0;
  std::vector<Sphere> spheres;
  EvalResult eval;
  double outside_volume = 0.0;
  double seconds = 0.0;
  std::string error;
};

// NAME=VALUE options, for the names of links that exist.
template <class T>
Expected<std::map<std::string, T>> namedValues(const std::vector<std::string>& items,
                                               const Robot& robot, const char* option) {
  std::map<std::string, T> out;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    const std::string name = item.substr(0, eq);
    bool known = false;
    for (const RobotLink& l : robot.links) known = known || l.name == name;
    if (eq == std::string::npos || !known)
      return Error{
          ErrorCode::kInvalidArgument,
          std::string(option) + " " + item + ": expected LINK=VALUE with a link of " + robot.name};
    try {
      size_t used = 0;
      const std::string v = item.substr(eq + 1);
      const double x = std::stod(v, &used);
      if (used != v.size() || !(x >= 0.0) || !std::isfinite(x)) throw std::invalid_argument(v);
      if (std::is_integral_v<T> && (x != std::floor(x) || x > 1e6)) throw std::invalid_argument(v);
      out[name] = static_cast<T>(x);
    } catch (const std::exception&) {
      return Error{ErrorCode::kInvalidArgument,
                   std::string(option) + " " + item +
                       (std::is_integral_v<T> ? ": the value must be a whole number >= 0"
                                              : ": the value must be a number >= 0")};
    }
  }
  return out;
}

FitOptions linkFitOptions(const RobotArgs& a, const LinkJob& j, int n, bool quick) {
  // The quality presets of `fit` (fit.hpp); the curve fits are quick ones: the fast preset
  // with fewer points and rounds.
  const auto quality = fitQualityFromName(a.quality);  // checked by the option parser
  FitOptions fo = fitPreset(n, quick ? FitQuality::kFast : quality.value());
  if (quick) {
    fo.target_points = kCurvePoints;
    fo.max_iterations = kCurveRounds;
  }
  fo.seed = a.seed;
  fo.original = j.repair.kind == RepairKind::kNone ? nullptr : &j.repair.original;
  return fo;
}

// Loads, repairs and indexes every link with geometry, the links in parallel (the wrap is
// single-threaded); the first error in link order is reported.
Expected<std::vector<LinkJob>> prepareLinks(const RobotArgs& a, const Robot& robot) {
  std::vector<LinkJob> jobs;
  for (const RobotLink& link : robot.links)
    if (!link.geometry.empty()) {
      jobs.emplace_back();
      jobs.back().link = &link;
    }
  std::vector<Status> status(jobs.size());
  tbb::parallel_for(size_t{0}, jobs.size(), [&](size_t i) {
    LinkJob& j = jobs[i];
    const RobotLink& link = *j.link;
    const std::string name = a.urdf + ": link '" + link.name + "'";
    j.primitives = linkSpheres(link);
    bool fitted = false;
    for (const LinkGeometry& g : link.geometry) {
      if (g.kind == LinkGeometry::Kind::kMesh) j.files.push_back(g.mesh_path);
      fitted = fitted || g.kind != LinkGeometry::Kind::kSphere;
    }
    if (!fitted) return;  // sphere primitives only
    auto solid = linkSolid(link, repairOptions(a.repair), name);
    if (!solid) {
      status[i] = solid.error();
      return;
    }
    j.repair = std::move(solid->repair);
    j.index = std::make_unique<SolidIndex>(j.repair.solid);
  });
  for (const Status& st : status)
    if (!st) return st.error();
  return jobs;
}

// The sphere counts: fixed links, then, with a budget, the split by measured curves
// (split_count) and the even split (even_count); the fits decide between them (pickFits).
Status chooseCounts(const RobotArgs& a, std::vector<LinkJob>* jobs) {
  bool any_free = false;
  for (LinkJob& j : *jobs) {
    if (!j.index) j.fixed = 0;  // only sphere primitives: nothing to fit
    any_free = any_free || j.fixed < 0;
  }
  if (a.budget <= 0 || !any_free) {
    int total = 0;
    for (LinkJob& j : *jobs) {
      j.count = j.fixed >= 0 ? j.fixed : kDefaultLinkSpheres;
      total += j.count + static_cast<int>(j.primitives.size());
    }
    if (a.budget > 0 && total > a.budget)
      return Error{ErrorCode::kInvalidArgument, a.urdf + ": --budget " + std::to_string(a.budget) +
                                                    ": the links' fixed counts "
                                                    "and sphere primitives already come to " +
                                                    std::to_string(total)};
    return {};
  }
  // Curves of the free links, the links in parallel (each fit is parallel too, and gives the
  // same spheres for any thread count).
  tbb::parallel_for(size_t{0}, jobs->size(), [&](size_t i) {
    LinkJob& j = (*jobs)[i];
    if (j.fixed >= 0) return;
    for (int k : kCurveCounts) {
      if (k > a.budget) break;
      auto f = fitSpheres(*j.index, linkFitOptions(a, j, k, true));
      if (!f) break;
      j.curve.counts.push_back(k);
      j.curve.outside_volume.push_back(f->energy);
    }
  });
  std::vector<LinkFitCurve> curves;
  std::vector<int> fixed;
  int primitives = 0;
  for (const LinkJob& j : *jobs) {
    curves.push_back(j.curve);
    fixed.push_back(j.fixed);
    primitives += static_cast<int>(j.primitives.size());
  }
  // The budget counts the sphere primitives, which are not fitted.
  auto budgetError = [&](const Error& e) {
    return Error{e.code, a.urdf + ": --budget " + std::to_string(a.budget) + ": " + e.message +
                             (primitives > 0 ? " (after the URDF's " + std::to_string(primitives) +
                                                   " sphere primitives)"
                                             : "")};
  };
  auto split = splitBudget(curves, fixed, a.budget - primitives);
  if (!split) return budgetError(split.error());
  auto even = evenSplit(fixed, a.budget - primitives);
  if (!even) return budgetError(even.error());
  for (size_t i = 0; i < jobs->size(); ++i) {
    LinkJob& j = (*jobs)[i];
    j.count = (*split)[i];
    if (j.fixed < 0) {
      j.split_count = (*split)[i];
      j.even_count = (*even)[i];
    }
  }
  return {};
}

LinkFit fitLinkAt(const RobotArgs& a, const LinkJob& j, int count) {
  const auto t0 = std::chrono::steady_clock::now();
  LinkFit out;
  out.count = count;
  if (j.index && count > 0) {
    auto f = fitSpheres(*j.index, linkFitOptions(a, j, count, false));
    if (!f) {
      out.error = f.error().message;
      return out;
    }
    out.spheres = f->spheres;
    out.outside_volume = f->energy;
    EvalOptions eo;
    eo.seed = a.seed;
    eo.union_samples = 0;
    eo.proximity_segments = 0;
    eo.shadow_resolution = 0;
    eo.original = j.repair.kind == RepairKind::kNone ? nullptr : &j.repair.original;
    out.eval = evaluateSpheres(*j.index, f->spheres, eo);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// Fits every link at its count, and free links under a budget at both the curve split's and
// the even split's counts (all fits in parallel); then keeps, per link, the fit of whichever
// count gives the least total outside volume within the budget (pickCandidates), so the
// result is never worse than either split. Fails with the first error in link order.
Status fitLinks(const RobotArgs& a, std::vector<LinkJob>* jobs) {
  std::vector<std::pair<size_t, int>> tasks;  // (link, count)
  for (size_t i = 0; i < jobs->size(); ++i) {
    const LinkJob& j = (*jobs)[i];
    tasks.emplace_back(i, j.count);
    if (j.even_count >= 0 && j.even_count != j.count) tasks.emplace_back(i, j.even_count);
  }
  std::vector<LinkFit> fits(tasks.size());
  tbb::parallel_for(size_t{0}, tasks.size(), [&](size_t t) {
    fits[t] = fitLinkAt(a, (*jobs)[tasks[t].first], tasks[t].second);
  });
  for (size_t t = 0; t < tasks.size(); ++t)
    if (!fits[t].error.empty())
      return Error{
          ErrorCode::kInvalidArgument,
          a.urdf + ": link '" + (*jobs)[tasks[t].first].link->name + "': " + fits[t].error};
  // Candidates per link, in task order; links with one fit have one candidate.
  std::vector<std::vector<LinkCandidate>> cand(jobs->size());
  std::vector<std::vector<size_t>> fit_of(jobs->size());
  int budget = 0;
  for (size_t t = 0; t < tasks.size(); ++t) {
    cand[tasks[t].first].push_back({fits[t].count, fits[t].outside_volume});
    fit_of[tasks[t].first].push_back(t);
  }
  for (const LinkJob& j : *jobs) budget += j.count;
  auto pick = pickCandidates(cand, budget);
  if (!pick) return pick.error();
  for (size_t i = 0; i < jobs->size(); ++i) {
    LinkJob& j = (*jobs)[i];
    LinkFit& f = fits[fit_of[i][(*pick)[i]]];
    j.count = f.count;
    j.spheres = j.primitives;
    j.spheres.insert(j.spheres.end(), f.spheres.begin(), f.spheres.end());
    for (Sphere& sp : j.spheres) sp.radius += j.padding;
    j.eval = f.eval;
    j.outside_volume = f.outside_volume;
    j.seconds = 0.0;
    for (size_t t : fit_of[i]) j.seconds += fits[t].seconds;
    // What each split would have cost, for the report.
    for (size_t t : fit_of[i]) {
      if (fits[t].count == j.split_count) j.split_volume = fits[t].outside_volume;
      if (fits[t].count == j.even_count) j.even_volume = fits[t].outside_volume;
    }
  }
  return {};
}

bool covered(const LinkJob& j) {
  return !j.index || j.count == 0 ||
         (j.eval.surface_covered && j.eval.interior_covered && j.eval.original_covered);
}

// Total outside volume of the free links under a budget: as chosen, and for each split.
struct BudgetTotals {
  bool any = false;
  double chosen = 0.0, split = 0.0, even = 0.0;
};

BudgetTotals budgetTotals(const std::vector<LinkJob>& jobs) {
  BudgetTotals t;
  for (const LinkJob& j : jobs)
    if (j.split_count >= 0) {
      t.any = true;
      t.chosen += j.outside_volume;
      t.split += j.split_volume;
      t.even += j.even_volume;
    }
  return t;
}

nlohmann::json robotJson(const RobotArgs& a, const Robot& robot, const std::vector<LinkJob>& jobs) {
  nlohmann::json links = nlohmann::json::array();
  for (const LinkJob& j : jobs) {
    nlohmann::json s = nlohmann::json::array();
    for (const Sphere& sp : j.spheres)
      s.push_back({sp.center.x(), sp.center.y(), sp.center.z(), sp.radius});
    nlohmann::json l = {{"link", j.link->name},      {"spheres", s},
                        {"count", j.spheres.size()}, {"primitives", j.primitives.size()},
                        {"files", j.files},          {"from_visual", j.link->from_visual},
                        {"skipped", j.skipped},      {"covered", covered(j)},
                        {"padding", j.padding},      {"seconds", j.seconds}};
    if (!j.curve.counts.empty())
      l["budget_curve"] = {{"counts", j.curve.counts}, {"outside_volume", j.curve.outside_volume}};
    if (j.split_count >= 0)
      l["budget_fits"] = {
          {"curve_split", {{"count", j.split_count}, {"outside_volume", j.split_volume}}},
          {"even_split", {{"count", j.even_count}, {"outside_volume", j.even_volume}}}};
    if (j.index) {
      l["er_sum"] = j.eval.er_sum;
      l["outside_volume"] = j.outside_volume;
      l["repair"] = repairJson(j.repair);
    }
    links.push_back(l);
  }
  nlohmann::json out = {
      {"robot", robot.name}, {"urdf", a.urdf}, {"seed", a.seed}, {"links", links}};
  if (const BudgetTotals t = budgetTotals(jobs); t.any)
    out["budget"] = {{"spheres", a.budget},
                     {"outside_volume", t.chosen},
                     {"curve_split_outside_volume", t.split},
                     {"even_split_outside_volume", t.even}};
  return out;
}

void printSummary(const std::vector<LinkJob>& jobs, double seconds) {
  std::fprintf(stderr, "%-28s %9s %-10s %7s %9s %7s %7s\n", "link", "triangles", "repair",
               "spheres", "E_r", "covered", "time s");
  for (const LinkJob& j : jobs)
    std::fprintf(stderr, "%-28s %9zu %-10s %7zu %9.4f %7s %7.2f\n", j.link->name.c_str(),
                 j.index ? j.repair.original.triangles.size() : size_t{0},
                 j.index ? repairName(j.repair.kind) : "-", j.spheres.size(),
                 j.index ? j.eval.er_sum : 0.0,
                 j.skipped    ? "skipped"
                 : covered(j) ? "yes"
                              : "NO",
                 j.seconds);
  for (const LinkJob& j : jobs)
    if (j.link->from_visual)
      std::fprintf(stderr, "%s: no <collision> geometry, its <visual> geometry was used\n",
                   j.link->name.c_str());
  if (const BudgetTotals t = budgetTotals(jobs); t.any)
    std::fprintf(stderr,
                 "budget: outside volume %.6g of the links it split (split by curves %.6g, "
                 "even split %.6g)\n",
                 t.chosen, t.split, t.even);
  std::fprintf(stderr, "total %.2f s\n", seconds);
}

int runRobot(const RobotArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  auto format = sphereFormatFromPath(a.out_path);
  const std::string ext = std::filesystem::path(a.out_path).extension().string();
  if (ext != ".json" && ext != ".urdf" && (!format || *format != SphereFormat::kYaml))
    return fail(Error{ErrorCode::kInvalidArgument,
                      a.out_path + ": robot output is .yml/.yaml (cuRobo), .urdf or .json"});
  RobotLoadOptions lo;
  lo.package_paths = a.package_paths;
  auto robot = loadRobot(a.urdf, lo);
  if (!robot) return fail(robot.error());
  auto counts = namedValues<int>(a.link_spheres, *robot, "--link-spheres");
  if (!counts) return fail(counts.error());
  auto pads = namedValues<double>(a.link_padding, *robot, "--link-padding");
  if (!pads) return fail(pads.error());
  auto joints = parseJointPositions(a.joint_positions, *robot);
  if (!joints) return fail(joints.error());
  auto jobs = prepareLinks(a, *robot);
  if (!jobs) return fail(jobs.error());
  for (LinkJob& j : *jobs) {
    if (auto it = counts->find(j.link->name); it != counts->end()) j.fixed = it->second;
    if (j.fixed == 0) {
      j.skipped = true;
      j.primitives.clear();
    }
    auto p = pads->find(j.link->name);
    j.padding = p != pads->end() ? p->second : a.padding;
  }
  if (Status s = chooseCounts(a, &*jobs); !s) return fail(s.error());
  if (Status s = fitLinks(a, &*jobs); !s) return fail(s.error());
  std::vector<LinkSpheres> out;
  for (const LinkJob& j : *jobs)
    if (!j.skipped) out.push_back({j.link->name, j.spheres});
  Status st;
  if (ext == ".json") {
    st = writeTextFile(a.out_path, robotJson(a, *robot, *jobs).dump(1) + "\n");
  } else if (ext == ".urdf") {
    st = writeSphereUrdf(a.urdf, a.out_path, out);
  } else {
    // cuRobo's self_collision_ignore: adjacent links and links whose spheres overlap at the
    // pose given (zero by default).
    const SelfCollisionPairs pairs = selfCollisionPairs(*robot, out, *joints);
    SphereFileMeta meta;
    meta.source_mesh = a.urdf;
    st = writeRobotSpheres(a.out_path, out, &pairs, meta);
  }
  if (!st) return fail(st.error());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) std::cout << robotJson(a, *robot, *jobs).dump() << '\n';
  if (!a.quiet) printSummary(*jobs, seconds);
  for (const LinkJob& j : *jobs)
    if (!covered(j)) {
      std::cerr << "sphereset: " << a.urdf << ": link '" << j.link->name
                << "' failed the coverage check (written to " << a.out_path << " anyway)\n";
      return kUncovered;
    }
  return kOk;
}

}  // namespace

Command registerRobot(CLI::App& app) {
  auto a = std::make_shared<RobotArgs>();
  CLI::App* cmd =
      app.add_subcommand("robot", "Fit collision spheres to every link of a URDF robot");
  cmd->add_option("urdf", a->urdf, "Robot description (URDF)")->required();
  cmd->add_option("-o,--output", a->out_path,
                  "Output: .yml/.yaml (cuRobo collision_spheres and self_collision_ignore), "
                  ".urdf (the input with sphere collisions) or .json (per link)")
      ->required();
  cmd->add_option("--joint-positions", a->joint_positions,
                  "JOINT=VALUE,...: the pose at which overlapping links are listed for "
                  "self_collision_ignore (default: all joints at 0)");
  cmd->add_option("--package-path", a->package_paths,
                  "Folder searched for package://NAME/ paths (repeatable; then ROS_PACKAGE_PATH)");
  cmd->add_option("--budget", a->budget,
                  "Spheres over the whole robot, split by what lowers the total outside volume "
                  "most (default 0: 8 per link)")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--link-spheres", a->link_spheres,
                  "LINK=N: N spheres for this link (0 skips it); repeatable");
  cmd->add_option("--padding", a->padding, "Distance added to every radius")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--link-padding", a->link_padding, "LINK=D: padding for this link; repeatable");
  cmd->add_option("--seed", a->seed, "Seed for sampling and initialisation")->capture_default_str();
  cmd->add_option("--quality", a->quality, "fast, default or best")
      ->capture_default_str()
      ->check(CLI::IsMember({"fast", "default", "best"}));
  cmd->add_flag("-q,--quiet", a->quiet, "No summary on stderr");
  cmd->add_flag("--json", a->json, "Print the per-link summary as one JSON object on stdout");
  addRepairArgs(cmd, &a->repair);
  cmd->add_option("--weld-tolerance", a->repair.weld,
                  "Merge vertices closer than this distance (default: automatic)")
      ->check(CLI::NonNegativeNumber);
  return {cmd, [a] { return runRobot(*a); }};
}

}  // namespace sphereset::cli

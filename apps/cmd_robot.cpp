// sphereset robot: collision spheres for every link of a robot described by a URDF or an MJCF, in
// the link frames (fitRobot, robot_fit.hpp, does the fitting), and the link pairs a planner may
// skip, found by sampling the joint space (sampleSelfCollisions, robot_collision.hpp). Outputs, one
// or more (-o repeated), by the name's ending: cuRobo's YAML with the self-collision ignore list,
// Lula's robot description, MoveIt's SRDF, the URDF with sphere collisions, the robot as an MJCF
// with sphere geoms (MuJoCo), a JSON report.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/view.hpp"

namespace sphereset::cli {
namespace {

struct RobotArgs {
  std::string urdf, joint_positions;
  std::vector<std::string> outputs;
  TableArgs fit;        // --quality and --seed
  TableArgs robot;      // the rows of robotFitOptionTable()
  TableArgs collision;  // the rows of collisionSamplingOptionTable() but default_pose
  RobotLoadArgs load;
  MeshArgs repair;  // repair options only (no mesh path)
  bool quiet = false, json = false;
  bool best_effort = false;  // --best-effort: write what was found when a limit is not met
};

enum class RobotOutput { kCurobo, kLula, kSrdf, kUrdf, kMjcf, kJson, kHtml };

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The format of an output by its name's ending (letter case ignored): .lula.yml/.lula.yaml
// (Lula), .yml/.yaml (cuRobo), .srdf, .urdf, .xml (MJCF), .json, .html (the view's page, static).
Expected<RobotOutput> robotOutput(const std::string& path) {
  std::string name = path;
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (endsWith(name, ".lula.yml") || endsWith(name, ".lula.yaml")) return RobotOutput::kLula;
  if (endsWith(name, ".yml") || endsWith(name, ".yaml")) return RobotOutput::kCurobo;
  if (endsWith(name, ".srdf")) return RobotOutput::kSrdf;
  if (endsWith(name, ".urdf")) return RobotOutput::kUrdf;
  if (endsWith(name, ".xml")) return RobotOutput::kMjcf;
  if (endsWith(name, ".json")) return RobotOutput::kJson;
  if (endsWith(name, ".html")) return RobotOutput::kHtml;
  return Error{ErrorCode::kInvalidArgument,
               path +
                   ": robot output is .yml/.yaml (cuRobo), .lula.yml/.lula.yaml (Lula), "
                   ".srdf, .urdf, .xml (MJCF), .json or .html"};
}

nlohmann::json collisionJson(const CollisionMatrix& m) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const DisabledPair& p : m.disabled)
    pairs.push_back({{"link1", p.link1},
                     {"link2", p.link2},
                     {"reason", disableReasonName(p.reason)},
                     {"collisions", p.collisions}});
  return {{"samples", m.samples},
          {"check", m.check == CollisionCheck::kMeshes ? "meshes" : "spheres"},
          {"pairs", m.pairs},
          {"enabled", m.enabled},
          {"adjacent", m.count(DisableReason::kAdjacent)},
          {"default", m.count(DisableReason::kDefault)},
          {"always", m.count(DisableReason::kAlways)},
          {"never", m.count(DisableReason::kNever)},
          {"seconds", m.seconds},
          {"disabled", pairs}};
}

nlohmann::json robotJson(const RobotArgs& a, const Robot& robot, const RobotFitResult& r,
                         const RobotFitOptions& fo, const CollisionMatrix& m) {
  nlohmann::json links = nlohmann::json::array();
  for (const RobotLinkFit& j : r.links) {
    nlohmann::json l = fieldsJson(robotLinkFields(j));
    nlohmann::json s = nlohmann::json::array();
    for (const Sphere& sp : j.spheres)
      s.push_back({sp.center.x(), sp.center.y(), sp.center.z(), sp.radius});
    l["spheres"] = s;
    if (j.fitted) l["repair"] = repairJson(j.repair);
    links.push_back(l);
  }
  nlohmann::json out = fieldsJson(robotFitFields(r));
  out["robot"] = robot.name;
  out["urdf"] = a.urdf;
  out["seed"] = fo.seed;
  out["budget"] = fo.budget;
  out["links"] = links;
  out["self_collision"] = collisionJson(m);
  return out;
}

void printSummary(const RobotFitResult& r, const CollisionMatrix& m, double seconds) {
  std::fprintf(stderr, "%-28s %9s %-10s %9s %7s %9s %9s %10s %7s %7s\n", "link", "triangles",
               "repair", "openings", "spheres", "E_r", "E_r walls", "protrusion", "covered",
               "time s");
  for (const RobotLinkFit& j : r.links)
    std::fprintf(stderr, "%-28s %9zu %-10s %9.3g %7zu %9.4f %9.4f %10.4g %7s %7.2f\n",
                 j.link.c_str(), j.fitted ? j.repair.original.triangles.size() : size_t{0},
                 j.fitted ? repairName(j.repair.kind) : "-", j.repair.fill_openings,
                 j.spheres.size(), j.fitted ? j.eval.er_sum : 0.0, j.fitted ? j.eval.er_walls : 0.0,
                 j.fitted ? j.eval.protrusion + j.padding : 0.0,
                 j.skipped   ? "skipped"
                 : j.covered ? "yes"
                             : "NO",
                 j.seconds);
  for (const RobotLinkFit& j : r.links)
    if (j.from_visual)
      std::fprintf(stderr, "%s: no <collision> geometry, its <visual> geometry was used\n",
                   j.link.c_str());
  if (r.tolerance)
    for (const RobotLinkFit& j : r.links)
      if (j.protrusion_limit > 0.0)
        std::fprintf(stderr, "%s: protrusion %.4g of its limit %.4g: %s\n", j.link.c_str(),
                     j.eval.protrusion + j.padding, j.protrusion_limit,
                     j.limit_met ? "met" : "NOT met");
  if (r.budget_split)
    std::fprintf(stderr,
                 "budget: outside volume %.6g of the links it split (split by curves %.6g)\n",
                 r.outside_volume, r.split_outside_volume);
  std::fprintf(stderr,
               "E_r is against each link's fitted solid: its envelope when openings is above 0 "
               "(openings narrower than that closed, the hollow behind them inside), else its "
               "walls; --link-solid-for LINK=walls|envelope decides a link\n");
  std::fprintf(stderr,
               "self-collision: %lld adjacent, %lld default, %lld always, %lld never, %lld of %lld "
               "pairs left to check (%d configurations on the %s, %.2f s)\n",
               static_cast<long long>(m.count(DisableReason::kAdjacent)),
               static_cast<long long>(m.count(DisableReason::kDefault)),
               static_cast<long long>(m.count(DisableReason::kAlways)),
               static_cast<long long>(m.count(DisableReason::kNever)),
               static_cast<long long>(m.enabled), static_cast<long long>(m.pairs), m.samples,
               m.check == CollisionCheck::kMeshes ? "link solids" : "spheres", m.seconds);
  std::fprintf(stderr, "total %.2f s\n", seconds);
}

// The outputs' formats, each checked before any work: a known ending, not an input, not given
// twice, writable.
Expected<std::vector<RobotOutput>> checkOutputs(const RobotArgs& a) {
  std::vector<RobotOutput> formats;
  for (size_t i = 0; i < a.outputs.size(); ++i) {
    auto f = robotOutput(a.outputs[i]);
    if (!f) return f.error();
    formats.push_back(*f);
    if (Status st = checkOutputPath(a.outputs[i], {a.urdf}); !st) return st.error();
    // The same file again (through links and relative paths too) would lose the first.
    const std::vector<std::string> earlier(a.outputs.begin(),
                                           a.outputs.begin() + static_cast<std::ptrdiff_t>(i));
    if (!earlier.empty())
      if (Status st = checkOutputPath(a.outputs[i], earlier); !st)
        return Error{ErrorCode::kInvalidArgument, a.outputs[i] + ": given twice as an output"};
  }
  return formats;
}

Status writeRobotOutput(const RobotArgs& a, const std::string& path, RobotOutput format,
                        const Robot& robot, const RobotFitResult& fit, const RobotFitOptions& fo,
                        const std::vector<LinkSpheres>& spheres, const CollisionMatrix& matrix,
                        const CollisionSamplingOptions& co) {
  switch (format) {
    case RobotOutput::kJson:
      return writeTextFile(path, jsonText(robotJson(a, robot, fit, fo, matrix), 1) + "\n");
    case RobotOutput::kUrdf:
      return writeSphereUrdf(a.urdf, path, spheres);
    case RobotOutput::kMjcf:
      // <contact><exclude> for the pairs the sampling found never in contact (pairs in contact
      // somewhere, adjacent ones too, keep their contacts, as the geoms had them).
      return writeSphereMjcf(a.urdf, path, spheres, neverPairs(matrix), robotLoadOptions(a.load));
    case RobotOutput::kSrdf:
      return writeSrdf(path, robot, matrix);
    case RobotOutput::kLula:
      return writeLulaDescription(path, robot, spheres, co.default_pose);
    case RobotOutput::kHtml: {
      // The view's page of the fit, static: each link's spheres on the solid it was fitted to.
      ViewLoadOptions vo;
      vo.repair = fo.repair;
      vo.link_solid = fo.link_solid;
      vo.link_solid_for = fo.link_solid_for;
      auto scene = robotViewScene(robot, a.urdf, spheres, vo);
      if (!scene) return scene.error();
      auto page = viewStaticPage(*scene);
      if (!page) return page.error();
      return writeTextFile(path, *page);
    }
    case RobotOutput::kCurobo: {
      // cuRobo's self_collision_ignore: every pair the sampling disabled.
      const SelfCollisionPairs pairs = ignoredPairs(matrix);
      SphereFileMeta meta;
      meta.source_mesh = a.urdf;
      return writeRobotSpheres(path, spheres, &pairs, meta);
    }
  }
  return {};
}

int runRobot(const RobotArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  // The options first: a bad value is refused before anything is read.
  RobotFitOptions fo;
  for (const auto& [name, text] : a.robot.given())
    if (Status st = setRobotFitOption(&fo, name, text); !st) return fail(st.error());
  FitRequest request;
  for (const auto& [name, text] : a.fit.given())
    if (Status st = setFitRequestOption(&request, name, text); !st) return fail(st.error());
  fo.quality = request.quality;
  fo.seed = request.seed;
  CollisionSamplingOptions co;
  for (const auto& [name, text] : a.collision.given())
    if (Status st = setCollisionSamplingOption(&co, name, text); !st) return fail(st.error());
  auto repair = repairOptions(a.repair);
  if (!repair) return fail(repair.error());
  fo.repair = std::move(repair).value();
  if (Status st = checkRobotFitOptions(fo); !st) return fail(st.error());
  if (Status st = checkRobotBestEffort(a.best_effort, fo); !st) return fail(st.error());
  auto formats = checkOutputs(a);
  if (!formats) return fail(formats.error());
  if (std::find(formats->begin(), formats->end(), RobotOutput::kHtml) != formats->end())
    if (int code = requirePage(); code != kOk) return code;
  const RobotLoadOptions lo = robotLoadOptions(a.load);
  auto robot = loadRobot(a.urdf, lo);
  if (!robot) return fail(robot.error());
  auto joints = parseJointPositions(a.joint_positions, *robot);
  if (!joints) return fail(joints.error());
  co.default_pose = *joints;  // the default pose of the sampling and of Lula's default_q
  fo.name = a.urdf;
  ProgressLine progress("robot");
  if (!a.quiet) {
    fo.steps = [&progress](const RobotProgress& p) {
      progress.show(p.stage, p.done, p.total, p.link.empty() ? "" : "link " + p.link);
    };
    co.progress = fo.steps;
  }
  auto fit = fitRobot(*robot, fo);
  if (!fit) return fail(fit.error());
  if (fit->tolerance && !fit->tolerance_met) {
    // The links over their protrusion limit, with what they reached.
    std::string over;
    for (const RobotLinkFit& j : fit->links)
      if (!j.limit_met) {
        char text[160];
        std::snprintf(text, sizeof text, "%s%s %.4g > %.4g with %zu spheres",
                      over.empty() ? "" : ", ", j.link.c_str(), j.eval.protrusion + j.padding,
                      j.protrusion_limit, j.spheres.size());
        over += text;
      }
    std::fprintf(
        stderr, "sphereset: %s: the protrusion limit is not met (%s)%s\n", a.urdf.c_str(),
        over.c_str(),
        a.best_effort ? "; the spheres found are written (--best-effort)" : "; nothing written");
    if (!a.best_effort) return kToleranceNotMet;
  }
  std::vector<LinkSpheres> out;
  for (const RobotLinkFit& j : fit->links)
    if (!j.skipped) out.push_back({j.link, j.spheres});
  const std::vector<CollisionSolid> solids = co.check == CollisionCheck::kMeshes
                                                 ? fitCollisionSolids(*robot, *fit)
                                                 : std::vector<CollisionSolid>{};
  auto matrix = sampleSelfCollisions(*robot, out, co, solids);
  if (!matrix) return fail(matrix.error());
  // All or nothing: every output written (and checked by its writer) beside its place under a
  // temporary name (ending as it does: writers go by the ending), then each renamed into place; a
  // refusal leaves none of them. (A rename in the folder just written to is not expected to fail;
  // if one does, the outputs renamed before it stay.)
  std::vector<std::string> parts;
  auto dropParts = [&] {
    std::error_code ec;
    for (const std::string& p : parts) std::filesystem::remove(p, ec);
  };
  for (size_t i = 0; i < a.outputs.size(); ++i) {
    const std::filesystem::path target(a.outputs[i]);
    parts.push_back((target.parent_path() /
                     ("." + target.filename().string() + ".partial" + target.extension().string()))
                        .string());
    if (Status st =
            writeRobotOutput(a, parts.back(), (*formats)[i], *robot, *fit, fo, out, *matrix, co);
        !st) {
      dropParts();
      // The writer names the temporary file; the user knows the output's name.
      std::string message = st.error().message;
      for (size_t at = message.find(parts.back()); at != std::string::npos;
           at = message.find(parts.back(), at + a.outputs[i].size()))
        message.replace(at, parts.back().size(), a.outputs[i]);
      return fail(Error{st.error().code, message});
    }
  }
  for (size_t i = 0; i < a.outputs.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(parts[i], a.outputs[i], ec);
    if (ec) {
      dropParts();
      return fail(Error{ErrorCode::kWriteFailed, a.outputs[i] + ": cannot write: " + ec.message()});
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) std::cout << jsonText(robotJson(a, *robot, *fit, fo, *matrix)) << '\n';
  if (!a.quiet) printSummary(*fit, *matrix, seconds);
  if (fit->tolerance && !fit->tolerance_met) return kToleranceNotMet;
  for (const RobotLinkFit& j : fit->links)
    if (!j.covered) {
      std::string written;
      for (const std::string& o : a.outputs) written += (written.empty() ? "" : ", ") + o;
      std::cerr << "sphereset: " << a.urdf << ": link '" << j.link
                << "' failed the coverage check (written to " << written << " anyway)\n";
      return kUncovered;
    }
  return kOk;
}

}  // namespace

Command registerRobot(CLI::App& app) {
  auto a = std::make_shared<RobotArgs>();
  CLI::App* cmd =
      app.add_subcommand("robot", "Fit collision spheres to every link of a URDF or MJCF robot");
  cmd->add_option("urdf", a->urdf, "Robot description (.urdf, or .xml: an MJCF read by MuJoCo)")
      ->required();
  cmd->add_option(
         "-o,--output", a->outputs,
         "Output, repeatable (one fit, several files), by the name's ending: "
         ".yml/.yaml (cuRobo collision_spheres and self_collision_ignore), "
         ".lula.yml/.lula.yaml (Lula robot description), .srdf (MoveIt: chain group "
         "and disable_collisions), .urdf (the input with sphere collisions), .xml (MJCF: the "
         "robot with sphere geoms, as MuJoCo loads it, and <contact><exclude> for the "
         "pairs found never in contact), .json "
         "(per link, and the self-collision pairs) or .html (a page of the robot and "
         "its spheres with their certificates, as `sphereset view --html` writes it)")
      ->required()
      ->allow_extra_args(false);
  cmd->add_option("--joint-positions", a->joint_positions,
                  "JOINT=VALUE,...: the default pose (rad or m): its collisions are disabled as "
                  "\"Default\", and it is Lula's default_q (default: all joints at 0)");
  addRobotLoadArgs(cmd, &a->load, "");
  addTableOptions(cmd, &a->robot, robotFitOptionTable());
  cmd->add_flag("--best-effort", a->best_effort,
                "When a protrusion limit is not met: write the spheres found anyway (the exit "
                "code is still 10)");
  // The sampling of self-collision pairs; its default pose is --joint-positions.
  addTableOptions(cmd, &a->collision, collisionSamplingOptionTable(), {"default_pose"});
  // --quality and --seed: the fit table's rows, parsed by the library.
  addTableOptions(cmd, &a->fit, fitRequestOptions(),
                  {"n", "points", "iterations", "restarts", "decimation", "padding", "optimizer",
                   "init", "method"});
  cmd->add_flag("-q,--quiet", a->quiet, "No progress and no summary on stderr");
  cmd->add_flag("--json", a->json, "Print the per-link summary as one JSON object on stdout");
  addRepairArgs(cmd, &a->repair);
  return {cmd, [a] { return runRobot(*a); }};
}

}  // namespace sphereset::cli

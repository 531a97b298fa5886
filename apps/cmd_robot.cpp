// sphereset robot: collision spheres for every link of a robot described by a URDF, in the link
// frames (fitRobot, robot_fit.hpp, does the fitting). Outputs: cuRobo's YAML with the
// self-collision ignore list, the URDF with sphere collisions, or a JSON report.
#include <algorithm>
#include <chrono>
#include <cmath>
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
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

struct RobotArgs {
  std::string urdf, out_path, joint_positions;
  TableArgs fit;    // --quality and --seed
  TableArgs robot;  // the rows of robotFitOptionTable()
  std::vector<std::string> package_paths;
  MeshArgs repair;  // repair options only (no mesh path)
  bool quiet = false, json = false;
};

nlohmann::json robotJson(const RobotArgs& a, const Robot& robot, const RobotFitResult& r,
                         const RobotFitOptions& fo) {
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
  return out;
}

void printSummary(const RobotFitResult& r, double seconds) {
  std::fprintf(stderr, "%-28s %9s %-10s %9s %7s %9s %9s %7s %7s\n", "link", "triangles", "repair",
               "openings", "spheres", "E_r", "E_r walls", "covered", "time s");
  for (const RobotLinkFit& j : r.links)
    std::fprintf(stderr, "%-28s %9zu %-10s %9.3g %7zu %9.4f %9.4f %7s %7.2f\n", j.link.c_str(),
                 j.fitted ? j.repair.original.triangles.size() : size_t{0},
                 j.fitted ? repairName(j.repair.kind) : "-", j.repair.fill_openings,
                 j.spheres.size(), j.fitted ? j.eval.er_sum : 0.0, j.fitted ? j.eval.er_walls : 0.0,
                 j.skipped   ? "skipped"
                 : j.covered ? "yes"
                             : "NO",
                 j.seconds);
  for (const RobotLinkFit& j : r.links)
    if (j.from_visual)
      std::fprintf(stderr, "%s: no <collision> geometry, its <visual> geometry was used\n",
                   j.link.c_str());
  if (r.budget_split)
    std::fprintf(stderr,
                 "budget: outside volume %.6g of the links it split (split by curves %.6g, "
                 "even split %.6g)\n",
                 r.outside_volume, r.split_outside_volume, r.even_outside_volume);
  std::fprintf(stderr,
               "E_r is against each link's fitted solid: its envelope when openings is above 0 "
               "(openings narrower than that closed, the hollow behind them inside), else its "
               "walls\n");
  std::fprintf(stderr, "total %.2f s\n", seconds);
}

int runRobot(const RobotArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  auto format = sphereFormatFromPath(a.out_path);
  const std::string ext = std::filesystem::path(a.out_path).extension().string();
  // The options first: a bad value is refused before anything is read.
  RobotFitOptions fo;
  for (const auto& [name, text] : a.robot.given())
    if (Status st = setRobotFitOption(&fo, name, text); !st) return fail(st.error());
  FitRequest request;
  for (const auto& [name, text] : a.fit.given())
    if (Status st = setFitRequestOption(&request, name, text); !st) return fail(st.error());
  fo.quality = request.quality;
  fo.seed = request.seed;
  auto repair = repairOptions(a.repair);
  if (!repair) return fail(repair.error());
  fo.repair = std::move(repair).value();
  if (Status st = checkRobotFitOptions(fo); !st) return fail(st.error());
  if (ext != ".json" && ext != ".urdf" && (!format || *format != SphereFormat::kYaml))
    return fail(Error{ErrorCode::kInvalidArgument,
                      a.out_path + ": robot output is .yml/.yaml (cuRobo), .urdf or .json"});
  if (Status st = checkOutputPath(a.out_path, {a.urdf}); !st) return fail(st.error());
  RobotLoadOptions lo;
  lo.package_paths = a.package_paths;
  auto robot = loadRobot(a.urdf, lo);
  if (!robot) return fail(robot.error());
  auto joints = parseJointPositions(a.joint_positions, *robot);
  if (!joints) return fail(joints.error());
  fo.name = a.urdf;
  auto fit = fitRobot(*robot, fo);
  if (!fit) return fail(fit.error());
  std::vector<LinkSpheres> out;
  for (const RobotLinkFit& j : fit->links)
    if (!j.skipped) out.push_back({j.link, j.spheres});
  Status st;
  if (ext == ".json") {
    st = writeTextFile(a.out_path, jsonText(robotJson(a, *robot, *fit, fo), 1) + "\n");
  } else if (ext == ".urdf") {
    st = writeSphereUrdf(a.urdf, a.out_path, out);
  } else {
    // cuRobo's self_collision_ignore: adjacent links and links whose spheres overlap at the
    // pose given (zero by default).
    auto pairs = selfCollisionPairs(*robot, out, *joints);
    if (!pairs) return fail(pairs.error());
    SphereFileMeta meta;
    meta.source_mesh = a.urdf;
    st = writeRobotSpheres(a.out_path, out, &*pairs, meta);
  }
  if (!st) return fail(st.error());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) std::cout << jsonText(robotJson(a, *robot, *fit, fo)) << '\n';
  if (!a.quiet) printSummary(*fit, seconds);
  for (const RobotLinkFit& j : fit->links)
    if (!j.covered) {
      std::cerr << "sphereset: " << a.urdf << ": link '" << j.link
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
  addTableOptions(cmd, &a->robot, robotFitOptionTable());
  // --quality and --seed: the fit table's rows, parsed by the library.
  addTableOptions(cmd, &a->fit, fitRequestOptions(),
                  {"n", "points", "iterations", "restarts", "decimation", "padding", "optimizer",
                   "init", "method"});
  cmd->add_flag("-q,--quiet", a->quiet, "No summary on stderr");
  cmd->add_flag("--json", a->json, "Print the per-link summary as one JSON object on stdout");
  addRepairArgs(cmd, &a->repair);
  return {cmd, [a] { return runRobot(*a); }};
}

}  // namespace sphereset::cli

// sphereset eval: measures how tightly a sphere set (or each level of a tree) bounds a mesh.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::cli {
namespace {

struct EvalArgs {
  MeshArgs mesh;
  std::string spheres_path, link;
  RobotLoadArgs load;  // MESH a robot: where its package:// meshes are, its collision group
  TableArgs eval;      // the rows of evalOptionTable()
  TableArgs robot;     // the robot table's link_solid(_for) rows
  bool json = false;
};

nlohmann::json evalJson(const EvalResult& r, size_t count) {
  nlohmann::json j = fieldsJson(evalResultFields(r));
  j["spheres"] = count;
  return j;
}

void printEval(const EvalResult& r, const EvalOptions& eo) {
  std::printf("  E_r summed       %.6f   (exact: sum of outside volumes / mesh volume)\n",
              r.er_sum);
  std::printf("  E_r union        %.6f +- %.6f (Monte Carlo, %lld samples)\n", r.er_union,
              r.er_union_stderr, static_cast<long long>(eo.union_samples));
  std::printf("  surface covered  %s (max gap %.3g of the diagonal, %lld triangles not covered)\n",
              r.surface_covered ? "yes" : "no", r.max_surface_gap,
              static_cast<long long>(r.uncovered_triangles));
  std::printf("  interior covered %s (max gap %.3g of the diagonal)\n",
              r.interior_covered ? "yes" : "no", r.max_interior_gap);
  if (eo.original)
    std::printf(
        "  original covered %s (max gap %.3g of the diagonal, %lld triangles not covered)\n",
        r.original_covered ? "yes" : "no", r.max_original_gap,
        static_cast<long long>(r.original_uncovered_triangles));
  if (r.protrusion_sphere >= 0)
    std::printf(
        "  protrusion       %.6g certified (%.4g of the diagonal); a point %.6g out in sphere "
        "%d at (%.6g, %.6g, %.6g)\n",
        r.protrusion, r.protrusion / r.bbox_diagonal, r.protrusion_witness_distance,
        r.protrusion_sphere, r.protrusion_witness.x(), r.protrusion_witness.y(),
        r.protrusion_witness.z());
  std::printf("  proximity error  %.6f of the diagonal (%d segments)\n", r.proximity_error,
              eo.proximity_segments);
  if (eo.shadow_resolution > 0)
    std::printf(
        "  shadow error     %.6f sky light, %.6f per light (RMS irradiance, %d² pixels, "
        "%d lights)\n",
        r.shadow_error_sky, r.shadow_error_lights, eo.shadow_resolution, eo.shadow_lights);
  std::printf("  time             %.2f s\n", r.seconds);
}

int runEval(EvalArgs a) {
  EvalOptions eo;
  for (const auto& [name, text] : a.eval.given())
    if (Status st = setEvalOption(&eo, name, text); !st) return fail(st.error());
  const std::string& spheres_path = a.spheres_path;
  // MESH may be a URDF: the --link's collision geometry is then measured, placed in the link
  // frame and repaired as the robot command does.
  Expected<SolidInput> m = Error{ErrorCode::kInvalidArgument, ""};
  if (isRobotDescriptionPath(a.mesh.path)) {
    if (a.link.empty())
      return fail(Error{ErrorCode::kInvalidArgument,
                        a.mesh.path + ": a URDF needs --link LINK (the link to measure)"});
    const RobotLoadOptions lo = robotLoadOptions(a.load);
    auto robot = loadRobot(a.mesh.path, lo);
    if (!robot) return fail(robot.error());
    const RobotLink* link = nullptr;
    for (const RobotLink& l : robot->links)
      if (l.name == a.link) link = &l;
    if (!link)
      return fail(Error{ErrorCode::kInvalidArgument,
                        a.mesh.path + ": no link '" + a.link + "' in " + robot->name});
    auto repair = repairOptions(a.mesh);
    if (!repair) return fail(repair.error());
    // The link's solid as the robot command makes it: its --link-solid and --link-solid-for
    // (the robot table's rows).
    RobotFitOptions ro;
    for (const auto& [name, text] : a.robot.given())
      if (Status st = setRobotFitOption(&ro, name, text); !st) return fail(st.error());
    if (Status st = checkLinkSolids(*robot, *repair, ro.link_solid, ro.link_solid_for, a.mesh.path);
        !st)
      return fail(st.error());
    m = linkSolid(*link, linkRepairOptions(*repair, ro.link_solid, ro.link_solid_for, a.link),
                  a.mesh.path + ": link '" + a.link + "'");
  } else {
    m = loadSolid(a.mesh);
  }
  if (!m) return fail(m.error());
  // A tree file gets one report per level (root first); a plain set one report; --link picks
  // one link of a file of several (a robot's YAML) and reports it as a plain set.
  std::vector<std::vector<Sphere>> sets;
  bool is_tree = false;
  if (!a.link.empty()) {
    auto links = readLinkSpheres(spheres_path);
    if (!links) return fail(links.error());
    std::string names;
    for (const LinkSpheres& ls : *links) {
      if (ls.link == a.link) sets.push_back(ls.spheres);
      names += (names.empty() ? "" : ", ") + ls.link;
    }
    if (sets.empty())
      return fail(Error{ErrorCode::kInvalidArgument,
                        spheres_path + ": no link '" + a.link + "' (it has " + names + ")"});
  } else {
    auto tree_in = readSphereTree(spheres_path);
    if (!tree_in) return fail(tree_in.error());
    // Plain sets read as two-level trees; a JSON tree file does not read as a plain set.
    is_tree = tree_in->depth >= 2 || !readSpheres(spheres_path).ok();
    for (int l = is_tree ? 0 : tree_in->depth; l <= tree_in->depth; ++l)
      sets.push_back(tree_in->level(l));
  }
  const SolidIndex index(m->repair.solid);
  eo.original = m->original();
  eo.walls = m->walls();
  const std::string rl = repairLine(m->repair);
  if (!a.json && !rl.empty())
    std::printf(
        "%s: %s\n  E_r is relative to the repaired solid's volume; coverage is certified "
        "for the repaired solid and for the original triangles\n",
        a.mesh.path.c_str(), rl.c_str());
  nlohmann::json levels = nlohmann::json::array();
  for (int l = 0; l < static_cast<int>(sets.size()); ++l) {
    const std::vector<Sphere>& spheres = sets[l];
    if (spheres.empty()) return fail(Error{ErrorCode::kInvalidData, spheres_path + ": no spheres"});
    auto evaluated = evaluateSpheres(index, spheres, eo);
    if (!evaluated)
      return fail(Error{evaluated.error().code, spheres_path + ": " + evaluated.error().message});
    const EvalResult& r = *evaluated;
    if (a.json) {
      nlohmann::json j = evalJson(r, spheres.size());
      if (is_tree) j["level"] = l;
      levels.push_back(j);
    } else {
      if (is_tree)
        std::printf("%s, level %d of %s: %zu spheres\n", a.mesh.path.c_str(), l,
                    spheres_path.c_str(), spheres.size());
      else
        std::printf("%s with %zu spheres from %s\n", a.mesh.path.c_str(), spheres.size(),
                    spheres_path.c_str());
      printEval(r, eo);
    }
  }
  if (a.json) {
    nlohmann::json j = is_tree ? nlohmann::json{{"levels", levels}} : levels[0];
    j["mesh"] = a.mesh.path;
    j["repair"] = repairJson(m->repair);
    j["spheres_file"] = spheres_path;
    j["seed"] = eo.seed;
    std::cout << jsonText(j) << '\n';
  }
  return kOk;
}

}  // namespace

Command registerEval(CLI::App& app) {
  auto a = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Measure how tightly a sphere set bounds a mesh");
  addMeshArgs(cmd, &a->mesh);
  cmd->add_option("spheres", a->spheres_path, "Sphere set (.txt, .json, .sph, .yaml)")->required();
  cmd->add_option("--link", a->link,
                  "The link to measure, in a file of several (a robot's YAML from `robot`); "
                  "with a URDF as MESH, also the link whose geometry is measured");
  addRobotLoadArgs(cmd, &a->load, "With a robot as MESH: ");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  addTableOptions(cmd, &a->eval, evalOptionTable());
  // With a URDF as MESH: the link's solid, as `sphereset robot` takes it.
  addTableOptions(cmd, &a->robot, robotFitOptionTable(),
                  {"budget", "default_link_spheres", "link_spheres", "padding", "link_padding"});
  return {cmd, [a] { return runEval(*a); }};
}

}  // namespace sphereset::cli

// sphereset render: draws the mesh with the spheres over it, from several views, to a PNG.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/render.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::cli {
namespace {

struct RenderArgs {
  MeshArgs mesh;
  std::string spheres, out, size = "1200x900", views = "front,side,top,three-quarter", up = "y";
  std::vector<std::string> package_paths;
  std::string joint_positions;
  bool up_given = false;
  RenderOptions ro;
  bool no_ground = false;
};

// Completes the render options from the text options; kInvalidArgument for a bad size, view
// or output extension.
Status renderOptions(const RenderArgs& a, RenderOptions* ro) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(a.size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    return Error{ErrorCode::kInvalidArgument, "--size: expected WxH, got '" + a.size + "'"};
  ro->width = w;
  ro->height = h;
  ro->up_axis = a.up[0] - 'x';
  ro->ground = !a.no_ground;
  ro->views.clear();
  std::stringstream vs(a.views);
  for (std::string v; std::getline(vs, v, ',');) {
    if (v == "front")
      ro->views.push_back(View::kFront);
    else if (v == "side")
      ro->views.push_back(View::kSide);
    else if (v == "top")
      ro->views.push_back(View::kTop);
    else if (v == "three-quarter")
      ro->views.push_back(View::kThreeQuarter);
    else
      return Error{ErrorCode::kInvalidArgument, "--views: unknown view '" + v + "'"};
  }
  if (std::filesystem::path(a.out).extension().string() != ".png")
    return Error{ErrorCode::kInvalidArgument, a.out + ": the output must be .png"};
  return {};
}

// A robot posed by forward kinematics: every link's geometry and spheres (a file of per-link
// spheres in the link frames, e.g. robot's YAML) moved to the root frame.
int renderRobot(const RenderArgs& a, RenderOptions ro) {
  RobotLoadOptions lo;
  lo.package_paths = a.package_paths;
  auto robot = loadRobot(a.mesh.path, lo);
  if (!robot) return fail(robot.error());
  auto joints = parseJointPositions(a.joint_positions, *robot);
  if (!joints) return fail(joints.error());
  const auto poses = linkPoses(*robot, *joints);
  Mesh all;
  for (const RobotLink& link : robot->links) {
    const auto pose = poses.find(link.name);
    if (pose == poses.end()) continue;
    auto m = linkMesh(link);
    if (!m) return fail(Error{m.error().code, a.mesh.path + ": " + m.error().message});
    const auto base = static_cast<int32_t>(all.vertices.size());
    for (const Vec3& v : m->vertices) all.vertices.push_back(pose->second * v);
    for (Triangle t : m->triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  std::vector<Sphere> spheres;
  if (!a.spheres.empty()) {
    auto links = readLinkSpheres(a.spheres);
    if (!links) return fail(links.error());
    for (const LinkSpheres& ls : *links) {
      const auto pose = poses.find(ls.link);
      if (pose == poses.end())
        return fail(Error{ErrorCode::kInvalidData,
                          a.spheres + ": link '" + ls.link + "' is not a link of " + robot->name});
      for (const Sphere& s : ls.spheres) spheres.push_back({pose->second * s.center, s.radius});
    }
  }
  if (!a.up_given) ro.up_axis = 2;  // URDF frames are z-up
  const SolidIndex index(all);
  auto img = renderScene(all.triangles.empty() ? nullptr : &index, spheres, ro);
  if (!img) return fail(img.error());
  Status st = writePng(a.out, *img);
  if (!st) return fail(st.error());
  return kOk;
}

int runRender(const RenderArgs& a) {
  RenderOptions ro = a.ro;
  Status opts = renderOptions(a, &ro);
  if (!opts) return fail(opts.error());
  if (std::filesystem::path(a.mesh.path).extension() == ".urdf") return renderRobot(a, ro);
  // The mesh is drawn even when it is not a closed solid.
  LoadOptions lo;
  lo.weld_tolerance = std::max(0.0, a.mesh.weld);  // negative: the default, exact
  auto m = loadMesh(a.mesh.path, lo);
  if (!m) return fail(m.error());
  std::vector<Sphere> spheres;
  if (!a.spheres.empty()) {
    auto t = readSphereTree(a.spheres);
    if (!t) return fail(t.error());
    spheres = t->leaves();
  }
  const SolidIndex index(m->mesh);
  auto img = renderScene(&index, spheres, ro);
  if (!img) return fail(img.error());
  Status st = writePng(a.out, *img);
  if (!st) return fail(st.error());
  return kOk;
}

}  // namespace

Command registerRender(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Draw the mesh with the spheres over it, from several views, to a PNG");
  cmd->add_option("mesh", a->mesh.path,
                  "Mesh file, or a robot (.urdf) drawn posed with per-link spheres")
      ->required();
  cmd->add_option("--package-path", a->package_paths,
                  "Robot: folder searched for package://NAME/ paths (repeatable)");
  cmd->add_option("--joint-positions", a->joint_positions,
                  "Robot: JOINT=VALUE,... (default: all joints at 0)");
  cmd->add_option("--weld-tolerance", a->mesh.weld,
                  "Merge vertices closer than this (absolute units)");
  cmd->add_option("spheres", a->spheres, "Sphere set or tree (its leaves are drawn)");
  cmd->add_option("-o,--output", a->out, "PNG file")->required();
  cmd->add_option("--size", a->size, "Image size WxH")->capture_default_str();
  cmd->add_option("--views", a->views,
                  "Up to four of front, side, top, three-quarter, comma-separated")
      ->capture_default_str();
  cmd->add_option("--up", a->up, "Up axis (default y; z for a robot)")
      ->each([a](const std::string&) { a->up_given = true; })
      ->check(CLI::IsMember({"x", "y", "z"}));
  cmd->add_option("--opacity", a->ro.sphere_opacity, "Opacity of each sphere surface")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--no-ground", a->no_ground, "No ground plane");
  return {cmd, [a] { return runRender(*a); }};
}

}  // namespace sphereset::cli

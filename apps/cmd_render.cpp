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
#include "sphereset/animate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/render.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_query.hpp"
#include "sphereset/solid_index.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace sphereset::cli {
namespace {

struct RenderArgs {
  MeshArgs mesh;
  std::string spheres, out, size = "1200x900", views = "front,side,top,three-quarter", up = "y";
  RobotLoadArgs robot_load;
  std::string joint_positions, link;
  bool up_given = false;
  RenderOptions ro;
  bool no_ground = false;
  // One PNG per frame of a deforming mesh (see renderFrames).
  std::vector<std::string> frames;
  std::string animation, clip, spheres_dir;
  TableArgs load;  // the rows of skinnedLoadOptionTable() (--fps)
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
// spheres in the link frames, e.g. robot's YAML) moved to the root frame; or, with --link, one
// link alone in its own frame.
int renderRobot(const RenderArgs& a, RenderOptions ro) {
  const RobotLoadOptions lo = robotLoadOptions(a.robot_load);
  auto robot = loadRobot(a.mesh.path, lo);
  if (!robot) return fail(robot.error());
  auto joints = parseJointPositions(a.joint_positions, *robot);
  if (!joints) return fail(joints.error());
  std::vector<LinkSpheres> links;
  if (!a.spheres.empty()) {
    auto read = readLinkSpheres(a.spheres);
    if (!read) return fail(read.error());
    links = std::move(read).value();
    // The file's links checked against the robot, its name on the message.
    if (auto posed = posedLinkSpheres(*robot, links); !posed)
      return fail(Error{posed.error().code, a.spheres + ": " + posed.error().message});
  }
  auto scene =
      a.link.empty() ? robotScene(*robot, links, *joints) : linkScene(*robot, links, a.link);
  if (!scene) return fail(Error{scene.error().code, a.mesh.path + ": " + scene.error().message});
  if (!a.up_given) ro.up_axis = 2;  // URDF frames are z-up
  const SolidIndex index(scene->mesh);
  auto img = renderScene(scene->mesh.triangles.empty() ? nullptr : &index, scene->spheres, ro);
  if (!img) return fail(img.error());
  Status st = writePng(a.out, *img);
  if (!st) return fail(st.error());
  return kOk;
}

// The PNG of frame i: OUT's stem followed by _0000, _0001..., in OUT's folder.
std::string framePng(const std::string& out, size_t i) {
  const std::filesystem::path p(out);
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%04zu.png", i);
  return (p.parent_path() / (p.stem().string() + buf)).string();
}

// A deforming mesh, one PNG per frame: the rest mesh's triangles with each frame's vertices
// (--frames meshes in the rest mesh's vertex order, or a skinned asset's clip), and the spheres
// `animate` wrote for that frame (--spheres-dir), all seen by the same cameras. Everything is
// read before anything is written, and a failure removes what was written.
int renderFrames(const RenderArgs& a, const RenderOptions& ro) {
  auto lo = loadOptions(a.mesh);
  if (!lo) return fail(lo.error());
  SkinnedLoadOptions so;
  so.clip = a.clip;
  for (const auto& [name, text] : a.load.given())
    if (Status st = setSkinnedLoadOption(&so, name, text); !st) return fail(st.error());
  auto rest = loadMesh(a.mesh.path, *lo);
  if (!rest) return fail(rest.error());
  std::vector<std::vector<Vec3>> frames;
  if (!a.animation.empty()) {
    auto anim = loadAnimation(a.animation, so);
    if (!anim) return fail(anim.error());
    for (AnimationFrame& f : anim->frames) frames.push_back(std::move(f.vertices));
  } else {
    for (const std::string& path : a.frames) {
      auto m = loadMesh(path, *lo);
      if (!m) return fail(m.error());
      frames.push_back(std::move(m->mesh.vertices));
    }
  }
  for (size_t i = 0; i < frames.size(); ++i)
    if (frames[i].size() != rest->mesh.vertices.size())
      return fail(Error{ErrorCode::kInvalidData,
                        (a.animation.empty() ? a.frames[i] : a.animation) + ": frame " +
                            std::to_string(i) + " has " + std::to_string(frames[i].size()) +
                            " vertices, the rest mesh " + a.mesh.path + " has " +
                            std::to_string(rest->mesh.vertices.size())});
  std::vector<std::vector<Sphere>> spheres(frames.size());
  if (!a.spheres_dir.empty())
    for (size_t i = 0; i < frames.size(); ++i) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "frame_%04zu", i);
      std::filesystem::path p = std::filesystem::path(a.spheres_dir) / (std::string(buf) + ".json");
      if (!std::filesystem::exists(p)) p.replace_extension(".txt");
      auto s = readSpheres(p.string());
      if (!s) return fail(s.error());
      spheres[i] = std::move(s).value();
    }
  // One view for the whole motion: the cameras frame every frame's mesh and spheres.
  RenderOptions fo = ro;
  Aabb all;
  for (size_t i = 0; i < frames.size(); ++i) {
    for (const Vec3& v : frames[i]) all.extend(v);
    for (const Sphere& s : spheres[i]) {
      all.extend(s.center - Vec3::Constant(s.radius));
      all.extend(s.center + Vec3::Constant(s.radius));
    }
  }
  fo.bounds = all;
  // A failure part-way removes the frames already written: all of them or none.
  std::vector<std::string> written;
  auto undo = [&](const Error& e) {
    std::error_code ec;
    for (const std::string& w : written) std::filesystem::remove(w, ec);
    return fail(e);
  };
  for (size_t i = 0; i < frames.size(); ++i) {
    const Mesh m{frames[i], rest->mesh.triangles};
    const SolidIndex index(m);
    auto img = renderScene(&index, spheres[i], fo);
    if (!img) return undo(img.error());
    const std::string path = framePng(a.out, i);
    Status st = writePng(path, *img);
    if (!st) return undo(st.error());
    written.push_back(path);
  }
  return kOk;
}

int runRender(const RenderArgs& a) {
  RenderOptions ro = a.ro;
  Status opts = renderOptions(a, &ro);
  if (!opts) return fail(opts.error());
  if (Status st = checkOutputPath(a.out, {a.mesh.path, a.spheres, a.animation}); !st)
    return fail(st.error());
  if (!a.frames.empty() || !a.animation.empty()) return renderFrames(a, ro);
  if (!a.spheres_dir.empty())
    return fail(Error{ErrorCode::kInvalidArgument, "--spheres-dir needs --frames or --animation"});
  const bool urdf = isRobotDescriptionPath(a.mesh.path);
  if (urdf) return renderRobot(a, ro);
  if (!a.link.empty())
    return fail(Error{ErrorCode::kInvalidArgument, "--link needs a robot (.urdf)"});
  // The mesh is drawn even when it is not a closed solid.
  auto lo = loadOptions(a.mesh);
  if (!lo) return fail(lo.error());
  auto m = loadMesh(a.mesh.path, *lo);
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
  addRobotLoadArgs(cmd, &a->robot_load, "Robot: ");
  cmd->add_option("--joint-positions", a->joint_positions,
                  "Robot: JOINT=VALUE,... (default: all joints at 0)");
  cmd->add_option("--link", a->link, "Robot: draw this link alone, in its own frame");
  addWeldArg(cmd, &a->mesh);
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
  auto* frames = cmd->add_option(
      "--frames", a->frames,
      "Deformed meshes in the mesh's vertex order: one PNG per frame, OUT_0000.png...");
  auto* anim = cmd->add_option("--animation", a->animation,
                               "Skinned, animated asset: one PNG per frame of its clip");
  frames->excludes(anim);
  cmd->add_option("--clip", a->clip, "Animation clip (default: the first)")->needs(anim);
  addTableOptions(cmd, &a->load, skinnedLoadOptionTable());
  a->load.options.at("fps")->needs(anim);
  cmd->add_option("--spheres-dir", a->spheres_dir,
                  "Folder written by animate: frame_0000.json (or .txt)... drawn on the frames");
  return {cmd, [a] { return runRender(*a); }};
}

}  // namespace sphereset::cli

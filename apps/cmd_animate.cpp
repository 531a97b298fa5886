// sphereset animate: moves a sphere set fitted at the rest pose through the frames of a
// deforming mesh (paper Sec. 6), certifies each frame and optionally grows radii to restore
// exact coverage; one sphere file per frame plus a JSON summary.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sphereset/animate.hpp"
#include "sphereset/load.hpp"
#include "sphereset/sphere_io.hpp"

namespace sphereset::cli {
namespace {

struct AnimateArgs {
  std::string rest, spheres, out, animation, clip, format = "json";
  std::vector<std::string> frames;
  TableArgs animate;  // the rows of animateOptionTable()
  TableArgs load;     // the rows of skinnedLoadOptionTable() (--fps)
  MeshArgs weld;      // only the repair table's weld_tolerance row
  bool rebound = false, fresh_fit = false, quiet = false;
};

// The frames of the command line: deformed meshes with the rest mesh's vertices, or a skinned
// asset's clip.
struct Frames {
  std::vector<AnimationFrame> frames;
  SkinWeights skin;
  bool skinned = false;
  std::string clip;
};

// `rest` as loaded: the frames of --frames are read through its clean-up (loadFrameMesh).
Expected<Frames> readFrames(const AnimateArgs& a, const LoadedMesh& rest,
                            const SkinnedLoadOptions& so) {
  Frames out;
  if (!a.animation.empty()) {
    auto anim = loadAnimation(a.animation, so);
    if (!anim) return anim.error();
    // The frames and the skin follow the asset's own vertex order and triangles: the library
    // refuses a rest mesh that is not the asset's bind pose (skin.bind_pose).
    out.frames = std::move(anim->frames);
    out.skin = std::move(anim->asset.skin);
    out.skinned = true;
    out.clip = anim->clip;
    return out;
  }
  for (const std::string& path : a.frames) {
    auto f = loadFrameMesh(path, rest);
    if (!f) return f.error();
    f->time = static_cast<double>(out.frames.size());
    out.frames.push_back(std::move(f).value());
  }
  return out;
}

std::string frameName(size_t i, const std::string& ext) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%04zu.", i);
  return buf + ext;
}

int runAnimate(const AnimateArgs& a) {
  if (a.frames.empty() == a.animation.empty())
    return fail(Error{ErrorCode::kInvalidArgument, "give either --frames or --animation"});
  std::vector<std::string> inputs = a.frames;
  inputs.insert(inputs.end(), {a.rest, a.spheres, a.animation});
  if (Status st = checkOutputFolder(a.out, inputs); !st) return fail(st.error());
  auto lo = loadOptions(a.weld);
  if (!lo) return fail(lo.error());
  // The options before anything is read: the library's tables parse and check them.
  AnimateOptions o;
  for (const auto& [name, text] : a.animate.given())
    if (Status st = setAnimateOption(&o, name, text); !st) return fail(st.error());
  SkinnedLoadOptions so;
  so.clip = a.clip;
  for (const auto& [name, text] : a.load.given())
    if (Status st = setSkinnedLoadOption(&so, name, text); !st) return fail(st.error());
  auto rest = loadMesh(a.rest, *lo);
  if (!rest) return fail(rest.error());
  const MeshDiagnosis d = diagnoseMesh(rest->mesh);
  if (!d.isSolid()) return fail(notSolidError(a.rest, d));
  auto spheres = readSpheres(a.spheres);
  if (!spheres) return fail(spheres.error());
  if (spheres->empty())
    return fail(Error{ErrorCode::kInvalidData, a.spheres + ": the file holds no spheres"});
  auto frames = readFrames(a, *rest, so);
  if (!frames) return fail(frames.error());

  o.rebound = a.rebound;
  o.fresh_fit = a.fresh_fit;
  o.fit.restarts = 1;
  ProgressLine progress("animate");
  if (!a.quiet) o.progress = [&](int f, int n) { progress.show("frame", f + 1, n, ""); };
  auto res = animateSpheres(rest->mesh, *spheres, frames->frames, o,
                            frames->skinned ? &frames->skin : nullptr);
  if (!res) return fail(Error{res.error().code, a.rest + ": " + res.error().message});
  const bool bones = res->weighting == CentreWeighting::kBones;

  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (ec) return fail(Error{ErrorCode::kWriteFailed, a.out + ": " + ec.message()});
  const std::string ext = a.format == "txt" ? "txt" : "json";
  nlohmann::json js = nlohmann::json::array();
  SphereFileMeta meta;
  meta.source_mesh = a.rest;
  for (size_t i = 0; i < res->frames.size(); ++i) {
    const AnimateFrameResult& f = res->frames[i];
    const std::string name = frameName(i, ext);
    Status st = writeSpheres((std::filesystem::path(a.out) / name).string(), f.spheres, meta);
    if (!st) return fail(st.error());
    nlohmann::json j = fieldsJson(animateFrameFields(f));
    j["frame"] = i;
    j["time"] = f.time;
    j["file"] = name;
    js.push_back(j);
  }
  const size_t n = res->frames.size();
  nlohmann::json summary = fieldsJson(animateResultFields(*res));
  summary["rest_mesh"] = a.rest;
  summary["spheres"] = a.spheres;
  summary["sphere_count"] = spheres->size();
  summary["source"] = a.animation.empty() ? "frames" : a.animation;
  summary["rebound"] = a.rebound;
  summary["fraction_covered"] = n ? double(res->frames_covered) / double(n) : 0.0;
  summary["frames"] = js;
  if (!a.animation.empty()) summary["clip"] = frames->clip;
  Status st = writeTextFile((std::filesystem::path(a.out) / "summary.json").string(),
                            jsonText(summary, 2) + "\n");
  if (!st) return fail(st.error());
  if (!a.quiet)
    std::cerr << "animate: " << n << " frames, " << res->frames_covered
              << " covered with fixed radii (" << (bones ? "bone" : "mean value")
              << " weights), written to " << a.out << '\n';
  if (!a.quiet && res->frames_crossing > 0)
    std::cerr << "animate: " << res->frames_crossing
              << " frames pass through themselves (crossing triangles): their E_r and coverage "
                 "are not meaningful\n";
  return kOk;
}

}  // namespace

Command registerAnimate(CLI::App& app) {
  auto a = std::make_shared<AnimateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "animate", "Move a sphere set fitted at the rest pose through a deforming mesh's frames");
  cmd->add_option("rest", a->rest, "Rest-pose mesh the spheres were fitted to")->required();
  cmd->add_option("spheres", a->spheres, "Sphere set of the rest pose")->required();
  cmd->add_option("-o,--output", a->out, "Output folder (frame_0000.json..., summary.json)")
      ->required();
  auto* frames = cmd->add_option("--frames", a->frames,
                                 "Deformed meshes with the rest mesh's vertices in its order");
  auto* anim = cmd->add_option("--animation", a->animation,
                               "Skinned, animated asset (FBX, glTF, COLLADA, .x, SMD); its bind "
                               "pose must be the rest mesh");
  frames->excludes(anim);
  cmd->add_option("--clip", a->clip, "Animation clip (default: the first)")->needs(anim);
  addTableOptions(cmd, &a->load, skinnedLoadOptionTable());
  a->load.options.at("fps")->needs(anim);
  cmd->add_flag("--rebound", a->rebound,
                "Grow radii minimally per frame so that the deformed mesh is covered exactly");
  cmd->add_flag("--fresh-fit", a->fresh_fit,
                "Also fit a fresh set to every frame and report its E_r (slow)");
  cmd->add_option("--format", a->format, "Sphere files per frame")
      ->capture_default_str()
      ->check(CLI::IsMember({"txt", "json"}));
  addTableOptions(cmd, &a->animate, animateOptionTable());
  // The repair table's weld row (rest and frames alike; not given: exact welding).
  addWeldArg(cmd, &a->weld);
  cmd->add_flag("-q,--quiet", a->quiet, "No progress on stderr");
  return {cmd, [a] { return runAnimate(*a); }};
}

}  // namespace sphereset::cli

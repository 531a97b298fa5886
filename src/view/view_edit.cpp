// The changes a page makes to a view's scene (view.hpp): edits of a set, the bound, a tree's
// level, a robot's joints, and the save. Each checks everything first and changes nothing on
// an error; each change recertifies what it touched and counts one version.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/view.hpp"
#include "view/view_fit.hpp"

namespace sphereset {
namespace {

Error invalid(const std::string& message) { return Error{ErrorCode::kInvalidArgument, message}; }

// A solid whose set may change now: one of the scene's, not being fitted.
Expected<ViewSolid*> solidAt(ViewScene* scene, int64_t solid) {
  if (solid < 0 || solid >= static_cast<int64_t>(scene->solids.size()))
    return invalid("no solid " + std::to_string(solid) + " (the scene has " +
                   std::to_string(scene->solids.size()) + ")");
  if (Status st = checkNotFitting(*scene, solid); !st) return st.error();
  ViewSolid* s = &scene->solids[static_cast<size_t>(solid)];
  if (s->set != 0)
    return invalid("solid " + std::to_string(solid) + " is the compared set (" +
                   scene->set_names.back() + "): it is shown, not edited");
  return s;
}

Status checkEditSphere(const std::string& what, const Sphere& s) {
  return checkSphere(what, s, ErrorCode::kInvalidArgument);
}

// Edits of one request the incremental certificate takes one by one; more (a request of thousands
// of adds took 18 s at 8 000, each add rebuilding the certificate's sphere index) get one full
// certificate of the edited set, which costs about as much as a few dozen single edits.
constexpr size_t kMaxIncrementalEdits = 64;

// The certificate after `edits` (checked, and applied already to the stored set): the solid's
// incremental certificate takes them one by one, each re-judging only what its old and new
// spheres reach. A certificate shared with a copy of the scene, none (the set was empty), one
// that refuses an edit (the last sphere deleted), or more than kMaxIncrementalEdits edits get a
// full certificate of the set instead.
void certifyEdits(ViewSolid* solid, const std::vector<ViewEdit>& edits) {
  CoverageCertificate* engine =
      solid->engine.use_count() == 1 && edits.size() <= kMaxIncrementalEdits ? solid->engine.get()
                                                                             : nullptr;
  for (const ViewEdit& e : edits) {
    if (engine == nullptr) break;
    const int index = static_cast<int>(e.index);
    Status st;
    switch (e.op) {
      case ViewEdit::Op::kSet:
        st = engine->setSphere(index, e.sphere);
        break;
      case ViewEdit::Op::kAdd:
        st = engine->addSphere(e.sphere);
        break;
      case ViewEdit::Op::kDelete:
        st = engine->removeSphere(index);
        break;
    }
    if (!st) engine = nullptr;
  }
  if (engine == nullptr)
    certifyViewSolid(solid);
  else
    solid->certificate = viewCertificate(*solid);
}

// Each solid's pose from the joint values: its link's frame in the root's; a link the root does
// not reach stays at the identity.
void updatePoses(ViewScene* scene, const std::map<std::string, Eigen::Isometry3d>& links) {
  scene->poses.assign(scene->solids.size(), Eigen::Isometry3d::Identity());
  for (size_t i = 0; i < scene->solids.size(); ++i) {
    const auto it = links.find(scene->solids[i].link);
    if (it != links.end()) scene->poses[i] = it->second;
  }
}

// A tree's levels back in their slots, each level's set in the order of its used slots.
Expected<SphereTree> editedTree(const ViewSolid& solid) {
  SphereTree t = *solid.tree;
  for (int l = 0; l <= t.depth; ++l) {
    const std::vector<Sphere>& set = solid.sets[static_cast<size_t>(l)];
    size_t k = 0;
    for (int64_t slot = t.levelBegin(l); slot < t.levelBegin(l) + t.levelSize(l); ++slot)
      if (t.used(slot)) {
        if (k < set.size()) t.nodes[static_cast<size_t>(slot)] = set[k];
        ++k;
      }
    if (k != set.size())
      return invalid("level " + std::to_string(l) + " holds " + std::to_string(set.size()) +
                     " spheres, its layout " + std::to_string(k) +
                     ": a tree keeps its layout (save a set with --output SET.txt)");
  }
  return t;
}

}  // namespace

Status applyViewEdits(ViewScene* scene, int64_t solid, const std::vector<ViewEdit>& edits) {
  auto s = solidAt(scene, solid);
  if (!s) return s.error();
  std::vector<Sphere> set = (*s)->spheres();
  for (size_t e = 0; e < edits.size(); ++e) {
    const ViewEdit& edit = edits[e];
    const std::string what = "edit " + std::to_string(e);
    if (edit.op != ViewEdit::Op::kAdd &&
        (edit.index < 0 || edit.index >= static_cast<int64_t>(set.size())))
      return invalid(what + ": no sphere " + std::to_string(edit.index) + " (the set has " +
                     std::to_string(set.size()) + ")");
    if (edit.op != ViewEdit::Op::kDelete)
      if (Status st = checkEditSphere(what, edit.sphere); !st) return st;
    switch (edit.op) {
      case ViewEdit::Op::kSet:
        set[static_cast<size_t>(edit.index)] = edit.sphere;
        break;
      case ViewEdit::Op::kAdd:
        if (set.size() >= static_cast<size_t>(limits::kMaxSpheres))
          return invalid(what + ": more than " + std::to_string(limits::kMaxSpheres) + " spheres");
        set.push_back(edit.sphere);
        break;
      case ViewEdit::Op::kDelete:
        set.erase(set.begin() + edit.index);
        break;
    }
  }
  (*s)->sets[static_cast<size_t>((*s)->level)] = std::move(set);
  certifyEdits(*s, edits);
  ++scene->version;
  return {};
}

Status boundViewSolid(ViewScene* scene, int64_t solid) {
  auto s = solidAt(scene, solid);
  if (!s) return s.error();
  BoundOptions bo;
  bo.original = (*s)->input->original();
  auto bounded = boundSpheres(*(*s)->index, (*s)->spheres(), bo);
  if (!bounded) return bounded.error();
  replaceViewSet(*s, std::move(bounded).value());
  ++scene->version;
  return {};
}

Status setViewLevel(ViewScene* scene, int64_t solid, int64_t level) {
  auto s = solidAt(scene, solid);
  if (!s) return s.error();
  if (!(*s)->tree) return invalid("solid " + std::to_string(solid) + " is a set, not a tree");
  const auto levels = static_cast<int64_t>((*s)->sets.size());
  if (level < 0 || level >= levels)
    return invalid("no level " + std::to_string(level) + " (the tree has levels 0 to " +
                   std::to_string(levels - 1) + ")");
  (*s)->level = static_cast<int>(level);
  certifyViewSolid(*s);
  ++scene->version;
  return {};
}

Status setViewJoints(ViewScene* scene, const std::map<std::string, double>& joints) {
  if (!scene->robot) {
    if (joints.empty()) return {};
    return invalid("no joint '" + joints.begin()->first + "' (the scene is a mesh)");
  }
  std::map<std::string, double> input = scene->joint_input;
  for (const auto& [name, value] : joints) input[name] = value;
  auto state = jointState(*scene->robot, input);
  if (!state) return state.error();
  auto poses = linkPoses(*scene->robot, state->values);
  if (!poses) return poses.error();
  // What the user set, clamped as jointState clamped it (so that a slider shows the limit).
  for (auto& [name, value] : input) value = state->values.at(name);
  scene->joint_input = std::move(input);
  scene->joint_values = std::move(state->values);
  updatePoses(scene, *poses);
  ++scene->version;
  return {};
}

std::string viewSavePath(const ViewScene& scene, ViewSaveFormat format) {
  if (scene.save_path.empty() || format == scene.save_format) return scene.save_path;
  const char* ending = format == ViewSaveFormat::kRobotUrdf   ? ".urdf"
                       : format == ViewSaveFormat::kRobotMjcf ? ".xml"
                       : format == ViewSaveFormat::kRobotLula ? ".lula.yml"
                                                              : ".yml";
  std::filesystem::path p(scene.save_path);
  // A Lula name ends in two parts (robot.lula.yml): both go; other dots stay (my.robot.v2).
  std::string stem = p.stem().string();
  constexpr std::string_view kLula = ".lula";
  if (stem.size() > kLula.size() &&
      stem.compare(stem.size() - kLula.size(), kLula.size(), kLula) == 0)
    stem.resize(stem.size() - kLula.size());
  return (p.parent_path() / (stem + ending)).string();
}

std::vector<ViewSaveFormat> viewSaveFormats(const ViewScene& scene) {
  if (scene.save_path.empty()) return {};
  if (scene.kind != ViewKind::kRobot) return {scene.save_format};
  std::vector<ViewSaveFormat> out = {ViewSaveFormat::kRobotYaml, ViewSaveFormat::kRobotUrdf};
  if (mujocoAvailable()) out.push_back(ViewSaveFormat::kRobotMjcf);
  out.push_back(ViewSaveFormat::kRobotLula);
  if (std::find(out.begin(), out.end(), scene.save_format) == out.end())
    out.insert(out.begin(), scene.save_format);
  return out;
}

Expected<ViewSaveFormat> viewRobotSaveFormat(const std::string& name) {
  if (name == "yaml") return ViewSaveFormat::kRobotYaml;
  if (name == "urdf") return ViewSaveFormat::kRobotUrdf;
  if (name == "mjcf") return ViewSaveFormat::kRobotMjcf;
  if (name == "lula") return ViewSaveFormat::kRobotLula;
  return invalid("save: '" + name + "' is not a robot format (yaml, urdf, mjcf or lula)");
}

Expected<int64_t> saveViewScene(const ViewScene& scene, std::optional<ViewSaveFormat> as) {
  if (scene.save_path.empty())
    return Error{ErrorCode::kInvalidArgument,
                 scene.title +
                     ": this scene has no file to save to (start sphereset view with "
                     "--output FILE)"};
  const ViewSaveFormat format = as.value_or(scene.save_format);
  const auto formats = viewSaveFormats(scene);
  if (std::find(formats.begin(), formats.end(), format) == formats.end())
    return invalid(scene.title + ": this scene cannot be saved as " +
                   viewSaveFormatName(scene, format));
  const std::string path = viewSavePath(scene, format);
  if (path != scene.save_path) {
    if (Status st = checkOutputPath(path, scene.inputs); !st) return st.error();
  }
  Status st;
  switch (format) {
    case ViewSaveFormat::kSet:
      st = writeSpheres(path, scene.solids.at(0).spheres(), scene.save_meta);
      break;
    case ViewSaveFormat::kTree: {
      auto tree = editedTree(scene.solids.at(0));
      if (!tree) return tree.error();
      st = writeSphereTree(path, *tree, scene.save_meta);
      break;
    }
    case ViewSaveFormat::kRobotYaml:
    case ViewSaveFormat::kRobotUrdf:
    case ViewSaveFormat::kRobotMjcf:
    case ViewSaveFormat::kRobotLula: {
      const std::vector<LinkSpheres> links = viewLinkSpheres(scene);
      if (format == ViewSaveFormat::kRobotUrdf)
        st = writeSphereUrdf(scene.urdf_path, path, links);
      else if (format == ViewSaveFormat::kRobotLula)
        st = writeLulaDescription(path, *scene.robot, links, {});
      else if (format == ViewSaveFormat::kRobotMjcf)
        st = writeSphereMjcf(scene.urdf_path, path, links, {}, scene.robot_load);
      else if (!scene.save_source.empty() && format == scene.save_format)
        st = rewriteLinkSpheres(scene.save_source, path, links);
      else
        st = writeRobotSpheres(path, links, nullptr, scene.save_meta);
      break;
    }
  }
  if (!st) return st.error();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) return Error{ErrorCode::kWriteFailed, path + ": " + ec.message()};
  return static_cast<int64_t>(bytes);
}

}  // namespace sphereset

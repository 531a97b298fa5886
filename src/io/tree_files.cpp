// Sphere-tree files: Bradshaw's .sph layout (every slot of every level) and JSON with explicit
// parent and child links; a plain sphere set read as a tree is a root over its spheres.
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/atomic_write.hpp"
#include "io/json_text.hpp"
#include "io/sphere_formats.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"
#include "util/read_file.hpp"

namespace sphereset {

using detail::jsonInteger;
using detail::parseJson;
using detail::readFileText;

namespace {}  // namespace

Expected<SphereTree> readSphereTree(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readFileText(path);
  if (!text) return text.error();
  return detail::parseSphereTree(*format, *text, path);
}

std::string formatSphereTree(SphereFormat format, const SphereTree& tree,
                             const SphereFileMeta& meta) {
  std::ostringstream os;
  if (format == SphereFormat::kSph) {
    // Bradshaw's layout: "levels branching", then every slot of every level as
    // "x y z r error"; unused slots have radius -1. The error column is written as 0.
    os << tree.levels() << ' ' << tree.branching << '\n';
    for (const Sphere& s : tree.nodes)
      os << detail::formatNumber(s.center.x()) << ' ' << detail::formatNumber(s.center.y()) << ' '
         << detail::formatNumber(s.center.z()) << ' '
         << detail::formatNumber(s.radius < 0.0 ? -1.0 : s.radius) << " 0\n";
    return os.str();
  }
  // JSON: the used nodes with their Bradshaw slot as id, level, parent and children.
  nlohmann::json j;
  j["generator"] = meta.generator;
  if (!meta.source_mesh.empty()) j["source_mesh"] = meta.source_mesh;
  j["branching"] = tree.branching;
  j["depth"] = tree.depth;
  nlohmann::json nodes = nlohmann::json::array();
  for (int l = 0; l <= tree.depth; ++l) {
    const int64_t b = tree.levelBegin(l), e = b + tree.levelSize(l);
    for (int64_t n = b; n < e; ++n) {
      if (!tree.used(n)) continue;
      nlohmann::json node;
      node["id"] = n;
      node["level"] = l;
      node["center"] = {tree.nodes[n].center.x(), tree.nodes[n].center.y(),
                        tree.nodes[n].center.z()};
      node["radius"] = tree.nodes[n].radius;
      node["parent"] = n == 0 ? nlohmann::json(nullptr) : nlohmann::json((n - 1) / tree.branching);
      nlohmann::json ch = nlohmann::json::array();
      if (l < tree.depth)
        for (int i = 0; i < tree.branching; ++i)
          if (tree.used(tree.child(n, i))) ch.push_back(tree.child(n, i));
      node["children"] = ch;
      nodes.push_back(node);
    }
  }
  j["nodes"] = nodes;
  os << detail::jsonText(j, 1) << '\n';
  return os.str();
}

Status writeSphereTree(const std::string& path, const SphereTree& tree,
                       const SphereFileMeta& meta) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  if (*format != SphereFormat::kSph && *format != SphereFormat::kJson)
    return Error{ErrorCode::kInvalidArgument, path + ": a sphere tree is written as .sph or .json"};
  Status st = checkSphereTree(tree, std::numeric_limits<double>::infinity());
  if (!st) return st;
  for (size_t i = 0; i < tree.nodes.size(); ++i)
    if (tree.used(static_cast<int64_t>(i))) {
      st = checkSphere(path + ": node " + std::to_string(i), tree.nodes[i]);
      if (!st) return st;
    }
  return writeFileAtomically(path, formatSphereTree(*format, tree, meta));
}

namespace {

// A flat set as a two-level tree: its minimal enclosing ball over the spheres.
SphereTree flatTree(const std::vector<Sphere>& spheres) {
  SphereTree t;
  t.depth = 1;
  t.branching = std::max<int>(2, static_cast<int>(spheres.size()));
  t.nodes.assign(1 + t.branching, Sphere{Vec3::Zero(), -1.0});
  t.nodes[0] = minimalEnclosingBall(spheres);
  for (size_t i = 0; i < spheres.size(); ++i) t.nodes[1 + i] = spheres[i];
  return t;
}

// A tree as read, through the library's one entry for trees (structure only: files from other
// tools may hold parents that do not quite enclose their children; queries check that again).
Expected<SphereTree> checkedTree(SphereTree t, const std::string& path) {
  auto made = makeSphereTree(t.branching, t.depth, std::move(t.nodes),
                             std::numeric_limits<double>::infinity());
  if (!made) return Error{made.error().code, path + ": " + made.error().message};
  return made;
}

}  // namespace

namespace detail {

Expected<SphereTree> parseSphereTree(SphereFormat format, const std::string& text,
                                     const std::string& path) {
  std::istringstream in(text);
  SphereTree t;
  if (format == SphereFormat::kSph) {
    std::string line;
    int levels = 0, branch = 0;
    if (!std::getline(in, line) || !(std::istringstream(line) >> levels >> branch) || levels < 1 ||
        branch < 1)
      return Error{ErrorCode::kInvalidData, path + ":1: expected \"levels branching\""};
    t.branching = branch;
    t.depth = levels - 1;
    const int64_t slots = SphereTree::slotCount(branch, t.depth);
    if (slots < 0) return Error{ErrorCode::kInvalidData, path + ": sphere tree too large"};
    // Each slot takes a line of at least 8 bytes ("0 0 0 0\n"): reserve no more than that.
    t.nodes.reserve(
        static_cast<size_t>(std::min<int64_t>(slots, static_cast<int64_t>(text.size() / 8) + 1)));
    int lineno = 1;
    while (static_cast<int64_t>(t.nodes.size()) < slots) {
      if (!std::getline(in, line))
        return Error{ErrorCode::kInvalidData, path + ": truncated after " +
                                                  std::to_string(t.nodes.size()) + " of " +
                                                  std::to_string(slots) + " nodes"};
      ++lineno;
      Sphere s;
      if (!(std::istringstream(line) >> s.center.x() >> s.center.y() >> s.center.z() >> s.radius))
        return Error{ErrorCode::kInvalidData,
                     path + ":" + std::to_string(lineno) + ": expected x y z r"};
      if (!s.center.allFinite() || !std::isfinite(s.radius))
        return Error{ErrorCode::kInvalidData,
                     path + ":" + std::to_string(lineno) + ": NaN or infinite value"};
      if (s.radius <= 0.0) s = {Vec3::Zero(), -1.0};  // unused slot
      t.nodes.push_back(s);
    }
    return checkedTree(std::move(t), path);
  }
  if (format == SphereFormat::kJson) {
    auto parsed = parseJson(in, path);
    if (!parsed) return parsed.error();
    nlohmann::json& j = *parsed;
    if (j.is_object() && j.contains("nodes") && j.contains("branching") && j.contains("depth")) {
      try {
        const auto branching = jsonInteger(j["branching"], 1, std::numeric_limits<int>::max());
        if (!branching)
          return Error{ErrorCode::kInvalidData,
                       path + ": \"branching\" must be an integer from 1 to " +
                           std::to_string(std::numeric_limits<int>::max())};
        const auto depth = jsonInteger(j["depth"], 0, 26);
        if (!depth)
          return Error{ErrorCode::kInvalidData,
                       path + ": \"depth\" must be an integer from 0 to 26"};
        t.branching = static_cast<int>(*branching);
        t.depth = static_cast<int>(*depth);
        const int64_t slots = SphereTree::slotCount(t.branching, t.depth);
        if (slots < 0) return Error{ErrorCode::kInvalidData, path + ": sphere tree too large"};
        t.nodes.assign(slots, Sphere{Vec3::Zero(), -1.0});
        for (const auto& n : j["nodes"]) {
          const auto id = jsonInteger(n.at("id"), 0, slots - 1);
          if (!id)
            return Error{ErrorCode::kInvalidData,
                         path + ": node \"id\" " +
                             (n.at("id").is_number() ? n.at("id").dump() + " " : std::string()) +
                             "is not a slot of the layout (an integer from 0 to " +
                             std::to_string(slots - 1) + ")"};
          Sphere s;
          for (int k = 0; k < 3; ++k) s.center[k] = n.at("center").at(k).get<double>();
          s.radius = n.at("radius").get<double>();
          Status st = checkSphere(path + ": node " + std::to_string(*id), s);
          if (!st) return st.error();
          t.nodes[*id] = s;
        }
      } catch (const nlohmann::json::exception& e) {
        return Error{ErrorCode::kInvalidData, path + ": malformed sphere tree (" + e.what() + ")"};
      }
      return checkedTree(std::move(t), path);
    }
  }
  auto flat = parseSpheres(format, text, path);
  if (!flat) return flat.error();
  if (flat->empty()) return Error{ErrorCode::kInvalidData, path + ": no spheres"};
  return flatTree(*flat);
}

}  // namespace detail

}  // namespace sphereset

// Sphere-set and sphere-tree files: plain text, JSON, Bradshaw's .sph and cuRobo-style YAML.
// Writes are atomic (temporary file in the same directory, then rename).
#include "sphereset/sphere_io.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "io/sphere_formats.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/tree.hpp"

namespace sphereset {
namespace {

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

Status checkSphere(const std::string& where, const Sphere& s) {
  if (!s.center.allFinite() || !std::isfinite(s.radius))
    return Error{ErrorCode::kInvalidData, where + ": NaN or infinite value"};
  if (s.radius < 0.0) return Error{ErrorCode::kInvalidData, where + ": negative radius"};
  return {};
}

std::string num(double x) { return detail::formatNumber(x); }

// The JSON document read from `in` (the file `path`).
Expected<nlohmann::json> parseJson(std::istream& in, const std::string& path) {
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    return Error{ErrorCode::kUnreadable, path + ": invalid JSON (" + e.what() + ")"};
  }
  return j;
}

// A JSON number that is an integer in [lo, hi], written as an integer or as an integral
// float ("2.0"); anything else is nullopt. Converting first would be undefined behaviour for
// floats out of range and would wrap or truncate the others into valid-looking values.
std::optional<int64_t> jsonInteger(const nlohmann::json& v, int64_t lo, int64_t hi) {
  if (v.is_number_unsigned()) {
    const uint64_t u = v.get<uint64_t>();
    if (u > static_cast<uint64_t>(hi)) return std::nullopt;
    return static_cast<int64_t>(u);
  }
  if (v.is_number_integer()) {
    const int64_t i = v.get<int64_t>();
    if (i < lo || i > hi) return std::nullopt;
    return i;
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (!(d >= static_cast<double>(lo) && d <= static_cast<double>(hi)) || d != std::floor(d))
      return std::nullopt;
    return static_cast<int64_t>(d);
  }
  return std::nullopt;
}

}  // namespace

std::string detail::formatNumber(double x) {
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

Expected<SphereFormat> sphereFormatFromPath(const std::string& path) {
  const std::string ext = extensionOf(path);
  if (ext == ".txt" || ext == ".xyzr") return SphereFormat::kText;
  if (ext == ".json") return SphereFormat::kJson;
  if (ext == ".sph") return SphereFormat::kSph;
  if (ext == ".yaml" || ext == ".yml") return SphereFormat::kYaml;
  return Error{ErrorCode::kInvalidArgument, path + ": unknown sphere-set extension '" + ext +
                                                "' (use .txt, .json, .sph or .yaml)"};
}

std::string formatSpheres(SphereFormat format, const std::vector<Sphere>& spheres,
                          const SphereFileMeta& meta) {
  std::ostringstream os;
  switch (format) {
    case SphereFormat::kText:
      os << "# " << meta.generator << ": " << spheres.size() << " spheres, x y z r\n";
      for (const Sphere& s : spheres)
        os << num(s.center.x()) << ' ' << num(s.center.y()) << ' ' << num(s.center.z()) << ' '
           << num(s.radius) << '\n';
      break;
    case SphereFormat::kJson: {
      nlohmann::json j;
      j["generator"] = meta.generator;
      if (!meta.source_mesh.empty()) j["mesh"] = meta.source_mesh;
      j["count"] = spheres.size();
      j["spheres"] = nlohmann::json::array();
      for (const Sphere& s : spheres)
        j["spheres"].push_back(
            {{"center", {s.center.x(), s.center.y(), s.center.z()}}, {"radius", s.radius}});
      os << j.dump(2) << '\n';
      break;
    }
    case SphereFormat::kSph: {
      // Two levels (root + leaves), branching factor = number of spheres. Each node line is
      // "x y z r error"; the error column is not used and written as 0.
      const Sphere root = minimalEnclosingBall(spheres);
      os << 2 << ' ' << std::max<size_t>(spheres.size(), 1) << '\n';
      os << num(root.center.x()) << ' ' << num(root.center.y()) << ' ' << num(root.center.z())
         << ' ' << num(root.radius) << " 0\n";
      for (const Sphere& s : spheres)
        os << num(s.center.x()) << ' ' << num(s.center.y()) << ' ' << num(s.center.z()) << ' '
           << num(s.radius) << " 0\n";
      break;
    }
    case SphereFormat::kYaml:
      os << "# " << meta.generator << ": " << spheres.size() << " spheres\n";
      os << "collision_spheres:\n  " << detail::yamlMappingKey(meta.name, 2) << "\n";
      for (const Sphere& s : spheres)
        os << "    - \"center\": [" << num(s.center.x()) << ", " << num(s.center.y()) << ", "
           << num(s.center.z()) << "]\n      \"radius\": " << num(s.radius) << '\n';
      break;
  }
  return os.str();
}

Status writeFileAtomically(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  std::string name = ".";
  name += target.filename().string();
  name += ".XXXXXX";
  const std::string tmpl = (dir / name).string();
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed, path + ": cannot create a file in '" + dir.string() +
                                              "' (" + std::strerror(errno) + ")"};
  const std::string tmp(buf.data());
  size_t done = 0;
  while (done < contents.size()) {
    const ssize_t w = ::write(fd, contents.data() + done, contents.size() - done);
    if (w <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      std::remove(tmp.c_str());
      return Error{ErrorCode::kWriteFailed, path + ": write failed (" + why + ")"};
    }
    done += static_cast<size_t>(w);
  }
  fchmod(fd, 0644);
  if (::close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + why + ")"};
  }
  return {};
}

Status writeSpheres(const std::string& path, const std::vector<Sphere>& spheres,
                    const SphereFileMeta& meta) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  for (size_t i = 0; i < spheres.size(); ++i) {
    Status st = checkSphere(path + ": sphere " + std::to_string(i), spheres[i]);
    if (!st) return st;
  }
  return writeFileAtomically(path, formatSpheres(*format, spheres, meta));
}

namespace {

// A whole file as a string.
Expected<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::kUnreadable, path + ": cannot be opened for reading"};
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return Error{ErrorCode::kUnreadable, path + ": read error"};
  return text;
}

}  // namespace

Expected<std::vector<Sphere>> readSpheres(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readText(path);
  if (!text) return text.error();
  return detail::parseSpheres(*format, *text, path);
}

Expected<std::vector<LinkSpheres>> readLinkSpheres(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readText(path);
  if (!text) return text.error();
  return detail::parseLinkSpheres(*format, *text, path);
}

std::string formatLinkSpheres(const std::vector<LinkSpheres>& links, const SphereFileMeta& meta) {
  return detail::formatYamlLinks(links, meta);
}

Status writeLinkSpheres(const std::string& path, const std::vector<LinkSpheres>& links,
                        const SphereFileMeta& meta) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  if (*format != SphereFormat::kYaml)
    return Error{ErrorCode::kInvalidArgument,
                 path + ": the spheres of several links are written as YAML (.yaml or .yml)"};
  for (size_t l = 0; l < links.size(); ++l) {
    if (links[l].link.empty())
      return Error{ErrorCode::kInvalidArgument,
                   path + ": link " + std::to_string(l) + " has no name"};
    for (size_t k = 0; k < l; ++k)
      if (links[k].link == links[l].link)
        return Error{ErrorCode::kInvalidArgument,
                     path + ": link '" + links[l].link + "' appears twice"};
    for (size_t i = 0; i < links[l].spheres.size(); ++i) {
      Status st = checkSphere(path + ": link '" + links[l].link + "' sphere " + std::to_string(i),
                              links[l].spheres[i]);
      if (!st) return st;
    }
  }
  return writeFileAtomically(path, formatLinkSpheres(links, meta));
}

Expected<SphereTree> readSphereTree(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readText(path);
  if (!text) return text.error();
  return detail::parseSphereTree(*format, *text, path);
}

namespace detail {

Expected<std::vector<Sphere>> parseSpheres(SphereFormat format, const std::string& text,
                                           const std::string& path) {
  std::istringstream in(text);
  std::vector<Sphere> out;

  if (format == SphereFormat::kJson) {
    auto parsed = parseJson(in, path);
    if (!parsed) return parsed.error();
    nlohmann::json& j = *parsed;
    const nlohmann::json* list = &j;
    if (j.is_object()) {
      if (!j.contains("spheres"))
        return Error{ErrorCode::kInvalidData, path + ": no \"spheres\" array"};
      list = &j["spheres"];
    }
    if (!list->is_array())
      return Error{ErrorCode::kInvalidData, path + ": \"spheres\" is not an array"};
    for (size_t i = 0; i < list->size(); ++i) {
      const auto& e = (*list)[i];
      const std::string where = path + ": sphere " + std::to_string(i);
      if (!e.is_object() || !e.contains("center") || !e.contains("radius") ||
          !e["center"].is_array() || e["center"].size() != 3 || !e["radius"].is_number())
        return Error{ErrorCode::kInvalidData,
                     where + ": needs \"center\": [x, y, z] and \"radius\""};
      Sphere s;
      for (int k = 0; k < 3; ++k) {
        if (!e["center"][k].is_number())
          return Error{ErrorCode::kInvalidData, where + ": center is not numeric"};
        s.center[k] = e["center"][k].get<double>();
      }
      s.radius = e["radius"].get<double>();
      Status st = checkSphere(where, s);
      if (!st) return st.error();
      out.push_back(s);
    }
    return out;
  }

  std::string line;
  int lineno = 0;
  if (format == SphereFormat::kYaml) {
    // One link: a file with several is refused rather than merged into one set.
    auto links = parseYamlLinks(text, path);
    if (!links) return links.error();
    if (links->size() == 1) return std::move(links->front().spheres);
    if (links->empty())
      return Error{ErrorCode::kInvalidData, path + ": collision_spheres is empty"};
    std::string names;
    for (size_t i = 0; i < links->size() && i < 8; ++i) names += (i ? ", " : "") + (*links)[i].link;
    if (links->size() > 8) names += ", ...";
    return Error{ErrorCode::kInvalidData, path + ": " + std::to_string(links->size()) + " links (" +
                                              names + "); a sphere set is the spheres of one link"};
  }

  if (format == SphereFormat::kSph) {
    // The deepest level of the tree that has spheres.
    auto tree = parseSphereTree(format, text, path);
    if (!tree) return tree.error();
    for (int l = tree->depth; l >= 0; --l) {
      std::vector<Sphere> level = tree->level(l);
      if (!level.empty()) return level;
    }
    return out;
  }

  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream is(line);
    Sphere s;
    if (!(is >> s.center.x())) continue;  // blank line
    std::string extra;
    if (!(is >> s.center.y() >> s.center.z() >> s.radius) || (is >> extra))
      return Error{ErrorCode::kInvalidData,
                   path + ":" + std::to_string(lineno) + ": expected four numbers x y z r"};
    Status st = checkSphere(path + ":" + std::to_string(lineno), s);
    if (!st) return st.error();
    out.push_back(s);
  }
  return out;
}

Expected<std::vector<LinkSpheres>> parseLinkSpheres(SphereFormat format, const std::string& text,
                                                    const std::string& path) {
  if (format == SphereFormat::kYaml) return parseYamlLinks(text, path);
  // Other formats hold one set: one link, named after the file.
  auto spheres = parseSpheres(format, text, path);
  if (!spheres) return spheres.error();
  std::vector<LinkSpheres> out(1);
  out[0].link = std::filesystem::path(path).stem().string();
  out[0].spheres = std::move(spheres).value();
  return out;
}

}  // namespace detail

std::string formatSphereTree(SphereFormat format, const SphereTree& tree,
                             const SphereFileMeta& meta) {
  std::ostringstream os;
  if (format == SphereFormat::kSph) {
    // Bradshaw's layout: "levels branching", then every slot of every level as
    // "x y z r error"; unused slots have radius -1. The error column is written as 0.
    os << tree.levels() << ' ' << tree.branching << '\n';
    for (const Sphere& s : tree.nodes)
      os << num(s.center.x()) << ' ' << num(s.center.y()) << ' ' << num(s.center.z()) << ' '
         << num(s.radius < 0.0 ? -1.0 : s.radius) << " 0\n";
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
  os << j.dump(1) << '\n';
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
    return t;
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
      return t;
    }
  }
  auto flat = parseSpheres(format, text, path);
  if (!flat) return flat.error();
  if (flat->empty()) return Error{ErrorCode::kInvalidData, path + ": no spheres"};
  return flatTree(*flat);
}

}  // namespace detail
}  // namespace sphereset

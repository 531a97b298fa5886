// Sphere-set files: plain text, JSON, Bradshaw's .sph and cuRobo-style YAML (yaml_spheres.cpp),
// and the helpers every sphere-file reader shares. Sphere trees are in tree_files.cpp, the atomic
// write in atomic_write.cpp.
#include "sphereset/sphere_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "io/atomic_write.hpp"
#include "io/json_text.hpp"
#include "io/sphere_formats.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/sphere_tree.hpp"
#include "util/number_text.hpp"
#include "util/read_file.hpp"

namespace sphereset {

using detail::extensionOf;
using detail::parseJson;
using detail::readFileText;

namespace detail {

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

}  // namespace detail

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

namespace {
constexpr std::pair<SphereFormat, const char*> kFormatNames[] = {
    {SphereFormat::kText, "txt"},
    {SphereFormat::kJson, "json"},
    {SphereFormat::kSph, "sph"},
    {SphereFormat::kYaml, "yaml"},
};
}  // namespace

const char* sphereFormatName(SphereFormat format) {
  for (const auto& [f, name] : kFormatNames)
    if (f == format) return name;
  return "txt";
}

Expected<SphereFormat> sphereFormatFromName(const std::string& name) {
  for (const auto& [f, n] : kFormatNames)
    if (name == n) return f;
  return Error{ErrorCode::kInvalidArgument,
               "format '" + name + "': expected txt, json, sph or yaml"};
}

std::string formatSpheres(SphereFormat format, const std::vector<Sphere>& spheres,
                          const SphereFileMeta& meta) {
  std::ostringstream os;
  switch (format) {
    case SphereFormat::kText:
      os << detail::commentLine(meta.generator + ": " + std::to_string(spheres.size()) +
                                " spheres, x y z r");
      for (const Sphere& s : spheres)
        os << detail::formatNumber(s.center.x()) << ' ' << detail::formatNumber(s.center.y()) << ' '
           << detail::formatNumber(s.center.z()) << ' ' << detail::formatNumber(s.radius) << '\n';
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
      os << detail::jsonText(j, 2) << '\n';
      break;
    }
    case SphereFormat::kSph: {
      // Two levels (root + leaves), branching factor = number of spheres. Each node line is
      // "x y z r error"; the error column is not used and written as 0.
      const Sphere root = minimalEnclosingBall(spheres);
      os << 2 << ' ' << std::max<size_t>(spheres.size(), 1) << '\n';
      os << detail::formatNumber(root.center.x()) << ' ' << detail::formatNumber(root.center.y())
         << ' ' << detail::formatNumber(root.center.z()) << ' ' << detail::formatNumber(root.radius)
         << " 0\n";
      for (const Sphere& s : spheres)
        os << detail::formatNumber(s.center.x()) << ' ' << detail::formatNumber(s.center.y()) << ' '
           << detail::formatNumber(s.center.z()) << ' ' << detail::formatNumber(s.radius) << " 0\n";
      break;
    }
    case SphereFormat::kYaml:
      os << detail::commentLine(meta.generator + ": " + std::to_string(spheres.size()) +
                                " spheres");
      os << "collision_spheres:\n  " << detail::yamlMappingKey(meta.name, 2) << "\n";
      detail::writeYamlSphereList(os, spheres);
      break;
  }
  return os.str();
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

Expected<std::vector<Sphere>> readSpheres(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readFileText(path);
  if (!text) return text.error();
  return detail::parseSpheres(*format, *text, path);
}

Expected<std::vector<LinkSpheres>> readLinkSpheres(const std::string& path) {
  auto format = sphereFormatFromPath(path);
  if (!format) return format.error();
  auto text = readFileText(path);
  if (!text) return text.error();
  return detail::parseLinkSpheres(*format, *text, path);
}

std::string formatLinkSpheres(const std::vector<LinkSpheres>& links, const SphereFileMeta& meta) {
  return detail::formatYamlLinks(links, meta);
}

namespace {

// The checks of writeLinkSpheres and writeRobotSpheres: a YAML file name, named and distinct
// links, valid spheres.
Status checkLinkSpheres(const std::string& path, const std::vector<LinkSpheres>& links) {
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
  return {};
}

}  // namespace

Status writeLinkSpheres(const std::string& path, const std::vector<LinkSpheres>& links,
                        const SphereFileMeta& meta) {
  Status st = checkLinkSpheres(path, links);
  if (!st) return st;
  return writeFileAtomically(path, formatLinkSpheres(links, meta));
}

Status rewriteLinkSpheres(const std::string& source, const std::string& path,
                          const std::vector<LinkSpheres>& links) {
  if (Status st = checkLinkSpheres(path, links); !st) return st;
  if (Status st = checkLinkSpheres(source, {}); !st) return st;
  auto text = readFileText(source);
  if (!text) return text.error();
  auto out = detail::replaceYamlLinks(*text, source, links);
  if (!out) return out.error();
  // What is written reads back as the links given.
  auto back = detail::parseYamlLinks(*out, path);
  if (!back || back->size() != links.size())
    return Error{ErrorCode::kInvalidData, source + ": the spheres did not read back from the copy"};
  return writeFileAtomically(path, *out);
}

std::string formatRobotSpheres(const std::vector<LinkSpheres>& links,
                               const SelfCollisionPairs* pairs, const SphereFileMeta& meta) {
  std::string out = detail::formatYamlLinks(links, meta);
  if (pairs != nullptr) out += detail::formatYamlSelfCollision(links, *pairs);
  return out;
}

Status writeRobotSpheres(const std::string& path, const std::vector<LinkSpheres>& links,
                         const SelfCollisionPairs* pairs, const SphereFileMeta& meta) {
  Status st = checkLinkSpheres(path, links);
  if (!st) return st;
  return writeFileAtomically(path, formatRobotSpheres(links, pairs, meta));
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
    std::vector<std::string> words;
    for (std::string w; is >> w;) words.push_back(w);
    if (words.empty()) continue;  // blank line (a line of other words is an error, not a skip)
    // Numbers whatever the locale ("nan" and "inf" included, for checkSphere to name).
    double v[4];
    bool numbers = words.size() == 4;
    for (size_t k = 0; numbers && k < 4; ++k) numbers = detail::parseNumber(words[k], &v[k]);
    if (!numbers)
      return Error{ErrorCode::kInvalidData,
                   path + ":" + std::to_string(lineno) + ": expected four numbers x y z r"};
    const Sphere s{Vec3(v[0], v[1], v[2]), v[3]};
    Status st = checkSphere(path + ":" + std::to_string(lineno), s);
    if (!st) return st.error();
    out.push_back(s);
  }
  return out;
}

namespace {

// The report of `sphereset robot -o ROBOT.json`: {"links": [{"link": NAME, "spheres": [[x, y, z,
// r], ...]}, ...]}, each link's spheres in its frame. Links that were skipped have none.
Expected<std::vector<LinkSpheres>> parseRobotReport(const nlohmann::json& j,
                                                    const std::string& path) {
  const nlohmann::json& links = j["links"];
  if (!links.is_array())
    return Error{ErrorCode::kInvalidData, path + ": \"links\" is not an array"};
  std::vector<LinkSpheres> out;
  size_t total = 0;
  for (size_t l = 0; l < links.size(); ++l) {
    const nlohmann::json& e = links[l];
    const std::string where = path + ": link " + std::to_string(l);
    if (!e.is_object() || !e.contains("link") || !e["link"].is_string() ||
        e["link"].get<std::string>().empty())
      return Error{ErrorCode::kInvalidData, where + ": needs a \"link\" name"};
    LinkSpheres ls{e["link"].get<std::string>(), {}};
    for (const LinkSpheres& seen : out)
      if (seen.link == ls.link)
        return Error{ErrorCode::kInvalidData, where + ": '" + ls.link + "' appears twice"};
    const nlohmann::json spheres = e.value("spheres", nlohmann::json::array());
    if (!spheres.is_array())
      return Error{ErrorCode::kInvalidData, where + ": \"spheres\" is not an array"};
    for (size_t i = 0; i < spheres.size(); ++i) {
      const nlohmann::json& v = spheres[i];
      const std::string at = where + " ('" + ls.link + "') sphere " + std::to_string(i);
      if (!v.is_array() || v.size() != 4)
        return Error{ErrorCode::kInvalidData, at + ": expected [x, y, z, r]"};
      Sphere s;
      for (int k = 0; k < 4; ++k)
        if (!v[k].is_number())
          return Error{ErrorCode::kInvalidData, at + ": expected four numbers"};
      s.center = Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
      s.radius = v[3].get<double>();
      if (Status st = checkSphere(at, s); !st) return st.error();
      ls.spheres.push_back(s);
      if (++total > static_cast<size_t>(limits::kMaxSpheres))
        return Error{ErrorCode::kInvalidData,
                     path + ": more than " + std::to_string(limits::kMaxSpheres) + " spheres"};
    }
    out.push_back(std::move(ls));
  }
  return out;
}

}  // namespace

Expected<std::vector<LinkSpheres>> parseLinkSpheres(SphereFormat format, const std::string& text,
                                                    const std::string& path) {
  if (format == SphereFormat::kYaml) return parseYamlLinks(text, path);
  if (format == SphereFormat::kJson) {
    // A robot's report (per link) reads as its links; any other JSON as one set.
    std::istringstream in(text);
    auto parsed = parseJson(in, path);
    if (!parsed) return parsed.error();
    if (parsed->is_object() && parsed->contains("links") && !parsed->contains("spheres"))
      return parseRobotReport(*parsed, path);
  }
  // Other formats hold one set: one link, named after the file.
  auto spheres = parseSpheres(format, text, path);
  if (!spheres) return spheres.error();
  std::vector<LinkSpheres> out(1);
  out[0].link = std::filesystem::path(path).stem().string();
  out[0].spheres = std::move(spheres).value();
  return out;
}

}  // namespace detail

}  // namespace sphereset

namespace sphereset {

Status writeTextFile(const std::string& path, const std::string& text) {
  return writeFileAtomically(path, text);
}

}  // namespace sphereset

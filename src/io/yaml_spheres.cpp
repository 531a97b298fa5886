// cuRobo's collision-sphere YAML through yaml-cpp: a "collision_spheres:" mapping of link names
// to lists of {center: [x, y, z], radius: r}, read link by link, and written for several links,
// with the self_collision_ignore and self_collision_buffer mappings of cuRobo's robot
// configuration layout when asked.
// yaml-cpp reports errors by throwing; nothing thrown leaves this file.
#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

#include "io/sphere_formats.hpp"
#include "util/number_text.hpp"
#include "util/utf8.hpp"

namespace sphereset::detail {
namespace {

// "file:line" for a node (yaml-cpp counts lines from 0).
std::string at(const std::string& name, const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  return m.is_null() ? name : name + ":" + std::to_string(m.line + 1);
}

// A plain scalar read as a number. Quoted scalars are strings in YAML, not numbers. YAML's
// .nan and .inf are numbers (refused later as not finite).
bool yamlNumber(const YAML::Node& node, double* out) {
  if (!node.IsScalar() || node.Tag() == "!") return false;
  const std::string& t = node.Scalar();
  if (t == ".nan" || t == ".NaN" || t == ".NAN") {
    *out = std::nan("");
    return true;
  }
  for (const char* inf : {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"})
    if (t == inf) {
      *out = HUGE_VAL;
      return true;
    }
  for (const char* inf : {"-.inf", "-.Inf", "-.INF"})
    if (t == inf) {
      *out = -HUGE_VAL;
      return true;
    }
  return parseNumber(t, out);
}

Error invalid(const std::string& what) { return Error{ErrorCode::kInvalidData, what}; }

// One sphere of a link: {center: [x, y, z], radius: r}, extra keys ignored. A key given twice is
// refused: YAML forbids it, and a reader that kept one of the two would let a line appended to a
// file (a name injected into a comment once did) change a sphere silently.
Expected<Sphere> readSphere(const YAML::Node& node, const std::string& where) {
  if (!node.IsMap()) return invalid(where + ": expected {center: [x, y, z], radius: r}");
  int centers = 0, radii = 0;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : std::string();
    centers += key == "center";
    radii += key == "radius";
  }
  if (centers > 1 || radii > 1)
    return invalid(where + ": " + (centers > 1 ? "center" : "radius") + " is given twice");
  const YAML::Node center = node["center"];
  const YAML::Node radius = node["radius"];
  if (!center.IsDefined()) return invalid(where + ": center is missing");
  if (!center.IsSequence() || center.size() != 3)
    return invalid(where + ": center must be a list of three numbers [x, y, z]");
  Sphere s;
  int k = 0;
  for (const YAML::Node& c : center)
    if (!yamlNumber(c, &s.center[k++])) return invalid(where + ": center is not numeric");
  if (!radius.IsDefined()) return invalid(where + ": radius is missing");
  if (!yamlNumber(radius, &s.radius)) return invalid(where + ": radius is not a number");
  if (!s.center.allFinite() || !std::isfinite(s.radius))
    return invalid(where + ": NaN or infinite value");
  if (s.radius < 0.0) return invalid(where + ": negative radius");
  return s;
}

// The node at a path of keys through mappings, or an undefined node. Only const access: the
// non-const operator[] of yaml-cpp inserts missing keys, and assigning a Node rebinds the node
// it refers to.
YAML::Node lookup(const YAML::Node& node, const std::vector<const char*>& keys, size_t first) {
  if (first == keys.size()) return node;
  if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node child = node[keys[first]];
  if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
  return lookup(child, keys, first + 1);
}

// The collision_spheres node, at the top level or nested in a robot configuration, with the
// keys that lead to it; an undefined node when there is none.
YAML::Node findCollisionSpheres(const YAML::Node& root, std::string* key_path) {
  const std::vector<const char*> paths[] = {{"collision_spheres"},
                                            {"robot_cfg", "kinematics", "collision_spheres"},
                                            {"kinematics", "collision_spheres"}};
  for (const auto& keys : paths) {
    const YAML::Node node = lookup(root, keys, 0);
    if (!node.IsDefined()) continue;
    key_path->clear();
    for (const char* key : keys) *key_path += (key_path->empty() ? "" : ": ") + std::string(key);
    return node;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

Expected<std::vector<LinkSpheres>> parseLinks(const std::string& text, const std::string& name) {
  const YAML::Node root = YAML::Load(text);
  if (!root.IsMap())
    return invalid(name +
                   ": not a YAML mapping with collision_spheres (expected collision_spheres: "
                   "{link: [{center: [x, y, z], radius: r}, ...], ...})");
  std::string key_path;
  const YAML::Node spheres = findCollisionSpheres(root, &key_path);
  if (!spheres.IsDefined())
    return invalid(name +
                   ": no collision_spheres mapping (looked at the top level, under "
                   "robot_cfg: kinematics: and under kinematics:)");
  std::vector<LinkSpheres> out;
  if (spheres.IsNull()) return out;
  if (spheres.IsScalar())
    return invalid(at(name, spheres) + ": " + key_path + " is '" + spheres.Scalar() +
                   "', the name of another file, not the spheres themselves: read that file");
  if (!spheres.IsMap() && !spheres.IsSequence())
    return invalid(at(name, spheres) + ": " + key_path +
                   " must map link names to lists of spheres");
  std::unordered_set<std::string> seen;
  size_t total = 0;
  auto addLink = [&](const YAML::Node& key, const YAML::Node& list) -> Status {
    if (!key.IsScalar() || key.Scalar().empty())
      return invalid(at(name, key) + ": " + key_path + ": a link name must be a non-empty string");
    LinkSpheres link{key.Scalar(), {}};
    const std::string where = ": link '" + link.link + "'";
    if (!seen.insert(link.link).second)
      return invalid(at(name, key) + where + " appears twice in " + key_path);
    // An empty entry ("link:" with nothing after it) is a link without spheres.
    if (!list.IsNull()) {
      if (!list.IsSequence())
        return invalid(at(name, list) + where + ": expected a list of spheres");
      for (const YAML::Node& node : list) {
        auto s = readSphere(
            node, at(name, node) + where + " sphere " + std::to_string(link.spheres.size()));
        if (!s) return s.error();
        link.spheres.push_back(*s);
        // Aliases can repeat a list without repeating its text: refuse more spheres than
        // the file has bytes, so that a small file cannot make a huge set.
        if (++total > text.size())
          return invalid(name + ": more spheres than the file has bytes (repeated aliases)");
      }
    }
    out.push_back(std::move(link));
    return {};
  };
  // cuRobo's mapping {link: [...], ...}, or Lula's list [{link: [...]}, ...].
  if (spheres.IsMap()) {
    for (const auto& entry : spheres)
      if (Status st = addLink(entry.first, entry.second); !st) return st.error();
    return out;
  }
  for (const YAML::Node& item : spheres) {
    if (!item.IsMap())
      return invalid(at(name, item) + ": " + key_path +
                     ": a list entry must map link names to lists of spheres (Lula's layout)");
    for (const auto& entry : item)
      if (Status st = addLink(entry.first, entry.second); !st) return st.error();
  }
  return out;
}

}  // namespace

namespace {

// One link's spheres as YAML nodes ({center: [x, y, z], radius: r}, the centre in flow style),
// numbers written as the file writers write them.
YAML::Node sphereListNode(const std::vector<Sphere>& spheres) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const Sphere& s : spheres) {
    YAML::Node centre(YAML::NodeType::Sequence);
    for (int k = 0; k < 3; ++k) centre.push_back(formatNumber(s.center[k]));
    centre.SetStyle(YAML::EmitterStyle::Flow);
    YAML::Node sphere(YAML::NodeType::Map);
    sphere["center"] = centre;
    sphere["radius"] = formatNumber(s.radius);
    list.push_back(sphere);
  }
  return list;
}

}  // namespace

Expected<std::string> replaceYamlLinks(const std::string& text, const std::string& name,
                                       const std::vector<LinkSpheres>& links) {
  try {
    if (auto read = parseLinks(text, name); !read) return read.error();  // a file we read
    YAML::Node root = YAML::Load(text);
    std::string key_path;
    const YAML::Node old = findCollisionSpheres(root, &key_path);
    // cuRobo's mapping, or Lula's list of one-link mappings when the file has that.
    YAML::Node spheres(old.IsSequence() ? YAML::NodeType::Sequence : YAML::NodeType::Map);
    for (const LinkSpheres& l : links) {
      if (old.IsSequence()) {
        YAML::Node entry(YAML::NodeType::Map);
        entry[l.link] = sphereListNode(l.spheres);
        spheres.push_back(entry);
      } else {
        spheres[l.link] = sphereListNode(l.spheres);
      }
    }
    // The same place as before: assigning through operator[] replaces the node in the tree.
    if (key_path == "collision_spheres")
      root["collision_spheres"] = spheres;
    else if (key_path == "kinematics: collision_spheres")
      root["kinematics"]["collision_spheres"] = spheres;
    else
      root["robot_cfg"]["kinematics"]["collision_spheres"] = spheres;
    YAML::Emitter out;
    out << root;
    if (!out.good())
      return Error{ErrorCode::kInvalidData,
                   name + ": cannot write YAML (" + out.GetLastError() + ")"};
    return std::string(out.c_str()) + "\n";
  } catch (const YAML::Exception& e) {
    return Error{ErrorCode::kUnreadable, oneLine(name + ": invalid YAML (" + e.msg + ")")};
  }
}

Expected<std::vector<LinkSpheres>> parseYamlLinks(const std::string& text,
                                                  const std::string& name) {
  try {
    auto links = parseLinks(text, name);
    if (!links) return Error{links.error().code, oneLine(links.error().message)};
    return links;
  } catch (const YAML::Exception& e) {
    const std::string where = e.mark.is_null() ? name
                                               : name + ":" + std::to_string(e.mark.line + 1) +
                                                     ":" + std::to_string(e.mark.column + 1);
    return Error{ErrorCode::kUnreadable, oneLine(where + ": invalid YAML (" + e.msg + ")")};
  } catch (const std::exception& e) {
    return Error{ErrorCode::kUnreadable, oneLine(name + ": invalid YAML (" + e.what() + ")")};
  }
}

std::string yamlKey(const std::string& raw) {
  // A YAML file is UTF-8: names made of other bytes (file names are bytes) are repaired.
  const std::string name = validUtf8(raw);
  // Plain when it is made of letters, digits and _-./, starts with neither '-' nor '.', and
  // reads as neither a number nor a YAML 1.1 boolean or null.
  bool plain = !name.empty() && name[0] != '-' && name[0] != '.';
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
          c == '/'))
      plain = false;
  if (plain) {
    std::string lower = name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* word : {"true", "false", "yes", "no", "on", "off", "null", "y", "n"})
      if (lower == word) plain = false;
    double ignored = 0.0;
    if (parseNumber(name, &ignored)) plain = false;
  }
  if (plain) return name;
  return yamlQuoted(name);
}

std::string yamlQuoted(const std::string& name) {
  std::string out = "\"";
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string commentLine(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "# ";
  for (size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20 || u == 0x7f) {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else if (u == 0xc2 && i + 1 < text.size() &&
               static_cast<unsigned char>(text[i + 1]) == 0x85) {
      out += "\\u0085";
      ++i;
    } else if (u == 0xe2 && i + 2 < text.size() &&
               static_cast<unsigned char>(text[i + 1]) == 0x80 &&
               (static_cast<unsigned char>(text[i + 2]) == 0xa8 ||
                static_cast<unsigned char>(text[i + 2]) == 0xa9)) {
      out += static_cast<unsigned char>(text[i + 2]) == 0xa8 ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out + "\n";
}

std::string yamlMappingKey(const std::string& name, int indent) {
  // YAML limits implicit keys to 1024 characters; longer ones take the explicit "? key" form.
  const std::string key = yamlKey(name);
  if (key.size() <= 1000) return key + ":";
  return "? " + key + "\n" + std::string(static_cast<size_t>(indent), ' ') + ":";
}

std::string formatYamlLinks(const std::vector<LinkSpheres>& links, const SphereFileMeta& meta) {
  size_t total = 0;
  for (const LinkSpheres& l : links) total += l.spheres.size();
  std::ostringstream os;
  os << commentLine(meta.generator + ": " + std::to_string(total) + " spheres in " +
                    std::to_string(links.size()) + " links");
  os << "collision_spheres:" << (links.empty() ? " {}\n" : "\n");
  for (const LinkSpheres& l : links) {
    os << "  " << yamlMappingKey(l.link, 2) << (l.spheres.empty() ? " []\n" : "\n");
    writeYamlSphereList(os, l.spheres);
  }
  return os.str();
}

std::string formatYamlSelfCollision(const std::vector<LinkSpheres>& links,
                                    const SelfCollisionPairs& pairs) {
  // Rank of a link name: its place in `links`, then first appearance in the pairs.
  std::map<std::string, size_t> rank;
  for (const LinkSpheres& l : links) rank.emplace(l.link, rank.size());
  for (const auto* list : {&pairs.adjacent, &pairs.overlapping})
    for (const auto& p : *list)
      for (const std::string& name : p) rank.emplace(name, rank.size());
  // Each pair once, under its earlier link.
  std::map<size_t, std::map<size_t, std::string>> ignore;
  for (const auto* list : {&pairs.adjacent, &pairs.overlapping})
    for (const auto& p : *list) {
      size_t a = rank.at(p[0]);
      size_t b = rank.at(p[1]);
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      ignore[a][b] = a == rank.at(p[0]) ? p[1] : p[0];
    }
  std::map<size_t, std::string> names;
  for (const auto& [name, r] : rank) names[r] = name;

  std::ostringstream os;
  os << "self_collision_ignore:" << (ignore.empty() ? " {}\n" : "\n");
  for (const auto& [a, others] : ignore) {
    os << "  " << yamlMappingKey(names[a], 2) << " [";
    bool first = true;
    for (const auto& [b, name] : others) {
      os << (first ? "" : ", ") << yamlQuoted(name);
      first = false;
    }
    os << "]\n";
  }
  bool any = false;
  for (const LinkSpheres& l : links) any = any || !l.spheres.empty();
  os << "self_collision_buffer:" << (any ? "\n" : " {}\n");
  for (const LinkSpheres& l : links)
    if (!l.spheres.empty()) os << "  " << yamlMappingKey(l.link, 2) << " 0.0\n";
  return os.str();
}

void writeYamlSphereList(std::ostream& os, const std::vector<Sphere>& spheres) {
  for (const Sphere& s : spheres)
    os << "    - \"center\": [" << formatNumber(s.center.x()) << ", " << formatNumber(s.center.y())
       << ", " << formatNumber(s.center.z()) << "]\n      \"radius\": " << formatNumber(s.radius)
       << '\n';
}

}  // namespace sphereset::detail

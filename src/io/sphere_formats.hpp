// Private: the sphere-file formats on text held in memory. The public readers (sphere_io.hpp)
// read the file and call these; the fuzzers call them directly. `name` stands for the file in
// error messages.
#pragma once

#include <cstdint>
#include <istream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"

namespace sphereset::detail {

Expected<std::vector<Sphere>> parseSpheres(SphereFormat format, const std::string& text,
                                           const std::string& name);
Expected<std::vector<LinkSpheres>> parseLinkSpheres(SphereFormat format, const std::string& text,
                                                    const std::string& name);
Expected<SphereTree> parseSphereTree(SphereFormat format, const std::string& text,
                                     const std::string& name);

// cuRobo's YAML (yaml_spheres.cpp): every link of the collision_spheres mapping, in file order,
// found at the top level or under robot_cfg: kinematics: (or kinematics:).
Expected<std::vector<LinkSpheres>> parseYamlLinks(const std::string& text, const std::string& name);
// The YAML document `text` (the file `name`, as parseYamlLinks reads it) with its
// collision_spheres replaced by `links`, in the same place and layout (cuRobo's mapping or
// Lula's list), every other key kept; comments are not kept.
Expected<std::string> replaceYamlLinks(const std::string& text, const std::string& name,
                                       const std::vector<LinkSpheres>& links);
// Several links in the layout the single-link YAML writer uses; an empty link as "[]".
std::string formatYamlLinks(const std::vector<LinkSpheres>& links, const SphereFileMeta& meta);
// cuRobo's self_collision_ignore and self_collision_buffer mappings for these links and pairs
// (see formatRobotSpheres).
std::string formatYamlSelfCollision(const std::vector<LinkSpheres>& links,
                                    const SelfCollisionPairs& pairs);
// The spheres of one link as the YAML writers list them, one "center"/"radius" entry each,
// indented under a link key.
void writeYamlSphereList(std::ostream& os, const std::vector<Sphere>& spheres);
// A link name as a YAML mapping key: as it is when it reads back as the same string, else
// double-quoted with escapes.
std::string yamlKey(const std::string& name);
// Always double-quoted, with escapes.
std::string yamlQuoted(const std::string& name);
// A comment line, "# " + `text` + newline, for YAML and the text sphere format alike: control
// characters and Unicode line breaks (U+0085, U+2028, U+2029) are written as escapes (\x0a,
// \u2028), so no text a file or a user names (a robot's name) can end the comment and start a
// key or a sphere line. The one writer of comments.
std::string commentLine(const std::string& text);
// The same followed by ':', in the explicit form "? key" then ':' on the next line (indented by
// `indent`) when the key is too long for an implicit one.
std::string yamlMappingKey(const std::string& name, int indent);

// The JSON document read from `in` (the file `path`); kUnreadable when it is not JSON.
Expected<nlohmann::json> parseJson(std::istream& in, const std::string& path);
// A JSON number that is an integer in [lo, hi], written as an integer or as an integral
// float ("2.0"); anything else is nullopt. Converting first would be undefined behaviour for
// floats out of range and would wrap or truncate the others into valid-looking values.
std::optional<int64_t> jsonInteger(const nlohmann::json& v, int64_t lo, int64_t hi);

// `x` with 17 significant digits, so that it reads back exactly: how every sphere writer
// prints numbers.
std::string formatNumber(double x);

}  // namespace sphereset::detail

// The SMD/VTA grammar check (smd_grammar.hpp). Reference: Valve Developer Community, "Studiomdl
// Data" (the SMD format); the fields of each line as assimp 5.2's SMDLoader reads them.
#include "io/smd_grammar.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "sphereset/limits.hpp"
#include "util/number_text.hpp"

namespace sphereset::detail {
namespace {

bool isInteger(const std::string& w) {
  if (w.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(w.c_str(), &end, 10);
  return end == w.c_str() + w.size() && errno != ERANGE && v >= -1 && v <= kMaxSmdIndex;
}

long long integer(const std::string& w) { return std::strtoll(w.c_str(), nullptr, 10); }

// A node, bone or link index of a node listed so far.
bool isNode(const std::string& w, long long nodes) {
  return isInteger(w) && integer(w) >= 0 && integer(w) < nodes;
}

bool isNumber(const std::string& w) {
  if (w.empty() || w.size() > kMaxSmdNumberChars) return false;
  // assimp reads the digits before the point as one 64-bit integer: more than 18 of them
  // overflow it (found by fuzzing: 24 digits made it ask for 33 GB).
  const size_t first = w.find_first_of("0123456789");
  const size_t last = w.find_first_not_of("0123456789", first);
  if (first != std::string::npos &&
      (last == std::string::npos ? w.size() : last) - first > kMaxSmdIntegerDigits)
    return false;
  double v = 0.0;
  return detail::parseNumber(w, &v) && std::fabs(v) <= limits::kMaxCoordinate;  // false: NaN
}

// "ID "NAME" PARENT": the name quoted, without quotes inside; nodes numbered 0, 1, ... in
// order, each parent listed before its child (or -1): no cycle, no gap (assimp indexes its
// arrays by these numbers and follows the parents: a node that is its own parent made it ask
// for 26 GB).
bool nodeLine(const std::string& line, long long* nodes) {
  const size_t q0 = line.find('"'), q1 = q0 == std::string::npos ? q0 : line.find('"', q0 + 1);
  if (q1 == std::string::npos) return false;
  std::istringstream head(line.substr(0, q0)), tail(line.substr(q1 + 1));
  std::string id, parent, extra;
  if (!(head >> id) || (head >> extra) || !isInteger(id) || integer(id) != *nodes ||
      !(tail >> parent) || (tail >> extra) || !isInteger(parent) || integer(parent) >= *nodes)
    return false;
  ++*nodes;
  return true;
}

// An index (a node's when `nodes` >= 0) then `floats` numbers, and (vertex lines) an optional
// list of links to nodes.
bool fieldsLine(const std::vector<std::string>& w, size_t floats, bool links, long long nodes) {
  if (w.size() < 1 + floats || !isInteger(w[0])) return false;
  if (nodes >= 0 ? !isNode(w[0], nodes) : integer(w[0]) < 0) return false;
  for (size_t k = 1; k <= floats; ++k)
    if (!isNumber(w[k])) return false;
  if (w.size() == 1 + floats) return true;
  if (!links || !isInteger(w[1 + floats])) return false;
  const long long n = std::strtoll(w[1 + floats].c_str(), nullptr, 10);
  if (n < 0 || w.size() != 2 + floats + 2 * static_cast<size_t>(n)) return false;
  for (size_t k = 2 + floats; k < w.size(); k += 2)
    if (!isNode(w[k], nodes) || !isNumber(w[k + 1])) return false;
  return true;
}

}  // namespace

std::string smdProblem(std::istream& in) {
  std::string section, line;
  int triangle_line = 0;  // 0: a material comes next; 1..3: the triangle's vertex lines
  bool version = false;
  long long nodes = 0;  // listed so far
  for (int64_t lineno = 1; std::getline(in, line); ++lineno) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // assimp ends a line at a carriage return too: one inside a line would split it there.
    if (line.find('\r') != std::string::npos)
      return "line " + std::to_string(lineno) + ": a carriage return inside the line";
    std::istringstream split(line);
    std::vector<std::string> w;
    for (std::string s; split >> s;) w.push_back(s);
    // assimp 5.2 never returns from a nodes section holding a line of spaces or tabs, an empty
    // line before its first node, or an indented "end" (found by fuzzing): there, every line
    // starts at its first column.
    if (section == "nodes" && (w.empty() || line[0] == ' ' || line[0] == '\t'))
      return "line " + std::to_string(lineno) + ": a blank or indented line in the 'nodes' section";
    if (w.empty() || w[0].rfind("//", 0) == 0) continue;
    const std::string where = "line " + std::to_string(lineno) + ": ";
    if (section.empty()) {
      if (!version) {
        if (w.size() != 2 || w[0] != "version" || !isInteger(w[1]))
          return where + "expected \"version 1\"";
        version = true;
      } else if (w.size() == 1 && (w[0] == "nodes" || w[0] == "skeleton" || w[0] == "triangles" ||
                                   w[0] == "vertexanimation")) {
        section = w[0];
        triangle_line = 0;
      } else {
        return where + "expected a section (nodes, skeleton, triangles, vertexanimation)";
      }
      continue;
    }
    if (w.size() == 1 && w[0] == "end" && triangle_line == 0) {
      // A skeleton has at least one node.
      if (section == "nodes" && nodes == 0) return where + "the 'nodes' section lists no node";
      section.clear();
      continue;
    }
    bool ok = false;
    if (section == "nodes") {
      ok = nodeLine(line, &nodes);
    } else if (w[0] == "time" && (section == "skeleton" || section == "vertexanimation")) {
      ok = w.size() == 2 && isInteger(w[1]);
    } else if (section == "skeleton" || section == "vertexanimation") {
      ok = fieldsLine(w, 6, false, section == "skeleton" ? nodes : -1);
    } else if (triangle_line == 0) {
      ok = true;  // the material's name
      triangle_line = 1;
    } else {
      ok = fieldsLine(w, 8, true, nodes);
      triangle_line = triangle_line == 3 ? 0 : triangle_line + 1;
    }
    if (!ok) return where + "not a line of the '" + section + "' section";
  }
  if (!section.empty()) return "the '" + section + "' section is not closed by a line 'end'";
  if (!version) return "expected \"version 1\"";
  return "";
}

}  // namespace sphereset::detail

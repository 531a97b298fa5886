// The files a posed-robot query reads besides the robot and its spheres: point clouds (the
// vertices of PLY/OFF through the project's own readers, "v" lines of OBJ, "x y z" text) and
// trajectories (CSV: joint names, then one waypoint per row), both read strictly, every error
// naming the file and, for text, the line.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <string_view>

#include "io/off_ply.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot_query.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace {

std::string_view trimmed(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The whole of `text` as a number (from_chars: no locale, no leading '+' or spaces).
bool wholeNumber(std::string_view text, double* out) {
  if (text.empty()) return false;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), *out);
  return ec == std::errc() && ptr == text.data() + text.size();
}

// Calls f(line_number, line) for each line of `text` (1-based, '\r' kept for trimmed()).
template <class F>
Status eachLine(const std::string& text, F&& f) {
  size_t start = 0;
  for (int64_t lineno = 1; start <= text.size(); ++lineno) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (Status st = f(lineno, std::string_view(text).substr(start, end - start)); !st) return st;
    start = end + 1;
  }
  return {};
}

// The words of a line separated by spaces or tabs.
std::vector<std::string_view> lineWords(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (true) {
    i = line.find_first_not_of(" \t\r", i);
    if (i == std::string_view::npos) return out;
    const size_t e = std::min(line.find_first_of(" \t\r", i), line.size());
    out.push_back(line.substr(i, e - i));
    i = e;
  }
}

// "x y z" lines (obj: "v x y z [w | r g b]" lines, the others ignored).
Expected<std::vector<Vec3>> parsePointText(const std::string& text, const std::string& path,
                                           bool obj) {
  std::vector<Vec3> out;
  Status st = eachLine(text, [&](int64_t lineno, std::string_view line) -> Status {
    const std::string where = path + ":" + std::to_string(lineno);
    if (const size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    std::vector<std::string_view> w = lineWords(line);
    if (obj) {
      if (w.empty() || w[0] != "v") return {};
      w.erase(w.begin());
    }
    if (w.empty()) return {};
    Vec3 p;
    bool ok = obj ? w.size() >= 3 : w.size() == 3;
    for (int k = 0; ok && k < 3; ++k) ok = wholeNumber(w[k], &p[k]);
    if (!ok)
      return Error{ErrorCode::kInvalidData,
                   where + (obj ? ": expected v x y z" : ": expected three numbers x y z")};
    if (Status c = limits::checkCoordinates(where, std::span<const double>(p.data(), 3)); !c)
      return Error{ErrorCode::kInvalidData, c.error().message};
    out.push_back(p);
    return {};
  });
  if (!st) return st.error();
  return out;
}

}  // namespace

Expected<std::vector<Vec3>> readPointCloud(const std::string& path) {
  const std::string ext = detail::extensionOf(path);
  std::vector<Vec3> points;
  if (ext == ".ply" || ext == ".off") {
    auto raw = ext == ".ply" ? detail::readPly(path) : detail::readOff(path);
    if (!raw) return raw.error();
    points = std::move(raw->vertices);
  } else if (ext == ".obj" || ext == ".xyz" || ext == ".txt") {
    auto text = detail::readFileText(path);
    if (!text) return text.error();
    auto parsed = parsePointText(*text, path, ext == ".obj");
    if (!parsed) return parsed.error();
    points = std::move(parsed).value();
  } else {
    return Error{ErrorCode::kUnreadable,
                 path + ": unknown point cloud extension (expected .ply, .off, .obj, .xyz, .txt)"};
  }
  if (points.empty()) return Error{ErrorCode::kInvalidData, path + ": no points"};
  return points;
}

Expected<std::vector<std::map<std::string, double>>> readTrajectory(const std::string& path,
                                                                    const Robot& robot) {
  auto text = detail::readFileText(path);
  if (!text) return text.error();
  std::set<std::string> joints;
  for (const RobotJoint& j : robot.joints) joints.insert(j.name);
  std::vector<std::string> header;
  std::vector<std::map<std::string, double>> out;
  Status st = eachLine(*text, [&](int64_t lineno, std::string_view line) -> Status {
    if (trimmed(line).empty()) return {};
    const std::string where = path + ":" + std::to_string(lineno) + ": ";
    auto bad = [&](const std::string& what) {
      return Error{ErrorCode::kInvalidData, where + what};
    };
    std::vector<std::string_view> cells;
    for (size_t b = 0;;) {
      const size_t e = line.find(',', b);
      cells.push_back(trimmed(line.substr(b, e == std::string_view::npos ? e : e - b)));
      if (e == std::string_view::npos) break;
      b = e + 1;
    }
    if (header.empty()) {
      for (std::string_view c : cells) {
        const std::string name(c);
        if (name.empty()) return bad("a column without a joint name");
        if (joints.count(name) == 0)
          return bad("no joint '" + name + "' in robot '" + robot.name + "'");
        if (std::find(header.begin(), header.end(), name) != header.end())
          return bad("joint '" + name + "' appears twice");
        header.push_back(name);
      }
      return {};
    }
    if (cells.size() != header.size())
      return bad(std::to_string(cells.size()) + " values, the header names " +
                 std::to_string(header.size()) + " joints");
    if (static_cast<int64_t>(out.size()) >= limits::kMaxWaypoints)
      return bad("more than " + std::to_string(limits::kMaxWaypoints) + " waypoints");
    std::map<std::string, double> row;
    for (size_t k = 0; k < cells.size(); ++k) {
      double v = 0.0;
      if (!wholeNumber(cells[k], &v) || !std::isfinite(v))
        return bad("joint '" + header[k] + "': '" + std::string(cells[k]) +
                   "' is not a finite number");
      row[header[k]] = v;
    }
    // The library's own checks of a configuration (mimic joints), with the line.
    if (auto state = jointState(robot, row); !state) return bad(state.error().message);
    out.push_back(std::move(row));
    return {};
  });
  if (!st) return st.error();
  if (header.empty())
    return Error{ErrorCode::kInvalidData, path + ": empty, expected a header row of joint names"};
  if (out.empty()) return Error{ErrorCode::kInvalidData, path + ": no waypoints after the header"};
  return out;
}

}  // namespace sphereset

// Reading robot descriptions in the URDF format (http://wiki.ros.org/urdf/XML) through urdfdom:
// the <link> elements with their <collision> geometry (or <visual> when a link has none: box,
// cylinder, sphere, mesh with scale, each with its <origin>), the <joint> elements (type,
// parent, child, origin, axis, limits), and the resolution of mesh file names: relative to the
// URDF's folder, absolute, file:// and package://NAME/... (ROS package folders found by folder
// name or by the <name> of their package.xml). Materials, inertia, dynamics, mimic joints,
// transmissions and Gazebo extensions are not read.
#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <numbers>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "robot/mjcf.hpp"
#include "robot/xml_text.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot.hpp"
#include "util/number_text.hpp"
#include "util/read_file.hpp"
#include "util/utf8.hpp"

namespace sphereset {
namespace {

using detail::oneLine;

namespace fs = std::filesystem;

// How deep below a package search folder a package.xml is looked for (the folder itself is
// level 0).
constexpr int kPackageSearchDepth = 3;

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

// Collects urdfdom's error messages (it reports through console_bridge instead of returning
// them) so that a parse failure can say why, and keeps them off the terminal.
class CaptureErrors : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    if (first_error.empty()) first_error = text;
    // urdfdom follows an element's error with "Could not parse <what> element for Link [name]":
    // the link is named once.
    const size_t at = text.find("Link [");
    if (link.empty() && at != std::string::npos) {
      const size_t end = text.find(']', at);
      if (end != std::string::npos) link = text.substr(at + 6, end - at - 6);
    }
  }
  std::string first_error;
  std::string link;  // the link named by urdfdom's messages, if any
};

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

bool isDirectory(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// The <name> of a package.xml, or "" when it has none or does not parse.
std::string packageXmlName(const fs::path& package_xml) {
  TiXmlDocument doc;
  if (!doc.LoadFile(package_xml.string().c_str())) return {};
  const TiXmlElement* root = doc.RootElement();
  if (root == nullptr) return {};
  const TiXmlElement* name = root->FirstChildElement("name");
  if (name == nullptr || name->GetText() == nullptr) return {};
  std::string s = name->GetText();
  const auto first = s.find_first_not_of(" \t\r\n");
  const auto last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// Folders at or below `dir` (down to kPackageSearchDepth levels) holding a package.xml named
// `package`, breadth first, sorted by name within a level. A package folder is not entered.
std::vector<fs::path> findPackageByXml(const fs::path& dir, const std::string& package) {
  std::vector<fs::path> found;
  std::vector<fs::path> level = {dir};
  for (int depth = 0; depth <= kPackageSearchDepth && !level.empty(); ++depth) {
    std::vector<fs::path> next;
    for (const fs::path& d : level) {
      if (isFile(d / "package.xml")) {
        if (packageXmlName(d / "package.xml") == package) found.push_back(d);
        continue;
      }
      if (depth == kPackageSearchDepth) continue;
      std::error_code ec;
      std::vector<fs::path> children;
      for (fs::directory_iterator it(d, fs::directory_options::skip_permission_denied, ec), end;
           !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!name.empty() && name[0] != '.' && isDirectory(it->path())) {
          children.push_back(it->path());
        }
      }
      std::sort(children.begin(), children.end());
      next.insert(next.end(), children.begin(), children.end());
    }
    level = std::move(next);
  }
  return found;
}

// The package search folders: the options' then ROS_PACKAGE_PATH's.
std::vector<fs::path> packageSearchDirs(const RobotLoadOptions& options) {
  std::vector<fs::path> dirs(options.package_paths.begin(), options.package_paths.end());
  if (options.use_ros_package_path) {
    if (const char* env = std::getenv("ROS_PACKAGE_PATH")) {
      std::stringstream ss(env);
      std::string item;
      while (std::getline(ss, item, ':')) {
        if (!item.empty()) dirs.emplace_back(item);
      }
    }
  }
  return dirs;
}

// Resolves a URDF mesh file name to an existing file. On failure, `tried` lists every
// candidate path (or search folder without the package) and "" is returned.
std::string resolveMeshPath(const std::string& uri, const fs::path& urdf_dir,
                            const RobotLoadOptions& options, std::vector<std::string>& tried) {
  auto attempt = [&](const fs::path& p) {
    if (isFile(p)) return true;
    tried.push_back(p.string());
    return false;
  };
  if (uri.starts_with(kPackageScheme)) {
    const std::string rest_of_uri = uri.substr(kPackageScheme.size());
    const auto slash = rest_of_uri.find('/');
    const std::string package = rest_of_uri.substr(0, slash);
    const std::string rest = slash == std::string::npos ? "" : rest_of_uri.substr(slash + 1);
    const std::vector<fs::path> dirs = packageSearchDirs(options);
    if (dirs.empty())
      tried.push_back("(no package search folder: none given, ROS_PACKAGE_PATH unset)");
    for (const fs::path& d : dirs) {
      bool package_found = false;
      if (isDirectory(d / package)) {
        package_found = true;
        if (attempt(d / package / rest)) return (d / package / rest).string();
      }
      for (const fs::path& p : findPackageByXml(d, package)) {
        if (p == d / package) continue;
        package_found = true;
        if (attempt(p / rest)) return (p / rest).string();
      }
      if (!package_found) tried.push_back(d.string() + " (no package " + package + ")");
    }
    return {};
  }
  fs::path p =
      uri.starts_with(kFileScheme) ? fs::path(uri.substr(kFileScheme.size())) : fs::path(uri);
  if (p.is_relative()) p = urdf_dir / p;
  p = p.lexically_normal();
  return attempt(p) ? p.string() : std::string();
}

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Vec3(pose.position.x, pose.position.y, pose.position.z);
  const urdf::Rotation& r = pose.rotation;
  t.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  return t;
}

// One geometry element of a link; errors name the link.
Expected<LinkGeometry> convertGeometry(const urdf::Geometry& g, const urdf::Pose& origin,
                                       const std::string& link, const fs::path& urdf_dir,
                                       const RobotLoadOptions& options,
                                       const std::string& urdf_path) {
  LinkGeometry out;
  out.origin = toIsometry(origin);
  switch (g.type) {
    case urdf::Geometry::SPHERE:
      out.kind = LinkGeometry::Kind::kSphere;
      out.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::BOX: {
      const urdf::Vector3& d = static_cast<const urdf::Box&>(g).dim;
      out.kind = LinkGeometry::Kind::kBox;
      out.box_size = Vec3(d.x, d.y, d.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      out.kind = LinkGeometry::Kind::kCylinder;
      out.radius = c.radius;
      out.length = c.length;
      break;
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(g);
      out.kind = LinkGeometry::Kind::kMesh;
      out.scale = Vec3(m.scale.x, m.scale.y, m.scale.z);
      std::vector<std::string> tried;
      out.mesh_path = resolveMeshPath(m.filename, urdf_dir, options, tried);
      if (out.mesh_path.empty()) {
        std::string list;
        for (const std::string& t : tried) list += (list.empty() ? "" : ", ") + t;
        return Error{ErrorCode::kUnreadable, urdf_path + ": link '" + link + "': mesh '" +
                                                 m.filename + "' not found; tried: " + list};
      }
      break;
    }
    default:
      return Error{ErrorCode::kInvalidData,
                   urdf_path + ": link '" + link + "': unknown geometry type"};
  }
  // Sizes and the origin within the coordinate limit (a 1e300 box once "enclosed no volume":
  // its volume overflowed), as every coordinate the library takes.
  const std::array<double, 9> values = {
      out.radius,       out.length,       out.box_size.x(),
      out.box_size.y(), out.box_size.z(), out.scale.x(),
      out.scale.y(),    out.scale.z(),    out.origin.translation().norm()};
  if (Status st = limits::checkCoordinates("sizes, scale and origin", values); !st)
    return Error{ErrorCode::kInvalidData,
                 urdf_path + ": link '" + link + "': " + st.error().message};
  return out;
}

RobotJoint convertJoint(const urdf::Joint& j) {
  RobotJoint out;
  out.name = j.name;
  out.parent = j.parent_link_name;
  out.child = j.child_link_name;
  switch (j.type) {
    case urdf::Joint::FIXED:
      out.type = RobotJoint::Type::kFixed;
      break;
    case urdf::Joint::REVOLUTE:
      out.type = RobotJoint::Type::kRevolute;
      break;
    case urdf::Joint::CONTINUOUS:
      out.type = RobotJoint::Type::kContinuous;
      break;
    case urdf::Joint::PRISMATIC:
      out.type = RobotJoint::Type::kPrismatic;
      break;
    default:
      out.type = RobotJoint::Type::kOther;
      break;
  }
  out.origin = toIsometry(j.parent_to_joint_origin_transform);
  const Vec3 axis(j.axis.x, j.axis.y, j.axis.z);
  if (axis.norm() > 0.0) out.axis = axis.normalized();
  if (j.limits) {
    out.lower = j.limits->lower;
    out.upper = j.limits->upper;
  }
  if (j.mimic)
    out.mimic = RobotJoint::Mimic{j.mimic->joint_name, j.mimic->multiplier, j.mimic->offset};
  return out;
}

// A joint's limits as the library can pose and sample it: finite (urdfdom reads "nan" and
// "inf"); a prismatic joint's within limits::kMaxCoordinate, a length. A revolute joint's may be
// any finite angle (its poses repeat every turn: jointSampleRange).
Status checkJointLimits(const RobotJoint& j) {
  const std::string what = "joint '" + j.name + "'";
  if (!std::isfinite(j.lower) || !std::isfinite(j.upper))
    return Error{ErrorCode::kInvalidData, what + ": a limit is not a finite number (lower " +
                                              detail::numberText(j.lower) + ", upper " +
                                              detail::numberText(j.upper) + ")"};
  if (j.type == RobotJoint::Type::kPrismatic &&
      std::max(std::fabs(j.lower), std::fabs(j.upper)) > limits::kMaxCoordinate)
    return Error{ErrorCode::kInvalidData,
                 what + ": prismatic limits beyond " + detail::numberText(limits::kMaxCoordinate) +
                     " in magnitude (lower " + detail::numberText(j.lower) + ", upper " +
                     detail::numberText(j.upper) + ")"};
  return {};
}

// The names of the elements `tag` under <robot>, in file order (urdfdom keeps them in maps).
std::vector<std::string> namesInFileOrder(const std::string& xml, const char* tag) {
  std::vector<std::string> names;
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  const TiXmlElement* robot = doc.RootElement();
  if (robot == nullptr) return names;
  for (const TiXmlElement* e = robot->FirstChildElement(tag); e != nullptr;
       e = e->NextSiblingElement(tag)) {
    if (const char* name = e->Attribute("name")) names.emplace_back(name);
  }
  return names;
}

// urdfdom's parse with its console output captured; serialised because console_bridge's
// output handler is global.
urdf::ModelInterfaceSharedPtr parseQuietly(const std::string& xml, std::string& message,
                                           std::string& link) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  CaptureErrors capture;
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    if (capture.first_error.empty()) capture.first_error = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  message = oneLine(capture.first_error);
  link = capture.link;
  return model;
}

}  // namespace

Expected<Robot> loadRobot(const std::string& urdf_path, const RobotLoadOptions& options) {
  if (detail::extensionOf(urdf_path) == ".xml") return detail::loadMjcf(urdf_path, options);
  auto text = detail::readXmlText(urdf_path, "URDF");
  if (!text) return text.error();
  const std::string& xml = *text;
  std::string message, bad_link;
  const urdf::ModelInterfaceSharedPtr model = parseQuietly(xml, message, bad_link);
  if (!model) {
    return Error{ErrorCode::kInvalidData,
                 urdf_path + ": not a valid URDF" + (message.empty() ? "" : ": " + message)};
  }
  // urdfdom drops an element it cannot parse (a <collision> with "0,2" for a number, a
  // misspelled attribute) with an error on the console and goes on: the link would then be
  // fitted to its visual geometry, or vanish. Any error it reports is ours.
  if (!message.empty())
    return Error{
        ErrorCode::kInvalidData,
        urdf_path + ": " + (bad_link.empty() ? "" : "link '" + bad_link + "': ") + message};

  const fs::path urdf_dir = fs::absolute(fs::path(urdf_path)).parent_path();
  Robot robot;
  robot.name = model->getName();
  if (model->getRoot()) robot.root = model->getRoot()->name;

  for (const std::string& name : namesInFileOrder(xml, "link")) {
    urdf::LinkConstSharedPtr link = model->getLink(name);
    if (!link) continue;
    RobotLink out;
    out.name = name;
    auto add = [&](const urdf::GeometrySharedPtr& g, const urdf::Pose& origin) -> Status {
      if (!g) return {};
      Expected<LinkGeometry> geometry =
          convertGeometry(*g, origin, name, urdf_dir, options, urdf_path);
      if (!geometry) return geometry.error();
      out.geometry.push_back(std::move(*geometry));
      return {};
    };
    for (const urdf::CollisionSharedPtr& c : link->collision_array) {
      if (!c) continue;
      if (Status s = add(c->geometry, c->origin); !s) return s.error();
    }
    if (out.geometry.empty()) {
      for (const urdf::VisualSharedPtr& v : link->visual_array) {
        if (!v) continue;
        if (Status s = add(v->geometry, v->origin); !s) return s.error();
      }
      out.from_visual = !out.geometry.empty();
    }
    robot.links.push_back(std::move(out));
  }
  for (const std::string& name : namesInFileOrder(xml, "joint")) {
    urdf::JointConstSharedPtr joint = model->getJoint(name);
    if (!joint) continue;
    robot.joints.push_back(convertJoint(*joint));
    if (Status st = checkJointLimits(robot.joints.back()); !st)
      return Error{ErrorCode::kInvalidData, urdf_path + ": " + st.error().message};
  }
  // The joints must settle with no value given: a <mimic> cycle, or a mimic of no joint, is the
  // file's defect, reported as such when it is read (it was once blamed on --joint-positions,
  // given or not).
  if (auto settled = jointState(robot, {}); !settled)
    return Error{ErrorCode::kInvalidData, urdf_path + ": " + settled.error().message};
  return robot;
}

Expected<std::map<std::string, double>> parseJointValues(const std::string& text) {
  std::map<std::string, double> out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    const size_t eq = item.find('=');
    double v = 0.0;
    if (eq == std::string::npos || !detail::parseNumber(std::string_view(item).substr(eq + 1), &v))
      return Error{ErrorCode::kInvalidArgument, item + ": expected JOINT=VALUE (a number)"};
    if (!out.emplace(item.substr(0, eq), v).second)
      return Error{ErrorCode::kInvalidArgument,
                   "joint '" + item.substr(0, eq) + "' is given twice"};
    start = end + 1;
  }
  return out;
}

bool isRobotDescriptionPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".urdf" || ext == ".xml";
}

bool isMovable(const RobotJoint& j) {
  return j.type == RobotJoint::Type::kRevolute || j.type == RobotJoint::Type::kContinuous ||
         j.type == RobotJoint::Type::kPrismatic;
}

std::pair<double, double> jointSampleRange(const RobotJoint& j) {
  constexpr double kPi = std::numbers::pi;
  const double lo = std::min(j.lower, j.upper), hi = std::max(j.lower, j.upper);
  const bool full_turn = j.type == RobotJoint::Type::kRevolute && !(hi - lo < 2.0 * kPi);
  if (j.type == RobotJoint::Type::kContinuous || full_turn) return {-kPi, kPi};
  return {lo, hi};
}

const char* jointTypeName(RobotJoint::Type type) {
  switch (type) {
    case RobotJoint::Type::kFixed:
      return "fixed";
    case RobotJoint::Type::kRevolute:
      return "revolute";
    case RobotJoint::Type::kContinuous:
      return "continuous";
    case RobotJoint::Type::kPrismatic:
      return "prismatic";
    case RobotJoint::Type::kOther:
      break;
  }
  return "other";
}

}  // namespace sphereset

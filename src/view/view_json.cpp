// The view's JSON and binary answers (docs/view.md), and the static page that inlines them.
#include "view/view_json.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>

#include "sphereset/fit.hpp"
#include "sphereset/options.hpp"
#include "view/view_page.hpp"

namespace sphereset {

std::string viewSaveFormatName(const ViewScene& scene, ViewSaveFormat format) {
  switch (format) {
    case ViewSaveFormat::kRobotYaml:
      return "yaml";
    case ViewSaveFormat::kRobotUrdf:
      return "urdf";
    case ViewSaveFormat::kRobotMjcf:
      return "mjcf";
    case ViewSaveFormat::kRobotLula:
      return "lula";
    case ViewSaveFormat::kSet:
    case ViewSaveFormat::kTree:
      break;
  }
  auto f = sphereFormatFromPath(scene.save_path);
  return f ? sphereFormatName(*f) : sphereFormatName(SphereFormat::kText);
}

namespace view_json {

nlohmann::json spheres(const std::vector<Sphere>& set) {
  nlohmann::json a = nlohmann::json::array();
  for (const Sphere& s : set) a.push_back({s.center.x(), s.center.y(), s.center.z(), s.radius});
  return a;
}

nlohmann::json certificate(const ViewCertificate& c) {
  return {{"spheres", c.spheres},
          {"er_sum", c.er_sum},
          {"outside_volume", c.outside_volume},
          {"volume", c.volume},
          {"surface_covered", c.surface_covered},
          {"interior_covered", c.interior_covered},
          {"original_covered", c.original_covered},
          {"covered", c.covered},
          {"max_gap", c.max_gap ? nlohmann::json(*c.max_gap) : nlohmann::json()},
          {"uncovered_triangles", c.uncovered_triangles},
          {"protrusion", c.protrusion ? nlohmann::json(*c.protrusion) : nlohmann::json()},
          {"protrusion_witness",
           {c.protrusion_witness.x(), c.protrusion_witness.y(), c.protrusion_witness.z()}},
          {"sphere_protrusion", c.sphere_protrusion},
          {"seconds", c.seconds}};
}

nlohmann::json solid(const ViewSolid& s) {
  const Mesh& shown = s.displayed();
  const Aabb box = boundingBox(shown);
  nlohmann::json levels;
  if (s.tree) levels = {{"count", s.sets.size()}, {"current", s.level}};
  return {{"name", s.name},
          {"link", s.link.empty() ? nlohmann::json() : nlohmann::json(s.link)},
          {"triangles", shown.triangles.size()},
          {"vertices", shown.vertices.size()},
          {"bounds",
           {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}}},
          {"diagonal", box.diagonal()},
          {"repaired", viewSolidRepaired(s)},
          {"set", s.set},
          {"spheres", spheres(s.spheres())},
          {"levels", levels},
          {"certificate", certificate(s.certificate)}};
}

nlohmann::json joints(const ViewScene& scene) {
  nlohmann::json a = nlohmann::json::array();
  if (!scene.robot) return a;
  // The joints a user moves: revolute, continuous and prismatic, not mimics (they follow).
  for (const RobotJoint& j : scene.robot->joints) {
    if (!isMovable(j) || j.mimic) continue;
    const auto [lower, upper] = jointSampleRange(j);
    const auto v = scene.joint_values.find(j.name);
    a.push_back({{"name", j.name},
                 {"type", jointTypeName(j.type)},
                 {"lower", lower},
                 {"upper", upper},
                 {"value", v == scene.joint_values.end() ? 0.0 : v->second}});
  }
  return a;
}

nlohmann::json poses(const ViewScene& scene) {
  nlohmann::json a = nlohmann::json::array();
  for (const Eigen::Isometry3d& p : scene.poses) {
    nlohmann::json m = nlohmann::json::array();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m.push_back(p.matrix()(r, c));
    a.push_back(m);
  }
  return a;
}

nlohmann::json save(const ViewScene& sc) {
  if (sc.save_path.empty()) return nullptr;
  nlohmann::json as = nlohmann::json::array();
  for (const ViewSaveFormat f : viewSaveFormats(sc))
    as.push_back({{"format", viewSaveFormatName(sc, f)}, {"path", viewSavePath(sc, f)}});
  return {{"path", sc.save_path}, {"format", viewSaveFormatName(sc, sc.save_format)}, {"as", as}};
}

nlohmann::json collisions(const ViewScene& sc) {
  if (!sc.robot) return nullptr;
  return {{"allowed", sc.allowed_pairs},
          {"allowed_source", sc.allowed_source},
          {"contact", viewContactPairs(sc)}};
}

// The fit request's quality row (fitRequestOptions): the names the page offers and its default,
// so that the page lists what the library takes, not a copy of it.
nlohmann::json fitChoices() {
  const OptionSpec* quality = findOption(fitRequestOptions(), "quality");
  nlohmann::json names = nlohmann::json::array();
  for (const char* name : quality->choices) names.push_back(name);
  return {{"qualities", names}, {"quality", quality->default_text}};
}

nlohmann::json scene(const ViewScene& sc) {
  nlohmann::json solids = nlohmann::json::array();
  for (const ViewSolid& s : sc.solids) solids.push_back(solid(s));
  return {{"kind", sc.kind == ViewKind::kRobot ? "robot" : "mesh"},
          {"title", sc.title},
          {"sets", sc.set_names},
          {"version", sc.version},
          {"solids", solids},
          {"joints", joints(sc)},
          {"poses", poses(sc)},
          {"collisions", collisions(sc)},
          {"fit", fitChoices()},
          {"save", save(sc)}};
}

nlohmann::json kinematics(const Robot& robot) {
  auto matrix = [](const Eigen::Isometry3d& m) {
    nlohmann::json a = nlohmann::json::array();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) a.push_back(m.matrix()(r, c));
    return a;
  };
  auto vec = [](const Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
  nlohmann::json joints_json = nlohmann::json::array();
  for (const RobotJoint& j : robot.joints) {
    const bool limited =
        j.type == RobotJoint::Type::kRevolute || j.type == RobotJoint::Type::kPrismatic;
    joints_json.push_back(
        {{"name", j.name},
         {"type", jointTypeName(j.type)},
         {"parent", j.parent},
         {"child", j.child},
         {"origin", matrix(j.origin)},
         {"axis", vec(j.axis)},
         {"anchor", vec(j.anchor)},
         {"reference", j.reference},
         {"limits", limited ? nlohmann::json{std::min(j.lower, j.upper), std::max(j.lower, j.upper)}
                            : nlohmann::json()},
         {"mimic", j.mimic ? nlohmann::json{{"joint", j.mimic->joint},
                                            {"multiplier", j.mimic->multiplier},
                                            {"offset", j.mimic->offset}}
                           : nlohmann::json()}});
  }
  return {{"root", robot.root}, {"joints", joints_json}};
}

nlohmann::json levelSets(const ViewSolid& s) {
  nlohmann::json a = nlohmann::json::array();
  for (size_t l = 0; l < s.sets.size(); ++l) {
    ViewSolid level = s;
    level.level = static_cast<int>(l);
    level.engine = nullptr;
    if (static_cast<int>(l) == s.level)
      level.certificate = s.certificate;
    else
      certifyViewSolid(&level);
    nlohmann::json c = certificate(level.certificate);
    c["seconds"] = 0.0;
    a.push_back({{"spheres", spheres(level.spheres())}, {"certificate", c}});
  }
  return a;
}

}  // namespace view_json

namespace {

void putU32(std::string* out, uint32_t v) {
  for (int b = 0; b < 4; ++b) out->push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
}

void putF32(std::string* out, double v) {
  const auto f = static_cast<float>(v);
  uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  putU32(out, bits);
}

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size())
      v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out.push_back(kDigits[(v >> 18) & 63]);
    out.push_back(kDigits[(v >> 12) & 63]);
    out.push_back(i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=');
    out.push_back(i + 2 < bytes.size() ? kDigits[v & 63] : '=');
  }
  return out;
}

}  // namespace

std::string viewSceneJson(const ViewScene& scene) {
  return view_json::scene(scene).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string viewGeometry(const ViewSolid& solid, ViewSurface surface) {
  const Mesh& m = surface == ViewSurface::kRepaired ? solid.input->repair.solid : solid.displayed();
  std::string out;
  constexpr size_t kHeaderBytes = 8, kVertexBytes = 12, kTriangleBytes = 12;
  out.reserve(kHeaderBytes + kVertexBytes * m.vertices.size() +
              kTriangleBytes * m.triangles.size());
  putU32(&out, static_cast<uint32_t>(m.vertices.size()));
  putU32(&out, static_cast<uint32_t>(m.triangles.size()));
  for (const Vec3& v : m.vertices)
    for (int k = 0; k < 3; ++k) putF32(&out, v[k]);
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) putU32(&out, static_cast<uint32_t>(t[static_cast<size_t>(k)]));
  return out;
}

bool viewPageAvailable() { return !view_page::html().empty(); }

Expected<std::string> inlineViewData(std::string_view html, const ViewScene& scene) {
  const size_t at = html.find(view_page::kDataMarker);
  if (at == std::string_view::npos)
    return Error{ErrorCode::kInvalidData,
                 "the page has no data marker " + std::string(view_page::kDataMarker)};
  nlohmann::json data = view_json::scene(scene);
  // A page file is the same bytes for the same inputs: no timings, and no save path of the
  // machine that wrote it (it cannot save).
  data["save"] = nullptr;
  for (size_t i = 0; i < scene.solids.size(); ++i) {
    data["solids"][i]["geometry"] = base64(viewGeometry(scene.solids[i]));
    if (viewSolidRepaired(scene.solids[i]))
      data["solids"][i]["repaired_geometry"] =
          base64(viewGeometry(scene.solids[i], ViewSurface::kRepaired));
    data["solids"][i]["certificate"]["seconds"] = 0.0;
    // A tree's every level with its certificate: changing the level is not an edit.
    if (scene.solids[i].tree)
      data["solids"][i]["level_sets"] = view_json::levelSets(scene.solids[i]);
  }
  // The robot's joint tree: the page poses the robot itself (posing is not an edit).
  if (scene.robot) data["kinematics"] = view_json::kinematics(*scene.robot);
  // '<' only occurs inside JSON strings, where \u003c means the same: the text can then never
  // close the script element.
  std::string text;
  for (const char c : data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)) {
    if (c == '<')
      text += "\\u003c";
    else
      text += c;
  }
  std::string out(html.substr(0, at));
  out += "<script id=\"sphereset-data\" type=\"application/json\">" + text + "</script>";
  out += html.substr(at + view_page::kDataMarker.size());
  return out;
}

Status checkViewPage() {
  if (viewPageAvailable()) return {};
  return Error{ErrorCode::kInvalidData,
               "this build has no view page (web/ was not built: Node.js and npm were missing "
               "when it was configured)"};
}

Expected<std::string> viewStaticPage(const ViewScene& scene) {
  if (Status st = checkViewPage(); !st) return st.error();
  return inlineViewData(view_page::html(), scene);
}

}  // namespace sphereset

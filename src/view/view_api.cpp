// The view's HTTP API as a pure function (docs/view.md): a request checked in order (size, Host
// and Origin, token, path, method, body: every field typed, finite and in range) and answered;
// the scene changes only through the library's functions, which check again and change nothing
// on an error.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/options.hpp"
#include "sphereset/view.hpp"
#include "view/view_json.hpp"
#include "view/view_page.hpp"

namespace sphereset {
namespace {

// HTTP statuses of the contract.
constexpr int kHttpOk = 200;
constexpr int kHttpBadRequest = 400;
constexpr int kHttpUnauthorized = 401;
constexpr int kHttpForbidden = 403;
constexpr int kHttpNotFound = 404;
constexpr int kHttpBadMethod = 405;
constexpr int kHttpTooLarge = 413;
constexpr int kHttpServerError = 500;

constexpr const char* kTokenHeader = "x-sphereset-token";

std::string jsonText(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

ViewResponse answer(const nlohmann::json& j) {
  return {kHttpOk, "application/json", jsonText(j), {}};
}

// Longest error message sent back: it may quote what the request held.
constexpr size_t kMaxMessageChars = 400;

// An error answer: one line (a control character of a quoted field or path becomes a space),
// at most kMaxMessageChars characters.
ViewResponse refuse(int status, const std::string& message) {
  std::string line = message.substr(0, kMaxMessageChars);
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return {status, "application/json", jsonText({{"error", line}}), {}};
}

// A library error as an answer: a file that could not be written or read (the save's) is the
// server's trouble, anything else the request's.
ViewResponse refuse(const Error& e) {
  const bool server = e.code == ErrorCode::kWriteFailed || e.code == ErrorCode::kUnreadable;
  return refuse(server ? kHttpServerError : kHttpBadRequest, e.message);
}

// The values of header `name` (lower case), as often as it was sent.
std::vector<std::string> headerValues(const ViewRequest& r, const std::string& name) {
  std::vector<std::string> v;
  for (const auto& [k, value] : r.headers)
    if (k == name) v.push_back(value);
  return v;
}

// The Host values that name this server: its address, localhost and 127.0.0.1, with its port.
std::set<std::string> ownHosts(const ViewAccess& a) {
  const std::string port = ":" + std::to_string(a.port);
  const bool v6 = a.host.find(':') != std::string::npos;
  return {(v6 ? "[" + a.host + "]" : a.host) + port, "localhost" + port, "127.0.0.1" + port};
}

bool sameToken(const std::string& given, const std::string& token) {
  if (given.size() != token.size() || token.empty()) return false;
  unsigned char diff = 0;  // every byte compared, whatever the first difference
  for (size_t i = 0; i < token.size(); ++i) diff |= static_cast<unsigned char>(given[i] ^ token[i]);
  return diff == 0;
}

// Whether `value` is "ADDRESS:PORT" with ADDRESS a numeric IPv4 address or a bracketed IPv6
// one: what a browser sends to a server reached by its address. A name, which DNS could point
// anywhere (rebinding), is not one.
bool addressHost(const std::string& value, int port) {
  const std::string tail = ":" + std::to_string(port);
  if (value.size() <= tail.size() || value.compare(value.size() - tail.size(), tail.size(), tail))
    return false;
  const std::string address = value.substr(0, value.size() - tail.size());
  if (address.size() > 2 && address.front() == '[' && address.back() == ']')
    return address.find_first_not_of("0123456789abcdefABCDEF:.", 1) == address.size() - 1;
  int dots = 0;
  for (const char c : address) {
    if (c == '.')
      ++dots;
    else if (c < '0' || c > '9')
      return false;
  }
  return dots == 3;
}

// 0 when the request may go on; else the status that refuses it, with `why`.
int checkAccess(const ViewAccess& a, const ViewRequest& r, std::string* why) {
  const std::set<std::string> hosts = ownHosts(a);
  const std::vector<std::string> host = headerValues(r, "host");
  // On every address (--host 0.0.0.0 or ::) the server is reached by any of its addresses.
  const bool any = a.host == "0.0.0.0" || a.host == "::";
  const auto own = [&](const std::string& h) {
    return hosts.count(h) > 0 || (any && addressHost(h, a.port));
  };
  if (host.size() != 1 || !own(host[0])) {
    *why = "Host is not this server's address";
    return kHttpForbidden;
  }
  // A browser sends Origin with every cross-site POST: only this server's own page may edit.
  const std::vector<std::string> origin = headerValues(r, "origin");
  const std::string scheme = "http://";
  if (origin.size() > 1 || (origin.size() == 1 && (origin[0].rfind(scheme, 0) != 0 ||
                                                   !own(origin[0].substr(scheme.size()))))) {
    *why = "Origin is not this server's page";
    return kHttpForbidden;
  }
  std::vector<std::string> tokens = headerValues(r, kTokenHeader);
  if (r.path == "/" && tokens.empty()) {
    const auto q = r.query.find("token");
    if (q != r.query.end()) tokens.push_back(q->second);
  }
  if (tokens.size() != 1 || !sameToken(tokens[0], a.token)) {
    *why = tokens.empty() ? "no token" : "wrong token";
    return kHttpUnauthorized;
  }
  return 0;
}

// Reading a request's body: every field checked, one message for the first that is wrong.
struct BodyError {
  std::string message;
};

void onlyFields(const nlohmann::json& j, const std::set<std::string>& allowed,
                const std::string& where) {
  if (!j.is_object()) throw BodyError{where + " must be a JSON object"};
  for (const auto& [key, value] : j.items())
    if (!allowed.count(key)) throw BodyError{where + ": unknown field '" + key + "'"};
}

const nlohmann::json& field(const nlohmann::json& j, const std::string& key,
                            const std::string& where) {
  const auto it = j.find(key);
  if (it == j.end()) throw BodyError{where + ": missing field '" + key + "'"};
  return *it;
}

int64_t integerField(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const nlohmann::json& v = field(j, key, where);
  if (v.is_number_unsigned()) {
    if (v.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int64_t>::max()))
      throw BodyError{where + ": '" + key + "' is out of range"};
    return static_cast<int64_t>(v.get<uint64_t>());
  }
  if (!v.is_number_integer()) throw BodyError{where + ": '" + key + "' must be an integer"};
  return v.get<int64_t>();
}

double number(const nlohmann::json& v, const std::string& what) {
  if (!v.is_number()) throw BodyError{what + " must be a number"};
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw BodyError{what + " must be finite"};
  return d;
}

Sphere sphereField(const nlohmann::json& j, const std::string& where) {
  const nlohmann::json& v = field(j, "sphere", where);
  if (!v.is_array() || v.size() != 4) throw BodyError{where + ": 'sphere' must be [x, y, z, r]"};
  Sphere s;
  for (int k = 0; k < 3; ++k) s.center[k] = number(v[static_cast<size_t>(k)], where + ": sphere");
  s.radius = number(v[3], where + ": sphere radius");
  return s;
}

std::vector<ViewEdit> editsOf(const nlohmann::json& body) {
  const nlohmann::json& list = field(body, "edits", "body");
  if (!list.is_array()) throw BodyError{"body: 'edits' must be a list"};
  std::vector<ViewEdit> edits;
  for (size_t e = 0; e < list.size(); ++e) {
    const std::string where = "edit " + std::to_string(e);
    const nlohmann::json& j = list[e];
    onlyFields(j, {"op", "index", "sphere"}, where);
    const nlohmann::json& op = field(j, "op", where);
    ViewEdit edit;
    if (op == "set") {
      edit.op = ViewEdit::Op::kSet;
      edit.index = integerField(j, "index", where);
      edit.sphere = sphereField(j, where);
    } else if (op == "add") {
      onlyFields(j, {"op", "sphere"}, where);
      edit.op = ViewEdit::Op::kAdd;
      edit.sphere = sphereField(j, where);
    } else if (op == "delete") {
      onlyFields(j, {"op", "index"}, where);
      edit.op = ViewEdit::Op::kDelete;
      edit.index = integerField(j, "index", where);
    } else {
      throw BodyError{where + ": 'op' must be \"set\", \"add\" or \"delete\""};
    }
    edits.push_back(edit);
  }
  return edits;
}

nlohmann::json setAnswer(const ViewScene& scene, int64_t solid) {
  const ViewSolid& s = scene.solids[static_cast<size_t>(solid)];
  return {{"version", scene.version},
          {"spheres", view_json::spheres(s.spheres())},
          {"certificate", view_json::certificate(s.certificate)},
          {"collisions", view_json::collisions(scene)}};
}

// The POST endpoints, each on a parsed body.
ViewResponse postEdit(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {"solid", "edits"}, "body");
  const int64_t solid = integerField(body, "solid", "body");
  if (Status st = applyViewEdits(scene, solid, editsOf(body)); !st) return refuse(st.error());
  return answer(setAnswer(*scene, solid));
}

ViewResponse postBound(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {"solid"}, "body");
  const int64_t solid = integerField(body, "solid", "body");
  if (Status st = boundViewSolid(scene, solid); !st) return refuse(st.error());
  return answer(setAnswer(*scene, solid));
}

ViewResponse postLevel(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {"solid", "level"}, "body");
  const int64_t solid = integerField(body, "solid", "body");
  const int64_t level = integerField(body, "level", "body");
  if (Status st = setViewLevel(scene, solid, level); !st) return refuse(st.error());
  return answer(setAnswer(*scene, solid));
}

ViewResponse postPose(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {"joints"}, "body");
  const nlohmann::json& j = field(body, "joints", "body");
  if (!j.is_object()) throw BodyError{"body: 'joints' must be an object"};
  std::map<std::string, double> values;
  for (const auto& [name, v] : j.items()) values[name] = number(v, "joint '" + name + "'");
  if (Status st = setViewJoints(scene, values); !st) return refuse(st.error());
  return answer({{"version", scene->version},
                 {"poses", view_json::poses(*scene)},
                 {"joints", view_json::joints(*scene)},
                 {"collisions", view_json::collisions(*scene)}});
}

// The path is the scene's, fixed when it was loaded; the body names nothing.
// {"format": "yaml"|"urdf"|"mjcf"} saves a robot as another format, beside the save path.
ViewResponse postSave(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {"format"}, "body");
  std::optional<ViewSaveFormat> as;
  if (body.contains("format")) {
    if (!body["format"].is_string())
      throw BodyError{"body: 'format' must be yaml, urdf, mjcf or lula"};
    auto f = viewRobotSaveFormat(body["format"].get<std::string>());
    if (!f) return refuse(f.error());
    as = *f;
  }
  auto bytes = saveViewScene(*scene, as);
  if (!bytes) return refuse(bytes.error());
  return answer(
      {{"path", viewSavePath(*scene, as.value_or(scene->save_format))}, {"bytes", *bytes}});
}

// The tolerance's rows of a fit body (max_protrusion a number or a text such as "5%", max_er,
// max_spheres), each handed to the library's table as the text a user types; a bad value is
// refused in the table's words.
Status setBodyTolerance(const nlohmann::json& body, ToleranceOptions* t) {
  for (const char* name : {"max_protrusion", "max_er", "max_spheres"}) {
    if (!body.contains(name)) continue;
    const nlohmann::json& v = body[name];
    std::string text;
    if (v.is_string())
      text = v.get<std::string>();
    else if (v.is_number_integer())
      text = std::to_string(v.get<int64_t>());
    else if (v.is_number())
      text = optionText(v.get<double>());
    else
      throw BodyError{std::string("body: '") + name + "' must be a number or a text"};
    if (Status st = setToleranceOption(t, name, text); !st) return st;
  }
  return {};
}

// POST /api/fit {"solid": K, "spheres": n, "quality": q}, {"solid": K, "max_protrusion": D,
// "max_er": X, "max_spheres": M, "quality": q} (a tolerance instead of n), or for a robot
// {"budget": B, "max_protrusion": D, "quality": q} ("robot": true instead of a budget with a
// limit).
ViewResponse postFit(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(
      body,
      {"solid", "spheres", "budget", "robot", "quality", "max_protrusion", "max_er", "max_spheres"},
      "body");
  ViewFitRequest r;
  if (Status st = setBodyTolerance(body, &r.tolerance); !st) return refuse(st.error());
  // By the body's keys, as the command line's flags: a count with a tolerance, or a cap without
  // one, is refused in the library's words.
  FitRequest given;
  given.count_given = body.contains("spheres");
  if (Status st = checkToleranceRequest(given, r.tolerance); !st) return refuse(st.error());
  if (body.contains("budget") || body.contains("robot")) {
    // A robot's links each have their own cap: no max_spheres.
    onlyFields(body, {"budget", "robot", "quality", "max_protrusion", "max_er"}, "body");
    if (body.contains("robot")) {
      if (!body["robot"].is_boolean() || !body["robot"].get<bool>())
        throw BodyError{"body: 'robot' must be true"};
      r.robot = true;
    }
    if (body.contains("budget")) {
      r.budget = static_cast<int>(
          std::clamp<int64_t>(integerField(body, "budget", "body"), 0, limits::kMaxSpheres + 1));
      if (r.budget == 0) throw BodyError{"body: 'budget' must be at least 1"};
    }
  } else {
    r.solid = integerField(body, "solid", "body");
    if (body.contains("spheres") || !r.tolerance.active())
      r.spheres = static_cast<int>(
          std::clamp<int64_t>(integerField(body, "spheres", "body"), 0, limits::kMaxSpheres + 1));
  }
  if (body.contains("quality")) {
    const nlohmann::json& q = body["quality"];
    if (!q.is_string()) throw BodyError{"body: 'quality' must be fast, default or best"};
    auto quality = fitQualityFromName(q.get<std::string>());
    if (!quality) return refuse(quality.error());
    r.quality = *quality;
  }
  if (Status st = startViewFit(scene, r); !st) return refuse(st.error());
  return answer({{"state", "running"}});
}

// POST /api/fit/status {}: how the fit is; a finished one is applied (and its sets sent).
ViewResponse postFitStatus(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {}, "body");
  const ViewFitStatus st = viewFitStatus(scene);
  nlohmann::json j = {{"state", st.state},         {"fraction", st.fraction},
                      {"stage", st.stage},         {"error", st.error},
                      {"solids", st.solids},       {"counts", st.counts},
                      {"tolerance", st.tolerance}, {"tolerance_met", st.tolerance_met},
                      {"applied", st.applied},     {"version", scene->version}};
  if (st.applied) {
    nlohmann::json sets = nlohmann::json::array();
    for (const int64_t k : st.solids) sets.push_back(setAnswer(*scene, k));
    j["sets"] = sets;
  }
  return answer(j);
}

ViewResponse postFitCancel(ViewScene* scene, const nlohmann::json& body) {
  onlyFields(body, {}, "body");
  cancelViewFit(scene);
  return answer({{"state", viewFitStatus(scene).state}});
}

// The GET endpoints.
ViewResponse getPage(const ViewScene&, const ViewRequest&) {
  if (Status st = checkViewPage(); !st) return refuse(kHttpServerError, st.error().message);
  return {kHttpOk, "text/html; charset=utf-8", std::string(view_page::html()), {}};
}

ViewResponse getScene(const ViewScene& scene, const ViewRequest&) {
  return {kHttpOk, "application/json", viewSceneJson(scene), {}};
}

// /api/geometry?solid=K[&surface=displayed|repaired], K a decimal index.
ViewResponse getGeometry(const ViewScene& scene, const ViewRequest& r) {
  ViewSurface surface = ViewSurface::kDisplayed;
  if (const auto f = r.query.find("surface"); f != r.query.end()) {
    if (f->second == "repaired")
      surface = ViewSurface::kRepaired;
    else if (f->second != "displayed")
      return refuse(kHttpBadRequest, "geometry: 'surface' must be displayed or repaired");
  }
  const auto q = r.query.find("solid");
  const std::string k = q == r.query.end() ? "" : q->second;
  constexpr size_t kMaxIndexDigits = 9;
  if (k.empty() || k.size() > kMaxIndexDigits ||
      k.find_first_not_of("0123456789") != std::string::npos)
    return refuse(kHttpBadRequest, "geometry: 'solid' must be a solid's index");
  const auto solid = std::stoll(k);
  if (solid >= static_cast<int64_t>(scene.solids.size()))
    return refuse(kHttpBadRequest,
                  "no solid " + k + " (the scene has " + std::to_string(scene.solids.size()) + ")");
  return {kHttpOk,
          "application/octet-stream",
          viewGeometry(scene.solids[static_cast<size_t>(solid)], surface),
          {}};
}

// The routes, the only paths answered: each path reads (GET, and HEAD) or changes (POST).
struct Route {
  std::string_view path;
  ViewResponse (*get)(const ViewScene&, const ViewRequest&);
  ViewResponse (*post)(ViewScene*, const nlohmann::json&);
};
constexpr Route kRoutes[] = {
    {"/", getPage, nullptr},
    {"/api/scene", getScene, nullptr},
    {"/api/geometry", getGeometry, nullptr},
    {"/api/edit", nullptr, postEdit},
    {"/api/bound", nullptr, postBound},
    {"/api/level", nullptr, postLevel},
    {"/api/pose", nullptr, postPose},
    {"/api/save", nullptr, postSave},
    {"/api/fit", nullptr, postFit},
    {"/api/fit/status", nullptr, postFitStatus},
    {"/api/fit/cancel", nullptr, postFitCancel},
};

const Route* routeOf(const std::string& path) {
  for (const Route& r : kRoutes)
    if (r.path == path) return &r;
  return nullptr;
}

// The answer before its headers.
ViewResponse dispatch(ViewScene* scene, const ViewAccess& access, const ViewRequest& request) {
  if (request.body.size() > static_cast<size_t>(limits::kMaxViewRequestBytes))
    return refuse(kHttpTooLarge,
                  "the body is over " + std::to_string(limits::kMaxViewRequestBytes) + " bytes");
  std::string why;
  if (const int status = checkAccess(access, request, &why); status != 0)
    return refuse(status, why);
  const Route* route = routeOf(request.path);
  if (route == nullptr) return refuse(kHttpNotFound, "no such path: " + request.path);
  const bool reads = request.method == "GET" || request.method == "HEAD";
  if (route->get != nullptr) {
    if (!reads)
      return refuse(kHttpBadMethod, request.method + " is not allowed on " + request.path);
    return route->get(*scene, request);
  }
  if (request.method != "POST")
    return refuse(kHttpBadMethod, request.method + " is not allowed on " + request.path);
  const std::vector<std::string> type = headerValues(request, "content-type");
  if (type.size() != 1 || type[0].rfind("application/json", 0) != 0)
    return refuse(kHttpBadRequest, "the body must be JSON (Content-Type: application/json)");
  try {
    const nlohmann::json body = nlohmann::json::parse(request.body);
    return route->post(scene, body);
  } catch (const nlohmann::json::exception& e) {
    return refuse(kHttpBadRequest, std::string("bad JSON: ") + e.what());
  } catch (const BodyError& e) {
    return refuse(kHttpBadRequest, e.message);
  }
}

}  // namespace

std::string randomViewToken() {
  std::random_device rd;
  constexpr int kTokenWords = 4;  // 4 × 32 = 128 bits
  std::string out;
  for (int w = 0; w < kTokenWords; ++w) {
    const uint32_t v = rd();
    static constexpr char kHex[] = "0123456789abcdef";
    for (int d = 7; d >= 0; --d) out.push_back(kHex[(v >> (4 * d)) & 0xfu]);
  }
  return out;
}

const std::vector<std::pair<std::string, std::string>>& viewResponseHeaders() {
  static const std::vector<std::pair<std::string, std::string>> kHeaders = {
      {"Cache-Control", "no-store"},
      {"X-Content-Type-Options", "nosniff"},
      {"Referrer-Policy", "no-referrer"},
      {"X-Frame-Options", "DENY"},
  };
  return kHeaders;
}

ViewResponse handleViewRequest(ViewScene* scene, const ViewAccess& access,
                               const ViewRequest& request) {
  ViewResponse out = dispatch(scene, access, request);
  out.headers = viewResponseHeaders();
  return out;
}

}  // namespace sphereset

// MJCF output (https://mujoco.readthedocs.io/en/2.2.2/XMLreference.html): a robot with the
// collision geoms of chosen links replaced by sphere geoms, as a file MuJoCo loads. The starting
// model is MuJoCo's own: the MJCF (or the URDF, through MuJoCo's URDF reader) compiled by
// mj_loadXML and written back by mj_saveLastXML, which resolves includes and keeps classes,
// defaults, visual geoms, actuators and the rest. Its <body> elements come in MuJoCo's body
// order and their <geom> children in geom order, which ties each element to the compiled model
// (checked by count). Each body's compiled inertia is written out explicitly and the compiler
// told not to derive inertia from geoms, so replacing geoms does not change the dynamics. The
// result is loaded by MuJoCo from its own folder before it is returned.
#include <tinyxml.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "io/atomic_write.hpp"
#include "robot/mjcf.hpp"
#include "robot/mujoco_model.hpp"
#include "robot/sphere_writers.hpp"
#include "robot/xml_text.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"
#include "util/utf8.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;
using detail::oneLine;

// The attributes of the first replaced geom that its sphere geoms keep (the contract:
// what decides who they collide with and how).
constexpr const char* kKeptGeomAttributes[] = {"class",       "group",  "contype",
                                               "conaffinity", "condim", "friction"};

// The shortest decimal text that reads back as exactly `x`.
std::string mjcfNumber(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return r.ec == std::errc() ? std::string(buf, r.ptr) : std::string("nan");
}

std::string mjcfNumbers(const double* v, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) {
    if (i > 0) out += ' ';
    out += mjcfNumber(v[i]);
  }
  return out;
}

std::string printed(const TiXmlDocument& doc) {
  TiXmlPrinter printer;
  printer.SetIndent("  ");
  doc.Accept(&printer);
  return printer.Str();
}

// The <body> elements under `parent` in document (pre-)order.
void collectBodies(TiXmlElement* parent, std::vector<TiXmlElement*>& out) {
  for (TiXmlElement* b = parent->FirstChildElement("body"); b != nullptr;
       b = b->NextSiblingElement("body")) {
    out.push_back(b);
    collectBodies(b, out);
  }
}

// Replaces body `b`'s collision geoms (elements `geoms`, in geom order) by `spheres`.
void replaceGeoms(const mjModel& m, int b, const std::string& link,
                  const std::vector<TiXmlElement*>& geoms, const std::vector<Sphere>& spheres,
                  const RobotLoadOptions& options, TiXmlElement* body) {
  // Planes and height fields are not fitted (they are not solids): they stay.
  std::vector<TiXmlElement*> old;
  for (size_t k = 0; k < geoms.size(); ++k) {
    const int g = m.body_geomadr[b] + static_cast<int>(k);
    if (detail::isCollisionGeom(m, g, options) && m.geom_type[g] != mjGEOM_PLANE &&
        m.geom_type[g] != mjGEOM_HFIELD)
      old.push_back(geoms[k]);
  }
  for (size_t i = 0; i < spheres.size(); ++i) {
    TiXmlElement geom("geom");
    geom.SetAttribute("name", link + "_sphere_" + std::to_string(i));
    if (!old.empty())
      for (const char* a : kKeptGeomAttributes)
        if (const char* v = old.front()->Attribute(a)) geom.SetAttribute(a, v);
    geom.SetAttribute("type", "sphere");
    geom.SetAttribute("size", mjcfNumber(spheres[i].radius));
    geom.SetAttribute("pos", mjcfNumbers(spheres[i].center.data(), 3));
    if (old.empty()) {
      body->InsertEndChild(geom);
    } else {
      body->InsertBeforeChild(old.front(), geom);
    }
  }
  for (TiXmlElement* g : old) body->RemoveChild(g);
}

// The child elements of `parent` whose tag is one of `tags`, in document order.
std::vector<TiXmlElement*> childElements(TiXmlElement* parent,
                                         std::initializer_list<std::string_view> tags) {
  std::vector<TiXmlElement*> out;
  for (TiXmlElement* e = parent->FirstChildElement(); e != nullptr; e = e->NextSiblingElement())
    for (std::string_view t : tags)
      if (e->ValueStr() == t) out.push_back(e);
  return out;
}

// MuJoCo 2.2.2 writes numbers with six significant digits (a stream's default precision):
// body `b`'s frame, its joints, its sites and its primitive geoms get back the compiled
// model's doubles. (A mesh geom's compiled frame includes the mesh's re-centring, which the
// written file does not: its six digits stay. Replaced geoms are written in full anyway.)
void restorePrecision(const mjModel& m, int b, TiXmlElement* body) {
  if (b > 0) {
    body->SetAttribute("pos", mjcfNumbers(m.body_pos + 3 * b, 3));
    body->SetAttribute("quat", mjcfNumbers(m.body_quat + 4 * b, 4));
  }
  const std::vector<TiXmlElement*> joints = childElements(body, {"joint", "freejoint"});
  if (static_cast<int>(joints.size()) == m.body_jntnum[b])
    for (int k = 0; k < m.body_jntnum[b]; ++k) {
      const int j = m.body_jntadr[b] + k;
      TiXmlElement* e = joints[static_cast<size_t>(k)];
      if (m.jnt_type[j] == mjJNT_FREE) continue;
      e->SetAttribute("pos", mjcfNumbers(m.jnt_pos + 3 * j, 3));
      if (m.jnt_type[j] != mjJNT_BALL) e->SetAttribute("axis", mjcfNumbers(m.jnt_axis + 3 * j, 3));
      if (e->Attribute("range") != nullptr)
        e->SetAttribute("range", mjcfNumbers(m.jnt_range + 2 * j, 2));
      if (e->Attribute("ref") != nullptr && m.jnt_type[j] != mjJNT_BALL)
        e->SetAttribute("ref", mjcfNumber(m.qpos0[m.jnt_qposadr[j]]));
    }
  const std::vector<TiXmlElement*> geoms = childElements(body, {"geom"});
  if (static_cast<int>(geoms.size()) == m.body_geomnum[b])
    for (int k = 0; k < m.body_geomnum[b]; ++k) {
      const int g = m.body_geomadr[b] + k;
      const int type = m.geom_type[g];
      if (type == mjGEOM_MESH || type == mjGEOM_HFIELD) continue;
      TiXmlElement* e = geoms[static_cast<size_t>(k)];
      const int sizes = type == mjGEOM_SPHERE                                 ? 1
                        : (type == mjGEOM_CAPSULE || type == mjGEOM_CYLINDER) ? 2
                                                                              : 3;
      e->RemoveAttribute("fromto");
      e->SetAttribute("pos", mjcfNumbers(m.geom_pos + 3 * g, 3));
      e->SetAttribute("quat", mjcfNumbers(m.geom_quat + 4 * g, 4));
      e->SetAttribute("size", mjcfNumbers(m.geom_size + 3 * g, sizes));
    }
  std::vector<int> sites;
  for (int s = 0; s < m.nsite; ++s)
    if (m.site_bodyid[s] == b) sites.push_back(s);
  const std::vector<TiXmlElement*> site_elements = childElements(body, {"site"});
  if (site_elements.size() == sites.size())
    for (size_t k = 0; k < sites.size(); ++k) {
      site_elements[k]->SetAttribute("pos", mjcfNumbers(m.site_pos + 3 * sites[k], 3));
      site_elements[k]->SetAttribute("quat", mjcfNumbers(m.site_quat + 4 * sites[k], 4));
    }
}

// Body `b`'s compiled inertia as an explicit <inertial> (replacing any), when it has mass.
void writeInertial(const mjModel& m, int b, TiXmlElement* body) {
  if (!(m.body_mass[b] > 0.0)) return;
  while (TiXmlElement* old = body->FirstChildElement("inertial")) body->RemoveChild(old);
  TiXmlElement inertial("inertial");
  inertial.SetAttribute("pos", mjcfNumbers(m.body_ipos + 3 * b, 3));
  inertial.SetAttribute("quat", mjcfNumbers(m.body_iquat + 4 * b, 4));
  inertial.SetAttribute("mass", mjcfNumber(m.body_mass[b]));
  inertial.SetAttribute("diaginertia", mjcfNumbers(m.body_inertia + 3 * b, 3));
  if (TiXmlElement* first = body->FirstChildElement()) {
    body->InsertBeforeChild(first, inertial);
  } else {
    body->InsertEndChild(inertial);
  }
}

// Every asset file named by a path that resolves from `out_dir` (relative where one exists),
// found from the model's folder through the compiler's meshdir, texturedir and assetdir, which
// are then dropped, as is a strippath that would cut those paths.
void relocateAssets(TiXmlElement* root, const fs::path& model_dir, const fs::path& out_dir) {
  std::map<std::string, std::string> dirs;
  for (TiXmlElement* c = root->FirstChildElement("compiler"); c != nullptr;
       c = c->NextSiblingElement("compiler"))
    for (const char* a : {"meshdir", "texturedir", "assetdir"}) {
      if (const char* v = c->Attribute(a)) dirs[a] = v;
      c->RemoveAttribute(a);
    }
  // The paths written are the ones to follow (strippath would keep their file names alone).
  for (TiXmlElement* c = root->FirstChildElement("compiler"); c != nullptr;
       c = c->NextSiblingElement("compiler"))
    if (c->Attribute("strippath") != nullptr) c->SetAttribute("strippath", "false");
  std::error_code ec;
  const fs::path out_abs = fs::weakly_canonical(fs::absolute(out_dir), ec);
  for (TiXmlElement* asset = root->FirstChildElement("asset"); asset != nullptr;
       asset = asset->NextSiblingElement("asset"))
    for (TiXmlElement* e = asset->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string own = e->ValueStr() == "texture" ? "texturedir" : "meshdir";
      for (TiXmlAttribute* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
        if (a->NameTStr().rfind("file", 0) != 0) continue;
        const fs::path file = a->ValueStr();
        fs::path found = file;
        if (!file.is_absolute()) {
          found = model_dir / dirs[own] / file;
          for (const fs::path& c : {model_dir / dirs[own] / file,
                                    model_dir / dirs["assetdir"] / file, model_dir / file})
            if (fs::exists(c, ec)) {
              found = c;
              break;
            }
        }
        const fs::path abs = fs::weakly_canonical(fs::absolute(found), ec);
        const fs::path rel = abs.lexically_relative(out_abs);
        a->SetValue((rel.empty() ? abs : rel).generic_string());
      }
    }
}

// A compiled model and the text MuJoCo writes back for it (the same bodies and geoms, in order).
struct Start {
  detail::MjModelPtr model;
  std::string xml;
};

// The URDF's starting model: the listed links' collisions already spheres (formatSphereUrdf),
// every other mesh path resolved as loadRobot resolves it, visuals dropped, and MuJoCo told to
// keep every link a body and to read paths as given.
Expected<Start> urdfStart(const std::string& in, const std::vector<LinkSpheres>& spheres,
                          const RobotLoadOptions& options) {
  auto robot = loadRobot(in, options);
  if (!robot) return robot.error();
  auto text = formatSphereUrdf(in, spheres);
  if (!text) return text.error();
  TiXmlDocument doc;
  doc.Parse(text->c_str());
  TiXmlElement* root = doc.RootElement();
  std::map<std::string, const RobotLink*> links;
  for (const RobotLink& l : robot->links) links.emplace(l.name, &l);
  for (TiXmlElement* link = root->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    while (TiXmlElement* v = link->FirstChildElement("visual")) link->RemoveChild(v);
    const char* name = link->Attribute("name");
    const auto it = links.find(name ? name : "");
    if (it == links.end() || it->second->from_visual) continue;
    size_t k = 0;
    for (TiXmlElement* c = link->FirstChildElement("collision"); c != nullptr;
         c = c->NextSiblingElement("collision"), ++k) {
      TiXmlElement* g = c->FirstChildElement("geometry");
      TiXmlElement* mesh = g ? g->FirstChildElement("mesh") : nullptr;
      if (mesh != nullptr && k < it->second->geometry.size())
        mesh->SetAttribute(
            "filename",
            fs::absolute(it->second->geometry[k].mesh_path).lexically_normal().string());
    }
  }
  while (TiXmlElement* old = root->FirstChildElement("mujoco")) root->RemoveChild(old);
  TiXmlElement mujoco("mujoco");
  TiXmlElement compiler("compiler");
  compiler.SetAttribute("strippath", "false");
  compiler.SetAttribute("fusestatic", "false");
  compiler.SetAttribute("discardvisual", "true");
  mujoco.InsertEndChild(compiler);
  root->InsertEndChild(mujoco);
  const detail::TempFile tmp(".urdf");
  if (tmp.path().empty())
    return Error{ErrorCode::kWriteFailed, in + ": no temporary file for MuJoCo's reading"};
  std::ofstream(tmp.path(), std::ios::binary) << printed(doc);
  Start out;
  auto model = detail::compileWithMujoco(tmp.path(), in, &out.xml);
  if (!model) return model.error();
  out.model = std::move(*model);
  return out;
}

Expected<Start> mjcfStart(const std::string& in, const RobotLoadOptions& options) {
  auto robot = loadRobot(in, options);  // its checks and errors first
  if (!robot) return robot.error();
  Start out;
  auto model = detail::compileWithMujoco(in, in, &out.xml);
  if (!model) return model.error();
  out.model = std::move(*model);
  return out;
}

// MuJoCo's model of `text` as a file in `dir` (so that relative paths resolve as they will).
Expected<detail::MjModelPtr> loadFrom(const std::string& text, const fs::path& dir,
                                      const std::string& name) {
  const detail::TempFile tmp(".xml", dir.string());
  if (tmp.path().empty())
    return Error{ErrorCode::kWriteFailed,
                 name + ": cannot create a file in '" + dir.string() + "'"};
  std::ofstream(tmp.path(), std::ios::binary) << text;
  auto model = detail::compileWithMujoco(tmp.path(), name);
  if (!model)
    return Error{model.error().code,
                 name + ": the MJCF written does not load in MuJoCo: " + model.error().message};
  return model;
}

// One <exclude> per pair naming two bodies that MuJoCo does not already keep apart; the text
// unchanged when there is none.
Expected<std::string> addExcludes(TiXmlDocument& doc, const mjModel& m,
                                  const std::vector<std::array<std::string, 2>>& exclude) {
  std::set<std::pair<int, int>> pairs;
  for (const auto& [x, y] : exclude) {
    const int a = mj_name2id(&m, mjOBJ_BODY, x.c_str()), b = mj_name2id(&m, mjOBJ_BODY, y.c_str());
    if (a < 0 || b < 0 || a == b || detail::bodiesFiltered(m, a, b)) continue;
    pairs.emplace(std::min(a, b), std::max(a, b));
  }
  if (pairs.empty()) return std::string();
  TiXmlElement* root = doc.RootElement();
  TiXmlElement* contact = root->FirstChildElement("contact");
  if (contact == nullptr) contact = root->InsertEndChild(TiXmlElement("contact"))->ToElement();
  for (const auto& [a, b] : pairs) {
    TiXmlElement e("exclude");
    e.SetAttribute("body1", detail::mujocoName(m, mjOBJ_BODY, a, "body"));
    e.SetAttribute("body2", detail::mujocoName(m, mjOBJ_BODY, b, "body"));
    contact->InsertEndChild(e);
  }
  return printed(doc);
}

}  // namespace

Expected<std::string> formatSphereMjcf(const std::string& in_robot, const std::string& out_path,
                                       const std::vector<LinkSpheres>& spheres,
                                       const std::vector<std::array<std::string, 2>>& exclude,
                                       const RobotLoadOptions& options) {
  auto listed = detail::spheresByLink(in_robot, spheres);
  if (!listed) return listed.error();
  const bool urdf = detail::extensionOf(in_robot) != ".xml";
  auto start = urdf ? urdfStart(in_robot, spheres, options) : mjcfStart(in_robot, options);
  if (!start) return start.error();
  const mjModel& m = *start->model;

  TiXmlDocument doc;
  doc.Parse(start->xml.c_str());
  TiXmlElement* root = doc.RootElement();
  TiXmlElement* world = root ? root->FirstChildElement("worldbody") : nullptr;
  if (doc.Error() || world == nullptr)
    return Error{ErrorCode::kInvalidData, in_robot +
                                              ": MuJoCo wrote the model without a "
                                              "<worldbody>"};
  std::vector<TiXmlElement*> bodies = {world};
  collectBodies(world, bodies);
  if (static_cast<int>(bodies.size()) != m.nbody)
    return Error{ErrorCode::kInvalidData, in_robot + ": MuJoCo wrote " +
                                              std::to_string(bodies.size()) + " bodies of its " +
                                              std::to_string(m.nbody)};
  std::set<std::string> found;
  for (int b = 0; b < m.nbody; ++b) {
    std::vector<TiXmlElement*> geoms;
    for (TiXmlElement* g = bodies[b]->FirstChildElement("geom"); g != nullptr;
         g = g->NextSiblingElement("geom"))
      geoms.push_back(g);
    if (static_cast<int>(geoms.size()) != m.body_geomnum[b])
      return Error{ErrorCode::kInvalidData,
                   in_robot + ": MuJoCo wrote " + std::to_string(geoms.size()) + " geoms of its " +
                       std::to_string(m.body_geomnum[b]) + " in body " + std::to_string(b)};
    restorePrecision(m, b, bodies[b]);
    const std::string name = detail::mujocoName(m, mjOBJ_BODY, b, "body");
    const auto it = listed->find(name);
    if (it != listed->end()) {
      found.insert(name);
      // (From a URDF, the body's geoms are already these spheres, in six digits.)
      replaceGeoms(m, b, name, geoms, *it->second, options, bodies[b]);
    }
    if (b > 0) writeInertial(m, b, bodies[b]);
  }
  for (const auto& [name, list] : *listed)
    if (!urdf && found.count(name) == 0 && !list->empty())
      return Error{ErrorCode::kInvalidArgument, in_robot + ": no body named '" + name + "'"};
  TiXmlElement* compiler = root->FirstChildElement("compiler");
  if (compiler == nullptr) {
    TiXmlElement fresh("compiler");
    compiler = root->FirstChildElement()
                   ? root->InsertBeforeChild(root->FirstChildElement(), fresh)->ToElement()
                   : root->InsertEndChild(fresh)->ToElement();
  }
  compiler->SetAttribute("inertiafromgeom", "false");
  const fs::path model_dir = fs::absolute(in_robot).parent_path();
  const fs::path out_dir = fs::absolute(out_path).parent_path();
  relocateAssets(root, model_dir, out_dir);
  std::string text = printed(doc);
  auto written = loadFrom(text, out_dir, in_robot);
  if (!written) return written.error();
  auto with_excludes = addExcludes(doc, **written, exclude);
  if (!with_excludes) return with_excludes.error();
  if (with_excludes->empty()) return text;
  if (auto again = loadFrom(*with_excludes, out_dir, in_robot); !again) return again.error();
  return *with_excludes;
}

Status writeSphereMjcf(const std::string& in_robot, const std::string& out_path,
                       const std::vector<LinkSpheres>& spheres,
                       const std::vector<std::array<std::string, 2>>& exclude,
                       const RobotLoadOptions& options) {
  // The robot's own description is never replaced by its spheres.
  if (Status st = checkOutputPath(out_path, {in_robot}); !st) return st;
  auto text = formatSphereMjcf(in_robot, out_path, spheres, exclude, options);
  if (!text) return text.error();
  return writeFileAtomically(out_path, *text);
}

}  // namespace sphereset

// URDF output (http://wiki.ros.org/urdf/XML): an input URDF with the <collision> elements of
// chosen links replaced by one sphere collision per fitted sphere. The document goes through
// TinyXML (as urdfdom reads it), which keeps elements, attributes (in order) and comments but
// not the original indentation.
#include <tinyxml.h>

#include <charconv>
#include <cmath>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "io/atomic_write.hpp"
#include "robot/sphere_writers.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/read_file.hpp"
#include "util/utf8.hpp"

namespace sphereset {
namespace {

using detail::oneLine;

// The shortest decimal text that reads back as exactly `x`.
std::string number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return r.ec == std::errc() ? std::string(buf, r.ptr) : std::string("nan");
}

std::string vec3(const Vec3& v) {
  return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

// <collision name="sphere_i"><origin .../><geometry><sphere radius="r"/></geometry></collision>
TiXmlElement sphereCollision(size_t i, const Sphere& s) {
  TiXmlElement collision("collision");
  collision.SetAttribute("name", "sphere_" + std::to_string(i));
  TiXmlElement origin("origin");
  origin.SetAttribute("xyz", vec3(s.center));
  origin.SetAttribute("rpy", "0 0 0");
  collision.InsertEndChild(origin);
  TiXmlElement sphere("sphere");
  sphere.SetAttribute("radius", number(s.radius));
  TiXmlElement geometry("geometry");
  geometry.InsertEndChild(sphere);
  collision.InsertEndChild(geometry);
  return collision;
}

// Replaces the collisions of one <link>.
void replaceCollisions(TiXmlElement* link, const std::vector<Sphere>& spheres) {
  std::vector<TiXmlElement*> old;
  for (TiXmlElement* c = link->FirstChildElement("collision"); c != nullptr;
       c = c->NextSiblingElement("collision"))
    old.push_back(c);
  for (size_t i = 0; i < spheres.size(); ++i) {
    const TiXmlElement collision = sphereCollision(i, spheres[i]);
    if (old.empty()) {
      link->InsertEndChild(collision);
    } else {
      link->InsertBeforeChild(old.front(), collision);
    }
  }
  for (TiXmlElement* c : old) link->RemoveChild(c);
}

}  // namespace

namespace detail {

Expected<std::map<std::string, const std::vector<Sphere>*>> spheresByLink(
    const std::string& in_path, const std::vector<LinkSpheres>& spheres) {
  const auto invalid = [&](ErrorCode code, const std::string& what) {
    return Error{code, oneLine(in_path + ": " + what)};
  };
  std::map<std::string, const std::vector<Sphere>*> by_link;
  for (const LinkSpheres& ls : spheres) {
    if (!by_link.emplace(ls.link, &ls.spheres).second)
      return invalid(ErrorCode::kInvalidArgument, "link '" + ls.link + "' is listed twice");
    for (size_t i = 0; i < ls.spheres.size(); ++i) {
      const Sphere& s = ls.spheres[i];
      const std::string where = "link '" + ls.link + "' sphere " + std::to_string(i);
      if (!s.center.allFinite() || !std::isfinite(s.radius))
        return invalid(ErrorCode::kInvalidData, where + ": NaN or infinite value");
      if (s.radius < 0.0) return invalid(ErrorCode::kInvalidData, where + ": negative radius");
    }
  }
  return by_link;
}

}  // namespace detail

Expected<std::string> formatSphereUrdf(const std::string& in_urdf,
                                       const std::vector<LinkSpheres>& spheres) {
  const auto invalid = [&](ErrorCode code, const std::string& what) {
    return Error{code, oneLine(in_urdf + ": " + what)};
  };
  // The spheres by link name, checked before the file is read.
  auto listed = detail::spheresByLink(in_urdf, spheres);
  if (!listed) return listed.error();
  const std::map<std::string, const std::vector<Sphere>*>& by_link = *listed;

  auto text = detail::readFileText(in_urdf);
  if (!text) return Error{text.error().code, oneLine(text.error().message)};
  TiXmlDocument doc;
  doc.Parse(text->c_str());
  if (doc.Error())
    return invalid(ErrorCode::kInvalidData, "not XML (line " + std::to_string(doc.ErrorRow()) +
                                                ": " + doc.ErrorDesc() + ")");
  TiXmlElement* robot = doc.RootElement();
  if (robot == nullptr || robot->ValueStr() != "robot")
    return invalid(ErrorCode::kInvalidData, "not a URDF: no <robot> root element");

  std::map<std::string, bool> found;
  for (TiXmlElement* link = robot->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    const char* name = link->Attribute("name");
    if (name == nullptr) continue;
    const auto it = by_link.find(name);
    if (it == by_link.end()) continue;
    replaceCollisions(link, *it->second);
    found[name] = true;
  }
  for (const LinkSpheres& ls : spheres)
    if (!found[ls.link])
      return invalid(ErrorCode::kInvalidArgument, "no link named '" + ls.link + "'");

  TiXmlPrinter printer;
  printer.SetIndent("  ");
  doc.Accept(&printer);
  return printer.Str();
}

Status writeSphereUrdf(const std::string& in_urdf, const std::string& out_path,
                       const std::vector<LinkSpheres>& spheres) {
  // The robot's own description is never replaced by its spheres.
  if (Status st = checkOutputPath(out_path, {in_urdf}); !st) return st;
  auto text = formatSphereUrdf(in_urdf, spheres);
  if (!text) return text.error();
  return writeFileAtomically(out_path, *text);
}

}  // namespace sphereset

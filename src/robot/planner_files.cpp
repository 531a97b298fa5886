// The files planners read beside the URDF: MoveIt's SRDF (wiki.ros.org/srdf: <group> with a
// <chain>, <disable_collisions> with the setup assistant's reasons), written through TinyXML,
// and Lula's robot description YAML (Isaac Sim's robot_description.yaml: api_version, cspace,
// root_link, default_q, cspace_to_urdf_rules, composite_task_spaces, collision_spheres as a list
// of one-link mappings).
#include <tinyxml.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/atomic_write.hpp"
#include "io/sphere_formats.hpp"
#include "sphereset/robot_collision.hpp"

namespace sphereset {
namespace {

// A number as YAML reads a float: formatNumber's text, with ".0" when it has no point or
// exponent.
std::string yamlFloat(double x) {
  std::string s = detail::formatNumber(x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

std::optional<RobotChain> longestChain(const Robot& robot) {
  std::map<std::string, const RobotJoint*> parent_joint;  // child link -> its joint
  std::map<std::string, std::vector<const RobotJoint*>> child_joints;
  for (const RobotJoint& j : robot.joints) {
    parent_joint.emplace(j.child, &j);
    child_joints[j.parent].push_back(&j);
  }
  // Movable joints from the root to each link, walking the tree from the root.
  std::map<std::string, int> depth{{robot.root, 0}};
  std::vector<std::string> todo{robot.root};
  while (!todo.empty()) {
    const std::string link = todo.back();
    todo.pop_back();
    for (const RobotJoint* j : child_joints[link]) {
      if (depth.count(j->child) > 0) continue;  // not a tree: the first path counts
      depth[j->child] = depth[link] + (isMovable(*j) && !j->mimic ? 1 : 0);
      todo.push_back(j->child);
    }
  }
  const RobotLink* best = nullptr;
  int most = 0;
  for (const RobotLink& l : robot.links) {
    const auto d = depth.find(l.name);
    if (d != depth.end() && d->second > most) {
      most = d->second;
      best = &l;
    }
  }
  if (best == nullptr) return std::nullopt;
  std::vector<const RobotJoint*> path;  // from the tip back to the root
  std::set<std::string> seen;
  for (std::string link = best->name; link != robot.root && seen.insert(link).second;) {
    const auto j = parent_joint.find(link);
    if (j == parent_joint.end()) break;
    path.push_back(j->second);
    link = j->second->parent;
  }
  RobotChain chain;
  for (auto j = path.rbegin(); j != path.rend(); ++j)
    if (isMovable(**j) && !(*j)->mimic) chain.joints.push_back((*j)->name);
  for (auto j = path.rbegin(); j != path.rend(); ++j)
    if (isMovable(**j) && !(*j)->mimic) {
      chain.base_link = (*j)->parent;
      break;
    }
  for (const RobotJoint* j : path)
    if (isMovable(*j) && !j->mimic) {
      chain.tip_link = j->child;
      break;
    }
  return chain;
}

std::string formatSrdf(const Robot& robot, const CollisionMatrix& matrix) {
  TiXmlDocument doc;
  doc.InsertEndChild(TiXmlDeclaration("1.0", "", ""));
  std::ostringstream note;
  note << " sphereset: self-collision pairs from " << matrix.samples
       << " random configurations, measured on the "
       << (matrix.check == CollisionCheck::kMeshes ? "link solids" : "sphere sets") << ": "
       << matrix.count(DisableReason::kAdjacent) << " adjacent, "
       << matrix.count(DisableReason::kDefault) << " default, "
       << matrix.count(DisableReason::kAlways) << " always, " << matrix.count(DisableReason::kNever)
       << " never, " << matrix.enabled << " pairs left to check ";
  TiXmlComment header(note.str().c_str());
  doc.InsertEndChild(header);
  TiXmlElement root("robot");
  root.SetAttribute("name", robot.name);
  if (const auto chain = longestChain(robot)) {
    TiXmlComment about(
        " the longest serial chain of movable joints from the root (mimic joints not counted) ");
    root.InsertEndChild(about);
    TiXmlElement group("group");
    group.SetAttribute("name", "manipulator");
    TiXmlElement c("chain");
    c.SetAttribute("base_link", chain->base_link);
    c.SetAttribute("tip_link", chain->tip_link);
    group.InsertEndChild(c);
    root.InsertEndChild(group);
  }
  for (const DisabledPair& p : matrix.disabled) {
    TiXmlElement d("disable_collisions");
    d.SetAttribute("link1", p.link1);
    d.SetAttribute("link2", p.link2);
    d.SetAttribute("reason", disableReasonName(p.reason));
    root.InsertEndChild(d);
  }
  doc.InsertEndChild(root);
  TiXmlPrinter printer;
  printer.SetIndent("  ");
  doc.Accept(&printer);
  return printer.Str();
}

Status writeSrdf(const std::string& path, const Robot& robot, const CollisionMatrix& matrix) {
  return writeFileAtomically(path, formatSrdf(robot, matrix));
}

Expected<std::string> formatLulaDescription(const Robot& robot,
                                            const std::vector<LinkSpheres>& spheres,
                                            const std::map<std::string, double>& default_pose) {
  auto state = jointState(robot, default_pose);
  if (!state) return Error{state.error().code, "default_pose: " + state.error().message};
  std::set<std::string> names;
  size_t total = 0;
  for (const LinkSpheres& l : spheres) {
    if (l.link.empty())
      return Error{ErrorCode::kInvalidArgument, "Lula description: a link has no name"};
    if (!names.insert(l.link).second)
      return Error{ErrorCode::kInvalidArgument,
                   "Lula description: link '" + l.link + "' appears twice"};
    for (size_t i = 0; i < l.spheres.size(); ++i)
      if (Status st = checkSphere(
              "Lula description: link '" + l.link + "' sphere " + std::to_string(i), l.spheres[i]);
          !st)
        return st.error();
    total += l.spheres.size();
  }
  std::vector<const RobotJoint*> cspace, rules;
  for (const RobotJoint& j : robot.joints)
    if (isMovable(j)) (j.mimic ? rules : cspace).push_back(&j);

  std::ostringstream os;
  os << detail::commentLine("sphereset: Lula robot description of " + robot.name + ", " +
                            std::to_string(total) + " collision spheres in " +
                            std::to_string(spheres.size()) + " links");
  os << "api_version: 1.0\n";
  os << "cspace:" << (cspace.empty() ? " []\n" : "\n");
  for (const RobotJoint* j : cspace) os << "  - " << detail::yamlKey(j->name) << '\n';
  os << "root_link: " << detail::yamlKey(robot.root) << '\n';
  os << "default_q: [";
  for (size_t i = 0; i < cspace.size(); ++i)
    os << (i ? ", " : "") << yamlFloat(state->values.at(cspace[i]->name));
  os << "]\n";
  os << "cspace_to_urdf_rules:" << (rules.empty() ? " []\n" : "\n");
  for (const RobotJoint* j : rules)
    os << "  - {name: " << detail::yamlKey(j->name)
       << ", rule: fixed, value: " << yamlFloat(state->values.at(j->name)) << "}\n";
  os << "composite_task_spaces: []\n";
  os << "collision_spheres:" << (spheres.empty() ? " []\n" : "\n");
  for (const LinkSpheres& l : spheres) {
    os << "  - " << detail::yamlMappingKey(l.link, 4) << (l.spheres.empty() ? " []\n" : "\n");
    detail::writeYamlSphereList(os, l.spheres);
  }
  return os.str();
}

Status writeLulaDescription(const std::string& path, const Robot& robot,
                            const std::vector<LinkSpheres>& spheres,
                            const std::map<std::string, double>& default_pose) {
  auto text = formatLulaDescription(robot, spheres, default_pose);
  if (!text) return Error{text.error().code, path + ": " + text.error().message};
  return writeFileAtomically(path, *text);
}

}  // namespace sphereset

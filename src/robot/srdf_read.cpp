// Reading MoveIt's SRDF (the Semantic Robot Description Format, wiki.ros.org/srdf): the
// <disable_collisions link1="A" link2="B" reason="R"/> elements under <robot>, the pairs a
// planner never checks. Only those are read; groups, end effectors and poses are not needed by
// sphereset.
#include <tinyxml.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "sphereset/robot_collision.hpp"
#include "util/read_file.hpp"

namespace sphereset {
namespace {

DisableReason reasonOf(const char* text) {
  const std::string r = text ? text : "";
  if (r == "Adjacent") return DisableReason::kAdjacent;
  if (r == "Default") return DisableReason::kDefault;
  if (r == "Always") return DisableReason::kAlways;
  return DisableReason::kNever;  // "Never", "User" and other reasons: never checked
}

}  // namespace

Expected<std::vector<DisabledPair>> readSrdfDisabledPairs(const std::string& path,
                                                          const Robot& robot) {
  auto text = detail::readFileText(path);
  if (!text) return text.error();
  TiXmlDocument doc;
  doc.Parse(text->c_str());
  if (doc.Error())
    return Error{ErrorCode::kInvalidData, path + ": not XML (" + doc.ErrorDesc() + ", line " +
                                              std::to_string(doc.ErrorRow()) + ")"};
  const TiXmlElement* root = doc.RootElement();
  if (root == nullptr || std::string(root->Value()) != "robot")
    return Error{ErrorCode::kInvalidData, path + ": an SRDF's root element is <robot>"};
  std::map<std::string, size_t> order;
  for (size_t i = 0; i < robot.links.size(); ++i) order.emplace(robot.links[i].name, i);
  std::vector<DisabledPair> pairs;
  int line = 0;
  for (const TiXmlElement* e = root->FirstChildElement("disable_collisions"); e != nullptr;
       e = e->NextSiblingElement("disable_collisions")) {
    line = e->Row();
    const char* a = e->Attribute("link1");
    const char* b = e->Attribute("link2");
    if (a == nullptr || b == nullptr)
      return Error{ErrorCode::kInvalidData, path + ": line " + std::to_string(line) +
                                                ": <disable_collisions> needs link1 and link2"};
    for (const char* name : {a, b})
      if (order.count(name) == 0)
        return Error{ErrorCode::kInvalidData, path + ": line " + std::to_string(line) + ": link '" +
                                                  name + "' is not a link of " + robot.name};
    DisabledPair p{a, b, reasonOf(e->Attribute("reason")), 0};
    if (order.at(p.link1) > order.at(p.link2)) std::swap(p.link1, p.link2);
    pairs.push_back(p);
  }
  std::stable_sort(pairs.begin(), pairs.end(), [&](const DisabledPair& x, const DisabledPair& y) {
    return std::make_pair(order.at(x.link1), order.at(x.link2)) <
           std::make_pair(order.at(y.link1), order.at(y.link2));
  });
  return pairs;
}

}  // namespace sphereset

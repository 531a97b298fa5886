// The planners' files written from a sampled self-collision matrix on the three-link test robot,
// each read back by an independent reader and compared with what was written: MoveIt's SRDF
// (TinyXML), Lula's robot description and cuRobo's YAML (yaml-cpp, and the library's reader).
#include <gtest/gtest.h>
#include <tinyxml.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/sphere_formats.hpp"
#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/sphere_io.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

class PlannerFiles : public test::TempDirTest {};

std::vector<LinkSpheres> threeLinkSpheres() {
  return {{"base_link", {Sphere{Vec3(0.5, 0, 0.5), 0.1}}},
          {"link1", {Sphere{Vec3(0, 0, 0.2), 0.05}, Sphere{Vec3(0.1, -0.2, 1.0 / 3.0), 0.07}}},
          {"link2", {Sphere{Vec3(0.45, 0, 0), 0.05}}},
          {"tool", {Sphere{Vec3(0, 0, 0), 0.05}}}};
}

CollisionMatrix sampled(const Robot& robot) {
  CollisionSamplingOptions o;
  o.samples = 1000;
  auto m = sampleSelfCollisions(robot, threeLinkSpheres(), o);
  EXPECT_TRUE(m.ok()) << m.error().message;
  return m.ok() ? *m : CollisionMatrix{};
}

using Triple = std::array<std::string, 3>;  // link1, link2, reason

std::vector<Triple> srdfPairs(const TiXmlElement* robot) {
  std::vector<Triple> out;
  for (const TiXmlElement* d = robot->FirstChildElement("disable_collisions"); d != nullptr;
       d = d->NextSiblingElement("disable_collisions"))
    out.push_back({d->Attribute("link1"), d->Attribute("link2"), d->Attribute("reason")});
  return out;
}

std::vector<Triple> matrixPairs(const CollisionMatrix& m) {
  std::vector<Triple> out;
  for (const DisabledPair& p : m.disabled)
    out.push_back({p.link1, p.link2, disableReasonName(p.reason)});
  return out;
}

TEST_F(PlannerFiles, LongestChainOfMovableJoints) {
  const Robot robot = test::threeLinkRobot();
  const auto chain = longestChain(robot);
  ASSERT_TRUE(chain.has_value());
  EXPECT_EQ(chain->base_link, "base_link");
  EXPECT_EQ(chain->tip_link, "link2");  // tool hangs on a fixed joint
  EXPECT_EQ(chain->joints, (std::vector<std::string>{"joint1", "joint2"}));
  Robot fixed = robot;
  for (RobotJoint& j : fixed.joints) j.type = RobotJoint::Type::kFixed;
  EXPECT_FALSE(longestChain(fixed).has_value());
}

TEST_F(PlannerFiles, SrdfReadsBackAsWritten) {
  const Robot robot = test::threeLinkRobot();
  const CollisionMatrix m = sampled(robot);
  ASSERT_EQ(m.disabled.size(), 6u);
  const std::string file = path("three_link.srdf");
  ASSERT_TRUE(writeSrdf(file, robot, m).ok());
  TiXmlDocument doc;
  ASSERT_TRUE(doc.LoadFile(file.c_str())) << doc.ErrorDesc();
  const TiXmlElement* root = doc.RootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(std::string(root->Value()), "robot");
  EXPECT_EQ(std::string(root->Attribute("name")), "three_link");
  const TiXmlElement* group = root->FirstChildElement("group");
  ASSERT_NE(group, nullptr);
  EXPECT_EQ(std::string(group->Attribute("name")), "manipulator");
  const TiXmlElement* chain = group->FirstChildElement("chain");
  ASSERT_NE(chain, nullptr);
  EXPECT_EQ(std::string(chain->Attribute("base_link")), "base_link");
  EXPECT_EQ(std::string(chain->Attribute("tip_link")), "link2");
  EXPECT_EQ(srdfPairs(root), matrixPairs(m));
  const std::set<std::string> moveit_reasons = {"Adjacent", "Default", "Always", "Never"};
  for (const Triple& t : srdfPairs(root)) EXPECT_EQ(moveit_reasons.count(t[2]), 1u) << t[2];
}

// The library's own reader gives back the pairs and reasons written, in the robot's order.
TEST_F(PlannerFiles, SrdfPairsReadBackByTheLibrary) {
  const Robot robot = test::threeLinkRobot();
  const CollisionMatrix m = sampled(robot);
  const std::string file = path("three_link.srdf");
  ASSERT_TRUE(writeSrdf(file, robot, m).ok());
  auto pairs = readSrdfDisabledPairs(file, robot);
  ASSERT_TRUE(pairs.ok()) << pairs.error().message;
  ASSERT_EQ(pairs->size(), m.disabled.size());
  for (size_t i = 0; i < pairs->size(); ++i) {
    EXPECT_EQ((*pairs)[i].link1, m.disabled[i].link1);
    EXPECT_EQ((*pairs)[i].link2, m.disabled[i].link2);
    EXPECT_EQ((*pairs)[i].reason, m.disabled[i].reason);
  }
  // Bad files: one line naming the file and the problem.
  const auto refused = [&](const std::string& name, const std::string& text,
                           const std::string& says) {
    auto r = readSrdfDisabledPairs(write(name, text), robot);
    ASSERT_FALSE(r.ok()) << name;
    EXPECT_NE(r.error().message.find(says), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
  };
  refused("broken.srdf", "<robot><disable_collisions", "not XML");
  refused("other.srdf", "<model/>", "root element is <robot>");
  refused("half.srdf", "<robot>\n<disable_collisions link1=\"link1\"/></robot>", "line 2");
  refused("ghost.srdf", "<robot><disable_collisions link1=\"link1\" link2=\"ghost\"/></robot>",
          "'ghost' is not a link");
  EXPECT_EQ(readSrdfDisabledPairs(path("missing.srdf"), robot).error().code,
            ErrorCode::kUnreadable);
}

TEST_F(PlannerFiles, SrdfWithoutAChainHasNoGroup) {
  Robot robot = test::threeLinkRobot();
  for (RobotJoint& j : robot.joints) j.type = RobotJoint::Type::kFixed;
  TiXmlDocument doc;
  doc.Parse(formatSrdf(robot, CollisionMatrix{}).c_str());
  ASSERT_FALSE(doc.Error()) << doc.ErrorDesc();
  EXPECT_EQ(doc.RootElement()->FirstChildElement("group"), nullptr);
  EXPECT_EQ(doc.RootElement()->FirstChildElement("disable_collisions"), nullptr);
}

std::vector<Sphere> yamlSpheres(const YAML::Node& list) {
  std::vector<Sphere> out;
  for (const YAML::Node& s : list) {
    const YAML::Node c = s["center"];
    out.push_back(Sphere{Vec3(c[0].as<double>(), c[1].as<double>(), c[2].as<double>()),
                         s["radius"].as<double>()});
  }
  return out;
}

bool sameSpheres(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].center != b[i].center || a[i].radius != b[i].radius) return false;
  return true;
}

TEST_F(PlannerFiles, LulaDescriptionReadsBackAsWritten) {
  Robot robot = test::threeLinkRobot();
  // tool_joint made a revolute mimic of joint2: held fixed by a rule, not in the c-space.
  for (RobotJoint& j : robot.joints)
    if (j.name == "tool_joint") {
      j.type = RobotJoint::Type::kRevolute;
      j.lower = -1;
      j.upper = 1;
      j.mimic = RobotJoint::Mimic{"joint2", 0.5, 0.0};
    }
  const std::vector<LinkSpheres> spheres = threeLinkSpheres();
  const std::string file = path("three_link.lula.yml");
  // joint2 = 100 is clamped to its upper limit 2.
  ASSERT_TRUE(
      writeLulaDescription(file, robot, spheres, {{"joint1", 0.5}, {"joint2", 100.0}}).ok());
  const YAML::Node root = YAML::LoadFile(file);
  EXPECT_EQ(root["api_version"].as<double>(), 1.0);
  EXPECT_EQ(root["cspace"].as<std::vector<std::string>>(),
            (std::vector<std::string>{"joint1", "joint2"}));
  EXPECT_EQ(root["root_link"].as<std::string>(), "base_link");
  EXPECT_EQ(root["default_q"].as<std::vector<double>>(), (std::vector<double>{0.5, 2.0}));
  const YAML::Node rules = root["cspace_to_urdf_rules"];
  ASSERT_TRUE(rules.IsSequence());
  ASSERT_EQ(rules.size(), 1u);
  EXPECT_EQ(rules[0]["name"].as<std::string>(), "tool_joint");
  EXPECT_EQ(rules[0]["rule"].as<std::string>(), "fixed");
  EXPECT_EQ(rules[0]["value"].as<double>(), 1.0);
  ASSERT_TRUE(root["composite_task_spaces"].IsSequence());
  EXPECT_EQ(root["composite_task_spaces"].size(), 0u);
  const YAML::Node list = root["collision_spheres"];
  ASSERT_TRUE(list.IsSequence());
  ASSERT_EQ(list.size(), spheres.size());
  for (size_t i = 0; i < spheres.size(); ++i) {
    ASSERT_TRUE(list[i].IsMap());
    ASSERT_EQ(list[i].size(), 1u);
    const auto entry = list[i].begin();
    EXPECT_EQ(entry->first.as<std::string>(), spheres[i].link);
    EXPECT_TRUE(sameSpheres(yamlSpheres(entry->second), spheres[i].spheres)) << spheres[i].link;
  }
  // The library's reader takes Lula's list as it takes cuRobo's mapping.
  auto back = readLinkSpheres(file);
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->size(), spheres.size());
  for (size_t i = 0; i < spheres.size(); ++i) {
    EXPECT_EQ((*back)[i].link, spheres[i].link);
    EXPECT_TRUE(sameSpheres((*back)[i].spheres, spheres[i].spheres)) << spheres[i].link;
  }
}

// A robot name holding a line break (a URDF's "&#10;") used to end the header comment and start a
// collision_spheres: key, which the library's own reader then took: every name and comment is
// escaped by the YAML writer, and the file reads back with the robot's spheres only.
TEST_F(PlannerFiles, ARobotNameCannotInjectYaml) {
  Robot robot = test::threeLinkRobot();
  for (const char* brk : {"\n", "\r", "\xe2\x80\xa8", "\xc2\x85"}) {
    robot.name = std::string("evil") + brk + "collision_spheres:" + brk + "  - base_link:" + brk +
                 "    - center: [9, 9, 9]" + brk + "      radius: 9";
    const std::vector<LinkSpheres> spheres = threeLinkSpheres();
    auto text = formatLulaDescription(robot, spheres, {});
    ASSERT_TRUE(text.ok()) << text.error().message;
    const std::string first = text->substr(0, text->find('\n'));
    EXPECT_NE(first.find("evil"), std::string::npos);
    EXPECT_NE(first.find("radius: 9"), std::string::npos) << "the whole name stays in the comment";
    EXPECT_EQ(first.find('\r'), std::string::npos);
    const std::string file = path("evil.lula.yml");
    ASSERT_TRUE(writeLulaDescription(file, robot, spheres, {}).ok());
    auto back = readLinkSpheres(file);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->size(), spheres.size());
    for (size_t i = 0; i < spheres.size(); ++i)
      EXPECT_TRUE(sameSpheres((*back)[i].spheres, spheres[i].spheres)) << spheres[i].link;
  }
  EXPECT_EQ(detail::commentLine("a\nb\x7f\xe2\x80\xa9"
                                "c"),
            "# a\\x0ab\\x7f\\u2029c\n");
}

TEST_F(PlannerFiles, LulaRefusesBadSpheresAndNames) {
  const Robot robot = test::threeLinkRobot();
  std::vector<LinkSpheres> s = threeLinkSpheres();
  s[2].spheres[0].radius = -1;
  auto text = formatLulaDescription(robot, s, {});
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(text.error().message.find("link 'link2' sphere 0: negative radius"), std::string::npos)
      << text.error().message;
  s = threeLinkSpheres();
  s.push_back(s[0]);
  EXPECT_EQ(formatLulaDescription(robot, s, {}).error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(writeLulaDescription(path("bad.lula.yml"), robot, s, {}).ok());
  EXPECT_FALSE(std::filesystem::exists(path("bad.lula.yml")));
}

TEST_F(PlannerFiles, CuroboYamlIgnoresTheSampledPairs) {
  const Robot robot = test::threeLinkRobot();
  const CollisionMatrix m = sampled(robot);
  const SelfCollisionPairs pairs = ignoredPairs(m);
  const std::string file = path("three_link.yml");
  ASSERT_TRUE(writeRobotSpheres(file, threeLinkSpheres(), &pairs).ok());
  auto back = readLinkSpheres(file);
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->size(), 4u);
  for (size_t i = 0; i < back->size(); ++i) {
    EXPECT_EQ((*back)[i].link, threeLinkSpheres()[i].link);
    EXPECT_TRUE(sameSpheres((*back)[i].spheres, threeLinkSpheres()[i].spheres));
  }
  // Every disabled pair once in self_collision_ignore, under its earlier link.
  const YAML::Node ignore = YAML::LoadFile(file)["self_collision_ignore"];
  std::set<std::array<std::string, 2>> listed;
  for (const auto& entry : ignore)
    for (const YAML::Node& other : entry.second)
      listed.insert({entry.first.as<std::string>(), other.as<std::string>()});
  std::set<std::array<std::string, 2>> expected;
  for (const DisabledPair& p : m.disabled) expected.insert({p.link1, p.link2});
  EXPECT_EQ(listed, expected);
  EXPECT_EQ(listed.size(), 6u);
}

}  // namespace
}  // namespace sphereset

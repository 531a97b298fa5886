// cuRobo robot YAML with the self-collision block: the collision_spheres mapping followed by
// self_collision_ignore (each pair once, under its earlier link) and self_collision_buffer,
// parsed back with yaml-cpp and by readLinkSpheres.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

class RobotYaml : public test::TempDirTest {};

std::vector<LinkSpheres> links() {
  return {{"base_link", {Sphere{Vec3(0.5, 0, 0.5), 0.1}}},
          {"link1", {Sphere{Vec3(0, 0, 0.2), 0.05}, Sphere{Vec3(0.1, -0.2, 1.0 / 3.0), 0.07}}},
          {"link2", {Sphere{Vec3(0.45, 0, 0), 0.05}}},
          {"empty", {}}};
}

SelfCollisionPairs pairs() {
  SelfCollisionPairs p;
  p.adjacent = {{"base_link", "link1"}, {"link1", "link2"}, {"link2", "tool"}};
  p.overlapping = {{"base_link", "link2"}, {"link2", "tool"}};
  return p;
}

std::vector<std::string> strings(const YAML::Node& list) {
  std::vector<std::string> out;
  for (const YAML::Node& n : list) out.push_back(n.as<std::string>());
  return out;
}

TEST_F(RobotYaml, IgnoreBlockParsesWithYamlCpp) {
  const SelfCollisionPairs p = pairs();
  const std::string text = formatRobotSpheres(links(), &p);
  const YAML::Node root = YAML::Load(text);
  ASSERT_TRUE(root["collision_spheres"].IsMap());
  const YAML::Node ignore = root["self_collision_ignore"];
  ASSERT_TRUE(ignore.IsMap()) << text;
  EXPECT_EQ(ignore.size(), 3u) << text;  // base_link, link1, link2; tool lists nothing
  EXPECT_EQ(strings(ignore["base_link"]), (std::vector<std::string>{"link1", "link2"}));
  EXPECT_EQ(strings(ignore["link1"]), (std::vector<std::string>{"link2"}));
  // link2-tool is adjacent and overlapping: listed once.
  EXPECT_EQ(strings(ignore["link2"]), (std::vector<std::string>{"tool"}));
  EXPECT_FALSE(ignore["tool"].IsDefined());
  // The cuRobo layout: a flow list of quoted names.
  EXPECT_NE(text.find("  base_link: [\"link1\", \"link2\"]\n"), std::string::npos) << text;

  const YAML::Node buffer = root["self_collision_buffer"];
  ASSERT_TRUE(buffer.IsMap()) << text;
  EXPECT_EQ(buffer.size(), 3u);  // not the link without spheres
  for (const char* name : {"base_link", "link1", "link2"})
    EXPECT_EQ(buffer[name].as<double>(), 0.0) << name;
  EXPECT_FALSE(buffer["empty"].IsDefined());
}

TEST_F(RobotYaml, WithoutPairsIsTheLinkSpheresFile) {
  EXPECT_EQ(formatRobotSpheres(links(), nullptr), formatLinkSpheres(links()));
  const SelfCollisionPairs none;
  const YAML::Node root = YAML::Load(formatRobotSpheres(links(), &none));
  EXPECT_TRUE(root["self_collision_ignore"].IsMap());
  EXPECT_EQ(root["self_collision_ignore"].size(), 0u);
}

TEST_F(RobotYaml, RoundTripThroughReadLinkSpheres) {
  const SelfCollisionPairs p = pairs();
  const std::string file = path("robot.yml");
  ASSERT_TRUE(writeRobotSpheres(file, links(), &p).ok());
  auto back = readLinkSpheres(file);
  ASSERT_TRUE(back.ok()) << back.error().message;
  const std::vector<LinkSpheres> want = links();
  ASSERT_EQ(back->size(), want.size());
  for (size_t l = 0; l < want.size(); ++l) {
    EXPECT_EQ((*back)[l].link, want[l].link);
    ASSERT_EQ((*back)[l].spheres.size(), want[l].spheres.size()) << want[l].link;
    for (size_t i = 0; i < want[l].spheres.size(); ++i) {
      EXPECT_EQ((*back)[l].spheres[i].center, want[l].spheres[i].center);  // exactly
      EXPECT_EQ((*back)[l].spheres[i].radius, want[l].spheres[i].radius);
    }
  }
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("self_collision_ignore:"), std::string::npos);
}

TEST_F(RobotYaml, WriteChecksLikeWriteLinkSpheres) {
  const SelfCollisionPairs p = pairs();
  const Status txt = writeRobotSpheres(path("robot.txt"), links(), &p);
  ASSERT_FALSE(txt.ok());
  EXPECT_EQ(txt.error().code, ErrorCode::kInvalidArgument);
  std::vector<LinkSpheres> twice = links();
  twice.push_back(twice[0]);
  const Status dup = writeRobotSpheres(path("robot.yml"), twice, &p);
  ASSERT_FALSE(dup.ok());
  EXPECT_EQ(dup.error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(std::filesystem::exists(path("robot.yml")));
}

}  // namespace
}  // namespace sphereset

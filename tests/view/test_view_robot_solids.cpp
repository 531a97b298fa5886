// A robot's scene in the view: its poses follow the joints, its saves keep the file's kind and
// other keys, and its links take the solids the robot command fits them to (link_solid for all,
// link_solid_for for one, robot_fit.hpp; a name the robot lacks is refused).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {
TEST_F(ViewTest, RobotPosesFollowTheJoints) {
  ViewScene scene = robotScene();
  nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["kind"], "robot");
  EXPECT_EQ(j["title"], "three_link");
  ASSERT_EQ(j["solids"].size(), 2u);
  EXPECT_EQ(j["solids"][0]["link"], "link1");
  EXPECT_EQ(j["solids"][1]["link"], "link2");
  ASSERT_EQ(j["joints"].size(), 2u);
  EXPECT_EQ(j["joints"][0]["name"], "joint1");
  EXPECT_EQ(j["joints"][0]["type"], "revolute");
  EXPECT_EQ(j["joints"][0]["upper"], 1.5);
  EXPECT_EQ(j["save"]["format"], "yaml");
  j = call(&scene, post("/api/pose", {{"joints", {{"joint1", 0.5}, {"joint2", 9.0}}}}));
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["joints"][1]["value"], 2.0);  // clamped to the limit
  const Robot robot = threeLinkRobot();
  const auto poses = linkPoses(robot, {{"joint1", 0.5}, {"joint2", 2.0}});
  ASSERT_TRUE(poses.ok());
  const Eigen::Matrix4d expect = poses->at("link2").matrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(j["poses"][1][4 * r + c].get<double>(), expect(r, c), 1e-12);
  call(&scene, post("/api/pose", {{"joints", {{"elbow", 0.1}}}}), 400);
  call(&scene, post("/api/pose", {{"joints", {{"joint1", "x"}}}}), 400);
  EXPECT_EQ(scene.version, 1);
  // The save writes every link of the file, edited ones as edited.
  call(&scene, post("/api/edit",
                    {{"solid", 1}, {"edits", {{{"op", "add"}, {"sphere", {0, 0, 0, 0.01}}}}}}));
  call(&scene, post("/api/save", nlohmann::json::object()));
  auto saved = readLinkSpheres(path("robot.yml"));
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  ASSERT_EQ(saved->size(), 2u);
  EXPECT_EQ((*saved)[1].link, "link2");
  expectSameSpheres((*saved)[1].spheres, scene.solids[1].spheres());
}

// A robot's YAML keeps what else it holds (cuRobo's ignore list) when the view saves into it.
TEST_F(ViewTest, ARobotsYamlSaveKeepsItsOtherKeys) {
  ViewScene scene = robotScene();
  {
    std::ofstream(path("robot.yml"), std::ios::app) << "self_collision_ignore:\n  link1: [link2]\n";
  }
  call(&scene, post("/api/edit",
                    {{"solid", 0}, {"edits", {{{"op", "add"}, {"sphere", {0, 0, 0.1, 0.02}}}}}}));
  call(&scene, post("/api/save", nlohmann::json::object()));
  auto saved = readLinkSpheres(path("robot.yml"));
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  ASSERT_EQ(saved->size(), 2u);
  expectSameSpheres((*saved)[0].spheres, scene.solids[0].spheres());
  const std::string text = test::readFile(path("robot.yml"));
  EXPECT_NE(text.find("self_collision_ignore"), std::string::npos) << text;
}

TEST_F(ViewTest, ARobotsSphereUrdfIsSavedAsAUrdf) {
  const std::string file = path("spheres.urdf");
  ASSERT_TRUE(writeSphereUrdf(
                  threeLinkUrdf(), file,
                  {{"link1", {{Vec3(0, 0, 0.2), 0.25}}}, {"link2", {{Vec3(0.1, -0.2, 0.3), 0.4}}}})
                  .ok());
  auto loaded = loadViewScene(threeLinkUrdf(), file, robotOptions());
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ViewScene& scene = *loaded;
  ASSERT_EQ(scene.solids.size(), 2u);
  EXPECT_EQ(scene.solids[1].link, "link2");
  nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["save"]["format"], "urdf");
  call(&scene, post("/api/edit",
                    {{"solid", 1}, {"edits", {{{"op", "add"}, {"sphere", {0, 0, 0, 0.01}}}}}}));
  call(&scene, post("/api/save", nlohmann::json::object()));
  RobotLoadOptions lo;
  lo.package_paths = {robotDir()};
  lo.use_ros_package_path = false;
  auto saved = loadRobot(file, lo);
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  for (const RobotLink& l : saved->links) {
    if (l.name == "link2") expectSameSpheres(linkSpheres(l), scene.solids[1].spheres());
    // A link the file did not give spheres keeps its own collision.
    if (l.name == "base_link") {
      ASSERT_EQ(l.geometry.size(), 1u);
      EXPECT_EQ(l.geometry[0].kind, LinkGeometry::Kind::kBox);
    }
  }
}

TEST_F(ViewTest, ARobotsLinksTakeTheirOwnSolids) {
  const std::string file = robotSpheres();
  ViewLoadOptions o = robotOptions();
  // The envelope for all but the two links drawn, which take their walls: no wrapping needed.
  o.link_solid = LinkSolid::kEnvelope;
  o.link_solid_for = {{"link1", LinkSolid::kWalls}, {"link2", LinkSolid::kWalls}};
  auto loaded = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ASSERT_EQ(loaded->solids.size(), 2u);
  o.link_solid_for["link2"] = LinkSolid::kEnvelope;
  auto envelope = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_FALSE(envelope.ok());
  EXPECT_NE(envelope.error().message.find("link 'link2'"), std::string::npos)
      << envelope.error().message;
  o.link_solid_for = {{"elbow", LinkSolid::kWalls}};
  auto bad = loadViewScene(threeLinkUrdf(), file, o);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.error().message.find("link_solid_for names 'elbow', not a link of"),
            std::string::npos)
      << bad.error().message;
}

}  // namespace
}  // namespace sphereset::test

// A robot's scene saved as another robot format (view.hpp, saveViewScene's `as`; POST
// /api/save {"format": ...}): beside the save path, with that format's ending, read back with
// the same spheres; the formats are listed in the scene; a mesh's scene and unknown formats are
// refused, and no request names a path.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "sphereset/robot.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

TEST_F(ViewTest, ARobotIsSavedAsAnotherRobotFormatBesideItsSavePath) {
  ViewScene scene = robotScene();
  const nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  ASSERT_EQ(j["save"]["format"], "yaml");
  std::vector<std::string> formats;
  for (const auto& a : j["save"]["as"]) formats.push_back(a["format"].get<std::string>());
  EXPECT_EQ(formats.size(), mujocoAvailable() ? 4u : 3u);
  EXPECT_EQ(formats[0], "yaml");
  EXPECT_EQ(formats[1], "urdf");
  EXPECT_EQ(formats.back(), "lula");

  call(&scene, post("/api/edit",
                    {{"solid", 1}, {"edits", {{{"op", "add"}, {"sphere", {0, 0, 0, 0.01}}}}}}));
  const nlohmann::json saved = call(&scene, post("/api/save", {{"format", "urdf"}}));
  const std::string urdf = saved["path"].get<std::string>();
  EXPECT_EQ(std::filesystem::path(urdf).filename(), "robot.urdf");
  EXPECT_EQ(std::filesystem::path(urdf).parent_path(),
            std::filesystem::path(scene.save_path).parent_path());
  RobotLoadOptions lo;
  lo.package_paths = {robotDir()};
  lo.use_ros_package_path = false;
  auto robot = loadRobot(urdf, lo);
  ASSERT_TRUE(robot.ok()) << robot.error().message;
  for (const RobotLink& l : robot->links)
    for (const ViewSolid& s : scene.solids)
      if (l.name == s.link) expectSameSpheres(linkSpheres(l), s.spheres());
  // Lula's description beside it, read back by the library's reader with the same spheres.
  const std::string lula = call(&scene, post("/api/save", {{"format", "lula"}}))["path"];
  EXPECT_EQ(std::filesystem::path(lula).filename(), "robot.lula.yml");
  auto back = readLinkSpheres(lula);
  ASSERT_TRUE(back.ok()) << back.error().message;
  for (const LinkSpheres& l : *back)
    for (const ViewSolid& s : scene.solids)
      if (l.link == s.link) expectSameSpheres(l.spheres, s.spheres());
  // The scene's own save still goes to its own file.
  EXPECT_EQ(call(&scene, post("/api/save", nlohmann::json::object()))["path"], scene.save_path);

  for (const nlohmann::json& bad :
       {nlohmann::json{{"format", "srdf"}}, nlohmann::json{{"format", 1}},
        nlohmann::json{{"path", "/tmp/x.yml"}}})
    call(&scene, post("/api/save", bad), 400);
  ViewScene mesh = boxScene();
  call(&mesh, post("/api/save", {{"format", "urdf"}}), 400);
}

// A save as another format never writes one of the scene's inputs: here the compared file has
// the name a URDF save would take.
TEST_F(ViewTest, ASaveAsNeverWritesAnInput) {
  const std::string yml = robotSpheres();
  const std::string compared = path("robot.urdf");
  ASSERT_TRUE(
      writeSphereUrdf(threeLinkUrdf(), compared, {{"link1", {{Vec3(0, 0, 0.2), 0.3}}}}).ok());
  ViewLoadOptions o = robotOptions();
  o.compare = compared;
  auto scene = loadViewScene(threeLinkUrdf(), yml, o);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const auto before = std::filesystem::last_write_time(compared);
  EXPECT_FALSE(saveViewScene(*scene, ViewSaveFormat::kRobotUrdf).ok());
  EXPECT_EQ(std::filesystem::last_write_time(compared), before);
  EXPECT_TRUE(saveViewScene(*scene).ok());  // its own file
}

}  // namespace
}  // namespace sphereset::test

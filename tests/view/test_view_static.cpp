// The static page (view.hpp, docs/view.md "Static pages"): the scene inlined where the page's
// marker stands, safely, the same bytes for the same inputs, and what the page needs to switch a
// tree's levels and pose a robot without a server.
#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

TEST_F(ViewTest, TheStaticPageInlinesTheScene) {
  ViewScene scene = boxScene();
  scene.title = "a</script><b>";
  auto page = inlineViewData("<html><!--SPHERESET_DATA--></html>", scene);
  ASSERT_TRUE(page.ok()) << page.error().message;
  const std::string open = "<script id=\"sphereset-data\" type=\"application/json\">";
  const size_t at = page->find(open);
  ASSERT_NE(at, std::string::npos);
  const size_t end = page->find("</script>", at);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(page->substr(end), "</script></html>");  // the title did not close the element
  const nlohmann::json j =
      nlohmann::json::parse(page->substr(at + open.size(), end - at - open.size()));
  EXPECT_EQ(j["title"], "a</script><b>");
  EXPECT_EQ(j["solids"][0]["geometry"].get<std::string>().size(), (8u + 96u + 144u + 2u) / 3u * 4u);
  EXPECT_FALSE(inlineViewData("<html></html>", scene).ok());
  auto built = viewStaticPage(scene);
  EXPECT_EQ(built.ok(), viewPageAvailable());
  // A page file holds no timing and no save path: the same inputs give the same bytes.
  EXPECT_TRUE(j["save"].is_null());
  EXPECT_EQ(j["solids"][0]["certificate"]["seconds"], 0.0);
}

// A scene loaded for a page file sets up no save (nothing is written beside the sphere file),
// and two loads give the same page.
TEST_F(ViewTest, APageFilesSceneHasNoSaveAndIsTheSameEachTime) {
  boxScene();  // writes the box and its set
  ViewLoadOptions o;
  o.page_file = true;
  auto a = loadViewScene(path("box.off"), path("box.txt"), o);
  auto b = loadViewScene(path("box.off"), path("box.txt"), o);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(a->save_path.empty());
  EXPECT_FALSE(saveViewScene(*a).ok());
  EXPECT_EQ(a->solids.size(), 1u);
  const std::string marker = "<!--SPHERESET_DATA-->";
  EXPECT_EQ(*inlineViewData(marker, *a), *inlineViewData(marker, *b));
}

// The data a static page switches and poses with: a tree's every level with the certificate of
// that level, and a robot's joint tree.
nlohmann::json pageData(const ViewScene& scene) {
  auto page = inlineViewData("<!--SPHERESET_DATA-->", scene);
  EXPECT_TRUE(page.ok());
  const std::string open = "<script id=\"sphereset-data\" type=\"application/json\">";
  const std::string text = page->substr(open.size(), page->size() - open.size() - 9);
  return nlohmann::json::parse(text);
}

TEST_F(ViewTest, AStaticPageHoldsEveryLevelAndTheJointTree) {
  ViewScene tree = treeScene();
  const nlohmann::json t = pageData(tree);
  const auto& sets = t["solids"][0]["level_sets"];
  ASSERT_EQ(sets.size(), tree.solids[0].sets.size());
  for (size_t l = 0; l < sets.size(); ++l) {
    ASSERT_TRUE(setViewLevel(&tree, 0, static_cast<int64_t>(l)));
    const std::vector<Sphere>& shown = tree.solids[0].spheres();
    ASSERT_EQ(sets[l]["spheres"].size(), shown.size());
    for (size_t i = 0; i < shown.size(); ++i) {
      EXPECT_EQ(sets[l]["spheres"][i][0].get<double>(), shown[i].center.x());
      EXPECT_EQ(sets[l]["spheres"][i][3].get<double>(), shown[i].radius);
    }
    EXPECT_DOUBLE_EQ(sets[l]["certificate"]["er_sum"].get<double>(),
                     tree.solids[0].certificate.er_sum);
    EXPECT_EQ(sets[l]["certificate"]["covered"].get<bool>(), tree.solids[0].certificate.covered);
  }
  ViewScene robot = robotScene();
  const nlohmann::json r = pageData(robot);
  ASSERT_TRUE(r.contains("kinematics"));
  EXPECT_EQ(r["kinematics"]["root"], robot.robot->root);
  ASSERT_EQ(r["kinematics"]["joints"].size(), robot.robot->joints.size());
  for (size_t i = 0; i < robot.robot->joints.size(); ++i) {
    const RobotJoint& j = robot.robot->joints[i];
    const auto& k = r["kinematics"]["joints"][i];
    EXPECT_EQ(k["child"], j.child);
    EXPECT_EQ(k["origin"][3].get<double>(), j.origin.translation().x());
    EXPECT_EQ(k["origin"][11].get<double>(), j.origin.translation().z());
  }
  EXPECT_FALSE(pageData(boxScene()).contains("kinematics"));
}

}  // namespace
}  // namespace sphereset::test

// A robot's self-collision in the view (view.hpp, viewContactPairs; the scene's "collisions"):
// the allowed pairs are the adjacent links, or an SRDF's disabled pairs (--srdf); the pairs in
// contact are those whose spheres overlap at the current pose and are not allowed, and they
// follow the joints and the edits. An SRDF for a mesh is refused.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "robot/robot_data.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

using Pair = std::array<std::string, 2>;

TEST_F(ViewTest, AdjacentLinksAreAllowedAndTheirOverlapIsNoContact) {
  ViewScene scene = robotScene();
  EXPECT_EQ(scene.allowed_source, "adjacent");
  EXPECT_NE(
      std::find(scene.allowed_pairs.begin(), scene.allowed_pairs.end(), Pair{"link1", "link2"}),
      scene.allowed_pairs.end());
  EXPECT_TRUE(viewContactPairs(scene).empty());
  const nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["collisions"]["allowed_source"], "adjacent");
  EXPECT_TRUE(j["collisions"]["contact"].empty());
  ViewScene box = boxScene();
  EXPECT_TRUE(call(&box, request("GET", "/api/scene"))["collisions"].is_null());
}

TEST_F(ViewTest, AnSrdfsPairsAreTheAllowedOnesAndContactsFollowEdits) {
  const std::string srdf =
      write("robot.srdf",
            "<robot name=\"three_link\"><disable_collisions link1=\"base_link\" link2=\"link1\" "
            "reason=\"Adjacent\"/></robot>");
  ViewLoadOptions o = robotOptions();
  o.srdf = srdf;
  auto loaded = loadViewScene(threeLinkUrdf(), robotSpheres(), o);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ViewScene& scene = *loaded;
  EXPECT_EQ(scene.allowed_source, "srdf");
  ASSERT_EQ(scene.allowed_pairs.size(), 1u);
  // link1's and link2's spheres overlap and the SRDF does not allow them: in contact.
  EXPECT_EQ(viewContactPairs(scene), std::vector<Pair>({{"link1", "link2"}}));
  // link2's sphere made tiny and moved away: no contact, and the edit's answer says so.
  const nlohmann::json a = call(
      &scene,
      post("/api/edit", {{"solid", 1},
                         {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {5, 5, 5, 0.01}}}}}}));
  EXPECT_TRUE(a["collisions"]["contact"].empty());
  EXPECT_TRUE(viewContactPairs(scene).empty());
  // A mesh with an SRDF, and an SRDF naming a link the robot lacks: refused.
  ViewLoadOptions mesh;
  mesh.srdf = srdf;
  boxScene();
  EXPECT_FALSE(loadViewScene(path("box.off"), path("box.txt"), mesh).ok());
  o.srdf = write("bad.srdf", "<robot><disable_collisions link1=\"link1\" link2=\"nope\"/></robot>");
  auto bad = loadViewScene(threeLinkUrdf(), robotSpheres(), o);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("'nope'"), std::string::npos);
}

}  // namespace
}  // namespace sphereset::test

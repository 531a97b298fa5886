// Two sets of one solid compared (ViewLoadOptions::compare, `view MESH A B`): the second set's
// solids come after the first's, certified on their own, marked set 1 and named in "sets"; they
// are never edited, fitted or saved, and a save never writes over the compared file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

TEST_F(ViewTest, ASecondSetIsShownAndCertifiedButNeverEdited) {
  boxScene();  // box.off and box.txt (covering)
  const std::string small = path("small.txt");
  ASSERT_TRUE(writeSpheres(small, {{Vec3(0.5, 0.5, 0.5), 0.3}}).ok());
  ViewLoadOptions o;
  o.compare = small;
  auto loaded = loadViewScene(path("box.off"), path("box.txt"), o);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ViewScene& scene = *loaded;
  ASSERT_EQ(scene.solids.size(), 2u);
  EXPECT_EQ(scene.solids[0].set, 0);
  EXPECT_EQ(scene.solids[1].set, 1);
  EXPECT_TRUE(scene.solids[0].certificate.covered);
  EXPECT_FALSE(scene.solids[1].certificate.covered);  // a ball of 0.3 inside the unit box
  const nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["sets"], nlohmann::json({"box.txt", "small.txt"}));
  EXPECT_EQ(j["solids"][1]["set"], 1);
  // The compared set is read-only: edits, bounds and fits refused; the first set still edits.
  const std::string why =
      call(&scene, post("/api/edit", {{"solid", 1}, {"edits", {{{"op", "delete"}, {"index", 0}}}}}),
           400)["error"];
  EXPECT_NE(why.find("compared set"), std::string::npos) << why;
  call(&scene, post("/api/bound", {{"solid", 1}}), 400);
  call(&scene, post("/api/fit", {{"solid", 1}, {"spheres", 2}}), 400);
  call(&scene, post("/api/edit", {{"solid", 0},
                                  {"edits", {{{"op", "add"}, {"sphere", {0.5, 0.5, 0.5, 0.1}}}}}}));
  // A save writes the first set to its file, and leaves the compared file alone.
  call(&scene, post("/api/save", nlohmann::json::object()));
  auto saved = readSpheres(path("box.txt"));
  ASSERT_TRUE(saved.ok());
  EXPECT_EQ(saved->size(), 3u);
  EXPECT_EQ(readSpheres(small)->size(), 1u);
  // --output naming the compared file is refused at load.
  o.output = small;
  EXPECT_FALSE(loadViewScene(path("box.off"), path("box.txt"), o).ok());
}

}  // namespace
}  // namespace sphereset::test

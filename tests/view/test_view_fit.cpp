// Fits started from the page (view.hpp, startViewFit; POST /api/fit, /api/fit/status,
// /api/fit/cancel): the fitted set is the library's fit with the same options, applied once with
// its certificate; a running fit refuses edits of its solid, can be cancelled (nothing changes)
// and refuses a second fit; a robot's budget fits every link within it; bad requests start
// nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "view/view_fit.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

// Asks how the fit is until it is no longer running (at most a minute).
nlohmann::json waitForFit(ViewScene* scene) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  nlohmann::json j;
  do {
    j = call(scene, ViewTest::post("/api/fit/status", nlohmann::json::object()));
    if (j["state"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (std::chrono::steady_clock::now() < end);
  return j;
}

TEST_F(ViewTest, APageFitIsTheLibrarysFitAppliedOnce) {
  ViewScene scene = boxScene();
  EXPECT_EQ(call(&scene, post("/api/fit/status", nlohmann::json::object()))["state"], "idle");
  const int64_t version = scene.version;
  call(&scene, post("/api/fit", {{"solid", 0}, {"spheres", 4}, {"quality", "fast"}}));
  const nlohmann::json done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_TRUE(done["applied"].get<bool>());
  EXPECT_EQ(done["fraction"].get<double>(), 1.0);
  EXPECT_EQ(scene.version, version + 1);
  ASSERT_EQ(done["sets"].size(), 1u);
  EXPECT_TRUE(done["sets"][0]["certificate"]["covered"].get<bool>());
  // The same spheres as fitSpheres with the preset, bit for bit.
  FitOptions o = fitPreset(4, FitQuality::kFast);
  o.original = scene.solids[0].input->original();
  auto fit = fitSpheres(*scene.solids[0].index, o);
  ASSERT_TRUE(fit.ok());
  expectSameSpheres(spheresOf(done["sets"][0]["spheres"]), fit->spheres);
  expectSameSpheres(scene.solids[0].spheres(), fit->spheres);
  // Asked again: done, not applied a second time.
  const nlohmann::json again = call(&scene, post("/api/fit/status", nlohmann::json::object()));
  EXPECT_FALSE(again["applied"].get<bool>());
  EXPECT_EQ(scene.version, version + 1);
}

TEST_F(ViewTest, ARunningFitRefusesEditsAndASecondFitAndCanBeCancelled) {
  ViewScene scene = boxScene();
  const std::vector<Sphere> before = scene.solids[0].spheres();
  call(&scene, post("/api/fit", {{"solid", 0}, {"spheres", 300}, {"quality", "best"}}));
  const auto edit =
      post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 0}}}}});
  EXPECT_NE(call(&scene, edit, 400)["error"].get<std::string>().find("being fitted"),
            std::string::npos);
  call(&scene, post("/api/bound", {{"solid", 0}}), 400);
  EXPECT_NE(call(&scene, post("/api/fit", {{"solid", 0}, {"spheres", 2}}), 400)["error"]
                .get<std::string>()
                .find("a fit is running"),
            std::string::npos);
  EXPECT_EQ(call(&scene, post("/api/fit/cancel", nlohmann::json::object()))["state"], "running");
  const nlohmann::json end = waitForFit(&scene);
  EXPECT_EQ(end["state"], "cancelled");
  EXPECT_FALSE(end["applied"].get<bool>());
  expectSameSpheres(scene.solids[0].spheres(), before);
  call(&scene, edit);  // editable again
}

// Done but not yet asked for: the solid still refuses edits (they would be replaced), and a
// second fit waits; the status applies it and edits go through again.
TEST_F(ViewTest, AFinishedFitIsAppliedBeforeTheSolidEditsAgain) {
  ViewScene scene = boxScene();
  call(&scene, post("/api/fit", {{"solid", 0}, {"spheres", 3}, {"quality", "fast"}}));
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  for (;;) {
    {
      std::lock_guard<std::mutex> g(scene.fit->mutex);
      if (scene.fit->status.state != "running") break;
    }
    ASSERT_LT(std::chrono::steady_clock::now(), end);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(scene.fit->status.state, "done") << scene.fit->status.error;
  const auto edit =
      post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 0}}}}});
  call(&scene, edit, 400);
  call(&scene, post("/api/fit", {{"solid", 0}, {"spheres", 2}}), 400);
  EXPECT_TRUE(waitForFit(&scene)["applied"].get<bool>());
  EXPECT_EQ(scene.solids[0].spheres().size(), 3u);
  call(&scene, edit);
  EXPECT_EQ(scene.solids[0].spheres().size(), 2u);
}

TEST_F(ViewTest, ARobotsBudgetFitsEveryLinkWithinIt) {
  ViewScene scene = robotScene();
  call(&scene, post("/api/fit", {{"budget", 6}, {"quality", "fast"}}));
  const nlohmann::json done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  int total = 0;
  for (const auto& [link, n] : done["counts"].items()) total += n.get<int>();
  EXPECT_LE(total, 6);
  EXPECT_GE(total, static_cast<int>(scene.solids.size()));
  for (const ViewSolid& s : scene.solids) {
    EXPECT_TRUE(s.certificate.covered) << s.link;
    EXPECT_EQ(static_cast<int>(s.spheres().size()), done["counts"][s.link].get<int>()) << s.link;
  }
}

// A tolerance instead of a count: the set applied is fitToTolerance's with the same options, and
// the status names its count and whether it was met; a tolerance no count meets applies the best
// count found and says so.
TEST_F(ViewTest, APageFitToAToleranceIsTheLibrarysSearch) {
  ViewScene scene = boxScene();
  call(&scene, post("/api/fit", {{"solid", 0}, {"max_protrusion", "20%"}, {"quality", "fast"}}));
  nlohmann::json done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_TRUE(done["tolerance"].get<bool>());
  EXPECT_TRUE(done["tolerance_met"].get<bool>());
  ToleranceOptions t;
  ASSERT_TRUE(setToleranceOption(&t, "max_protrusion", "20%").ok());
  t.original = scene.solids[0].input->original();
  t.walls = scene.solids[0].input->walls();
  FitRequest fr;
  fr.quality = FitQuality::kFast;
  auto found = fitToTolerance(*scene.solids[0].index, fr, t);
  ASSERT_TRUE(found.ok() && found->met);
  EXPECT_EQ(done["counts"]["mesh"].get<int>(), found->n);
  expectSameSpheres(scene.solids[0].spheres(), found->fit.spheres);
  // Nothing meets 1e-9 within two spheres: the best of the counts tried is applied, not met.
  call(&scene,
       post("/api/fit",
            {{"solid", 0}, {"max_protrusion", 1e-9}, {"max_spheres", 2}, {"quality", "fast"}}));
  done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_TRUE(done["tolerance"].get<bool>());
  EXPECT_FALSE(done["tolerance_met"].get<bool>());
  EXPECT_LE(scene.solids[0].spheres().size(), 2u);
  EXPECT_TRUE(scene.solids[0].certificate.covered);
}

// A robot with a protrusion limit: alone, every link its fewest spheres within it; with a budget,
// the budget holds. The limits are each link's (a percentage: of each link's own diagonal).
TEST_F(ViewTest, ARobotFitTakesAProtrusionLimit) {
  ViewScene scene = robotScene();
  call(&scene, post("/api/fit", {{"robot", true}, {"max_protrusion", "30%"}, {"quality", "fast"}}));
  nlohmann::json done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_TRUE(done["tolerance"].get<bool>() && done["tolerance_met"].get<bool>());
  for (const ViewSolid& s : scene.solids) {
    EXPECT_TRUE(s.certificate.covered) << s.link;
    // The view's certificate is looser than the fit's (0.01 of the diagonal against 0.001).
    ASSERT_TRUE(s.certificate.protrusion.has_value()) << s.link;
    EXPECT_LE(*s.certificate.protrusion, (0.3 + 0.01) * s.index->bounds().diagonal()) << s.link;
  }
  call(&scene, post("/api/fit", {{"budget", 4}, {"max_protrusion", 1e-9}, {"quality", "fast"}}));
  done = waitForFit(&scene);
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_FALSE(done["tolerance_met"].get<bool>());
  int total = 0;
  for (const auto& [link, n] : done["counts"].items()) total += n.get<int>();
  EXPECT_LE(total, 4);
}

TEST_F(ViewTest, BadFitRequestsStartNothing) {
  ViewScene scene = boxScene();
  for (const nlohmann::json& body : {
           nlohmann::json{{"solid", 0}, {"spheres", 0}},
           nlohmann::json{{"solid", 0}, {"spheres", -3}},
           nlohmann::json{{"solid", 0}, {"spheres", 100000000}},
           nlohmann::json{{"solid", 1}, {"spheres", 4}},
           nlohmann::json{{"solid", 0}, {"spheres", 4}, {"quality", "great"}},
           nlohmann::json{{"solid", 0}, {"spheres", 4}, {"quality", 3}},
           nlohmann::json{{"solid", 0}, {"spheres", 4}, {"path", "/tmp/x"}},
           nlohmann::json{{"budget", 8}},
           nlohmann::json{{"solid", 0}},
           nlohmann::json{{"solid", 0}, {"spheres", 4}, {"max_protrusion", "5%"}},
           nlohmann::json{{"solid", 0}, {"max_protrusion", "-1"}},
           nlohmann::json{{"solid", 0}, {"max_protrusion", "5%%"}},
           nlohmann::json{{"solid", 0}, {"max_er", "nan"}},
           nlohmann::json{{"solid", 0}, {"max_er", true}},
           nlohmann::json{{"solid", 0}, {"max_spheres", 8}},
           nlohmann::json{{"solid", 0}, {"spheres", 0}, {"max_protrusion", "5%"}},
           nlohmann::json{{"solid", 0}, {"spheres", -2}, {"max_er", 1}},
           nlohmann::json{{"solid", 0}, {"spheres", 4}, {"max_spheres", 8}},
           nlohmann::json{{"robot", true}, {"max_protrusion", "5%"}},
       })
    call(&scene, post("/api/fit", body), 400);
  // The routes keep the server's checks: no token, another site's Origin, a foreign Host.
  for (const auto& [header, value, status] : std::vector<std::tuple<std::string, std::string, int>>{
           {"x-sphereset-token", "0123", 401},
           {"origin", "http://evil.example", 403},
           {"host", "evil.example:8765", 403}}) {
    for (const std::string route : {"/api/fit", "/api/fit/status", "/api/fit/cancel"}) {
      ViewRequest r = post(route, route == "/api/fit" ? nlohmann::json{{"solid", 0}, {"spheres", 4}}
                                                      : nlohmann::json::object());
      for (auto& [k, v] : r.headers)
        if (k == header) v = value;
      call(&scene, r, status);
    }
  }
  EXPECT_EQ(call(&scene, post("/api/fit/status", nlohmann::json::object()))["state"], "idle");
  ViewScene tree = treeScene();
  call(&tree, post("/api/fit", {{"solid", 0}, {"spheres", 4}}), 400);
  ViewScene robot = robotScene();
  call(&robot, post("/api/fit", {{"budget", 1}}), 400);  // below one per link
  for (const nlohmann::json& body : {
           nlohmann::json{{"robot", true}},
           nlohmann::json{{"robot", false}, {"max_protrusion", "5%"}},
           nlohmann::json{{"robot", true}, {"max_er", 1}},
           nlohmann::json{{"budget", 8}, {"max_protrusion", "5%"}, {"max_spheres", 8}},
           nlohmann::json{{"robot", true}, {"max_protrusion", "5%"}, {"max_spheres", 256}},
       })
    call(&robot, post("/api/fit", body), 400);
  // The library checks a robot request whole before its thread starts: both forms of a limit.
  ViewFitRequest both;
  both.robot = true;
  both.tolerance.max_protrusion = 0.01;
  both.tolerance.max_protrusion_fraction = 0.05;
  Status st = startViewFit(&robot, both);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.error().message.find("both as a length and as a fraction"), std::string::npos)
      << st.error().message;
  EXPECT_EQ(call(&robot, post("/api/fit/status", nlohmann::json::object()))["state"], "idle");
}

}  // namespace
}  // namespace sphereset::test

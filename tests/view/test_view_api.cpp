// The view's API as a pure function (view.hpp, docs/view.md): the scene's fields, the geometry,
// edits and their certificates, the bound, a tree's levels, the save; and every bad request
// refused with its status and nothing changed (a robot's scene: test_view_robot_solids.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/solid_index.hpp"
#include "view/view_fixture.hpp"

namespace sphereset::test {
namespace {

TEST_F(ViewTest, SceneHoldsTheSolidItsSetAndCertificate) {
  ViewScene scene = boxScene();
  const nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["kind"], "mesh");
  EXPECT_EQ(j["title"], "box");
  EXPECT_EQ(j["version"], 0);
  ASSERT_EQ(j["solids"].size(), 1u);
  const nlohmann::json& s = j["solids"][0];
  EXPECT_TRUE(s["link"].is_null());
  EXPECT_EQ(s["triangles"], 12);
  EXPECT_EQ(s["vertices"], 8);
  EXPECT_DOUBLE_EQ(s["bounds"][1][2].get<double>(), 1.0);
  EXPECT_NEAR(s["diagonal"].get<double>(), std::sqrt(3.0), 1e-12);
  expectSameSpheres(spheresOf(s["spheres"]), {kBoxBall, {Vec3(0.5, 0.5, 0.5), 0.1}});
  EXPECT_TRUE(s["levels"].is_null());
  const nlohmann::json& c = s["certificate"];
  EXPECT_EQ(c["spheres"], 2);
  EXPECT_TRUE(c["covered"].get<bool>());
  EXPECT_EQ(c["outside_volume"].size(), 2u);
  EXPECT_NEAR(c["volume"].get<double>(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(c["max_gap"].get<double>(), 0.0);
  EXPECT_TRUE(j["joints"].empty());
  ASSERT_EQ(j["poses"].size(), 1u);
  EXPECT_EQ(j["poses"][0], nlohmann::json({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(j["save"]["path"], path("box.txt"));
  EXPECT_EQ(j["save"]["format"], "txt");
  // The page's quality list is the fit request's row, default included.
  EXPECT_EQ(j["fit"]["qualities"], nlohmann::json({"fast", "default", "best"}));
  EXPECT_EQ(j["fit"]["quality"], "default");
  for (const auto& name : j["fit"]["qualities"])
    EXPECT_TRUE(fitQualityFromName(name.get<std::string>()).ok()) << name;
}

TEST_F(ViewTest, GeometryIsTheDisplayedMeshInBinary) {
  ViewScene scene = boxScene();
  ViewRequest r = request("GET", "/api/geometry");
  r.query["solid"] = "0";
  const ViewResponse res = handleViewRequest(&scene, kAccess, r);
  ASSERT_EQ(res.status, 200) << res.body;
  EXPECT_EQ(res.content_type, "application/octet-stream");
  const Mesh& m = scene.solids[0].displayed();
  ASSERT_EQ(res.body.size(), 8u + 12u * 8u + 12u * 12u);
  uint32_t header[2];
  std::memcpy(header, res.body.data(), sizeof header);
  EXPECT_EQ(header[0], 8u);
  EXPECT_EQ(header[1], 12u);
  float v[3];
  std::memcpy(v, res.body.data() + 8 + 12 * 5, sizeof v);  // vertex 5
  for (int k = 0; k < 3; ++k) EXPECT_EQ(v[k], static_cast<float>(m.vertices[5][k]));
  uint32_t t[3];
  std::memcpy(t, res.body.data() + 8 + 12 * 8 + 12 * 11, sizeof t);  // triangle 11
  for (int k = 0; k < 3; ++k) EXPECT_EQ(t[k], static_cast<uint32_t>(m.triangles[11][k]));
}

TEST_F(ViewTest, EditUncoversAndBoundCoversAgain) {
  ViewScene scene = boxScene();
  nlohmann::json j = call(
      &scene, post("/api/edit",
                   {{"solid", 0},
                    {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {3.0, 0.5, 0.5, 0.2}}}}}}));
  EXPECT_EQ(j["version"], 1);
  EXPECT_FALSE(j["certificate"]["covered"].get<bool>());
  EXPECT_GT(j["certificate"]["max_gap"].get<double>(), 0.0);
  EXPECT_EQ(j["spheres"][0][0], 3.0);
  j = call(&scene, post("/api/bound", {{"solid", 0}}));
  EXPECT_EQ(j["version"], 2);
  EXPECT_TRUE(j["certificate"]["covered"].get<bool>());
  const std::vector<Sphere> bounded = spheresOf(j["spheres"]);
  EXPECT_EQ(bounded[0].center, Vec3(3.0, 0.5, 0.5));  // centres stay, radii grow
  EXPECT_GE(bounded[0].radius, 0.2);
  // The certificate is the evaluation's.
  const EvalResult e = coverageOnly(*scene.solids[0].index, bounded);
  EXPECT_TRUE(e.surface_covered && e.interior_covered);
  // add, then delete: indices as each edit finds the set.
  j = call(&scene, post("/api/edit", {{"solid", 0},
                                      {"edits",
                                       {{{"op", "add"}, {"sphere", {0.5, 0.5, 0.5, 0.05}}},
                                        {{"op", "delete"}, {"index", 0}}}}}));
  EXPECT_EQ(j["version"], 3);
  ASSERT_EQ(j["spheres"].size(), 2u);
  EXPECT_EQ(j["spheres"][1][3], 0.05);
}

// The certificate after a run of edits (taken incrementally) is the one a full certification of
// the same set gives, with the uncovered triangles listed; a copy of the scene taken before the
// edits keeps its own certificate.
TEST_F(ViewTest, EditedCertificateEqualsAFullOneAndListsTheGaps) {
  ViewScene scene = boxScene();
  const ViewScene before = scene;
  const nlohmann::json edits[] = {
      {{"op", "set"}, {"index", 0}, {"sphere", {0.5, 0.5, 1.3, 0.6}}},
      {{"op", "add"}, {"sphere", {0.0, 0.0, 0.0, 0.4}}},
      {{"op", "set"}, {"index", 1}, {"sphere", {0.5, 0.5, 0.3, 0.7}}},
      {{"op", "delete"}, {"index", 2}},
  };
  nlohmann::json j;
  for (const nlohmann::json& e : edits)
    j = call(&scene, post("/api/edit", {{"solid", 0}, {"edits", {e}}}));
  ViewSolid full = scene.solids[0];
  certifyViewSolid(&full);
  const ViewCertificate& c = scene.solids[0].certificate;
  EXPECT_FALSE(c.covered);
  EXPECT_FALSE(c.uncovered_triangles.empty());
  EXPECT_EQ(c.uncovered_triangles, full.certificate.uncovered_triangles);
  EXPECT_EQ(c.er_sum, full.certificate.er_sum);
  EXPECT_EQ(c.max_gap, full.certificate.max_gap);
  EXPECT_EQ(c.surface_covered, full.certificate.surface_covered);
  EXPECT_EQ(c.interior_covered, full.certificate.interior_covered);
  EXPECT_EQ(j["certificate"]["uncovered_triangles"].size(), c.uncovered_triangles.size());
  // The count agrees with the evaluation's.
  const EvalResult e = coverageOnly(*scene.solids[0].index, scene.solids[0].spheres());
  EXPECT_EQ(static_cast<int64_t>(c.uncovered_triangles.size()), e.uncovered_triangles);
  // The copy taken first is as it was.
  EXPECT_TRUE(before.solids[0].certificate.covered);
  EXPECT_TRUE(before.solids[0].certificate.uncovered_triangles.empty());
  EXPECT_EQ(before.solids[0].spheres().size(), 2u);
}

TEST_F(ViewTest, DeletingEverySphereLeavesAnUncoveredSet) {
  ViewScene scene = boxScene();
  const nlohmann::json j =
      call(&scene,
           post("/api/edit",
                {{"solid", 0},
                 {"edits", {{{"op", "delete"}, {"index", 1}}, {{"op", "delete"}, {"index", 0}}}}}));
  EXPECT_EQ(j["certificate"]["spheres"], 0);
  EXPECT_FALSE(j["certificate"]["covered"].get<bool>());
  EXPECT_TRUE(j["certificate"]["max_gap"].is_null());
  call(&scene, post("/api/bound", {{"solid", 0}}), 400);  // nothing to grow
  EXPECT_EQ(scene.version, 1);
}

TEST_F(ViewTest, SaveWritesTheSetWhereTheSceneSays) {
  ViewScene scene = boxScene();
  call(&scene,
       post("/api/edit",
            {{"solid", 0},
             {"edits",
              {{{"op", "set"}, {"index", 1}, {"sphere", {0.25, 0.75, 1.0 / 3.0, 0.125}}}}}}));
  const nlohmann::json j = call(&scene, post("/api/save", nlohmann::json::object()));
  EXPECT_EQ(j["path"], path("box.txt"));
  EXPECT_GT(j["bytes"].get<int64_t>(), 0);
  auto saved = readSpheres(path("box.txt"));
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  expectSameSpheres(*saved, scene.solids[0].spheres());
  const EvalResult e = coverageOnly(*scene.solids[0].index, *saved);
  EXPECT_EQ(e.surface_covered && e.interior_covered, scene.solids[0].certificate.covered);
}

TEST_F(ViewTest, OutputFixesTheSavePathAndFormat) {
  const std::string spheres = path("in.txt");
  ASSERT_TRUE(writeSpheres(spheres, {kBoxBall}).ok());
  ViewLoadOptions o;
  o.output = path("out.json");
  auto scene = loadViewScene(writeBox(), spheres, o);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const nlohmann::json j = call(&*scene, post("/api/save", nlohmann::json::object()));
  EXPECT_EQ(j["path"], path("out.json"));
  auto saved = readSpheres(path("out.json"));
  ASSERT_TRUE(saved.ok());
  expectSameSpheres(*saved, {kBoxBall});
  o.output = writeBox();  // the mesh itself: refused
  EXPECT_FALSE(loadViewScene(writeBox(), spheres, o).ok());
}

TEST_F(ViewTest, TreeLevelsChangeTheShownSet) {
  ViewScene scene = treeScene();
  nlohmann::json j = call(&scene, request("GET", "/api/scene"));
  EXPECT_EQ(j["solids"][0]["levels"], nlohmann::json({{"count", 3}, {"current", 2}}));
  EXPECT_EQ(j["solids"][0]["spheres"].size(), 4u);
  EXPECT_FALSE(j["solids"][0]["certificate"]["covered"].get<bool>());
  j = call(&scene, post("/api/level", {{"solid", 0}, {"level", 1}}));
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["spheres"].size(), 2u);
  EXPECT_TRUE(j["certificate"]["covered"].get<bool>());
  call(&scene, post("/api/level", {{"solid", 0}, {"level", 3}}), 400);
  call(&scene, post("/api/level", {{"solid", 0}, {"level", -1}}), 400);
  EXPECT_EQ(scene.version, 1);
  // An edit of level 1 goes back into its slots.
  call(&scene,
       post("/api/edit",
            {{"solid", 0},
             {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {0.5, 0.5, 0.5, 0.95}}}}}}));
  call(&scene, post("/api/save", nlohmann::json::object()));
  auto saved = readSphereTree(path("box_tree.sph"));
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  EXPECT_EQ(saved->depth, 2);
  expectSameSpheres(saved->level(1), scene.solids[0].spheres());
  // A level whose count changed no longer fits the layout: the save is refused.
  call(&scene, post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 1}}}}}));
  call(&scene, post("/api/save", nlohmann::json::object()), 400);
  // A set has no levels.
  ViewScene set = boxScene("set.txt");
  call(&set, post("/api/level", {{"solid", 0}, {"level", 0}}), 400);
}

TEST_F(ViewTest, ARepairedMeshShowsAndCertifiesItsOriginalTriangles) {
  // The unit cube with one triangle flipped: reoriented by the repair.
  const std::string mesh = write(
      "flipped.off",
      "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n3 0 2 3\n3 0 3 1\n"
      "3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 4 5\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n"
      "3 1 7 5\n");
  const std::string spheres = path("ball.txt");
  ASSERT_TRUE(writeSpheres(spheres, {kBoxBall}).ok());
  auto scene = loadViewScene(mesh, spheres);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const ViewSolid& s = scene->solids[0];
  ASSERT_NE(originalTriangles(s.input->repair), nullptr);
  EXPECT_EQ(&s.displayed(), originalTriangles(s.input->repair));
  EXPECT_TRUE(s.certificate.original_covered);
  EXPECT_TRUE(s.certificate.covered);
  // The page can ask for either surface; the scene says there are two.
  EXPECT_TRUE(call(&*scene, request("GET", "/api/scene"))["solids"][0]["repaired"].get<bool>());
  ViewRequest g = request("GET", "/api/geometry");
  g.query = {{"solid", "0"}, {"surface", "repaired"}};
  EXPECT_EQ(handleViewRequest(&*scene, kAccess, g).body, viewGeometry(s, ViewSurface::kRepaired));
  EXPECT_NE(viewGeometry(s, ViewSurface::kRepaired), viewGeometry(s));
  g.query["surface"] = "displayed";
  EXPECT_EQ(handleViewRequest(&*scene, kAccess, g).body, viewGeometry(s));
  g.query["surface"] = "other";
  call(&*scene, g, 400);
  // Shrunk to miss the corners: the original triangles are not covered any more either.
  ASSERT_TRUE(applyViewEdits(&*scene, 0, {{ViewEdit::Op::kSet, 0, {kBoxBall.center, 0.6}}}).ok());
  EXPECT_FALSE(scene->solids[0].certificate.original_covered);
  EXPECT_FALSE(scene->solids[0].certificate.covered);
}

// Every answer, refusals included, carries the safety headers; a POST to a path the table does
// not hold is "no such path", never a save.
TEST_F(ViewTest, EveryAnswerHasItsHeadersAndOnlyTheRoutesAnswer) {
  ViewScene scene = boxScene();
  const auto has = [](const ViewResponse& r, const std::string& name, const std::string& value) {
    for (const auto& [k, v] : r.headers)
      if (k == name && v == value) return true;
    return false;
  };
  ViewRequest unknown = post("/api/saveas", nlohmann::json::object());
  for (const ViewRequest& r : {request("GET", "/api/scene", ""), unknown,
                               request("GET", "/nothing", ""), post("/api/save", {{"x", 1}})}) {
    const ViewResponse a = handleViewRequest(&scene, kAccess, r);
    EXPECT_TRUE(has(a, "X-Content-Type-Options", "nosniff")) << r.path;
    EXPECT_TRUE(has(a, "Referrer-Policy", "no-referrer")) << r.path;
    EXPECT_TRUE(has(a, "Cache-Control", "no-store")) << r.path;
  }
  const ViewResponse a = handleViewRequest(&scene, kAccess, unknown);
  EXPECT_EQ(a.status, 404);
  EXPECT_NE(a.body.find("no such path: /api/saveas"), std::string::npos) << a.body;
}

// One request of thousands of adds used to take each through the incremental certificate (8 000
// adds: 18 s, holding the scene): many edits get one full certificate, the same as edit by edit.
TEST_F(ViewTest, ARequestOfManyAddsIsCertifiedInFull) {
  ViewScene scene = boxScene();
  nlohmann::json edits = nlohmann::json::array();
  for (int i = 0; i < 4000; ++i)
    edits.push_back(
        {{"op", "add"}, {"sphere", {0.001 * (i % 1000), 0.0005 * (i % 7), 0.1, 0.01 + 1e-6 * i}}});
  edits.push_back({{"op", "delete"}, {"index", 0}});
  const nlohmann::json j = call(&scene, post("/api/edit", {{"solid", 0}, {"edits", edits}}));
  EXPECT_EQ(scene.solids[0].spheres().size(), 2u + 4000u - 1u);
  ViewSolid full = scene.solids[0];
  certifyViewSolid(&full);
  const ViewCertificate& c = scene.solids[0].certificate;
  EXPECT_EQ(c.uncovered_triangles, full.certificate.uncovered_triangles);
  EXPECT_EQ(c.er_sum, full.certificate.er_sum);
  EXPECT_EQ(c.covered, full.certificate.covered);
  EXPECT_EQ(j["spheres"].size(), 4001u);
  // The next single edit is incremental again, on the full certificate's engine.
  call(&scene, post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 0}}}}}));
  full = scene.solids[0];
  certifyViewSolid(&full);
  EXPECT_EQ(scene.solids[0].certificate.er_sum, full.certificate.er_sum);
}

TEST_F(ViewTest, BadRequestsChangeNothing) {
  ViewScene scene = boxScene();
  const std::string before = viewSceneJson(scene);
  struct Case {
    std::string what;
    ViewRequest request;
    int status;
  };
  auto without = [](ViewRequest r, const std::string& header) {
    std::erase_if(r.headers, [&](const auto& h) { return h.first == header; });
    return r;
  };
  auto with = [&](ViewRequest r, const std::string& header, const std::string& value) {
    r = without(r, header);
    r.headers.emplace_back(header, value);
    return r;
  };
  const nlohmann::json good = {
      {"solid", 0}, {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", {0, 0, 0, 1}}}}}};
  auto edit = [&](const nlohmann::json& sphere) {
    return post("/api/edit",
                {{"solid", 0}, {"edits", {{{"op", "set"}, {"index", 0}, {"sphere", sphere}}}}});
  };
  const std::vector<Case> cases = {
      {"no token", without(post("/api/edit", good), "x-sphereset-token"), 401},
      {"wrong token", with(post("/api/edit", good), "x-sphereset-token", "0123"), 401},
      {"two tokens",
       [&] {
         ViewRequest r = post("/api/edit", good);
         r.headers.emplace_back("x-sphereset-token", "other");
         return r;
       }(),
       401},
      {"token in the query",
       [&] {
         ViewRequest r = without(post("/api/edit", good), "x-sphereset-token");
         r.query["token"] = kAccess.token;
         return r;
       }(),
       401},
      {"bad Host", with(post("/api/edit", good), "host", "evil.example:8765"), 403},
      {"Host of another port", with(post("/api/edit", good), "host", "127.0.0.1:80"), 403},
      {"no Host", without(post("/api/edit", good), "host"), 403},
      {"bad Origin", with(post("/api/edit", good), "origin", "http://evil.example"), 403},
      {"https Origin", with(post("/api/edit", good), "origin", "https://127.0.0.1:8765"), 403},
      {"null Origin", with(post("/api/edit", good), "origin", "null"), 403},
      {"bad JSON", request("POST", "/api/edit", "{\"solid\": 0,"), 400},
      {"not JSON", with(post("/api/edit", good), "content-type", "text/plain"), 400},
      {"string radius", edit({0, 0, 0, "1"}), 400},
      {"null radius", edit({0, 0, 0, nullptr}), 400},
      {"huge radius",
       request("POST", "/api/edit",
               R"({"solid":0,"edits":[{"op":"set","index":0,"sphere":[0,0,0,1e999]}]})"),
       400},
      {"negative radius", edit({0, 0, 0, -1}), 400},
      {"coordinate beyond the limit", edit({1e31, 0, 0, 1}), 400},
      {"three numbers", edit({0, 0, 1}), 400},
      {"index out of range",
       post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 2}}}}}), 400},
      {"negative index",
       post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", -1}}}}}), 400},
      {"float index",
       post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "delete"}, {"index", 0.5}}}}}), 400},
      {"one bad edit of two",
       post("/api/edit",
            {{"solid", 0},
             {"edits", {{{"op", "delete"}, {"index", 0}}, {{"op", "delete"}, {"index", 1}}}}}),
       400},
      {"unknown op", post("/api/edit", {{"solid", 0}, {"edits", {{{"op", "move"}}}}}), 400},
      {"unknown solid", post("/api/bound", {{"solid", 1}}), 400},
      {"solid as text", post("/api/bound", {{"solid", "0"}}), 400},
      {"unknown joint", post("/api/pose", {{"joints", {{"joint1", 0.1}}}}), 400},
      {"oversized body",
       request("POST", "/api/edit",
               std::string(static_cast<size_t>(limits::kMaxViewRequestBytes) + 1, ' ')),
       413},
      {"unknown path", request("GET", "/api/secrets"), 404},
      {"wrong method", request("GET", "/api/edit"), 405},
      {"POST to the scene", post("/api/scene", nlohmann::json::object()), 405},
      {"DELETE", request("DELETE", "/api/save"), 405},
      {"save path in the body", post("/api/save", {{"path", path("elsewhere.txt")}}), 400},
      {"save as a list", request("POST", "/api/save", "[]"), 400},
  };
  for (const Case& c : cases) {
    const ViewResponse res = handleViewRequest(&scene, kAccess, c.request);
    EXPECT_EQ(res.status, c.status) << c.what << ": " << res.body;
    const nlohmann::json j = nlohmann::json::parse(res.body);
    const std::string error = j.value("error", std::string());
    EXPECT_FALSE(error.empty()) << c.what;
    EXPECT_EQ(error.find('\n'), std::string::npos) << c.what;
    EXPECT_EQ(viewSceneJson(scene), before) << c.what;
  }
  EXPECT_FALSE(std::filesystem::exists(path("elsewhere.txt")));
  // Geometry of an unknown solid or without one.
  ViewRequest g = request("GET", "/api/geometry");
  call(&scene, g, 400);
  g.query["solid"] = "1";
  call(&scene, g, 400);
  g.query["solid"] = "-0";
  call(&scene, g, 400);
  EXPECT_EQ(scene.version, 0);
}

TEST_F(ViewTest, TheServersOwnNamesAreAccepted) {
  ViewScene scene = boxScene();
  for (const std::string host : {"127.0.0.1:8765", "localhost:8765"}) {
    ViewRequest r = request("GET", "/api/scene");
    r.headers = {
        {"host", host}, {"origin", "http://" + host}, {"x-sphereset-token", kAccess.token}};
    call(&scene, r, 200);
  }
  // The page itself: the token in the query.
  ViewRequest page = request("GET", "/");
  page.headers = {{"host", "localhost:8765"}};
  page.query["token"] = kAccess.token;
  EXPECT_EQ(handleViewRequest(&scene, kAccess, page).status, viewPageAvailable() ? 200 : 500);
  page.query["token"] = "x";
  EXPECT_EQ(handleViewRequest(&scene, kAccess, page).status, 401);
}

TEST_F(ViewTest, TokensAreFreshAndLongEnough) {
  const std::string a = randomViewToken(), b = randomViewToken();
  EXPECT_EQ(a.size(), 32u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace sphereset::test

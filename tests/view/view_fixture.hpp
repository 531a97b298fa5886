// The view tests' scenes: a unit box with one sphere that covers it, a two-level tree over the
// box, and the robot of the robot tests with spheres for two links; requests as the page sends
// them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"
#include "sphereset/view.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset::test {

// A sphere around the unit box [0, 1]³ (half its diagonal, and a margin).
inline const Sphere kBoxBall{Vec3(0.5, 0.5, 0.5), 0.5 * std::sqrt(3.0) + 1e-3};

// The address and token of the pure function's tests.
inline const ViewAccess kAccess{"0123456789abcdef0123456789abcdef", "127.0.0.1", 8765};

class ViewTest : public TempDirTest {
 public:
  // The unit box as an OFF file.
  std::string writeBox() {
    const Mesh m = makeBox(Vec3::Zero(), Vec3::Ones());
    std::string off = "OFF\n" + std::to_string(m.vertices.size()) + " " +
                      std::to_string(m.triangles.size()) + " 0\n";
    for (const Vec3& v : m.vertices)
      off +=
          std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z()) + "\n";
    for (const Triangle& t : m.triangles)
      off += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
             "\n";
    return write("box.off", off);
  }

  // The box with two spheres: the covering ball and a small one inside.
  ViewScene boxScene(const std::string& spheres_name = "box.txt") {
    const std::string spheres = path(spheres_name);
    EXPECT_TRUE(writeSpheres(spheres, {kBoxBall, {Vec3(0.5, 0.5, 0.5), 0.1}}).ok());
    auto scene = loadViewScene(writeBox(), spheres);
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    return scene.ok() ? std::move(scene).value() : ViewScene{};
  }

  // A tree over the box: branching 2, depth 2; the root and the level below cover it.
  ViewScene treeScene() {
    const Sphere big{kBoxBall.center, kBoxBall.radius + 0.6};
    std::vector<Sphere> nodes = {big,
                                 kBoxBall,
                                 {Vec3(0.5, 0.5, 0.5), 0.3},
                                 {Vec3(0.25, 0.5, 0.5), 0.2},
                                 {Vec3(0.75, 0.5, 0.5), 0.2},
                                 {Vec3(0.5, 0.5, 0.5), 0.1},
                                 {Vec3(0.5, 0.5, 0.4), 0.1}};
    auto tree = makeSphereTree(2, 2, nodes);
    EXPECT_TRUE(tree.ok()) << tree.error().message;
    const std::string file = path("box_tree.sph");
    EXPECT_TRUE(writeSphereTree(file, *tree).ok());
    auto scene = loadViewScene(writeBox(), file);
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    return scene.ok() ? std::move(scene).value() : ViewScene{};
  }

  // Spheres for the three-link robot's link1 and link2 (in cuRobo's YAML); the file's path.
  std::string robotSpheres() {
    const std::string file = path("robot.yml");
    EXPECT_TRUE(writeLinkSpheres(file, {{"link1", {{Vec3(0, 0, 0.2), 0.25}}},
                                        {"link2", {{Vec3(0.1, -0.2, 0.3), 0.4}}}})
                    .ok());
    return file;
  }

  // How the tests load the robot: its package folder, each link's walls (the envelope needs
  // the wrapping, GPL repair).
  static ViewLoadOptions robotOptions() {
    ViewLoadOptions o;
    o.robot_load.package_paths = {robotDir()};
    o.robot_load.use_ros_package_path = false;
    o.link_solid = LinkSolid::kWalls;
    return o;
  }

  // The three-link robot with robotSpheres().
  ViewScene robotScene() {
    auto scene = loadViewScene(threeLinkUrdf(), robotSpheres(), robotOptions());
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    return scene.ok() ? std::move(scene).value() : ViewScene{};
  }

  // A request as the page sends it: its own Host, the token, JSON.
  static ViewRequest request(const std::string& method, const std::string& path,
                             const std::string& body = "") {
    ViewRequest r;
    r.method = method;
    r.path = path;
    r.headers = {{"host", "127.0.0.1:8765"},
                 {"origin", "http://127.0.0.1:8765"},
                 {"x-sphereset-token", kAccess.token},
                 {"content-type", "application/json"}};
    r.body = body;
    return r;
  }
  static ViewRequest post(const std::string& path, const nlohmann::json& body) {
    return request("POST", path, body.dump());
  }
};

// The API's answer to `r`, checked to have `status`; its JSON (null for another content type).
inline nlohmann::json call(ViewScene* scene, const ViewRequest& r, int status = 200) {
  const ViewResponse res = handleViewRequest(scene, kAccess, r);
  EXPECT_EQ(res.status, status) << r.method << " " << r.path << ": " << res.body;
  if (res.content_type != "application/json") return {};
  return nlohmann::json::parse(res.body);
}

inline std::vector<Sphere> spheresOf(const nlohmann::json& a) {
  std::vector<Sphere> out;
  for (const auto& s : a)
    out.push_back(
        {Vec3(s[0].get<double>(), s[1].get<double>(), s[2].get<double>()), s[3].get<double>()});
  return out;
}

inline void expectSameSpheres(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a[i].center - b[i].center).norm(), 0.0, 1e-12) << i;
    EXPECT_NEAR(a[i].radius, b[i].radius, 1e-12) << i;
  }
}

}  // namespace sphereset::test

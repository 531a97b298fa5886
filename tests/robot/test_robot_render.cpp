// Pictures of the three-link robot: the posed robot fills its view (the cameras frame the
// geometry, not its bounding sphere), and one link alone draws something else.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/render.hpp"
#include "sphereset/robot_query.hpp"

namespace sphereset {
namespace {

// The box of the pixels that differ from the background: the sky depends on a pixel's ray
// direction only, which a view fixes whatever the scene, so a scene drawn fully transparent
// without ground gives the background alone.
struct Extent {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  long pixels = 0;
  int width() const { return x1 < 0 ? 0 : x1 - x0 + 1; }
  int height() const { return y1 < 0 ? 0 : y1 - y0 + 1; }
};

Extent drawnExtent(const Image& img, const RenderOptions& o) {
  RenderOptions bare = o;
  bare.sphere_opacity = 0.0;
  auto bg = renderScene(nullptr, {{Vec3::Zero(), 1.0}}, bare);
  EXPECT_TRUE(bg.ok());
  Extent e;
  for (int y = 1; y + 1 < img.height; ++y)  // the tile's one-pixel white border left out
    for (int x = 1; x + 1 < img.width; ++x)
      if (img.at(x, y) != bg->at(x, y)) {
        e.x0 = std::min(e.x0, x);
        e.x1 = std::max(e.x1, x);
        e.y0 = std::min(e.y0, y);
        e.y1 = std::max(e.y1, y);
        ++e.pixels;
      }
  return e;
}

const std::vector<LinkSpheres> kHandSpheres = {
    {"base_link", {{Vec3(0, 0, 0.05), 0.12}}},
    {"link1", {{Vec3(0, 0, 0.1), 0.06}, {Vec3(0, 0, 0.3), 0.06}}},
    {"link2", {{Vec3(0.1, -0.2, 0.3), 0.15}}}};

RenderOptions frontView() {
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.views = {View::kFront};
  o.up_axis = 2;
  o.ground = false;
  return o;
}

TEST(RobotRender, PosedRobotFillsTheView) {
  const Robot robot = test::threeLinkRobot();
  const RenderOptions o = frontView();
  for (const double q : {0.0, 0.8, -1.5}) {
    auto scene = robotScene(robot, kHandSpheres, {{"joint2", q}});
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const SolidIndex index(scene->mesh);
    auto img = renderScene(&index, scene->spheres, o);
    ASSERT_TRUE(img.ok());
    const Extent e = drawnExtent(*img, o);
    // At least 60% of the larger dimension, and most of the view along the robot's longer side.
    EXPECT_GE(std::max(e.width(), e.height()), 0.6 * std::max(o.width, o.height)) << q;
    EXPECT_TRUE(e.width() >= 0.85 * o.width || e.height() >= 0.85 * o.height)
        << "joint2 " << q << ": " << e.width() << "x" << e.height();
  }
}

TEST(RobotRender, OneLinkAloneIsDrawnInItsOwnFrame) {
  const Robot robot = test::threeLinkRobot();
  const RenderOptions o = frontView();
  auto whole = robotScene(robot, kHandSpheres);
  auto link = linkScene(robot, kHandSpheres, "link2");
  ASSERT_TRUE(whole.ok() && link.ok());
  EXPECT_LT(link->mesh.triangles.size(), whole->mesh.triangles.size());
  ASSERT_EQ(link->spheres.size(), 1u);
  EXPECT_EQ(link->spheres[0].center, Vec3(0.1, -0.2, 0.3));  // the link frame, not posed
  const SolidIndex wi(whole->mesh), li(link->mesh);
  auto a = renderScene(&wi, whole->spheres, o);
  auto b = renderScene(&li, link->spheres, o);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_NE(a->rgb, b->rgb);
  const Extent e = drawnExtent(*b, o);
  EXPECT_GT(e.pixels, o.width * o.height / 10);
  EXPECT_GE(std::max(e.width(), e.height()), 0.6 * std::max(o.width, o.height));

  auto bad = linkScene(robot, kHandSpheres, "elbow");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.error().message.find("no link 'elbow' in robot 'three_link'"), std::string::npos)
      << bad.error().message;
}

}  // namespace
}  // namespace sphereset

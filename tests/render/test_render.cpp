// The renderer on a known scene: where the sphere is, where nothing is, where the shadow is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "render/camera.hpp"
#include "sphereset/render.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

int brightness(const Image& img, double x, double y) {
  const auto c = img.at(static_cast<int>(x), static_cast<int>(y));
  return c[0] + c[1] + c[2];
}

TEST(Render, SpherePresentAbsentAndShadow) {
  const SolidIndex box(test::makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)));
  const std::vector<Sphere> ball = {{Vec3::Zero(), 1.8}};
  RenderOptions o;
  o.width = 240;
  o.height = 240;
  o.views = {View::kFront};
  o.up_axis = 1;
  auto with = renderScene(&box, ball, o);
  RenderOptions clear = o;  // the same framing, the sphere fully transparent
  clear.sphere_opacity = 0.0;
  auto without = renderScene(&box, ball, clear);
  ASSERT_TRUE(with.ok() && without.ok());
  const std::vector<Camera> cams = renderCameras(&box, ball, o);
  ASSERT_EQ(cams.size(), 1u);
  double px, py;
  // The box's front face centre: the translucent sphere changes it.
  ASSERT_TRUE(cams[0].project(Vec3(0, 0, 1), &px, &py));
  EXPECT_NEAR(px, 120, 2);
  const auto a = with->at(px, py), b = without->at(px, py);
  EXPECT_NE(a, b);
  // Just outside the sphere's silhouette on the left: the same pixel either way.
  ASSERT_TRUE(cams[0].project(Vec3(-2.0, 0.3, 0), &px, &py));
  EXPECT_EQ(with->at(px, py), without->at(px, py));
  // A sky pixel at the top-left corner is the background, with or without the sphere.
  EXPECT_EQ(with->at(3, 3), without->at(3, 3));

  // The shadow: the light comes from up + 0.45 z + 0.3 x, so the box's shadow falls on the
  // ground on the -z side; the ground on the +z side, as far from the box, is lit.
  o.views = {View::kTop};
  auto top = renderScene(&box, {}, o);
  ASSERT_TRUE(top.ok());
  const std::vector<Camera> tc = renderCameras(&box, {}, o);
  double sx, sy, lx, ly;
  ASSERT_TRUE(tc[0].project(Vec3(-0.3, -1, -1.6), &sx, &sy));
  ASSERT_TRUE(tc[0].project(Vec3(-0.3, -1, 1.6), &lx, &ly));
  EXPECT_LT(brightness(*top, sx, sy) + 100, brightness(*top, lx, ly));
}

// The picture does not depend on the scene's scale: a mesh 1e-30 across used to render blank
// (the scene's radius had an absolute floor of 1e-12).
TEST(Render, TinyScenesLookLikeUnitOnes) {
  const double tiny = 1e-30;
  const SolidIndex unit(test::makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1)));
  const SolidIndex small(test::makeBox(Vec3(-tiny, -tiny, -tiny), Vec3(tiny, tiny, tiny)));
  RenderOptions o;
  o.width = 120;
  o.height = 120;
  o.views = {View::kThreeQuarter};
  auto a = renderScene(&unit, {{Vec3::Zero(), 1.5}}, o);
  auto b = renderScene(&small, {{Vec3::Zero(), 1.5 * tiny}}, o);
  ASSERT_TRUE(a.ok() && b.ok());
  int differ = 0;
  for (size_t i = 0; i < a->rgb.size(); ++i)
    differ += std::abs(int(a->rgb[i]) - int(b->rgb[i])) > 2;
  EXPECT_LT(differ, static_cast<int>(a->rgb.size() / 100)) << differ;
}

TEST(Render, PngIsWrittenAndBadOptionsAreRefused) {
  const std::vector<Sphere> ball = {{Vec3::Zero(), 1.0}};
  RenderOptions o;
  o.width = 64;
  o.height = 48;
  auto img = renderScene(nullptr, ball, o);
  ASSERT_TRUE(img.ok());
  EXPECT_EQ(img->rgb.size(), 64u * 48u * 3u);
  const auto path = test::tempPath("render_test.png");
  ASSERT_TRUE(writePng(path.string(), *img).ok());
  std::ifstream in(path, std::ios::binary);
  unsigned char head[24] = {};
  in.read(reinterpret_cast<char*>(head), 24);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(head) + 1, 3), "PNG");
  // The IHDR chunk: width and height, big-endian, at bytes 16-23.
  auto be32 = [&](int at) {
    return (uint32_t{head[at]} << 24) | (uint32_t{head[at + 1]} << 16) |
           (uint32_t{head[at + 2]} << 8) | uint32_t{head[at + 3]};
  };
  EXPECT_EQ(std::string(reinterpret_cast<char*>(head) + 12, 4), "IHDR");
  EXPECT_EQ(be32(16), 64u);
  EXPECT_EQ(be32(20), 48u);
  std::filesystem::remove(path);
  EXPECT_FALSE(renderScene(nullptr, {}, o).ok());
  o.width = 5;
  EXPECT_FALSE(renderScene(nullptr, ball, o).ok());
}

}  // namespace
}  // namespace sphereset

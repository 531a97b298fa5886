// URDF output with sphere collisions: the three-link robot rewritten with spheres for two links,
// loaded back with loadRobot (listed links hold exactly their spheres, the others and the
// joints are unchanged), the rest of the document kept, and one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using Kind = LinkGeometry::Kind;

// The output is written in a temporary folder: its only mesh path is package://, resolved
// through the package folder given here, so it loads from anywhere.
RobotLoadOptions packageOptions() {
  RobotLoadOptions o;
  o.package_paths = {test::robotDir()};
  o.use_ros_package_path = false;
  return o;
}

std::vector<LinkSpheres> spheres() {
  return {{"link2",
           {Sphere{Vec3(0.1, -0.2, 1.0 / 3.0), 0.125}, Sphere{Vec3(0.45, 0, 0), 0.05},
            Sphere{Vec3(-1e-7, 2.5e3, 0), 0.1 + 0.2}}},
          {"base_link", {Sphere{Vec3(0, 0, 0.05), 0.18}}}};
}

std::string readText(const std::string& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class UrdfWrite : public test::TempDirTest {};

TEST_F(UrdfWrite, ListedLinksHoldExactlyTheirSpheres) {
  const std::string out = path("spheres.urdf");
  const Status st = writeSphereUrdf(test::threeLinkUrdf(), out, spheres());
  ASSERT_TRUE(st.ok()) << st.error().message;
  const auto text = formatSphereUrdf(test::threeLinkUrdf(), spheres());
  ASSERT_TRUE(text.ok()) << text.error().message;
  EXPECT_EQ(readText(out), *text);
  auto before = loadRobot(test::threeLinkUrdf(), packageOptions());
  auto after = loadRobot(out, packageOptions());
  ASSERT_TRUE(before.ok()) << before.error().message;
  ASSERT_TRUE(after.ok()) << after.error().message;
  EXPECT_EQ(after->name, "three_link");
  ASSERT_EQ(after->links.size(), 4u);

  for (const LinkSpheres& ls : spheres()) {
    const auto it = std::find_if(after->links.begin(), after->links.end(),
                                 [&](const RobotLink& l) { return l.name == ls.link; });
    ASSERT_NE(it, after->links.end()) << ls.link;
    EXPECT_FALSE(it->from_visual);
    ASSERT_EQ(it->geometry.size(), ls.spheres.size()) << ls.link;
    for (size_t i = 0; i < ls.spheres.size(); ++i) {
      const LinkGeometry& g = it->geometry[i];
      EXPECT_EQ(g.kind, Kind::kSphere);
      // Shortest round-trip numbers: exactly the same doubles.
      EXPECT_EQ(g.origin.translation(), ls.spheres[i].center) << ls.link << " " << i;
      EXPECT_TRUE(g.origin.linear().isIdentity(0.0));
      EXPECT_EQ(g.radius, ls.spheres[i].radius) << ls.link << " " << i;
    }
  }

  // link1 (cylinder) and tool (visual sphere) are unchanged.
  for (size_t l : {size_t{1}, size_t{3}}) {
    const RobotLink& a = before->links[l];
    const RobotLink& b = after->links[l];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.from_visual, b.from_visual);
    ASSERT_EQ(a.geometry.size(), b.geometry.size());
    for (size_t i = 0; i < a.geometry.size(); ++i) {
      EXPECT_EQ(a.geometry[i].kind, b.geometry[i].kind);
      EXPECT_EQ(a.geometry[i].radius, b.geometry[i].radius);
      EXPECT_EQ(a.geometry[i].length, b.geometry[i].length);
      EXPECT_TRUE(a.geometry[i].origin.isApprox(b.geometry[i].origin, 0.0));
    }
  }
  EXPECT_EQ(after->links[1].geometry[0].kind, Kind::kCylinder);
  EXPECT_TRUE(after->links[3].from_visual);

  ASSERT_EQ(before->joints.size(), after->joints.size());
  for (size_t j = 0; j < before->joints.size(); ++j) {
    const RobotJoint& a = before->joints[j];
    const RobotJoint& b = after->joints[j];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.parent, b.parent);
    EXPECT_EQ(a.child, b.child);
    EXPECT_EQ(a.type, b.type);
    EXPECT_TRUE(a.origin.isApprox(b.origin, 0.0)) << a.name;
    EXPECT_EQ(a.axis, b.axis);
    EXPECT_EQ(a.lower, b.lower);
    EXPECT_EQ(a.upper, b.upper);
  }
}

TEST_F(UrdfWrite, KeepsTheRestOfTheDocument) {
  auto text = formatSphereUrdf(test::threeLinkUrdf(), spheres());
  ASSERT_TRUE(text.ok()) << text.error().message;
  // Comments, visuals, unlisted collisions, joint attributes in their order.
  EXPECT_NE(text->find("<!-- A small synthetic robot"), std::string::npos) << *text;
  EXPECT_NE(text->find("<box size=\"1 1 1\" />"), std::string::npos) << *text;
  EXPECT_NE(text->find("<cylinder radius=\"0.05\" length=\"0.4\" />"), std::string::npos);
  EXPECT_NE(text->find("<limit lower=\"-1.5\" upper=\"1.5\" effort=\"10\" velocity=\"1\" />"),
            std::string::npos);
  // The replaced collisions are gone: no mesh and no box collision of the base.
  EXPECT_EQ(text->find("link.stl"), std::string::npos);
  EXPECT_EQ(text->find("0.2 0.3 0.1"), std::string::npos);
  EXPECT_NE(text->find("<collision name=\"sphere_2\">"), std::string::npos);
  EXPECT_NE(text->find("<origin xyz=\"0 0 0.05\" rpy=\"0 0 0\" />"), std::string::npos);
  EXPECT_NE(text->find("<sphere radius=\"0.18\" />"), std::string::npos);
}

TEST_F(UrdfWrite, EmptyListRemovesTheCollisions) {
  auto text = formatSphereUrdf(test::threeLinkUrdf(), {{"link1", {}}});
  ASSERT_TRUE(text.ok()) << text.error().message;
  EXPECT_EQ(text->find("<cylinder"), std::string::npos);
  EXPECT_NE(text->find("<box size=\"1 1 1\" />"), std::string::npos);  // link1's visual
}

TEST_F(UrdfWrite, Errors) {
  const std::string missing = path("missing.urdf");
  test::expectError(formatSphereUrdf(missing, spheres()), ErrorCode::kUnreadable, missing, "");
  const std::string junk = write("junk.urdf", "<robot><link name=\"a\"></robot>");
  test::expectError(formatSphereUrdf(junk, spheres()), ErrorCode::kInvalidData, junk, "not XML");
  const std::string other = write("other.urdf", "<?xml version=\"1.0\"?>\n<sdf><link/></sdf>");
  test::expectError(formatSphereUrdf(other, spheres()), ErrorCode::kInvalidData, other,
                    "no <robot>");
  test::expectError(formatSphereUrdf(test::threeLinkUrdf(), {{"nope", {}}}),
                    ErrorCode::kInvalidArgument, test::threeLinkUrdf(), "'nope'");
  const std::string out = path("out.urdf");
  const Status st = writeSphereUrdf(junk, out, spheres());
  ASSERT_FALSE(st.ok());
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace sphereset

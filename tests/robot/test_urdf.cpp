// URDF loading: links and joints in file order, collision and visual geometry, mesh paths
// resolved through package folders (by folder name, by package.xml name, ROS_PACKAGE_PATH),
// relative and file:// paths, and one-line errors for missing meshes and bad files.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <numbers>
#include <string>
#include <utility>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;
using Kind = LinkGeometry::Kind;

bool samePath(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

RobotLoadOptions packageOptions(std::vector<std::string> paths) {
  RobotLoadOptions o;
  o.package_paths = std::move(paths);
  o.use_ros_package_path = false;
  return o;
}

// Sets ROS_PACKAGE_PATH for one test and restores it afterwards.
class RosPackagePath {
 public:
  explicit RosPackagePath(const std::string& value) {
    if (const char* old = std::getenv("ROS_PACKAGE_PATH")) {
      old_ = old;
      had_ = true;
    }
    ::setenv("ROS_PACKAGE_PATH", value.c_str(), 1);
  }
  ~RosPackagePath() {
    if (had_) {
      ::setenv("ROS_PACKAGE_PATH", old_.c_str(), 1);
    } else {
      ::unsetenv("ROS_PACKAGE_PATH");
    }
  }

 private:
  std::string old_;
  bool had_ = false;
};

class Urdf : public test::TempDirTest {
 protected:
  // A one-link robot whose collision is a mesh of the given file name.
  std::string meshRobot(const std::string& name, const std::string& filename) const {
    return write(name,
                 "<robot name=\"r\"><link name=\"part\"><collision><geometry><mesh "
                 "filename=\"" +
                     filename + "\"/></geometry></collision></link></robot>");
  }
};

TEST_F(Urdf, LinksJointsAndGeometryKinds) {
  auto r = loadRobot(test::threeLinkUrdf(), packageOptions({test::robotDir()}));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->name, "three_link");
  EXPECT_EQ(r->root, "base_link");
  ASSERT_EQ(r->links.size(), 4u);
  EXPECT_EQ(r->links[0].name, "base_link");
  EXPECT_EQ(r->links[1].name, "link1");
  EXPECT_EQ(r->links[2].name, "link2");
  EXPECT_EQ(r->links[3].name, "tool");
  for (const RobotLink& l : r->links) ASSERT_EQ(l.geometry.size(), 1u) << l.name;

  EXPECT_EQ(r->links[0].geometry[0].kind, Kind::kBox);
  EXPECT_EQ(r->links[0].geometry[0].box_size, Vec3(0.2, 0.3, 0.1));
  // link1 has a visual box too: the collision cylinder wins.
  EXPECT_EQ(r->links[1].geometry[0].kind, Kind::kCylinder);
  EXPECT_FALSE(r->links[1].from_visual);
  EXPECT_EQ(r->links[1].geometry[0].radius, 0.05);
  EXPECT_EQ(r->links[1].geometry[0].length, 0.4);
  EXPECT_EQ(r->links[2].geometry[0].kind, Kind::kMesh);
  EXPECT_EQ(r->links[2].geometry[0].scale, Vec3(0.5, 1.5, 2.0));
  EXPECT_EQ(r->links[3].geometry[0].kind, Kind::kSphere);
  EXPECT_TRUE(r->links[3].from_visual);
  EXPECT_EQ(r->links[3].geometry[0].radius, 0.03);

  ASSERT_EQ(r->joints.size(), 3u);
  EXPECT_EQ(r->joints[0].name, "joint1");
  EXPECT_EQ(r->joints[0].type, RobotJoint::Type::kRevolute);
  EXPECT_EQ(r->joints[0].parent, "base_link");
  EXPECT_EQ(r->joints[0].child, "link1");
  EXPECT_EQ(r->joints[0].axis, Vec3::UnitZ());
  EXPECT_EQ(r->joints[0].lower, -1.5);
  EXPECT_EQ(r->joints[0].upper, 1.5);
  EXPECT_EQ(r->joints[2].type, RobotJoint::Type::kFixed);
}

TEST_F(Urdf, GeometryOriginFromXyzAndRpy) {
  auto r = loadRobot(test::threeLinkUrdf(), packageOptions({test::robotDir()}));
  ASSERT_TRUE(r.ok()) << r.error().message;
  const Eigen::Isometry3d& o = r->links[2].geometry[0].origin;
  // URDF's rpy: fixed-axis roll about x, then pitch about y, then yaw about z.
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(0.5, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.4, Vec3::UnitY()) *
       Eigen::AngleAxisd(0.3, Vec3::UnitX()))
          .toRotationMatrix();
  EXPECT_LT((o.linear() - expected).norm(), 1e-12);
  EXPECT_LT((o.translation() - Vec3(0.1, -0.2, 0.3)).norm(), 1e-12);
}

TEST_F(Urdf, PackageFoundByFolderNameInPackagePaths) {
  // The first folder has no such package; the second has it.
  auto r = loadRobot(test::threeLinkUrdf(), packageOptions({dir_.string(), test::robotDir()}));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(samePath(r->links[2].geometry[0].mesh_path, test::threeLinkStl()))
      << r->links[2].geometry[0].mesh_path;
}

TEST_F(Urdf, PackageFoundThroughRosPackagePath) {
  RosPackagePath env(dir_.string() + ":" + test::robotDir());
  auto r = loadRobot(test::threeLinkUrdf());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(samePath(r->links[2].geometry[0].mesh_path, test::threeLinkStl()))
      << r->links[2].geometry[0].mesh_path;

  RobotLoadOptions no_env;
  no_env.use_ros_package_path = false;
  EXPECT_FALSE(loadRobot(test::threeLinkUrdf(), no_env).ok());
}

TEST_F(Urdf, PackageFoundByPackageXmlNameInADifferentFolder) {
  // workspace/src/renamed/package.xml names three_link_description: two levels down.
  const fs::path pkg = dir_ / "workspace" / "src" / "renamed";
  fs::create_directories(pkg / "meshes");
  fs::copy_file(test::dataPath("robot/three_link_description/package.xml"), pkg / "package.xml");
  fs::copy_file(test::threeLinkStl(), pkg / "meshes" / "link.stl");
  auto r = loadRobot(test::threeLinkUrdf(), packageOptions({(dir_ / "workspace").string()}));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(samePath(r->links[2].geometry[0].mesh_path, (pkg / "meshes" / "link.stl").string()))
      << r->links[2].geometry[0].mesh_path;
}

TEST_F(Urdf, PackageXmlDeeperThanThreeLevelsIsNotFound) {
  const fs::path pkg = dir_ / "a" / "b" / "c" / "d";
  fs::create_directories(pkg / "meshes");
  fs::copy_file(test::dataPath("robot/three_link_description/package.xml"), pkg / "package.xml");
  fs::copy_file(test::threeLinkStl(), pkg / "meshes" / "link.stl");
  EXPECT_TRUE(loadRobot(test::threeLinkUrdf(), packageOptions({(dir_ / "a" / "b").string()})).ok());
  EXPECT_FALSE(loadRobot(test::threeLinkUrdf(), packageOptions({dir_.string()})).ok());
}

TEST_F(Urdf, MissingMeshNamesTheLinkAndEveryPathTried) {
  const std::string urdf =
      meshRobot("missing.urdf", "package://three_link_description/meshes/none.stl");
  const std::string empty_dir = (dir_ / "empty").string();
  fs::create_directories(empty_dir);
  auto r = loadRobot(urdf, packageOptions({test::robotDir(), empty_dir}));
  test::expectError(r, ErrorCode::kUnreadable, urdf, "'part'");
  const std::string& m = r.error().message;
  EXPECT_NE(m.find(test::robotDir() + "/three_link_description/meshes/none.stl"), std::string::npos)
      << m;
  EXPECT_NE(m.find(empty_dir), std::string::npos) << m;
  EXPECT_NE(m.find("package://three_link_description/meshes/none.stl"), std::string::npos) << m;

  const std::string relative = meshRobot("relative.urdf", "meshes/none.stl");
  test::expectError(loadRobot(relative), ErrorCode::kUnreadable,
                    (dir_ / "meshes" / "none.stl").string(), "'part'");
}

TEST_F(Urdf, RelativeAbsoluteAndFileUriPaths) {
  fs::create_directories(dir_ / "meshes");
  const std::string stl = (dir_ / "meshes" / "part.stl").string();
  fs::copy_file(test::threeLinkStl(), stl);
  for (const std::string& filename :
       {std::string("meshes/part.stl"), std::string("./meshes/../meshes/part.stl"), stl,
        "file://" + stl}) {
    auto r = loadRobot(meshRobot("r.urdf", filename), packageOptions({}));
    ASSERT_TRUE(r.ok()) << filename << ": " << r.error().message;
    ASSERT_EQ(r->links.size(), 1u);
    EXPECT_TRUE(samePath(r->links[0].geometry[0].mesh_path, stl)) << filename;
    EXPECT_FALSE(r->links[0].from_visual);
  }
}

TEST_F(Urdf, LinkWithoutGeometryIsAllowed) {
  const std::string urdf = write("world.urdf",
                                 "<robot name=\"w\"><link name=\"world\"/><link name=\"b\">"
                                 "<collision><geometry><sphere radius=\"1\"/></geometry>"
                                 "</collision></link><joint name=\"j\" type=\"fixed\"><parent "
                                 "link=\"world\"/><child link=\"b\"/></joint></robot>");
  auto r = loadRobot(urdf);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->root, "world");
  ASSERT_EQ(r->links.size(), 2u);
  EXPECT_TRUE(r->links[0].geometry.empty());
  EXPECT_FALSE(r->links[0].from_visual);
  auto m = linkMesh(r->links[0]);
  ASSERT_TRUE(m.ok());
  EXPECT_TRUE(m->triangles.empty());
}

TEST_F(Urdf, BadFilesAreOneLineErrors) {
  const std::string missing = path("none.urdf");
  test::expectError(loadRobot(missing), ErrorCode::kUnreadable, missing, "cannot open");
  const std::string garbage = write("garbage.urdf", "this is not XML <robot");
  test::expectError(loadRobot(garbage), ErrorCode::kInvalidData, garbage, "not a valid URDF");
  const std::string no_links = write("no_links.urdf", "<robot name=\"x\"></robot>");
  test::expectError(loadRobot(no_links), ErrorCode::kInvalidData, no_links, "not a valid URDF");
  const std::string bad_joint =
      write("bad_joint.urdf",
            "<robot name=\"x\"><link name=\"a\"/><joint name=\"j\" type=\"revolute\"><parent "
            "link=\"a\"/><child link=\"missing\"/></joint></robot>");
  test::expectError(loadRobot(bad_joint), ErrorCode::kInvalidData, bad_joint, "not a valid URDF");
  // Found by fuzzing: TinyXML read past its buffer on a 0xff byte in a name. A URDF is UTF-8.
  const std::string latin1 =
      write("latin1.urdf", "<robot name=\"x\"><link name=\"caf\xe9\"/></robot>");
  test::expectError(loadRobot(latin1), ErrorCode::kInvalidData, latin1,
                    "not UTF-8 text (byte 0xe9 at offset 31)");
  const std::string utf8 =
      write("utf8.urdf", "<robot name=\"x\"><link name=\"caf\xc3\xa9\"/></robot>");
  EXPECT_TRUE(loadRobot(utf8).ok());
}

// urdfdom drops a <collision> it cannot parse, with a console message, and goes on: the link
// was fitted to its 1 m visual box instead of its 5 cm cylinder, or vanished with no visual.
// Each such message is now the load's error, naming the link.
TEST_F(Urdf, ElementsUrdfdomCannotParseAreErrorsNotDropped) {
  const std::string head =
      "<robot name=\"r\"><link name=\"a\"><visual><geometry><box size=\"1 1 1\"/></geometry>"
      "</visual><collision>";
  const std::string tail = "</collision></link></robot>";
  const std::string comma =
      write("comma.urdf", head +
                              "<origin xyz=\"0 0 0,2\"/><geometry><cylinder radius=\"0.025\" "
                              "length=\"0.05\"/></geometry>" +
                              tail);
  test::expectError(loadRobot(comma), ErrorCode::kInvalidData, comma,
                    "link 'a': Unable to parse component [0,2]");
  const std::string typo =
      write("typo.urdf",
            head + "<geometry><cylinder radius=\"0.025\" lenght=\"0.05\"/></geometry>" + tail);
  test::expectError(loadRobot(typo), ErrorCode::kInvalidData, typo,
                    "link 'a': Cylinder shape must have both length and radius");
  const std::string nan_origin =
      write("nan_origin.urdf",
            "<robot name=\"r\"><link name=\"b\"><collision><origin xyz=\"nan 0 0\"/><geometry>"
            "<box size=\"1 1 1\"/></geometry></collision></link></robot>");
  test::expectError(loadRobot(nan_origin), ErrorCode::kInvalidData, nan_origin, "link 'b'");
}

TEST_F(Urdf, MimicJointsAreRead) {
  const std::string urdf = write(
      "mimic.urdf",
      "<robot name=\"g\"><link name=\"palm\"/><link name=\"l\"/><link name=\"r\"/>"
      "<joint name=\"left\" type=\"prismatic\"><parent link=\"palm\"/><child link=\"l\"/>"
      "<axis xyz=\"0 1 0\"/><limit lower=\"0\" upper=\"0.04\" effort=\"1\" velocity=\"1\"/>"
      "</joint><joint name=\"right\" type=\"prismatic\"><parent link=\"palm\"/><child "
      "link=\"r\"/><axis xyz=\"0 1 0\"/><limit lower=\"-0.04\" upper=\"0\" effort=\"1\" "
      "velocity=\"1\"/><mimic joint=\"left\" multiplier=\"-1\" offset=\"0\"/></joint></robot>");
  auto r = loadRobot(urdf);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->joints.size(), 2u);
  ASSERT_TRUE(r->joints[1].mimic.has_value());
  EXPECT_EQ(r->joints[1].mimic->joint, "left");
  EXPECT_EQ(r->joints[1].mimic->multiplier, -1.0);
  auto poses = linkPoses(*r, {{"left", 0.02}});
  ASSERT_TRUE(poses.ok());
  EXPECT_NEAR(poses->at("r").translation().y(), -0.02, 1e-12);
}

// Mimic joints in a cycle used to be reported by every pose as a fault of --joint-positions,
// given or not: the file is refused when it is read, naming it and the joint.
TEST_F(Urdf, AMimicCycleIsTheFilesDefect) {
  const std::string urdf =
      write("cycle.urdf",
            "<robot name=\"g\"><link name=\"palm\"/><link name=\"l\"/><link name=\"r\"/>"
            "<joint name=\"left\" type=\"prismatic\"><parent link=\"palm\"/><child link=\"l\"/>"
            "<axis xyz=\"0 1 0\"/><limit lower=\"0\" upper=\"0.04\" effort=\"1\" velocity=\"1\"/>"
            "<mimic joint=\"right\"/></joint><joint name=\"right\" type=\"prismatic\"><parent "
            "link=\"palm\"/><child link=\"r\"/><axis xyz=\"0 1 0\"/><limit lower=\"-0.04\" "
            "upper=\"0\" effort=\"1\" velocity=\"1\"/><mimic joint=\"left\" multiplier=\"-1\"/>"
            "</joint></robot>");
  auto r = loadRobot(urdf);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(r.error().message.find("cycle.urdf: joint '"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("form a cycle"), std::string::npos) << r.error().message;
  EXPECT_EQ(r.error().message.find("joint-positions"), std::string::npos);
}

// Billion-laughs and external-entity files used to get "Could not find the 'robot' element".
TEST_F(Urdf, DocumentTypeDeclarationsAreRefusedByName) {
  const std::string laughs =
      write("laughs.urdf",
            "<?xml version=\"1.0\"?><!DOCTYPE robot [<!ENTITY a \"ha\"><!ENTITY b \"&a;&a;&a;\">]>"
            "<robot name=\"&b;\"><link name=\"x\"/></robot>");
  const std::string external =
      write("external.urdf",
            "<?xml version=\"1.0\"?><!DOCTYPE robot [<!ENTITY e SYSTEM \"file:///etc/passwd\">]>"
            "<robot name=\"r\"><link name=\"&e;\"/></robot>");
  for (const std::string& f : {laughs, external}) {
    auto r = loadRobot(f);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
    EXPECT_NE(r.error().message.find("a document type declaration"), std::string::npos)
        << r.error().message;
  }
}

// A 1e300 box used to reach the fit and "enclose no volume" (its volume overflowed).
TEST_F(Urdf, PrimitiveSizesBeyondTheCoordinateLimitAreRefused) {
  const std::string urdf = write("huge_box.urdf",
                                 "<robot name=\"r\"><link name=\"x\"><collision><geometry><box "
                                 "size=\"1e300 1 1\"/></geometry></collision></link></robot>");
  auto r = loadRobot(urdf);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(r.error().message.find("huge_box.urdf: link 'x': sizes, scale and origin"),
            std::string::npos)
      << r.error().message;
  EXPECT_NE(r.error().message.find("at most 1e+30"), std::string::npos) << r.error().message;
}

// URDF detection by extension was case-sensitive at three doors and not at others: one rule.
TEST(UrdfPath, AnyCaseOfTheExtensionIsARobot) {
  for (const char* yes : {"a.urdf", "dir/ARM.URDF", "x.Urdf"})
    EXPECT_TRUE(isRobotDescriptionPath(yes));
  for (const char* no : {"a.obj", "urdf", "a.urdf.obj", "a.urdfx"})
    EXPECT_FALSE(isRobotDescriptionPath(no)) << no;
}

// 50 000 nested elements used to overflow the stack inside TinyXML (a segfault); the depth is
// checked before parsing.
TEST_F(Urdf, DeeplyNestedElementsAreRefused) {
  std::string xml = "<robot name=\"deep\"><link name=\"a\"/>";
  for (int i = 0; i < 50000; ++i) xml += "<x a='>'>";
  for (int i = 0; i < 50000; ++i) xml += "</x>";
  xml += "</robot>\n";
  const std::string p = write("deep.urdf", xml);
  test::expectError(loadRobot(p), ErrorCode::kInvalidData, p, "nested more than 256 deep");
  // Comments (here 300 unclosed tags in one) and self-closing elements are not nesting.
  std::string flat = "<robot name=\"flat\"><!--";
  for (int i = 0; i < 300; ++i) flat += "<a>";
  flat += "--><link name=\"a\"/></robot>\n";
  auto r = loadRobot(write("flat.urdf", flat));
  EXPECT_TRUE(r.ok()) << r.error().message;
}

// Limits urdfdom accepts but no pose can use: "nan" and "inf", and a prismatic joint moving
// beyond the coordinate limit, are refused naming the joint; a revolute joint's huge limits are
// kept (its poses repeat every turn) and sampled over one turn.
TEST_F(Urdf, JointLimitsThatCannotBePosedAreRefused) {
  auto robotWith = [&](const std::string& name, const std::string& type, const std::string& lo,
                       const std::string& hi) {
    return write(name,
                 "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" "
                 "type=\"" +
                     type +
                     "\"><parent link=\"a\"/><child link=\"b\"/><axis "
                     "xyz=\"0 0 1\"/><limit lower=\"" +
                     lo + "\" upper=\"" + hi + "\" effort=\"1\" velocity=\"1\"/></joint></robot>");
  };
  auto refused = loadRobot(robotWith("nan.urdf", "revolute", "nan", "1"));
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, ErrorCode::kInvalidData);
  // urdfdom refuses "nan" itself; the reader's own check catches what it lets through.
  EXPECT_NE(refused.error().message.find("nan.urdf: "), std::string::npos)
      << refused.error().message;
  EXPECT_NE(refused.error().message.find("(nan)"), std::string::npos) << refused.error().message;
  refused = loadRobot(robotWith("far.urdf", "prismatic", "-1e308", "1e308"));
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("joint 'j': prismatic limits beyond 1e+30"),
            std::string::npos)
      << refused.error().message;
  auto huge = loadRobot(robotWith("huge.urdf", "revolute", "-1e308", "1e308"));
  ASSERT_TRUE(huge) << huge.error().message;
  ASSERT_EQ(huge->joints.size(), 1u);
  EXPECT_TRUE(isMovable(huge->joints[0]));
  const auto [lo, hi] = jointSampleRange(huge->joints[0]);
  EXPECT_DOUBLE_EQ(lo, -std::numbers::pi);
  EXPECT_DOUBLE_EQ(hi, std::numbers::pi);
  auto small = loadRobot(robotWith("small.urdf", "prismatic", "0.1", "-0.2"));
  ASSERT_TRUE(small);
  EXPECT_EQ(jointSampleRange(small->joints[0]), std::make_pair(-0.2, 0.1));
}

}  // namespace
}  // namespace sphereset

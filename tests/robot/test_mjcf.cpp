// MJCF robots read through MuJoCo (loadRobot of an .xml): the links, joints, geometry and
// excluded pairs as MuJoCo compiled them, checked against MuJoCo itself: link poses against
// mj_kinematics at random joint values, and each link's mesh against MuJoCo's posed geoms.
// Bad files: MuJoCo's message with its line, and what is refused before MuJoCo reads the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "robot/mujoco_oracle.hpp"
#include "robot/robot_data.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "test_support.hpp"

namespace sphereset::test {
namespace {

std::string armXml() { return dataPath("robot/mjcf/arm.xml"); }

Robot arm() {
  auto r = loadRobot(armXml());
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? *r : Robot{};
}

const RobotLink* findLink(const Robot& r, const std::string& name) {
  for (const RobotLink& l : r.links)
    if (l.name == name) return &l;
  return nullptr;
}

const RobotJoint* findJoint(const Robot& r, const std::string& name) {
  for (const RobotJoint& j : r.joints)
    if (j.name == name) return &j;
  return nullptr;
}

bool hasPair(const Robot& r, const std::string& a, const std::string& b) {
  for (const auto& p : r.excluded_pairs)
    if ((p[0] == a && p[1] == b) || (p[0] == b && p[1] == a)) return true;
  return false;
}

TEST(Mjcf, ReadsWhatMuJoCoCompiled) {
  ASSERT_TRUE(mujocoAvailable());
  const Robot r = arm();
  EXPECT_EQ(r.name, "mjcf_arm");
  EXPECT_EQ(r.root, "world");
  // Every body a link, and one geometry-less link for the body of two joints.
  for (const char* name : {"world", "base", "link1", "link2", "wrist/wx", "wrist", "palm",
                           "finger_left", "finger_right", "pendulum"})
    EXPECT_NE(findLink(r, name), nullptr) << name;
  EXPECT_TRUE(findLink(r, "wrist/wx")->geometry.empty());
  // Kinds: the table (the floor plane left out), capsule by fromto, meshes as compiled.
  using K = LinkGeometry::Kind;
  ASSERT_EQ(findLink(r, "world")->geometry.size(), 1u);
  EXPECT_EQ(findLink(r, "world")->geometry[0].kind, K::kBox);
  EXPECT_EQ(findLink(r, "world")->geometry[0].box_size, Vec3(0.6, 0.6, 0.04));
  ASSERT_EQ(findLink(r, "base")->geometry.size(), 1u);  // the visual sphere left out
  const LinkGeometry& capsule = findLink(r, "link1")->geometry.at(0);
  EXPECT_EQ(capsule.kind, K::kCapsule);
  EXPECT_DOUBLE_EQ(capsule.radius, 0.05);
  EXPECT_NEAR(capsule.length, 0.4, 1e-12);
  EXPECT_NEAR((capsule.origin.translation() - Vec3(0.0, 0.0, 0.2)).norm(), 0.0, 1e-12);
  EXPECT_EQ(findLink(r, "link2")->geometry.at(0).kind, K::kTriangles);
  EXPECT_EQ(findLink(r, "link2")->geometry.at(0).triangles->triangles.size(), 300u);
  EXPECT_EQ(findLink(r, "wrist")->geometry.at(0).kind, K::kEllipsoid);
  EXPECT_EQ(findLink(r, "wrist")->geometry.at(1).kind, K::kCylinder);
  // Joints: degrees read as radians, the anchor, the ref, slide fingers, the ball joint.
  const RobotJoint* j1 = findJoint(r, "j1");
  ASSERT_NE(j1, nullptr);
  EXPECT_EQ(j1->type, RobotJoint::Type::kRevolute);
  EXPECT_NEAR(j1->upper, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(j1->anchor, Vec3(0.01, 0.0, 0.0));
  EXPECT_NEAR(findJoint(r, "j2")->reference, 10.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_EQ(findJoint(r, "fl")->type, RobotJoint::Type::kPrismatic);
  EXPECT_EQ(findJoint(r, "swing")->type, RobotJoint::Type::kOther);
  EXPECT_EQ(findJoint(r, "wx")->child, "wrist/wx");
  EXPECT_EQ(findJoint(r, "wy")->parent, "wrist/wx");
  // MuJoCo's filter: welded bodies, the weld parent, contype/conaffinity that never match,
  // and the <exclude>.
  EXPECT_TRUE(hasPair(r, "wrist", "palm"));
  EXPECT_TRUE(hasPair(r, "link1", "link2"));
  EXPECT_TRUE(hasPair(r, "finger_left", "finger_right"));
  EXPECT_TRUE(hasPair(r, "link1", "wrist"));
  EXPECT_FALSE(hasPair(r, "base", "wrist"));
  // The self-collision pairs take them as adjacent.
  auto pairs = selfCollisionPairs(r, {});
  ASSERT_TRUE(pairs.ok());
  EXPECT_NE(std::find(pairs->adjacent.begin(), pairs->adjacent.end(),
                      std::array<std::string, 2>{"link1", "wrist"}),
            pairs->adjacent.end());
}

TEST(Mjcf, LinkPosesAreMuJoCosAtRandomJointValues) {
  const Robot r = arm();
  MjScene mj(armXml());
  ASSERT_TRUE(mj.model) << mj.error;
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const auto q = randomJointValues(r, rng);
    mj.pose(q);
    auto poses = linkPoses(r, q);
    ASSERT_TRUE(poses.ok()) << poses.error().message;
    for (int b = 1; b < mj.model->nbody; ++b) {
      const Eigen::Isometry3d& ours = poses->at(mj.bodyName(b));
      const mjtNum* x = mj.data->xpos + 3 * b;
      const mjtNum* w = mj.data->xquat + 4 * b;
      EXPECT_LT((ours.translation() - Vec3(x[0], x[1], x[2])).norm(), 1e-12) << mj.bodyName(b);
      const Eigen::Quaterniond theirs(w[0], w[1], w[2], w[3]);
      EXPECT_LT(Eigen::Quaterniond(ours.rotation()).angularDistance(theirs), 1e-9)
          << mj.bodyName(b);
    }
  }
}

TEST(Mjcf, LinkMeshesContainMuJoCosGeomsAsPosed) {
  // Each link's mesh (primitives drawn circumscribed) holds the points MuJoCo puts on its
  // collision geoms' surfaces: every point within the mesh's bounding box grown by rounding.
  const Robot r = arm();
  MjScene mj(armXml());
  ASSERT_TRUE(mj.model) << mj.error;
  std::mt19937_64 rng(5);
  const auto q = randomJointValues(r, rng);
  mj.pose(q);
  auto poses = linkPoses(r, q);
  ASSERT_TRUE(poses.ok());
  const mjModel& m = *mj.model;
  for (int g = 0; g < m.ngeom; ++g) {
    if (m.geom_contype[g] == 0 && m.geom_conaffinity[g] == 0) continue;
    if (m.geom_type[g] == mjGEOM_PLANE) continue;
    const std::string body = mj.bodyName(m.geom_bodyid[g]);
    auto mesh = linkMesh(*findLink(r, body));
    ASSERT_TRUE(mesh.ok());
    Aabb box;
    for (const Vec3& v : mesh->vertices) box.extend(poses->at(body) * v);
    for (const Vec3& p : geomSurface(m, g, 500, rng)) {
      const Vec3 w = mj.toWorld(g, p);
      EXPECT_TRUE((w.array() >= box.min.array() - 1e-9).all() &&
                  (w.array() <= box.max.array() + 1e-9).all())
          << body << " geom " << g << ": " << w.transpose();
    }
  }
}

TEST(Mjcf, CollisionGroupChoosesTheGeoms) {
  RobotLoadOptions o;
  o.mjcf_collision_group = 2;  // the visual class: base's sphere
  auto r = loadRobot(armXml(), o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(findLink(*r, "base")->geometry.size(), 1u);
  EXPECT_EQ(findLink(*r, "base")->geometry[0].kind, LinkGeometry::Kind::kSphere);
  EXPECT_TRUE(findLink(*r, "link1")->geometry.empty());
  o.mjcf_collision_group = 6;
  expectError(loadRobot(armXml(), o), ErrorCode::kInvalidArgument, "", "from 0 to 5");
}

// A model's text written to a fresh file beside nothing else.
std::string writeModel(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(Mjcf, BadFilesAreRefusedWithTheirReason) {
  const std::string body = "<mujoco><worldbody><body name='b'><joint type='hinge'/>";
  struct Case {
    const char* name;
    std::string text;
    ErrorCode code;
    const char* words;
  };
  const std::vector<Case> cases = {
      {"syntax.xml", "<mujoco><worldbody><geom type='box' size='1 1'></worldbody></mujoco>",
       ErrorCode::kInvalidData, "Line number=1"},
      {"unknown.xml", "<mujoco><worldbody><gem/></worldbody></mujoco>", ErrorCode::kInvalidData,
       "MuJoCo: "},
      {"no_geoms.xml", "<mujoco><worldbody><body name='b'/></worldbody></mujoco>",
       ErrorCode::kInvalidData, "no body has collision geoms"},
      {"planes.xml",
       "<mujoco><worldbody><body name='b'><geom type='plane' size='1 1 1'/></body></worldbody>"
       "</mujoco>",
       ErrorCode::kInvalidData, "body 'b': its collision geoms are planes or height fields"},
      {"include.xml", "<mujoco><include file='missing_part.xml'/></mujoco>",
       ErrorCode::kInvalidData, "missing_part.xml"},
      {"composite.xml",
       "<mujoco><worldbody><body><composite type='grid' count='1000 1000 1' spacing='0.1'>"
       "<geom size='0.01'/></composite></body></worldbody></mujoco>",
       ErrorCode::kInvalidData, "composites are not read"},
      {"hfield.xml",
       "<mujoco><asset><hfield name='h' nrow='100000' ncol='100000' size='1 1 1 1'/></asset>"
       "</mujoco>",
       ErrorCode::kInvalidData, "nrow=\"100000\""},
      {"device.xml", "<mujoco><asset><mesh name='m' file='/dev/zero'/></asset></mujoco>",
       ErrorCode::kInvalidData, "not a file"},
      {"folder.xml", "<mujoco><asset><mesh name='m' file='.'/></asset></mujoco>",
       ErrorCode::kInvalidData, "not a file"},
      {"doctype.xml", "<!DOCTYPE x [<!ENTITY a 'b'>]><mujoco/>", ErrorCode::kInvalidData,
       "document type declaration"},
      {"binary.xml", std::string("<mujoco>\xff</mujoco>"), ErrorCode::kInvalidData, "not UTF-8"},
      {"not_mjcf.xml", "<robotx/>", ErrorCode::kInvalidData, "MuJoCo: "},
      {"empty.xml", "", ErrorCode::kInvalidData, "MuJoCo: "},
      {"massless.xml", body + "<geom size='0.1' mass='0'/></body></worldbody></mujoco>",
       ErrorCode::kInvalidData, "mass"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = writeModel(c.name, c.text);
    expectError(loadRobot(path), c.code, path, c.words);
    std::filesystem::remove(path);
  }
  expectError(loadRobot(tempPath("absent.xml").string()), ErrorCode::kUnreadable, "absent.xml",
              "cannot open the MJCF file");
}

TEST(Mjcf, TenThousandBodiesAreRefusedWithoutACrash) {
  std::string text = "<mujoco><worldbody>";
  for (int i = 0; i <= limits::kMaxMjcfBodies; ++i) text += "<body><geom size='.1'/></body>";
  text += "</worldbody></mujoco>";
  const std::string path = writeModel("many.xml", text);
  auto r = loadRobot(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidData);
  EXPECT_NE(r.error().message.find(path), std::string::npos) << r.error().message;
  std::filesystem::remove(path);
}

TEST(Mjcf, DeepNestingIsRefusedBeforeMuJoCo) {
  std::string text = "<mujoco><worldbody>";
  for (int i = 0; i < 300; ++i) text += "<body>";
  for (int i = 0; i < 300; ++i) text += "</body>";
  text += "</worldbody></mujoco>";
  const std::string path = writeModel("deep.xml", text);
  expectError(loadRobot(path), ErrorCode::kInvalidData, path, "nested more than 256");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace sphereset::test

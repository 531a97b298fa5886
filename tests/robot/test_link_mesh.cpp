// Each link as one mesh in the link frame (box and cylinder volumes in closed form, a mesh
// placed by its origin and scale, sphere primitives) and forward kinematics of the joint chain
// (closed-form poses, joint limits).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "robot/robot_data.hpp"
#include "sphereset/load.hpp"
#include "sphereset/robot.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

constexpr double kLinkMeshTol = 1e-12;

const RobotLink& link(const Robot& r, const std::string& name) {
  for (const RobotLink& l : r.links) {
    if (l.name == name) return l;
  }
  ADD_FAILURE() << "no link " << name;
  return r.links.front();
}

TEST(LinkMesh, BoxIsAClosedSolidOfTheBoxVolume) {
  const Robot r = test::threeLinkRobot();
  auto m = linkMesh(link(r, "base_link"));
  ASSERT_TRUE(m.ok()) << m.error().message;
  const MeshDiagnosis d = diagnoseMesh(*m);
  EXPECT_TRUE(d.isSolid());
  EXPECT_NEAR(d.volume, 0.2 * 0.3 * 0.1, kLinkMeshTol);
  // Origin z = 0.05: the box stands on the link frame's xy plane.
  EXPECT_LT((d.bbox.min - Vec3(-0.1, -0.15, 0.0)).norm(), kLinkMeshTol);
  EXPECT_LT((d.bbox.max - Vec3(0.1, 0.15, 0.1)).norm(), kLinkMeshTol);
}

TEST(LinkMesh, CylinderIsAPrismOverTheCircumscribedPolygon) {
  const Robot r = test::threeLinkRobot();
  constexpr double kRadius = 0.05, kLength = 0.4;
  for (int segments : {3, 16, 48}) {
    auto m = linkMesh(link(r, "link1"), segments);
    ASSERT_TRUE(m.ok()) << m.error().message;
    const MeshDiagnosis d = diagnoseMesh(*m);
    EXPECT_TRUE(d.isSolid()) << segments;
    // The polygon holds the circle: its area is segments · r² · tan(π / segments) ≥ π r².
    const double polygon_area =
        segments * kRadius * kRadius * std::tan(std::numbers::pi / segments);
    EXPECT_NEAR(d.volume, polygon_area * kLength, kLinkMeshTol) << segments;
    EXPECT_GE(d.volume, std::numbers::pi * kRadius * kRadius * kLength);
    EXPECT_NEAR(d.bbox.min.z(), 0.0, kLinkMeshTol);
    EXPECT_NEAR(d.bbox.max.z(), kLength, kLinkMeshTol);
  }
  EXPECT_FALSE(linkMesh(link(r, "link1"), 2).ok());
}

TEST(LinkMesh, MeshIsScaledThenPlacedByItsOrigin) {
  const Robot r = test::threeLinkRobot();
  auto m = linkMesh(link(r, "link2"));
  ASSERT_TRUE(m.ok()) << m.error().message;
  auto file = loadMesh(test::threeLinkStl());
  ASSERT_TRUE(file.ok());
  // The origin built from the URDF's numbers (xyz, then fixed-axis roll, pitch, yaw).
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.5, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.4, Vec3::UnitY()) *
       Eigen::AngleAxisd(0.3, Vec3::UnitX()))
          .toRotationMatrix();
  Aabb expected;
  for (const Vec3& v : file->mesh.vertices) {
    expected.extend(rotation * v.cwiseProduct(Vec3(0.5, 1.5, 2.0)) + Vec3(0.1, -0.2, 0.3));
  }
  const Aabb got = boundingBox(*m);
  EXPECT_LT((got.min - expected.min).norm(), 1e-9);
  EXPECT_LT((got.max - expected.max).norm(), 1e-9);
  EXPECT_EQ(m->triangles.size(), file->mesh.triangles.size());
  // Volume scales by the scale's determinant; a rigid origin keeps it.
  EXPECT_NEAR(signedVolume(*m), 0.5 * 1.5 * 2.0 * signedVolume(file->mesh), 1e-9);
}

TEST(LinkMesh, MirroringScaleKeepsTrianglesOutward) {
  const Robot r = test::threeLinkRobot();
  RobotLink mirrored = link(r, "link2");
  mirrored.geometry[0].scale = Vec3(-1.0, 1.0, 1.0);
  auto m = linkMesh(mirrored);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_GT(signedVolume(*m), 0.0);
}

TEST(LinkMesh, SpherePrimitivesAsExactSpheresAndADrawing) {
  const Robot r = test::threeLinkRobot();
  const RobotLink& tool = link(r, "tool");
  const std::vector<Sphere> spheres = linkSpheres(tool);
  ASSERT_EQ(spheres.size(), 1u);
  EXPECT_LT((spheres[0].center - Vec3(0.0, 0.0, 0.05)).norm(), kLinkMeshTol);
  EXPECT_EQ(spheres[0].radius, 0.03);
  EXPECT_TRUE(linkSpheres(link(r, "base_link")).empty());

  auto m = linkMesh(tool, 24);
  ASSERT_TRUE(m.ok()) << m.error().message;
  const MeshDiagnosis d = diagnoseMesh(*m);
  EXPECT_TRUE(d.isSolid());
  const double ball = 4.0 / 3.0 * std::numbers::pi * std::pow(0.03, 3);
  // The drawing holds the ball (tests/robot/test_primitive_mesh.cpp proves it face by face), and
  // not by much.
  EXPECT_GT(d.volume, ball);
  EXPECT_LT(d.volume, 1.1 * ball);
  for (const Vec3& v : m->vertices) EXPECT_GE((v - spheres[0].center).norm(), 0.03);
}

TEST(LinkMesh, ElementsAreConcatenated) {
  const Robot r = test::threeLinkRobot();
  RobotLink both;
  both.name = "both";
  both.geometry = {link(r, "base_link").geometry[0], link(r, "link1").geometry[0]};
  auto m = linkMesh(both, 16);
  ASSERT_TRUE(m.ok());
  auto box = linkMesh(link(r, "base_link"));
  auto cylinder = linkMesh(link(r, "link1"), 16);
  ASSERT_TRUE(box.ok() && cylinder.ok());
  EXPECT_EQ(m->triangles.size(), box->triangles.size() + cylinder->triangles.size());
  EXPECT_NEAR(signedVolume(*m), signedVolume(*box) + signedVolume(*cylinder), kLinkMeshTol);
  EXPECT_EQ(diagnoseMesh(*m).components, 2);
}

TEST(LinkMesh, MissingMeshFileNamesTheLink) {
  RobotLink l;
  l.name = "gone";
  LinkGeometry g;
  g.kind = LinkGeometry::Kind::kMesh;
  g.mesh_path = test::tempPath("no_such_mesh.stl").string();
  l.geometry = {g};
  test::expectError(linkMesh(l), ErrorCode::kUnreadable, g.mesh_path, "'gone'");
}

TEST(LinkPoses, ChainAtZero) {
  const Robot r = test::threeLinkRobot();
  const auto poses = *linkPoses(r);
  ASSERT_EQ(poses.size(), 4u);
  EXPECT_TRUE(poses.at("base_link").isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_LT((poses.at("link1").translation() - Vec3(0, 0, 0.1)).norm(), kLinkMeshTol);
  EXPECT_LT((poses.at("link2").translation() - Vec3(0, 0, 0.5)).norm(), kLinkMeshTol);
  EXPECT_LT((poses.at("tool").translation() - Vec3(0.5, 0, 0.5)).norm(), kLinkMeshTol);
  EXPECT_LT((poses.at("tool").linear() - Eigen::Matrix3d::Identity()).norm(), kLinkMeshTol);
}

// Rotations about z and y written out.
Eigen::Matrix3d rotZ(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}
Eigen::Matrix3d rotY(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return m;
}

TEST(LinkPoses, ChainAtJointValues) {
  const Robot r = test::threeLinkRobot();
  const double q1 = 0.7, q2 = 0.4;
  const auto poses = *linkPoses(r, {{"joint1", q1}, {"joint2", q2}});
  EXPECT_LT((poses.at("link1").linear() - rotZ(q1)).norm(), kLinkMeshTol);
  EXPECT_LT((poses.at("link2").linear() - rotZ(q1) * rotY(q2)).norm(), kLinkMeshTol);
  EXPECT_LT((poses.at("link2").translation() - Vec3(0, 0, 0.5)).norm(), kLinkMeshTol);
  // The tool, 0.5 along link2's x: swung by both joints.
  const Vec3 tool = Vec3(0, 0, 0.5) + 0.5 * Vec3(std::cos(q2) * std::cos(q1),
                                                 std::cos(q2) * std::sin(q1), -std::sin(q2));
  EXPECT_LT((poses.at("tool").translation() - tool).norm(), kLinkMeshTol);
}

TEST(LinkPoses, RevoluteValuesAreClampedToTheLimits) {
  const Robot r = test::threeLinkRobot();
  const auto clamped = *linkPoses(r, {{"joint1", 5.0}, {"joint2", -9.0}});
  const auto at_limits = *linkPoses(r, {{"joint1", 1.5}, {"joint2", -2.0}});
  for (const char* name : {"link1", "link2", "tool"}) {
    EXPECT_TRUE(clamped.at(name).isApprox(at_limits.at(name), kLinkMeshTol)) << name;
  }
  // The clamps are said, one note each (they used to be silent).
  const auto state = jointState(r, {{"joint1", 5.0}, {"joint2", -9.0}});
  ASSERT_TRUE(state.ok());
  ASSERT_EQ(state->notes.size(), 2u);
  EXPECT_EQ(state->notes[0], "joint 'joint1': 5 is beyond its upper limit 1.5, clamped");
  EXPECT_EQ(state->values.at("joint2"), -2.0);
  EXPECT_TRUE(jointState(r, {{"joint1", 1.0}})->notes.empty());
  // Unknown joints and values that are not numbers are refused (NaN used to give NaN poses).
  test::expectError(linkPoses(r, {{"nope", 1.0}}), ErrorCode::kInvalidArgument, "'nope'",
                    "no joint");
  test::expectError(linkPoses(r, {{"joint1", std::nan("")}}), ErrorCode::kInvalidArgument,
                    "'joint1'", "not a finite number");
}

TEST(LinkPoses, PrismaticSlidesAlongItsAxisWithinItsLimits) {
  Robot r;
  r.root = "rail";
  RobotJoint slide;
  slide.name = "slide";
  slide.parent = "rail";
  slide.child = "carriage";
  slide.type = RobotJoint::Type::kPrismatic;
  slide.origin.translation() = Vec3(1.0, 0.0, 0.0);
  slide.axis = Vec3::UnitY();
  slide.lower = -0.5;
  slide.upper = 0.25;
  r.joints = {slide};
  EXPECT_LT((linkPoses(r, {{"slide", 0.2}})->at("carriage").translation() - Vec3(1, 0.2, 0)).norm(),
            kLinkMeshTol);
  EXPECT_LT(
      (linkPoses(r, {{"slide", 3.0}})->at("carriage").translation() - Vec3(1, 0.25, 0)).norm(),
      kLinkMeshTol);
  EXPECT_LT(
      (linkPoses(r, {{"slide", -3.0}})->at("carriage").translation() - Vec3(1, -0.5, 0)).norm(),
      kLinkMeshTol);
}

// A parallel gripper: the right finger mimics the left one (multiplier -1), as grippers are
// written. Mimic joints used to stay at 0, so poses and self-collision pairs were wrong.
TEST(LinkPoses, MimicJointsFollowTheirLeader) {
  Robot r;
  r.name = "gripper";
  r.root = "palm";
  RobotJoint left;
  left.name = "left";
  left.parent = "palm";
  left.child = "left_finger";
  left.type = RobotJoint::Type::kPrismatic;
  left.axis = Vec3::UnitY();
  left.lower = 0.0;
  left.upper = 0.04;
  RobotJoint right = left;
  right.name = "right";
  right.child = "right_finger";
  right.lower = -0.04;
  right.upper = 0.0;
  right.mimic = RobotJoint::Mimic{"left", -1.0, 0.0};
  r.joints = {left, right};
  const auto poses = linkPoses(r, {{"left", 0.03}});
  ASSERT_TRUE(poses.ok()) << poses.error().message;
  EXPECT_LT((poses->at("left_finger").translation() - Vec3(0, 0.03, 0)).norm(), kLinkMeshTol);
  EXPECT_LT((poses->at("right_finger").translation() - Vec3(0, -0.03, 0)).norm(), kLinkMeshTol);
  // The follower's own value: accepted when it agrees, refused when it does not.
  EXPECT_TRUE(linkPoses(r, {{"left", 0.03}, {"right", -0.03}}).ok());
  test::expectError(linkPoses(r, {{"left", 0.03}, {"right", 0.01}}), ErrorCode::kInvalidArgument,
                    "'right' mimics 'left'", "give 'left' instead");
  // A mimic of nothing, and mimics in a cycle, are bad data.
  Robot bad = r;
  bad.joints[1].mimic->joint = "nothing";
  test::expectError(jointState(bad), ErrorCode::kInvalidData, "'right'", "not a joint");
  bad = r;
  bad.joints[0].mimic = RobotJoint::Mimic{"right", -1.0, 0.0};
  test::expectError(jointState(bad), ErrorCode::kInvalidData, "joint '", "cycle");
}

}  // namespace
}  // namespace sphereset

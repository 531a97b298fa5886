// An independent check of the robot fit's coverage with FCL, the collision library planners use
// (MoveIt's default checker): at random configurations of the test robot, every small probe
// sphere or box that FCL finds touching a link's mesh also touches that link's fitted spheres. FCL
// models the mesh as its triangles, so the probes that touch it are the ones near the surface,
// which the certificate says the spheres cover. And the self-collision pairs of the SRDF: the
// pairs disabled as "Never" do not collide in FCL, on the link meshes, at fresh random
// configurations, and the "Adjacent" ones are joined by a joint.
#include <fcl/fcl.h>
#include <gtest/gtest.h>
#include <tinyxml.h>

#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/robot_fit.hpp"
#ifdef SPHERESET_TEST_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset {
namespace {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fclMesh(const Mesh& m) {
  std::vector<fcl::Vector3d> points(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  for (const Triangle& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

bool touch(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&a, &b, request, result);
  return result.isCollision();
}

// A configuration within the limits (continuous joints over a turn each way).
std::map<std::string, double> randomConfiguration(const Robot& robot, std::mt19937& rng) {
  std::map<std::string, double> q;
  for (const RobotJoint& j : robot.joints) {
    if (j.type == RobotJoint::Type::kContinuous)
      q[j.name] = std::uniform_real_distribution<double>(-3.14159, 3.14159)(rng);
    else if (j.type == RobotJoint::Type::kRevolute || j.type == RobotJoint::Type::kPrismatic)
      q[j.name] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
  }
  return q;
}

// The test robot fitted quickly, six spheres per link (each link's envelope where the wrap is
// built in).
Expected<RobotFitResult> fitForFcl(const Robot& robot) {
  RobotFitOptions fo;
  fo.quality = FitQuality::kFast;
  fo.default_link_spheres = 6;
  fo.name = "three_link";
#ifdef SPHERESET_TEST_REPAIR
  fo.repair.operations = cgalSolidOperations();
#endif
  return fitRobot(robot, fo);
}

TEST(FclCheck, EveryProbeTouchingALinkMeshTouchesItsSpheres) {
  const Robot robot = test::threeLinkRobot();
  ASSERT_FALSE(robot.links.empty());
  auto fit = fitForFcl(robot);
  ASSERT_TRUE(fit.ok()) << fit.error().message;
  std::mt19937 rng(7);
  int64_t hits = 0, misses = 0, links_checked = 0;
  for (int config = 0; config < 4; ++config) {
    auto poses = linkPoses(robot, randomConfiguration(robot, rng));
    ASSERT_TRUE(poses.ok()) << poses.error().message;
    for (const RobotLinkFit& lf : fit->links) {
      if (!lf.fitted) continue;
      const RobotLink* link = nullptr;
      for (const RobotLink& l : robot.links)
        if (l.name == lf.link) link = &l;
      ASSERT_NE(link, nullptr);
      auto mesh = linkMesh(*link);
      ASSERT_TRUE(mesh.ok()) << mesh.error().message;
      const Eigen::Isometry3d& pose = poses->at(lf.link);
      const fcl::Transform3d to_world(pose.matrix());
      const fcl::CollisionObjectd surface(fclMesh(*mesh), to_world);
      std::vector<fcl::CollisionObjectd> spheres;
      for (const Sphere& s : lf.spheres)
        spheres.emplace_back(std::make_shared<fcl::Sphered>(s.radius),
                             fcl::Transform3d(Eigen::Translation3d(pose * s.center)));
      // Probes of 1/500 of the link's size at random in its box (world frame), a tenth larger.
      Aabb box;
      for (const Vec3& v : mesh->vertices) box.extend(pose * v);
      const double r = 0.002 * box.diagonal();
      const Vec3 lo = box.min - 0.1 * (box.max - box.min), hi = box.max + 0.1 * (box.max - box.min);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int i = 0; i < 3000; ++i) {
        const Vec3 c = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
        // Every other probe a small box of the same size, turned at random.
        fcl::Transform3d at = fcl::Transform3d::Identity();
        at.translation() = c;
        std::shared_ptr<fcl::CollisionGeometryd> shape = std::make_shared<fcl::Sphered>(r);
        if (i % 2 == 1) {
          const Eigen::Quaterniond q(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
          at.linear() = q.normalized().toRotationMatrix();
          shape = std::make_shared<fcl::Boxd>(2 * r, 2 * r, 2 * r);
        }
        const fcl::CollisionObjectd probe(shape, at);
        if (!touch(probe, surface)) continue;
        ++hits;
        bool covered = false;
        for (const fcl::CollisionObjectd& s : spheres) covered = covered || touch(probe, s);
        if (!covered) ++misses;
        EXPECT_TRUE(covered) << lf.link << ": probe at " << c.transpose() << " (radius " << r
                             << ") touches the mesh, not the spheres";
        if (misses > 5) return;
      }
      ++links_checked;
    }
  }
  EXPECT_GE(links_checked, 8);  // two links with meshes or primitives, four configurations
  EXPECT_GT(hits, 500);         // the probes did meet the surfaces
  EXPECT_EQ(misses, 0);
}

// The pairs of an SRDF with the given reason, as written.
test::LinkPairs srdfPairsWith(const std::string& srdf, const std::string& reason) {
  TiXmlDocument doc;
  doc.Parse(srdf.c_str());
  EXPECT_FALSE(doc.Error()) << doc.ErrorDesc();
  test::LinkPairs out;
  if (doc.RootElement() == nullptr) return out;
  for (const TiXmlElement* d = doc.RootElement()->FirstChildElement("disable_collisions");
       d != nullptr; d = d->NextSiblingElement("disable_collisions"))
    if (reason == d->Attribute("reason"))
      out.push_back({d->Attribute("link1"), d->Attribute("link2")});
  return out;
}

TEST(FclCheck, SrdfNeverPairsDoNotCollideAndAdjacentPairsAreJoined) {
  const Robot robot = test::threeLinkRobot();
  ASSERT_FALSE(robot.links.empty());
  auto fit = fitForFcl(robot);
  ASSERT_TRUE(fit.ok()) << fit.error().message;
  std::vector<LinkSpheres> spheres;
  for (const RobotLinkFit& lf : fit->links) spheres.push_back({lf.link, lf.spheres});
  const std::vector<CollisionSolid> solids = fitCollisionSolids(robot, *fit);
  std::map<std::string, std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>>> meshes;
  for (const RobotLink& l : robot.links) {
    auto mesh = linkMesh(l);
    ASSERT_TRUE(mesh.ok()) << mesh.error().message;
    if (!mesh->triangles.empty()) meshes[l.name] = fclMesh(*mesh);
  }

  // On the spheres, then on the link solids.
  for (const CollisionCheck check : {CollisionCheck::kSpheres, CollisionCheck::kMeshes}) {
    CollisionSamplingOptions co;
    co.samples = 2000;
    co.seed = 1;
    co.check = check;
    auto matrix = sampleSelfCollisions(robot, spheres, co, solids);
    ASSERT_TRUE(matrix.ok()) << matrix.error().message;
    const std::string srdf = formatSrdf(robot, *matrix);
    const auto never = srdfPairsWith(srdf, "Never");
    const auto adjacent = srdfPairsWith(srdf, "Adjacent");
    ASSERT_FALSE(never.empty()) << srdf;
    ASSERT_EQ(adjacent.size(), 3u) << srdf;
    for (const auto& [a, b] : adjacent) {
      bool joined = false;
      for (const RobotJoint& j : robot.joints)
        joined = joined || (j.parent == a && j.child == b) || (j.parent == b && j.child == a);
      EXPECT_TRUE(joined) << a << " and " << b << " are not joined by a joint";
    }
    // Fresh configurations: another generator and seed than the sampling's.
    std::mt19937 rng(20261202);
    int64_t tested = 0;
    for (int config = 0; config < 3000; ++config) {
      auto poses = linkPoses(robot, randomConfiguration(robot, rng));
      ASSERT_TRUE(poses.ok()) << poses.error().message;
      for (const auto& [a, b] : never) {
        ASSERT_TRUE(meshes.count(a) && meshes.count(b)) << a << ", " << b;
        const fcl::CollisionObjectd oa(meshes[a], fcl::Transform3d(poses->at(a).matrix()));
        const fcl::CollisionObjectd ob(meshes[b], fcl::Transform3d(poses->at(b).matrix()));
        ++tested;
        ASSERT_FALSE(touch(oa, ob)) << a << " and " << b << " (\"Never\") collide in FCL";
      }
    }
    EXPECT_EQ(tested, 3000 * static_cast<int64_t>(never.size()));
  }
}

}  // namespace
}  // namespace sphereset

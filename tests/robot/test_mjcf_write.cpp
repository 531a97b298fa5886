// MJCF out (writeSphereMjcf), judged by MuJoCo: the written model loads from another folder;
// at random joint values posed by MuJoCo, every surface point of every original collision geom
// lies in a sphere geom of its body, the sphere geoms are where sphereset poses its spheres, and
// every contact MuJoCo finds between the original geoms of two bodies is a contact between their
// spheres too. The replaced geoms' attributes, the visual geoms, the dynamics and the excluded
// pairs are kept. From a URDF, through MuJoCo's own URDF reader, the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <string>

#include "robot/mujoco_oracle.hpp"
#include "robot/robot_data.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"
#include "sphereset/robot_fit.hpp"
#include "test_support.hpp"

#ifdef SPHERESET_TEST_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset::test {
namespace {

namespace fs = std::filesystem;

// Rounding allowance of a point in a sphere and of positions (length units, a 1 m robot).
constexpr double kCoverTol = 1e-9;
constexpr double kPoseTol = 1e-12;

struct Written {
  Robot robot;
  std::string in, out;
  std::vector<LinkSpheres> spheres;
  std::vector<std::array<std::string, 2>> exclude;
};

// Fits the robot (fast, a budget), samples its self-collision pairs and writes the sphere model
// into a folder of its own (so that its asset paths must resolve from there).
Written fitAndWrite(const std::string& in, const RobotLoadOptions& lo, int spheres_per_link,
                    const std::string& out_name) {
  Written w;
  w.in = in;
  auto robot = loadRobot(in, lo);
  EXPECT_TRUE(robot.ok()) << robot.error().message;
  if (!robot) return w;
  w.robot = *robot;
  RobotFitOptions o;
  o.quality = FitQuality::kFast;
  o.default_link_spheres = spheres_per_link;
  o.link_solid = LinkSolid::kWalls;
#ifdef SPHERESET_TEST_REPAIR
  o.repair.operations = cgalSolidOperations();  // the union of a body's overlapping geoms
#endif
  auto fit = fitRobot(w.robot, o);
  EXPECT_TRUE(fit.ok()) << fit.error().message;
  if (!fit) return w;
  for (const RobotLinkFit& l : fit->links)
    if (!l.skipped) w.spheres.push_back({l.link, l.spheres});
  CollisionSamplingOptions co;
  co.samples = 3000;
  auto matrix = sampleSelfCollisions(w.robot, w.spheres, co);
  EXPECT_TRUE(matrix.ok());
  w.exclude = neverPairs(*matrix);
  const fs::path dir = tempPath(out_name + "_dir");
  fs::create_directories(dir);
  w.out = (dir / (out_name + ".xml")).string();
  const Status st = writeSphereMjcf(in, w.out, w.spheres, w.exclude, lo);
  EXPECT_TRUE(st.ok()) << st.error().message;
  return w;
}

const Written& armWritten() {
  static const Written w = fitAndWrite(dataPath("robot/mjcf/arm.xml"), {}, 6, "arm_spheres");
  return w;
}

// The written sphere geoms of body `name` in the world: (centre, radius).
std::vector<Sphere> sphereGeoms(const MjScene& s, const std::string& name) {
  std::vector<Sphere> out;
  const mjModel& m = *s.model;
  for (int g = 0; g < m.ngeom; ++g) {
    const char* n = mj_id2name(&m, mjOBJ_GEOM, g);
    if (n == nullptr || std::string(n).rfind(name + "_sphere_", 0) != 0) continue;
    if (s.bodyName(m.geom_bodyid[g]) != name || m.geom_type[g] != mjGEOM_SPHERE) continue;
    const mjtNum* p = s.data->geom_xpos + 3 * g;
    out.push_back({Vec3(p[0], p[1], p[2]), m.geom_size[3 * g]});
  }
  return out;
}

bool inSome(const Vec3& p, const std::vector<Sphere>& spheres) {
  for (const Sphere& s : spheres)
    if ((p - s.center).norm() <= s.radius + kCoverTol) return true;
  return false;
}

bool isCollision(const mjModel& m, int g) {
  return m.geom_contype[g] != 0 || m.geom_conaffinity[g] != 0;
}

TEST(MjcfWrite, EveryCollisionGeomIsInItsBodysSpheresAtRandomPoses) {
  const Written& w = armWritten();
  MjScene original(w.in), spheres(w.out);
  ASSERT_TRUE(original.model) << original.error;
  ASSERT_TRUE(spheres.model) << spheres.error;
  std::mt19937_64 rng(11);
  const mjModel& m = *original.model;
  int64_t points = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const auto q = randomJointValues(w.robot, rng);
    original.pose(q);
    spheres.pose(q);
    for (int g = 0; g < m.ngeom; ++g) {
      if (!isCollision(m, g) || m.geom_type[g] == mjGEOM_PLANE) continue;
      const std::string body = original.bodyName(m.geom_bodyid[g]);
      const std::vector<Sphere> set = sphereGeoms(spheres, body);
      ASSERT_FALSE(set.empty()) << body;
      for (const Vec3& p : geomSurface(m, g, 300, rng)) {
        ++points;
        ASSERT_TRUE(inSome(original.toWorld(g, p), set)) << body << " geom " << g;
      }
    }
  }
  EXPECT_GT(points, 10000);
}

TEST(MjcfWrite, SphereGeomsAreWhereSpheresetPosesTheSpheres) {
  const Written& w = armWritten();
  MjScene spheres(w.out);
  ASSERT_TRUE(spheres.model) << spheres.error;
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 10; ++trial) {
    const auto q = randomJointValues(w.robot, rng);
    spheres.pose(q);
    auto poses = linkPoses(w.robot, q);
    ASSERT_TRUE(poses.ok());
    for (const LinkSpheres& ls : w.spheres) {
      const std::vector<Sphere> placed = sphereGeoms(spheres, ls.link);
      ASSERT_EQ(placed.size(), ls.spheres.size()) << ls.link;
      for (size_t i = 0; i < placed.size(); ++i) {
        EXPECT_LT((placed[i].center - poses->at(ls.link) * ls.spheres[i].center).norm(), kPoseTol);
        EXPECT_EQ(placed[i].radius, ls.spheres[i].radius);  // written in full, read back exactly
      }
    }
  }
  // And read back by sphereset itself: the same spheres.
  auto back = loadRobot(w.out);
  ASSERT_TRUE(back.ok()) << back.error().message;
  for (const LinkSpheres& ls : w.spheres)
    for (const RobotLink& l : back->links)
      if (l.name == ls.link) {
        const std::vector<Sphere> read = linkSpheres(l);
        ASSERT_EQ(read.size(), ls.spheres.size());
        for (size_t i = 0; i < read.size(); ++i) {
          EXPECT_LT((read[i].center - ls.spheres[i].center).norm(), kPoseTol);
          EXPECT_EQ(read[i].radius, ls.spheres[i].radius);
        }
      }
}

TEST(MjcfWrite, EveryContactOfTheGeomsIsAContactOfTheSpheres) {
  const Written& w = armWritten();
  MjScene original(w.in), spheres(w.out);
  ASSERT_TRUE(original.model && spheres.model);
  // MuJoCo collides a mesh as its convex hull: only convex meshes' contacts are the mesh's own.
  std::set<int> hulls;
  for (int g = 0; g < original.model->ngeom; ++g)
    if (original.model->geom_type[g] == mjGEOM_MESH && !convexMesh(*original.model, g))
      hulls.insert(g);
  EXPECT_EQ(hulls.size(), 1u);  // link2's mesh (the wedge is convex)
  std::mt19937_64 rng(17);
  int contacts = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto q = randomJointValues(w.robot, rng);
    original.pose(q, true);
    spheres.pose(q, true);
    const auto theirs = spheres.contactPairs();
    for (const auto& pair : original.contactPairs(hulls)) {
      ++contacts;
      EXPECT_EQ(theirs.count(pair), 1u) << pair.first << " - " << pair.second << " trial " << trial;
    }
  }
  EXPECT_GT(contacts, 20);  // the check was not vacuous
}

TEST(MjcfWrite, KeepsAttributesVisualsDynamicsAndTheExcludedPairs) {
  const Written& w = armWritten();
  MjScene original(w.in), spheres(w.out);
  ASSERT_TRUE(original.model && spheres.model);
  const mjModel& a = *original.model;
  const mjModel& b = *spheres.model;
  ASSERT_EQ(a.nbody, b.nbody);
  for (int body = 0; body < a.nbody; ++body) {
    SCOPED_TRACE(original.bodyName(body));
    EXPECT_NEAR(a.body_mass[body], b.body_mass[body], 1e-12 * (1.0 + a.body_mass[body]));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(a.body_inertia[3 * body + k], b.body_inertia[3 * body + k], 1e-12);
    // The first collision geom (a plane aside) and the visual and flat geoms of each body.
    int first = -1;
    std::multiset<int> kept_a, kept_b;
    for (int g = a.body_geomadr[body]; g >= 0 && g < a.body_geomadr[body] + a.body_geomnum[body];
         ++g) {
      const bool flat = a.geom_type[g] == mjGEOM_PLANE;
      if (isCollision(a, g) && !flat && first < 0) first = g;
      if (!isCollision(a, g) || flat) kept_a.insert(a.geom_type[g]);
    }
    for (int g = b.body_geomadr[body]; g >= 0 && g < b.body_geomadr[body] + b.body_geomnum[body];
         ++g) {
      const char* n = mj_id2name(&b, mjOBJ_GEOM, g);
      if (n != nullptr && std::string(n).find("_sphere_") != std::string::npos) {
        ASSERT_GE(first, 0);
        EXPECT_EQ(b.geom_contype[g], a.geom_contype[first]);
        EXPECT_EQ(b.geom_conaffinity[g], a.geom_conaffinity[first]);
        EXPECT_EQ(b.geom_condim[g], a.geom_condim[first]);
        EXPECT_EQ(b.geom_group[g], a.geom_group[first]);
        for (int k = 0; k < 3; ++k)
          EXPECT_EQ(b.geom_friction[3 * g + k], a.geom_friction[3 * first + k]);
      } else {
        kept_b.insert(b.geom_type[g]);
      }
    }
    EXPECT_EQ(kept_a, kept_b);  // the visual sphere of base, the floor of the world
  }
  EXPECT_EQ(a.nu, b.nu);  // the actuator
  // Every pair given to exclude is kept apart by MuJoCo in the sphere model.
  for (const auto& [x, y] : w.exclude) {
    const int p = mj_name2id(&b, mjOBJ_BODY, x.c_str()), q = mj_name2id(&b, mjOBJ_BODY, y.c_str());
    if (p < 0 || q < 0) continue;
    bool excluded = false;
    for (int e = 0; e < b.nexclude; ++e)
      excluded = excluded ||
                 b.exclude_signature[e] == ((std::min(p, q) + 1) << 16) + std::max(p, q) + 1 ||
                 b.exclude_signature[e] == ((std::max(p, q) + 1) << 16) + std::min(p, q) + 1;
    const int wp = b.body_weldid[p], wq = b.body_weldid[q];
    const bool welded =
        wp == wq ||
        (wp != 0 && wq != 0 &&
         (wp == b.body_weldid[b.body_parentid[wq]] || wq == b.body_weldid[b.body_parentid[wp]]));
    EXPECT_TRUE(excluded || welded) << x << " - " << y;
  }
  // The assets resolve from the output's folder, which is not the input's.
  EXPECT_NE(fs::path(w.out).parent_path(), fs::path(w.in).parent_path());
}

TEST(MjcfWrite, FromAUrdfThroughMuJoCosUrdfReader) {
  RobotLoadOptions lo;
  lo.package_paths = {robotDir()};
  lo.use_ros_package_path = false;
  const Written w = fitAndWrite(threeLinkUrdf(), lo, 4, "three_link_spheres");
  MjScene spheres(w.out);
  ASSERT_TRUE(spheres.model) << spheres.error;
  std::mt19937_64 rng(19);
  for (int trial = 0; trial < 10; ++trial) {
    const auto q = randomJointValues(w.robot, rng);
    spheres.pose(q);
    auto poses = linkPoses(w.robot, q);
    ASSERT_TRUE(poses.ok());
    for (const LinkSpheres& ls : w.spheres) {
      const std::vector<Sphere> placed = sphereGeoms(spheres, ls.link);
      ASSERT_EQ(placed.size(), ls.spheres.size()) << ls.link;
      for (size_t i = 0; i < placed.size(); ++i)
        EXPECT_LT((placed[i].center - poses->at(ls.link) * ls.spheres[i].center).norm(), kPoseTol);
      // The link's geometry, posed by sphereset, inside the spheres as MuJoCo posed them
      // (sphere primitives are spheres of the set themselves; their drawing is larger).
      RobotLink link;
      for (const RobotLink& l : w.robot.links)
        if (l.name == ls.link) link = l;
      std::erase_if(link.geometry,
                    [](const LinkGeometry& g) { return g.kind == LinkGeometry::Kind::kSphere; });
      auto mesh = linkMesh(link);
      ASSERT_TRUE(mesh.ok());
      for (const Vec3& v : mesh->vertices)
        EXPECT_TRUE(inSome(poses->at(ls.link) * v, placed)) << ls.link;
    }
  }
}

TEST(MjcfWrite, BadRequestsWriteNothing) {
  const std::string in = dataPath("robot/mjcf/arm.xml");
  const std::string out = tempPath("never_written.xml").string();
  expectError(formatSphereMjcf(in, out, {{"no_such_body", {Sphere{Vec3::Zero(), 0.1}}}}, {}),
              ErrorCode::kInvalidArgument, in, "no body named 'no_such_body'");
  expectError(formatSphereMjcf(in, out, {{"base", {Sphere{Vec3(NAN, 0, 0), 0.1}}}}, {}),
              ErrorCode::kInvalidData, in, "NaN");
  const Status same = writeSphereMjcf(in, in, {{"base", {Sphere{Vec3::Zero(), 0.1}}}}, {});
  EXPECT_FALSE(same.ok());
  EXPECT_EQ(same.error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace sphereset::test

// The posed-robot queries on the three-link test robot: per-link contacts against brute force
// (every link sphere against every obstacle) on random configurations, for points and for
// obstacle spheres; a trajectory whose k-th waypoint is the first to collide, on any thread
// count; and the inputs refused.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "robot/robot_data.hpp"
#include "sphereset/robot_query.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Random spheres in each link's frame (tool has none: its distance is infinite).
std::vector<LinkSpheres> randomLinkSpheres(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.2, 0.2), r(0.01, 0.08);
  std::vector<LinkSpheres> out = {{"base_link", {}}, {"link1", {}}, {"link2", {}}, {"tool", {}}};
  const int counts[] = {3, 5, 7, 0};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < counts[k]; ++i)
      out[k].spheres.push_back({Vec3(u(rng), u(rng), 2.0 * u(rng) + 0.2), r(rng)});
  return out;
}

std::map<std::string, double> randomJoints(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> j1(-1.5, 1.5), j2(-2.0, 2.0);
  return {{"joint1", j1(rng)}, {"joint2", j2(rng)}};
}

double pairGapOf(const Sphere& a, const Sphere& b) {
  return (a.center - b.center).norm() - a.radius - b.radius;
}

// Every link's contact by brute force, compared with robotContacts (which must also name a
// sphere and an obstacle that attain the distance).
void expectBruteForce(const Robot& robot, const std::vector<LinkSpheres>& spheres,
                      const Obstacles& obstacles, const std::map<std::string, double>& joints) {
  auto got = robotContacts(robot, spheres, obstacles, joints);
  ASSERT_TRUE(got.ok()) << got.error().message;
  auto posed = posedLinkSpheres(robot, spheres, joints);
  ASSERT_TRUE(posed.ok());
  ASSERT_EQ(got->links.size(), spheres.size());
  double least = kInfinity;
  bool any = false;
  for (size_t k = 0; k < spheres.size(); ++k) {
    double d = kInfinity;
    for (const Sphere& s : (*posed)[k].spheres)
      for (const Sphere& o : obstacles.spheres) d = std::min(d, pairGapOf(s, o));
    const LinkContact& c = got->links[k];
    EXPECT_EQ(c.link, spheres[k].link);
    if (std::isinf(d)) {
      EXPECT_TRUE(std::isinf(c.distance));
      EXPECT_EQ(c.sphere, -1);
      continue;
    }
    EXPECT_NEAR(c.distance, d, 1e-12) << c.link;
    EXPECT_EQ(c.collides, d < 0.0) << c.link;
    ASSERT_GE(c.sphere, 0);
    ASSERT_GE(c.obstacle, 0);
    EXPECT_NEAR(pairGapOf((*posed)[k].spheres[c.sphere], obstacles.spheres[c.obstacle]), d, 1e-12);
    least = std::min(least, d);
    any = any || d < 0.0;
  }
  EXPECT_NEAR(got->distance, least, 1e-12);
  EXPECT_EQ(got->collides, any);
}

TEST(RobotQuery, PointCloudMatchesBruteForce) {
  const Robot robot = test::threeLinkRobot();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> xy(-0.8, 0.8), z(-0.2, 1.2);
  std::vector<Vec3> cloud(100000);
  for (Vec3& p : cloud) p = Vec3(xy(rng), xy(rng), z(rng));
  auto obstacles = makeObstacles(cloud, "cloud");
  ASSERT_TRUE(obstacles.ok()) << obstacles.error().message;
  EXPECT_EQ(obstacles->spheres.size(), cloud.size());
  int colliding = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const std::vector<LinkSpheres> spheres = randomLinkSpheres(rng);
    const auto joints = randomJoints(rng);
    expectBruteForce(robot, spheres, *obstacles, joints);
    colliding += robotContacts(robot, spheres, *obstacles, joints)->collides;
  }
  EXPECT_GT(colliding, 0);  // a cloud this dense reaches some spheres
}

TEST(RobotQuery, ObstacleSpheresMatchBruteForce) {
  const Robot robot = test::threeLinkRobot();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> xy(-1.0, 1.0), z(-0.5, 1.5), r(0.0, 0.1);
  std::vector<Sphere> obstacles_in(300);
  for (Sphere& s : obstacles_in) s = {Vec3(xy(rng), xy(rng), z(rng)), r(rng)};
  auto obstacles = makeObstacles(obstacles_in, "obstacles");
  ASSERT_TRUE(obstacles.ok());
  for (int trial = 0; trial < 30; ++trial)
    expectBruteForce(robot, randomLinkSpheres(rng), *obstacles, randomJoints(rng));
  // One obstacle: a tree of one leaf.
  auto one = makeObstacles(std::vector<Sphere>{{Vec3(0, 0, 0.3), 0.01}}, "one");
  ASSERT_TRUE(one.ok());
  expectBruteForce(robot, randomLinkSpheres(rng), *one, {});
}

TEST(RobotQuery, PosedSpheresFollowTheLinkPoses) {
  const Robot robot = test::threeLinkRobot();
  const std::vector<LinkSpheres> spheres = {{"link2", {{Vec3(0.45, 0, 0), 0.05}}}};
  // link2's frame is at (0, 0, 0.5) turned about y by joint2: (x, 0, 0) -> (x cos q, 0,
  // 0.5 - x sin q).
  auto posed = posedLinkSpheres(robot, spheres, {{"joint2", 1.0}});
  ASSERT_TRUE(posed.ok());
  ASSERT_EQ(posed->size(), 1u);
  const Sphere& s = (*posed)[0].spheres.at(0);
  EXPECT_NEAR(s.center.x(), 0.45 * std::cos(1.0), 1e-12);
  EXPECT_NEAR(s.center.y(), 0.0, 1e-12);
  EXPECT_NEAR(s.center.z(), 0.5 - 0.45 * std::sin(1.0), 1e-12);
  EXPECT_EQ(s.radius, 0.05);
}

// joint2 sweeps 0, 0.2, ..., 2 rad; an obstacle sits where link2's sphere is at waypoint 6. The
// sphere (radius 0.05, 0.45 from the axis) moves 0.09 per step, more than the 0.07 the two radii
// reach, so waypoint 5 is clear and 6 is the first to collide.
TEST(RobotQuery, TrajectoryFindsTheFirstCollidingWaypoint) {
  const Robot robot = test::threeLinkRobot();
  const std::vector<LinkSpheres> spheres = {{"base_link", {{Vec3(0, 0, 0.05), 0.1}}},
                                            {"link2", {{Vec3(0.45, 0, 0), 0.05}}}};
  std::vector<std::map<std::string, double>> waypoints;
  for (int i = 0; i <= 10; ++i) waypoints.push_back({{"joint2", 0.2 * i}});
  auto at6 = posedLinkSpheres(robot, spheres, waypoints[6]);
  ASSERT_TRUE(at6.ok());
  auto obstacles = makeObstacles(
      std::vector<Sphere>{{Vec3(5, 5, 5), 0.1}, {(*at6)[1].spheres[0].center, 0.02}}, "obstacles");
  ASSERT_TRUE(obstacles.ok());
  auto traj = trajectoryContacts(robot, spheres, *obstacles, waypoints);
  ASSERT_TRUE(traj.ok()) << traj.error().message;
  EXPECT_EQ(traj->first_collision, 6);
  ASSERT_EQ(traj->waypoints.size(), waypoints.size());
  EXPECT_GT(traj->waypoints[5].distance, 0.0);
  const RobotContacts& w6 = traj->waypoints[6];
  EXPECT_TRUE(w6.collides);
  EXPECT_NEAR(w6.distance, -0.07, 1e-12);
  EXPECT_EQ(w6.closest_link, 1);
  EXPECT_EQ(w6.links[1].obstacle, 1);
  EXPECT_FALSE(w6.links[0].collides);
  for (size_t i = 0; i < waypoints.size(); ++i)
    expectBruteForce(robot, spheres, *obstacles, waypoints[i]);
  // The same on one thread.
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  auto serial = trajectoryContacts(robot, spheres, *obstacles, waypoints);
  ASSERT_TRUE(serial.ok());
  EXPECT_EQ(serial->first_collision, 6);
  for (size_t i = 0; i < waypoints.size(); ++i) {
    EXPECT_EQ(serial->waypoints[i].distance, traj->waypoints[i].distance);
    EXPECT_EQ(serial->waypoints[i].links[1].obstacle, traj->waypoints[i].links[1].obstacle);
  }
  // No collision anywhere: -1; touching (distance 0) is not a collision.
  auto far = makeObstacles(std::vector<Sphere>{{Vec3(5, 5, 5), 0.1}}, "far");
  EXPECT_EQ(trajectoryContacts(robot, spheres, *far, waypoints)->first_collision, -1);
  const Vec3 c = (*at6)[1].spheres[0].center;
  auto touching = makeObstacles(std::vector<Vec3>{c + Vec3(0, 0.05, 0)}, "touching");
  auto t = robotContacts(robot, spheres, *touching, waypoints[6]);
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t->distance, 0.0, 1e-15);
  EXPECT_EQ(t->collides, t->distance < 0.0);
}

TEST(RobotQuery, BadInputsAreRefusedNamingThem) {
  const Robot robot = test::threeLinkRobot();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  test::expectError(makeObstacles(std::vector<Vec3>{Vec3(0, 0, 0), Vec3(nan, 0, 0)}, "c.ply"),
                    ErrorCode::kInvalidData, "c.ply: point 1", "finite");
  test::expectError(makeObstacles(std::vector<Vec3>{Vec3(kInfinity, 0, 0)}, "c.ply"),
                    ErrorCode::kInvalidData, "c.ply: point 0", "finite");
  test::expectError(makeObstacles(std::vector<Sphere>{{Vec3(0, 0, 0), -1.0}}, "o.txt"),
                    ErrorCode::kInvalidData, "o.txt: sphere 0", "negative");
  test::expectError(makeObstacles(std::vector<Vec3>{}, "c.xyz"), ErrorCode::kInvalidData, "c.xyz",
                    "no points");
  auto obstacles = makeObstacles(std::vector<Vec3>{Vec3(1, 1, 1)}, "c");
  ASSERT_TRUE(obstacles.ok());
  const std::vector<LinkSpheres> unknown = {{"elbow", {{Vec3::Zero(), 0.1}}}};
  test::expectError(robotContacts(robot, unknown, *obstacles), ErrorCode::kInvalidData,
                    "link 'elbow'", "not a link of robot 'three_link'");
  const std::vector<LinkSpheres> twice = {{"link1", {}}, {"link1", {}}};
  test::expectError(robotContacts(robot, twice, *obstacles), ErrorCode::kInvalidData,
                    "link 'link1'", "listed twice");
  const std::vector<LinkSpheres> negative = {{"link1", {{Vec3::Zero(), 0.1}, {Vec3::Zero(), -2}}}};
  test::expectError(robotContacts(robot, negative, *obstacles), ErrorCode::kInvalidData,
                    "link 'link1' sphere 1", "negative");
  const std::vector<LinkSpheres> fine = {{"link1", {{Vec3::Zero(), 0.1}}}};
  test::expectError(robotContacts(robot, fine, *obstacles, {{"joint9", 1.0}}),
                    ErrorCode::kInvalidArgument, "joint9", "no joint");
  test::expectError(trajectoryContacts(robot, fine, *obstacles, {{}, {{"joint1", nan}}}),
                    ErrorCode::kInvalidArgument, "waypoint 1: joint 'joint1'", "finite");
  test::expectError(robotContacts(robot, fine, Obstacles{}), ErrorCode::kInvalidArgument,
                    "obstacles", "makeObstacles");
}

class RobotQueryFiles : public test::TempDirTest {};

TEST_F(RobotQueryFiles, TrajectoryCsvIsReadStrictly) {
  const Robot robot = test::threeLinkRobot();
  auto ok = readTrajectory(write("t.csv", "joint2, joint1\r\n0.5,-1\n\n1e-1 ,0\n"), robot);
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  ASSERT_EQ(ok->size(), 2u);
  EXPECT_EQ((*ok)[0].at("joint2"), 0.5);
  EXPECT_EQ((*ok)[0].at("joint1"), -1.0);
  EXPECT_EQ((*ok)[1].at("joint2"), 0.1);
  using test::expectError;
  expectError(readTrajectory(write("u.csv", "joint1,joint9\n0,0\n"), robot),
              ErrorCode::kInvalidData, "u.csv:1:", "no joint 'joint9' in robot 'three_link'");
  expectError(readTrajectory(write("n.csv", "joint1,joint2\n0,0\n0,abc\n"), robot),
              ErrorCode::kInvalidData, "n.csv:3:", "joint 'joint2': 'abc' is not a finite number");
  expectError(readTrajectory(write("i.csv", "joint1\nnan\n"), robot), ErrorCode::kInvalidData,
              "i.csv:2:", "not a finite number");
  expectError(readTrajectory(write("r.csv", "joint1,joint2\n0,0\n0,0,0\n"), robot),
              ErrorCode::kInvalidData, "r.csv:3:", "3 values, the header names 2 joints");
  expectError(readTrajectory(write("e.csv", ""), robot), ErrorCode::kInvalidData, "e.csv", "empty");
  expectError(readTrajectory(write("h.csv", "joint1\n"), robot), ErrorCode::kInvalidData, "h.csv",
              "no waypoints");
  expectError(readTrajectory(write("d.csv", "joint1,joint1\n0,0\n"), robot),
              ErrorCode::kInvalidData, "d.csv:1:", "appears twice");
  expectError(readTrajectory(path("missing.csv"), robot), ErrorCode::kUnreadable, "missing.csv",
              "");
}

TEST_F(RobotQueryFiles, PointCloudsAreReadFromTextObjPlyAndOff) {
  auto xyz = readPointCloud(write("c.xyz", "# cloud\n0 0 0\n1 2 3\n\n-1e-3 4 5\n"));
  ASSERT_TRUE(xyz.ok()) << xyz.error().message;
  ASSERT_EQ(xyz->size(), 3u);
  EXPECT_EQ((*xyz)[1], Vec3(1, 2, 3));
  auto obj = readPointCloud(write("c.obj", "v 1 2 3\nvn 0 0 1\nv 4 5 6 1\nf 1 2 1\n"));
  ASSERT_TRUE(obj.ok()) << obj.error().message;
  EXPECT_EQ(obj->size(), 2u);
  auto ply = readPointCloud(
      write("c.ply",
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0 0\n1 1 1\n"));
  ASSERT_TRUE(ply.ok()) << ply.error().message;
  EXPECT_EQ(ply->size(), 2u);
  auto off = readPointCloud(write("c.off", "OFF\n2 0 0\n0 0 0\n1 0 0\n"));
  ASSERT_TRUE(off.ok()) << off.error().message;
  EXPECT_EQ(off->size(), 2u);
  using test::expectError;
  expectError(readPointCloud(write("b.xyz", "0 0 0\n1 2\n")), ErrorCode::kInvalidData, "b.xyz:2",
              "expected three numbers");
  expectError(readPointCloud(write("n.xyz", "0 0 0\n1 nan 2\n")), ErrorCode::kInvalidData,
              "n.xyz:2", "finite");
  expectError(readPointCloud(write("e.xyz", "# nothing\n")), ErrorCode::kInvalidData, "e.xyz",
              "no points");
  expectError(readPointCloud(write("c.stl", "solid x\n")), ErrorCode::kUnreadable, "c.stl",
              "unknown point cloud extension");
}

// The spheres of a sphere URDF written by formatSphereUrdf come back as they were given; a link
// left with its visual geometry only (tool, when not listed) is not taken for spheres.
TEST_F(RobotQueryFiles, SphereUrdfGivesTheLinkSpheres) {
  const std::vector<LinkSpheres> spheres = {
      {"base_link", {{Vec3(0, 0, 0.05), 0.12}}},
      {"link2", {{Vec3(0.1, 0, 0), 0.05}, {Vec3(0.3, 0, 0), 0.04}}}};
  auto text = formatSphereUrdf(test::threeLinkUrdf(), spheres);
  ASSERT_TRUE(text.ok()) << text.error().message;
  RobotLoadOptions lo;
  lo.package_paths = {test::robotDir()};
  lo.use_ros_package_path = false;
  auto robot = loadRobot(write("spheres.urdf", *text), lo);
  ASSERT_TRUE(robot.ok()) << robot.error().message;
  const std::vector<LinkSpheres> back = urdfLinkSpheres(*robot);
  ASSERT_EQ(back.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back[k].link, spheres[k].link);
    ASSERT_EQ(back[k].spheres.size(), spheres[k].spheres.size());
    for (size_t i = 0; i < back[k].spheres.size(); ++i) {
      EXPECT_EQ(back[k].spheres[i].center, spheres[k].spheres[i].center);
      EXPECT_EQ(back[k].spheres[i].radius, spheres[k].spheres[i].radius);
    }
  }
}

}  // namespace
}  // namespace sphereset

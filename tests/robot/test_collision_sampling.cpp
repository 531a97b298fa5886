// The self-collision sampling against a brute-force oracle: on a 16-link chain with random
// spheres, every configuration posed again (collisionSampleConfiguration, linkPoses) and every
// pair of sphere sets tested gives the same Never, Always and enabled pairs as the sampling,
// whose sweep-and-prune broad phase looks at the pairs whose bounds meet only. And its progress:
// calls that end at the sample count, and a throw that cancels.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphereset/robot.hpp"
#include "sphereset/robot_collision.hpp"

namespace sphereset {
namespace {

std::string numbered(char prefix, int i) {
  std::string s(1, prefix);
  s += std::to_string(i);
  return s;
}

// Links l0..l15, each 0.1 above its parent, revolute about x or y within ±1.5.
Robot chain(int links) {
  Robot r;
  r.name = "chain";
  r.root = "l0";
  for (int i = 0; i < links; ++i) {
    RobotLink l;
    l.name = numbered('l', i);
    r.links.push_back(l);
    if (i == 0) continue;
    RobotJoint j;
    j.name = numbered('j', i);
    j.parent = numbered('l', i - 1);
    j.child = l.name;
    j.type = RobotJoint::Type::kRevolute;
    j.origin.translation() = Vec3(0, 0, 0.1);
    j.axis = i % 2 ? Vec3::UnitX() : Vec3::UnitY();
    j.lower = -1.5;
    j.upper = 1.5;
    r.joints.push_back(j);
  }
  return r;
}

std::vector<LinkSpheres> randomSpheres(const Robot& robot, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> xy(-0.05, 0.05), z(0.0, 0.1), r(0.02, 0.06);
  std::vector<LinkSpheres> out;
  for (const RobotLink& l : robot.links) {
    LinkSpheres ls{l.name, {}};
    for (int k = 0; k < 2; ++k) ls.spheres.push_back({Vec3(xy(rng), xy(rng), z(rng)), r(rng)});
    out.push_back(ls);
  }
  return out;
}

TEST(CollisionSampling, BroadPhaseAgreesWithEveryPairTested) {
  const Robot robot = chain(16);
  const std::vector<LinkSpheres> spheres = randomSpheres(robot, 5);
  CollisionSamplingOptions o;
  o.samples = 400;
  o.seed = 3;
  o.always_fraction = 0.5;
  auto m = sampleSelfCollisions(robot, spheres, o);
  ASSERT_TRUE(m.ok()) << m.error().message;

  // The oracle: each configuration posed again, every pair of links, every pair of spheres.
  const size_t n = spheres.size();
  std::map<std::pair<size_t, size_t>, int64_t> count;
  for (int64_t i = 0; i < o.samples; ++i) {
    auto poses = linkPoses(robot, collisionSampleConfiguration(robot, o.seed, i));
    ASSERT_TRUE(poses.ok());
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b) {
        bool touch = false;
        for (const Sphere& sa : spheres[a].spheres)
          for (const Sphere& sb : spheres[b].spheres) {
            const Vec3 ca = poses->at(spheres[a].link) * sa.center;
            const Vec3 cb = poses->at(spheres[b].link) * sb.center;
            touch = touch || (ca - cb).norm() <= sa.radius + sb.radius;
          }
        count[{a, b}] += touch;
      }
  }
  std::map<std::string, std::string> expected;  // "a/b" -> reason, pairs that may be skipped
  for (const auto& [ab, c] : count) {
    const std::string key = spheres[ab.first].link + "/" + spheres[ab.second].link;
    if (ab.second == ab.first + 1)
      expected[key] = "Adjacent";
    else if (c == 0)
      expected[key] = "Never";
    else if (c >= o.always_fraction * o.samples)
      expected[key] = "Always";
  }
  std::map<std::string, std::string> got;
  for (const DisabledPair& p : m->disabled)
    if (p.reason != DisableReason::kDefault)
      got[p.link1 + "/" + p.link2] = disableReasonName(p.reason);
    else
      expected.erase(p.link1 + "/" + p.link2);  // in contact at the zero pose: not sampled
  EXPECT_EQ(got, expected);
  // The spheres reach past their neighbours: some pairs meet in some samples only.
  EXPECT_GT(m->enabled, 0);
  EXPECT_GT(m->count(DisableReason::kNever), 0);
}

TEST(CollisionSampling, ProgressEndsAtTheSampleCountAndAThrowCancels) {
  const Robot robot = chain(6);
  const std::vector<LinkSpheres> spheres = randomSpheres(robot, 1);
  CollisionSamplingOptions o;
  o.samples = 5000;
  std::vector<int64_t> done;
  o.progress = [&](const RobotProgress& p) {
    EXPECT_EQ(p.stage, "self-collision");
    EXPECT_EQ(p.total, 5000);
    done.push_back(p.done);
  };
  ASSERT_TRUE(sampleSelfCollisions(robot, spheres, o).ok());
  ASSERT_GE(done.size(), 2u);
  EXPECT_EQ(done.back(), 5000);
  for (size_t k = 1; k < done.size(); ++k) EXPECT_GT(done[k], done[k - 1]);
  o.progress = [](const RobotProgress& p) {
    if (p.done > 0) throw std::runtime_error("stop");
  };
  EXPECT_THROW((void)sampleSelfCollisions(robot, spheres, o), std::runtime_error);
}

}  // namespace
}  // namespace sphereset

// The whole-robot fit (fitRobot) on the synthetic three-link robot: every fitted link is
// covered (checked by brute force too), the budget is kept and never loses to the curve split,
// fixed and skipped links are honoured, and the result does not depend on the thread count.
// A long chain of boxes: memory follows the links being fitted, not the links.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "broken_meshes.hpp"
#include "robot_data.hpp"
#include "sphereset/robot_fit.hpp"
#include "test_support.hpp"
#ifdef SPHERESET_TEST_REPAIR
#include "sphereset/repair_cgal.hpp"
#endif

namespace sphereset::test {
namespace {

RobotFitOptions fastOptions() {
  RobotFitOptions o;
  o.quality = FitQuality::kFast;
  o.name = "three_link.urdf";
#ifdef SPHERESET_TEST_REPAIR
  o.repair.operations = cgalSolidOperations();
#else
  o.link_solid = LinkSolid::kWalls;  // the envelope needs the wrapping
#endif
  return o;
}

const RobotLinkFit* find(const RobotFitResult& r, const std::string& link) {
  for (const RobotLinkFit& l : r.links)
    if (l.link == link) return &l;
  return nullptr;
}

TEST(FitRobot, BudgetIsKeptEveryLinkCoveredAndTheSplitNotBeaten) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.budget = 12;
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r->budget_split);
  size_t total = 0;
  for (const RobotLinkFit& l : r->links) {
    total += l.spheres.size();
    EXPECT_TRUE(l.covered) << l.link;
    if (!l.fitted) continue;
    // Independent check: random points on the link's original triangles, every sphere.
    expectPointsCovered(l.repair.original, l.spheres);
  }
  EXPECT_LE(total, 12u);
  EXPECT_LE(r->outside_volume, r->split_outside_volume * (1 + 1e-12));
  // The tool link is one sphere primitive, kept exact.
  const RobotLinkFit* tool = find(*r, "tool");
  ASSERT_NE(tool, nullptr);
  EXPECT_FALSE(tool->fitted);
  EXPECT_EQ(tool->spheres.size(), 1u);
}

TEST(FitRobot, FixedSkippedAndPaddedLinks) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.link_spheres = {{"base_link", 2}, {"link1", 0}, {"link2", 3}};
  o.link_padding = {{"link2", 0.01}};
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(find(*r, "base_link")->spheres.size(), 2u);
  EXPECT_TRUE(find(*r, "link1")->skipped);
  EXPECT_TRUE(find(*r, "link1")->spheres.empty());
  EXPECT_EQ(find(*r, "link2")->spheres.size(), 3u);
  EXPECT_EQ(find(*r, "link2")->padding, 0.01);
  EXPECT_FALSE(r->budget_split);
  o.link_spheres = {{"elbow", 2}};
  auto bad = fitRobot(robot, o);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("'elbow'"), std::string::npos);
}

TEST(FitRobot, ProtrusionLimitGivesEachLinkItsFewestSpheresThatMeetIt) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.max_protrusion = 0.05;
  o.link_max_protrusion = {{"link2", 0.06}};
  o.link_padding = {{"link2", 0.005}};
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r->tolerance);
  EXPECT_TRUE(r->tolerance_met);
  int limited = 0;
  for (const RobotLinkFit& l : r->links) {
    if (!l.fitted) continue;
    ++limited;
    const double limit = l.link == "link2" ? 0.06 : 0.05;
    EXPECT_EQ(l.protrusion_limit, limit) << l.link;
    EXPECT_TRUE(l.limit_met && l.covered) << l.link;
    // The padded spheres' certified protrusion is within the limit.
    EXPECT_LE(l.eval.protrusion + l.padding, limit) << l.link;
    expectPointsCovered(l.repair.original, l.spheres);
    // Per sphere (the result's field): one padded bound per fitted sphere, the largest the
    // link's.
    std::vector<double> per;
    for (const ResultField& f : robotLinkFields(l))
      if (std::string(f.name) == "sphere_protrusion") per = std::get<std::vector<double>>(f.value);
    ASSERT_EQ(per.size(), l.spheres.size() - static_cast<size_t>(l.primitives)) << l.link;
    EXPECT_DOUBLE_EQ(*std::max_element(per.begin(), per.end()), l.eval.protrusion + l.padding);
  }
  EXPECT_GE(limited, 2);
  // A limit no count meets within the cap: reported, not an error.
  o.max_protrusion = 1e-9;
  o.link_max_protrusion.clear();
  o.link_padding.clear();
  o.budget = 8;
  auto tight = fitRobot(robot, o);
  ASSERT_TRUE(tight.ok()) << tight.error().message;
  EXPECT_TRUE(tight->tolerance);
  EXPECT_FALSE(tight->tolerance_met);
  size_t total = 0;
  for (const RobotLinkFit& l : tight->links) {
    total += l.spheres.size();
    if (l.fitted) {
      EXPECT_FALSE(l.limit_met) << l.link;
    }
    EXPECT_TRUE(l.covered) << l.link;
  }
  EXPECT_LE(total, 8u);  // within the budget
}

// A limit with a budget: the budget's spheres go where the worst link is furthest over its limit.
// With twice the room of every link's fewest count, every link meets it within the budget; with
// one sphere a link, the budget holds and the result says the limit is not met, as each link's
// certified protrusion says.
TEST(FitRobot, ProtrusionLimitWithABudgetMeetsItWithinTheBudget) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.max_protrusion = 0.05;
  auto alone = fitRobot(robot, o);
  ASSERT_TRUE(alone.ok()) << alone.error().message;
  size_t fewest = 0;
  for (const RobotLinkFit& l : alone->links) fewest += l.spheres.size();
  o.budget = 2 * static_cast<int>(fewest);
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->tolerance && r->tolerance_met);
  size_t total = 0;
  for (const RobotLinkFit& l : r->links) {
    total += l.spheres.size();
    if (!l.fitted) continue;
    EXPECT_TRUE(l.limit_met && l.covered) << l.link;
    EXPECT_LE(l.eval.protrusion + l.padding, 0.05) << l.link;
  }
  EXPECT_LE(total, static_cast<size_t>(o.budget));
  o.budget = static_cast<int>(r->links.size());
  auto one_each = fitRobot(robot, o);
  ASSERT_TRUE(one_each.ok()) << one_each.error().message;
  EXPECT_FALSE(one_each->tolerance_met);
  total = 0;
  for (const RobotLinkFit& l : one_each->links) {
    total += l.spheres.size();
    if (l.fitted) {
      EXPECT_EQ(l.limit_met, l.covered && l.eval.protrusion + l.padding <= 0.05) << l.link;
    }
  }
  EXPECT_LE(total, static_cast<size_t>(o.budget));
}

TEST(FitRobot, ProtrusionLimitWithRestartsFitsEachCountAlone) {
  // --quality best has restarts and decimation, which a progressive run cannot honour: the
  // limited link's counts are independent fits, and the limit is met all the same.
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.quality = FitQuality::kBest;
  o.link_spheres = {{"base_link", 1}, {"link2", 1}};
  o.link_max_protrusion = {{"link1", 0.05}};
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  const RobotLinkFit* link1 = find(*r, "link1");
  ASSERT_NE(link1, nullptr);
  EXPECT_TRUE(link1->limit_met && link1->covered);
  EXPECT_LE(link1->eval.protrusion, 0.05);
  EXPECT_TRUE(r->tolerance_met);
}

TEST(FitRobot, ProtrusionLimitsRefuseWhatCannotHold) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.link_max_protrusion = {{"link1", 0.02}};
  o.link_spheres = {{"link1", 3}};
  auto both = fitRobot(robot, o);
  ASSERT_FALSE(both.ok());
  EXPECT_NE(both.error().message.find("both link_spheres and link_max_protrusion"),
            std::string::npos);
  o.link_spheres.clear();
  o.budget = 10;  // a budget needs a limit for every free link
  auto partial = fitRobot(robot, o);
  ASSERT_FALSE(partial.ok());
  EXPECT_NE(partial.error().message.find("has no protrusion limit"), std::string::npos);
  o.budget = 0;
  o.link_padding = {{"link1", 0.05}};  // the padding alone is over the limit
  auto padded = fitRobot(robot, o);
  ASSERT_FALSE(padded.ok());
  EXPECT_NE(padded.error().message.find("leaves nothing of its protrusion limit"),
            std::string::npos);
  o.link_padding.clear();
  o.link_max_protrusion = {{"elbow", 0.02}};
  auto unknown = fitRobot(robot, o);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().message.find("'elbow'"), std::string::npos);
  RobotFitOptions t;
  EXPECT_FALSE(setRobotFitOption(&t, "link_max_protrusion", "link1=0").ok());
  EXPECT_FALSE(setRobotFitOption(&t, "max_protrusion", "-1").ok());
  EXPECT_FALSE(setRobotFitOption(&t, "max_protrusion", "nan").ok());
  EXPECT_FALSE(setRobotFitOption(&t, "max_protrusion", "0").ok());
  EXPECT_TRUE(setRobotFitOption(&t, "link_max_protrusion", "link1=0.01").ok());
  EXPECT_FALSE(setRobotFitOption(&t, "link_max_protrusion", "link1=0.02").ok());  // twice
  EXPECT_FALSE(setRobotFitOption(&t, "link_max_protrusion", "link1=2%").ok());    // twice too
  EXPECT_FALSE(setRobotFitOption(&t, "max_protrusion", "0%").ok());
  EXPECT_FALSE(setRobotFitOption(&t, "max_protrusion", "5%%").ok());
  // A struct set in code is checked as the text would be.
  t = RobotFitOptions{};
  t.max_protrusion = 0.01;
  t.max_protrusion_fraction = 0.05;
  EXPECT_FALSE(checkRobotFitOptions(t).ok());
  t.max_protrusion = 0.0;
  t.link_max_protrusion_fraction = {{"link1", -0.1}};
  EXPECT_FALSE(checkRobotFitOptions(t).ok());
}

// A limit given as a percentage ("P%") is a fraction of each link's own solid's bounding-box
// diagonal; a link's own length comes before it. The row keeps one form: the later text wins.
TEST(FitRobot, PercentLimitsAreFractionsOfEachLinksDiagonal) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  ASSERT_TRUE(setRobotFitOption(&o, "max_protrusion", "0.5").ok());
  ASSERT_TRUE(setRobotFitOption(&o, "max_protrusion", "20%").ok());
  EXPECT_EQ(o.max_protrusion, 0.0);
  EXPECT_DOUBLE_EQ(o.max_protrusion_fraction, 0.2);
  ASSERT_TRUE(setRobotFitOption(&o, "link_max_protrusion", "link2=0.06").ok());
  ASSERT_TRUE(setRobotFitOption(&o, "link_max_protrusion", "link1=15%").ok());
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  int fraction_links = 0;
  for (const RobotLinkFit& l : r->links) {
    if (!l.fitted) continue;
    const double diagonal = SolidIndex(l.repair.solid).bounds().diagonal();
    const double expected = l.link == "link2" ? 0.06 : (l.link == "link1" ? 0.15 : 0.2) * diagonal;
    fraction_links += l.link != "link2";
    EXPECT_DOUBLE_EQ(l.protrusion_limit, expected) << l.link;
    if (l.limit_met) {
      EXPECT_LE(l.eval.protrusion + l.padding, expected) << l.link;
    }
  }
  EXPECT_GE(fraction_links, 1);
  EXPECT_TRUE(r->tolerance_met);
}

TEST(FitRobot, LinkSolidForDecidesOneLink) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.link_spheres = {{"base_link", 1}, {"link1", 2}, {"link2", 2}};
#ifdef SPHERESET_TEST_REPAIR
  // Walls for all but link2, whose envelope closes openings up to the size given.
  o.link_solid = LinkSolid::kWalls;
  o.repair.fill_openings = 0.05;
  o.link_solid_for = {{"link2", LinkSolid::kEnvelope}};
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(find(*r, "link2")->repair.fill_openings, 0.05);
  EXPECT_STREQ(solidName(find(*r, "link2")->repair), "envelope");
  EXPECT_FALSE(find(*r, "link2")->repair.walls.triangles.empty());
  // At the automatic size link2's envelope encloses no hollow, so the rule keeps its walls,
  // unless the envelope is chosen for it.
  RobotFitOptions automatic = fastOptions();
  automatic.link_spheres = o.link_spheres;
  auto by_rule = fitRobot(robot, automatic);
  ASSERT_TRUE(by_rule.ok()) << by_rule.error().message;
  EXPECT_STREQ(solidName(find(*by_rule, "link2")->repair), "walls");
  automatic.link_solid_for = {{"link2", LinkSolid::kEnvelope}};
  auto chosen = fitRobot(robot, automatic);
  ASSERT_TRUE(chosen.ok()) << chosen.error().message;
  EXPECT_STREQ(solidName(find(*chosen, "link2")->repair), "envelope");
  EXPECT_GT(find(*chosen, "link2")->repair.fill_openings, 0.0);
  EXPECT_TRUE(find(*chosen, "link2")->covered);
#else
  // The envelope for every link but none can be made without the wrapping: the links given
  // walls are fitted, the one left to the envelope fails.
  o.link_solid = LinkSolid::kEnvelope;
  o.link_solid_for = {{"base_link", LinkSolid::kWalls}, {"link1", LinkSolid::kWalls}};
  auto envelope = fitRobot(robot, o);
  ASSERT_FALSE(envelope.ok());
  EXPECT_NE(envelope.error().message.find("link 'link2'"), std::string::npos);
  o.link_solid_for["link2"] = LinkSolid::kWalls;
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
#endif
  for (const char* walls : {"base_link", "link1"}) {
    EXPECT_EQ(find(*r, walls)->repair.fill_openings, 0.0) << walls;
    EXPECT_STREQ(solidName(find(*r, walls)->repair), "walls") << walls;
  }
  for (const RobotLinkFit& l : r->links) EXPECT_TRUE(l.covered) << l.link;
  o.link_solid_for = {{"elbow", LinkSolid::kEnvelope}};
  auto bad = fitRobot(robot, o);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message,
            "three_link.urdf: link_solid_for names 'elbow', not a link of " + robot.name);
}

TEST(FitRobot, SameSpheresOnOneAndTwoThreads) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.budget = 10;
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return fitRobot(robot, o);
  };
  auto a = run(1), b = run(2);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->links.size(), b->links.size());
  for (size_t i = 0; i < a->links.size(); ++i) {
    ASSERT_EQ(a->links[i].spheres.size(), b->links[i].spheres.size());
    for (size_t k = 0; k < a->links[i].spheres.size(); ++k) {
      EXPECT_EQ(a->links[i].spheres[k].center, b->links[i].spheres[k].center);
      EXPECT_EQ(a->links[i].spheres[k].radius, b->links[i].spheres[k].radius);
    }
  }
}

TEST(FitRobot, StepsCountEveryLinkCurveAndFitAndAThrowCancels) {
  const Robot robot = test::threeLinkRobot();
  RobotFitOptions o = fastOptions();
  o.budget = 12;
  std::map<std::string, std::vector<int64_t>> done;
  std::map<std::string, int64_t> total;
  o.steps = [&](const RobotProgress& p) {  // one call at a time: no lock needed here
    done[p.stage].push_back(p.done);
    total[p.stage] = p.total;
    EXPECT_FALSE(p.link.empty());
  };
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(done.size(), 2u);
  int fitted = 0;
  for (const RobotLinkFit& l : r->links) fitted += l.fitted;
  EXPECT_EQ(total["link curves"], fitted);  // every fitted link is free under the budget
  EXPECT_GE(total["link fits"], fitted);    // and fitted at one count or more
  for (const auto& [stage, d] : done) {
    ASSERT_EQ(static_cast<int64_t>(d.size()), total[stage]) << stage;
    for (size_t k = 0; k < d.size(); ++k) EXPECT_EQ(d[k], static_cast<int64_t>(k) + 1) << stage;
  }
  o.steps = [](const RobotProgress& p) {
    if (p.stage == "link fits") throw std::runtime_error("stop");
  };
  EXPECT_THROW((void)fitRobot(robot, o), std::runtime_error);
}

// The peak resident memory of this process so far, in MB.
double peakMegabytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

// AddressSanitizer keeps freed memory in quarantine (256 MB) and adds its shadow: the resident
// peak then measures the sanitizer, not the fit.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

TEST(FitRobot, MemoryFollowsTheLinksInFlightNotTheLinks) {
  if (kSanitized) GTEST_SKIP() << "resident memory under AddressSanitizer is the sanitizer's";
  // 40 box links (no joints needed for the fit). Each link's index remembered about 6.5 MB of
  // answers until the whole robot was done: 60 links then took about 400 MB, and a 1000-link
  // chain ran out of memory. Now a link forgets them after its last fit.
  Robot robot;
  robot.name = "chain";
  for (int i = 0; i < 40; ++i) {
    RobotLink link;
    link.name = "l";
    link.name += std::to_string(i);
    LinkGeometry box;
    box.kind = LinkGeometry::Kind::kBox;
    box.box_size = Vec3(0.04, 0.04, 0.1);
    link.geometry.push_back(box);
    robot.links.push_back(link);
  }
  RobotFitOptions o;
  o.quality = FitQuality::kFast;
  o.link_solid = LinkSolid::kWalls;
  const double before = peakMegabytes();
  auto r = fitRobot(robot, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->links.size(), 40u);
  for (const RobotLinkFit& l : r->links) EXPECT_TRUE(l.covered) << l.link;
  EXPECT_LT(peakMegabytes() - before, 150.0) << "MB more at the peak";
}

}  // namespace
}  // namespace sphereset::test

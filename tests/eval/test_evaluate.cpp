// Evaluation metrics on sets with known answers.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <numbers>

#include "eval/shadow.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/query.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"
#include "tree/query_oracles.hpp"

namespace sphereset {
namespace {

using test::kPi;

TEST(Evaluate, CircumscribedSphereOfCube) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const double r = std::sqrt(3.0) / 2.0;
  const std::vector<Sphere> one = {{Vec3::Constant(0.5), r}};
  EvalOptions o;
  o.union_samples = 100000;
  o.proximity_segments = 200;
  const EvalResult e = *evaluateSpheres(idx, one, o);
  const double exact = 4.0 / 3.0 * kPi * r * r * r - 1.0;
  EXPECT_NEAR(e.er_sum, exact, 1e-12);
  EXPECT_NEAR(e.er_union, exact, 4 * e.er_union_stderr);
  EXPECT_GT(e.er_union_stderr, 0.0);
  EXPECT_TRUE(e.surface_covered);
  EXPECT_EQ(e.max_surface_gap, 0.0);
  EXPECT_TRUE(e.interior_covered);
  // Segments between points of a convex solid never leave it: zero outside length, and the
  // sphere also covers them.
  EXPECT_NEAR(e.proximity_error, 0.0, 1e-12);
}

TEST(Evaluate, UnionCountsOverlapOnce) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const double r = std::sqrt(3.0) / 2.0;
  const std::vector<Sphere> twice = {{Vec3::Constant(0.5), r}, {Vec3::Constant(0.5), r}};
  EvalOptions o;
  o.proximity_segments = 0;
  const EvalResult e = *evaluateSpheres(idx, twice, o);
  const double exact = 4.0 / 3.0 * kPi * r * r * r - 1.0;
  EXPECT_NEAR(e.er_sum, 2 * exact, 1e-12);
  EXPECT_NEAR(e.er_union, exact, 4 * e.er_union_stderr + 1e-12);
}

TEST(Evaluate, MissingCornerIsFoundWithItsGap) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  // Centred sphere that misses the corners by √3/2 - 0.8.
  const std::vector<Sphere> s = {{Vec3::Constant(0.5), 0.8}};
  EvalOptions o;
  o.union_samples = 1000;
  o.proximity_segments = 0;
  const EvalResult e = *evaluateSpheres(idx, s, o);
  EXPECT_FALSE(e.surface_covered);
  EXPECT_FALSE(e.interior_covered);
  EXPECT_NEAR(e.max_surface_gap, (std::sqrt(3.0) / 2.0 - 0.8) / std::sqrt(3.0), 2e-12);
  EXPECT_EQ(e.uncovered_triangles, 12);
}

TEST(Evaluate, HollowShellOfSpheresLeavesTheInteriorUncovered) {
  // Spheres on the surface of a large cube cover its faces but not its centre.
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Constant(10.0)));
  std::vector<Sphere> shell;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int f = 0; f < 6; ++f) {
        Vec3 p;
        const double a = i, b = j, c = (f % 2) ? 10.0 : 0.0;
        if (f < 2)
          p = Vec3(c, a, b);
        else if (f < 4)
          p = Vec3(a, c, b);
        else
          p = Vec3(a, b, c);
        shell.push_back({p, 0.9});
      }
  EvalOptions o;
  o.union_samples = 1000;
  o.proximity_segments = 0;
  const EvalResult e = *evaluateSpheres(idx, shell, o);
  EXPECT_TRUE(e.surface_covered);
  EXPECT_FALSE(e.interior_covered);
  EXPECT_GT(e.max_interior_gap, 0.15);
}

TEST(Evaluate, ResultsDoNotDependOnThreads) {
  const SolidIndex idx(test::makeTorus(1.0, 0.4, 32, 16));
  const std::vector<Sphere> s = {
      {Vec3(1, 0, 0), 0.6}, {Vec3(-1, 0, 0), 0.6}, {Vec3(0, 1, 0), 0.6}, {Vec3(0, -1, 0), 0.6}};
  EvalOptions o;
  o.union_samples = 50000;
  o.proximity_segments = 300;
  const EvalResult a = *evaluateSpheres(idx, s, o);
  EvalResult b;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    b = *evaluateSpheres(idx, s, o);
  }
  EXPECT_EQ(a.er_sum, b.er_sum);
  EXPECT_EQ(a.max_surface_gap, b.max_surface_gap);
  EXPECT_EQ(a.er_union, b.er_union);
  EXPECT_EQ(a.proximity_error, b.proximity_error);
  EXPECT_GT(a.proximity_error, 0.0);
}

TEST(Evaluate, OutsideLengthAgainstSpheres) {
  const std::vector<Sphere> s = {{Vec3(0, 0, 0), 1.0}, {Vec3(1.5, 0, 0), 1.0}};
  // Segment from x=-2 to x=4 along the axis: covered [-1, 2.5], outside 1 + 1.5.
  EXPECT_NEAR(segmentOutsideLengthBruteForce(s, Vec3(-2, 0, 0), Vec3(4, 0, 0)), 2.5, 1e-12);
  EXPECT_NEAR(segmentOutsideLengthBruteForce(s, Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(segmentOutsideLengthBruteForce(s, Vec3(-2, 5, 0), Vec3(4, 5, 0)), 6.0, 1e-12);
}

TEST(Evaluate, ShadowsOfASphereMeshAndOfThatSphereAgree) {
  // A fine icosphere and the ball it approximates cast nearly the same shadow; a ball twice
  // as large, or no ball at all, does not.
  const SolidIndex idx(test::makeIcosphere(1.0, 4));
  const std::vector<Sphere> same = {{Vec3::Zero(), 1.0}};
  const std::vector<Sphere> big = {{Vec3::Zero(), 2.0}};
  const ShadowResult a = compareShadows(idx, same, 2, 32, 48);
  const ShadowResult b = compareShadows(idx, big, 2, 32, 48);
  const ShadowResult none = compareShadows(idx, {}, 2, 32, 48);
  EXPECT_EQ(a.pixels, 32 * 32);
  EXPECT_LT(a.sky_rms, 0.01);
  EXPECT_LT(a.lights_rms, 0.03);
  EXPECT_GT(b.sky_rms, 5 * a.sky_rms);
  EXPECT_GT(none.sky_rms, 5 * a.sky_rms);
  // The up axis only turns the scene: a sphere looks the same from every axis.
  const ShadowResult ay = compareShadows(idx, same, 1, 32, 48);
  EXPECT_NEAR(ay.sky_rms, a.sky_rms, 0.003);
  // A flat plank is not: lying flat (up z) it shades the ground far more than standing on
  // its thin edge (up y), so an ignored up axis would show.
  const SolidIndex plank(test::makeBox(Vec3::Zero(), Vec3(4.0, 1.0, 0.2)));
  const ShadowResult flat = compareShadows(plank, {}, 2, 32, 48);
  const ShadowResult edge = compareShadows(plank, {}, 1, 32, 48);
  EXPECT_GT(flat.sky_rms, 1.2 * edge.sky_rms) << flat.sky_rms << " vs " << edge.sky_rms;
}

TEST(Evaluate, HemisphereDirectionsAreUnitUpwardAndBalanced) {
  const Vec3 up = Vec3(1, 2, 2).normalized();
  const auto dirs = hemisphereDirections(500, up);
  Vec3 mean = Vec3::Zero();
  for (const Vec3& d : dirs) {
    EXPECT_NEAR(d.norm(), 1.0, 1e-12);
    EXPECT_GT(d.dot(up), 0.0);
    mean += d / 500.0;
  }
  // Uniform over the hemisphere: the mean direction is up/2.
  EXPECT_NEAR((mean - 0.5 * up).norm(), 0.0, 0.01);
}

// The evaluation checks its own options and spheres: a shadow raster of 100000² pixels used to
// reach MemoryError through Python, which had no upper limits.
TEST(Evaluate, OptionsAndSpheresAreCheckedByTheLibrary) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const std::vector<Sphere> one = {{Vec3::Constant(0.5), 1.0}};
  EvalOptions o;
  o.shadow_resolution = 100000;
  test::expectError(evaluateSpheres(idx, one, o), ErrorCode::kInvalidArgument,
                    "shadow_resolution '100000'", "an integer from 0 to 4096");
  EXPECT_TRUE(setEvalOption(&o, "shadow_resolution", "1e5").error().message.find("1e5") !=
              std::string::npos);
  const Status unknown = setEvalOption(&o, "resolution", "3");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("expected seed, samples, segments, up"),
            std::string::npos);
  EXPECT_TRUE(setEvalOption(&o, "up", "z"));
  EXPECT_EQ(o.up_axis, 2);
  EvalOptions fine;
  fine.union_samples = 0;
  fine.shadow_resolution = 0;
  fine.proximity_segments = 0;
  test::expectError(evaluateSpheres(idx, {}, fine), ErrorCode::kInvalidArgument, "no spheres",
                    "evaluate");
  const std::vector<Sphere> nan = {{Vec3(std::nan(""), 0, 0), 1.0}};
  test::expectError(evaluateSpheres(idx, nan, fine), ErrorCode::kInvalidArgument, "sphere 0",
                    "NaN");
  EXPECT_TRUE(evaluateSpheres(idx, one, fine).ok());
}

// The evaluation polls from inside its loops, so a caller can cancel it (Python's Ctrl-C): the
// shadows of a 2048² raster under 4096 lights used to run for hours, uninterruptible.
TEST(Evaluate, PollsFromInsideItsLoopsAndCanBeCancelled) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const std::vector<Sphere> one = {{Vec3::Constant(0.5), 1.0}};
  EvalOptions o;
  o.union_samples = 50000;
  o.proximity_segments = 100;
  o.shadow_resolution = 16;
  o.poll_interval = 0.0;
  int polls = 0;
  o.poll = [&] { ++polls; };
  const auto plain = evaluateSpheres(idx, one, o);
  ASSERT_TRUE(plain.ok());
  EXPECT_GT(polls, 10);  // from the calling thread only: its share of the items
  struct Stop {};
  int calls = 0;
  o.poll = [&] {
    if (++calls == 7) throw Stop{};
  };
  EXPECT_THROW((void)evaluateSpheres(idx, one, o), Stop);
  EXPECT_EQ(calls, 7);
  o.poll_interval = -1.0;
  EXPECT_FALSE(evaluateSpheres(idx, one, o).ok());
}

}  // namespace
}  // namespace sphereset

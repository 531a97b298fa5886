// The fit with unusual counts (few points per sphere, few or no interior points), and the
// presets: their names, values and what a request overrides.
#include <gtest/gtest.h>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::expectCovers;

// Fits n spheres from about `points` points (half of them interior by default) with each
// method and expects n covering spheres.
void expectNSpheres(const SolidIndex& idx, FitOptions o) {
  for (const FitMethod m : {FitMethod::kKMeans, FitMethod::kVariational}) {
    o.method = m;
    const auto r = fitSpheres(idx, o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_LT(r->interior_points, o.num_spheres);  // the case under test
    ASSERT_EQ(r->spheres.size(), static_cast<size_t>(o.num_spheres));
    ASSERT_EQ(r->outside_volume.size(), r->spheres.size());
    expectCovers(idx, r->spheres);
  }
}

TEST(FitOptions, FewerInteriorPointsThanSpheresStillGiveNSpheres) {
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  FitOptions o;
  o.num_spheres = 40;
  o.target_points = 50;  // about 25 interior points
  o.max_iterations = 20;
  expectNSpheres(idx, o);
  o.init = FitInit::kRandom;
  expectNSpheres(idx, o);
}

TEST(FitOptions, NoInteriorShareSeedsOnTheSurface) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3(2.0, 1.0, 0.5)));
  FitOptions o;
  o.num_spheres = 8;
  o.target_points = 400;
  o.interior_share = 0.0;  // at most a few interior points
  o.max_iterations = 20;
  expectNSpheres(idx, o);
}

TEST(FitOptions, DecimationWithFewPointsEndsWithNSpheres) {
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  FitOptions o;
  o.num_spheres = 30;
  o.target_points = 50;
  o.decimation = 1.0;  // asks for 30 extra spheres; only the points beyond n can be extra
  o.max_iterations = 20;
  const auto r = fitSpheres(idx, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->spheres.size(), 30u);
  expectCovers(idx, r->spheres);
}

TEST(FitOptions, MoreSpheresThanPointsIsRefusedWithAdvice) {
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  FitOptions o;
  o.num_spheres = 80;
  o.target_points = 50;
  for (const FitMethod m : {FitMethod::kVariational, FitMethod::kKMeans, FitMethod::kOctree}) {
    o.method = m;
    const auto r = fitSpheres(idx, o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(r.error().message.find("--points"), std::string::npos) << r.error().message;
  }
}

// A rod 1e-4 thick along its bounding box's diagonal fills 1e-8 of the box: an interior grid
// spaced for the requested points would have some 1e11 cells. The grid is capped instead, and
// the fit completes with its n covering spheres.
TEST(FitOptions, ThinRodAlongTheBoxDiagonalSamplesABoundedGrid) {
  const Mesh bar = test::makeBox(Vec3::Zero(), Vec3(std::sqrt(3.0), 1e-4, 1e-4));
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), Vec3::Ones()).toRotationMatrix();
  const SolidIndex idx(test::transformed(bar, turn, Vec3::Zero(), 1.0));
  const Aabb& box = idx.bounds();
  ASSERT_LT(signedVolume(idx.mesh()), 1e-7 * (box.max - box.min).prod());
  FitOptions o;
  o.num_spheres = 4;
  o.target_points = 1000;
  o.max_iterations = 10;
  const auto r = fitSpheres(idx, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->spheres.size(), 4u);
  EXPECT_GT(r->points, 500);  // the surface samples at least
  expectCovers(idx, r->spheres);
}

TEST(FitPresets, NamesAndOverrides) {
  for (FitQuality q : {FitQuality::kFast, FitQuality::kDefault, FitQuality::kBest})
    EXPECT_EQ(fitQualityFromName(fitQualityName(q)).value(), q);
  test::expectError(fitQualityFromName("great"), ErrorCode::kInvalidArgument, "great",
                    "expected fast, default or best");
  EXPECT_EQ(fitMethodFromName("octree").value(), FitMethod::kOctree);
  EXPECT_FALSE(sphereOptimizerFromName("newton").ok());

  const FitOptions fast = fitPreset(10, FitQuality::kFast);
  EXPECT_EQ(fast.target_points, 1250);  // 0.25 × max(5000, 1000)
  EXPECT_EQ(fast.max_iterations, 20);
  EXPECT_EQ(fast.optimizer_evaluations, 20);
  EXPECT_EQ(fast.max_failed_teleports, 1);
  const FitOptions best = fitPreset(100, FitQuality::kBest);
  EXPECT_EQ(best.target_points, 10000);
  EXPECT_EQ(best.restarts, 4);
  EXPECT_EQ(best.decimation, 0.5);
  // The help's defaults restate the presets' rounds and restarts: they must follow them.
  auto helpDefault = [](const std::string& name) {
    for (const OptionSpec& spec : fitRequestOptions())
      if (spec.name == name) return std::string(spec.default_text);
    return std::string();
  };
  const FitOptions plain = fitPreset(10, FitQuality::kDefault);
  EXPECT_EQ(helpDefault("iterations"), std::to_string(plain.max_iterations) + "; quality fast: " +
                                           std::to_string(fast.max_iterations));
  EXPECT_EQ(helpDefault("restarts"),
            std::to_string(plain.restarts) + "; quality best: " + std::to_string(best.restarts));
  FitRequest req;
  req.num_spheres = 100;
  req.quality = FitQuality::kBest;
  req.restarts = 2;
  req.points = 777;
  req.seed = 9;
  const FitOptions fo = fitOptionsFor(req);
  EXPECT_EQ(fo.restarts, 2);
  EXPECT_EQ(fo.decimation, 0.5);
  EXPECT_EQ(fo.target_points, 777);
  EXPECT_EQ(fo.seed, 9u);
  EXPECT_EQ(fo.max_iterations, 100);
}

}  // namespace
}  // namespace sphereset

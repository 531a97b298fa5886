// The fit with unusual counts: few points per sphere, few or no interior points.
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

}  // namespace
}  // namespace sphereset

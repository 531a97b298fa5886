// The optimal radii for given centres (src/fit/optimal_radii.cpp): the program's figures are
// consistent (lower bound <= objective <= the start's energy), a sphere the others make useless
// shrinks, the kept set still covers the surface (checked by brute force, independently of the
// sphere grid and the split), the fit reports the gap only when asked, and the result does not
// depend on the number of threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "fit/coverage_oracle.hpp"
#include "fit/optimal_radii.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using test::totalSov;
using test::uncoveredSurfacePoints;

TEST(OptimalRadii, ASphereTheOtherMakesUselessShrinks) {
  // The circumscribed sphere of the cube covers it alone; a second, huge sphere is useless.
  const Mesh m = test::makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const SolidIndex idx(m);
  std::vector<Sphere> sp = {{Vec3(0, 0, 0), std::sqrt(3.0) * (1 + 1e-9)}, {Vec3(0.5, 0, 0), 3.0}};
  const double start = totalSov(idx, sp);
  const detail::RadiiStats st = detail::optimalRadii(idx, {Vec3(0, 0, 0)}, 0.1, 0.1, &sp);
  ASSERT_TRUE(st.solved);
  EXPECT_TRUE(st.kept);
  EXPECT_DOUBLE_EQ(st.start, start);
  EXPECT_LE(st.lower_bound, st.objective);
  EXPECT_LE(st.objective, start);
  EXPECT_LT(sp[1].radius, 1.0);  // shrunk from 3 to about what it need hold
  EXPECT_LT(st.energy, 0.5 * start);
  EXPECT_DOUBLE_EQ(st.energy, totalSov(idx, sp));
  EXPECT_EQ(uncoveredSurfacePoints(m, sp, 200), 0);
}

FitOptions torusFit(bool radii) {
  FitOptions o;
  o.num_spheres = 12;
  o.target_points = 3000;
  o.optimal_radii = radii;
  return o;
}

TEST(OptimalRadii, TheFitReportsItsGapAndStaysCovered) {
  const Mesh m = test::makeTorus(1.0, 0.3, 48, 24);
  const SolidIndex idx(m);
  auto with = fitSpheres(idx, torusFit(true));
  auto without = fitSpheres(idx, torusFit(false));
  ASSERT_TRUE(with.ok() && without.ok());
  EXPECT_EQ(without->radii.gap, -1.0);
  const RadiiCertificate& c = with->radii;
  ASSERT_GE(c.gap, 0.0);
  EXPECT_LE(c.gap, 1.0);
  EXPECT_LE(c.lower_bound, c.objective);
  // The start is a solution of the program, so its optimum is no worse.
  EXPECT_LE(c.objective, c.start * (1 + 1e-9));
  EXPECT_GT(c.units, 0);
  // Same clustering and refinement: the program only ever keeps a set with less outside volume.
  EXPECT_LE(with->energy, without->energy * (1 + 1e-12));
  auto ev = evaluateSpheres(idx, with->spheres);
  ASSERT_TRUE(ev.ok());
  EXPECT_TRUE(ev->surface_covered);
  EXPECT_TRUE(ev->interior_covered);
  EXPECT_EQ(uncoveredSurfacePoints(m, with->spheres, 20), 0);
}

TEST(OptimalRadii, TheBestQualityRunsIt) {
  EXPECT_TRUE(fitPreset(16, FitQuality::kBest).optimal_radii);
  EXPECT_FALSE(fitPreset(16, FitQuality::kDefault).optimal_radii);
  EXPECT_FALSE(fitPreset(16, FitQuality::kFast).optimal_radii);
}

TEST(OptimalRadii, SameSpheresWhateverTheThreads) {
  const SolidIndex idx(test::robotLink());
  FitOptions o = torusFit(false);
  o.num_spheres = 10;
  auto fit = fitSpheres(idx, o);
  ASSERT_TRUE(fit.ok());
  std::vector<Sphere> one = fit->spheres, two = fit->spheres;
  for (Sphere& s : one) s.radius *= 1.05;  // room for the program to shrink
  two = one;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    detail::optimalRadii(idx, {}, 0.01, 0.01, &one);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    detail::optimalRadii(idx, {}, 0.01, 0.01, &two);
  }
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].center, two[i].center) << i;
    EXPECT_EQ(one[i].radius, two[i].radius) << i;
  }
}

}  // namespace
}  // namespace sphereset

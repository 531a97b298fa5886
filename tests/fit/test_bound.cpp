// The guaranteed bound and the evaluation's coverage certificate agree: whatever the bound
// proves covered, the certificate reports covered; what one sphere alone covers.
#include <gtest/gtest.h>

#include <cmath>

#include "fit/bound.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::coverageOnly;

// A long box and two spheres that meet exactly at the cross-section x = m (m = 100/3, on no
// dyadic grid line): pieces of the long faces that straddle it are held by neither sphere at
// any depth.
Mesh longBox() { return test::makeBox(Vec3::Zero(), Vec3(100.0, 1.0, 1.0)); }
std::vector<Sphere> spheresMeetingOffGrid() {
  const double m = 100.0 / 3.0, a = 0.5 * m, b = 0.5 * (100.0 - m);
  return {{Vec3(a, 0.5, 0.5), std::sqrt(a * a + 0.5)},
          {Vec3(m + b, 0.5, 0.5), std::sqrt(b * b + 0.5)}};
}

// The long box and its two spheres (longBox): the bound splits the straddling pieces to its
// deepest level, where one sphere grows by a sliver to hold them.
TEST(Bound, TheCertificateAcceptsWhatTheBoundProvesAtItsDeepestSplit) {
  const SolidIndex idx(longBox());
  const std::vector<Sphere> before = spheresMeetingOffGrid();
  std::vector<Sphere> spheres = before;
  EXPECT_FALSE(coverageOnly(idx, spheres).surface_covered);
  const detail::BoundStats st = detail::boundSurface(idx, &spheres, /*min_edge=*/0.0);
  EXPECT_GE(st.enlarged, 1);
  // The pieces that made a sphere grow are 100 / 2^10 long: nothing shallower holds them.
  const double growth =
      std::max(spheres[0].radius - before[0].radius, spheres[1].radius - before[1].radius);
  EXPECT_GT(growth, 0.0);
  EXPECT_LT(growth, 100.0 / 1024.0);
  const EvalResult e = coverageOnly(idx, spheres);
  EXPECT_TRUE(e.surface_covered);
  EXPECT_EQ(e.surface_uncertified_area, 0.0);
  EXPECT_EQ(e.uncovered_triangles, 0);
}

// The pieces a sphere grew for are kept only for the spheres asked (held_for), the same list as
// when every sphere's is kept; the others' lists are empty, and the radii are the same.
TEST(Bound, HeldPiecesAreKeptOnlyForTheSpheresAsked) {
  const SolidIndex idx(longBox());
  const std::vector<Sphere> before = spheresMeetingOffGrid();
  std::vector<Sphere> all_spheres = before;
  std::vector<std::vector<Vec3>> all;
  detail::SurfaceBoundOptions o;
  o.held = &all;
  detail::boundSurface(idx, &all_spheres, o);
  ASSERT_EQ(all.size(), 2u);
  const int grown = all[0].empty() ? 1 : 0;
  ASSERT_FALSE(all[grown].empty());
  std::vector<Sphere> some_spheres = before;
  std::vector<std::vector<Vec3>> some(5, std::vector<Vec3>(3, Vec3::Ones()));  // refilled
  const std::vector<bool> asked = {grown == 0, grown == 1};
  o.held = &some;
  o.held_for = &asked;
  detail::boundSurface(idx, &some_spheres, o);
  ASSERT_EQ(some.size(), 2u);
  EXPECT_EQ(some[grown], all[grown]);
  EXPECT_TRUE(some[1 - grown].empty());
  for (size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(some_spheres[i].radius, all_spheres[i].radius);
}

// boundSpheres (fit.hpp) grows a given set until the certificate confirms it: centres stay,
// radii only grow, the original triangles given are covered too; bad sets are refused.
TEST(Bound, BoundSpheresCoversFromAnySetWithoutMovingCentres) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3(2.0, 1.0, 1.0)));
  const std::vector<Sphere> before = {{Vec3(0.5, 0.5, 0.5), 0.2}, {Vec3(1.5, 0.5, 0.5), 0.0}};
  EXPECT_FALSE(coverageOnly(idx, before).surface_covered);
  auto bounded = boundSpheres(idx, before);
  ASSERT_TRUE(bounded.ok()) << bounded.error().message;
  ASSERT_EQ(bounded->size(), before.size());
  for (size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ((*bounded)[i].center, before[i].center);
    EXPECT_GE((*bounded)[i].radius, before[i].radius);
  }
  test::expectCovers(idx, *bounded);
  // Triangles beyond the solid (an original input's) are held too when given.
  const Mesh outside = test::makeBox(Vec3(2.0, 0.0, 0.0), Vec3(2.5, 1.0, 1.0));
  BoundOptions o;
  o.original = &outside;
  auto with_original = boundSpheres(idx, before, o);
  ASSERT_TRUE(with_original.ok());
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = &outside;
  EXPECT_TRUE(evaluateSpheres(idx, *with_original, eo)->original_covered);
  EXPECT_FALSE(evaluateSpheres(idx, *bounded, eo)->original_covered);
  // Refused: no spheres, a NaN, a negative radius, a depth beyond the limit.
  EXPECT_EQ(boundSpheres(idx, {}).error().code, ErrorCode::kInvalidArgument);
  EXPECT_FALSE(boundSpheres(idx, {{Vec3(NAN, 0, 0), 1.0}}).ok());
  EXPECT_FALSE(boundSpheres(idx, {{Vec3::Zero(), -1.0}}).ok());
  o.interior_max_depth = 99;
  EXPECT_FALSE(boundSpheres(idx, before, o).ok());
}

// The interior bound with the cubes' geometry kept from bound to bound (as a progressive run's
// fits and steps keep it) grows the same spheres as without, whole and within a region.
TEST(Bound, TheInteriorBoundGrowsTheSameSpheresWithKeptGeometry) {
  const SolidIndex idx(test::robotLink());
  const Aabb& b = idx.bounds();
  constexpr int kDepth = 3;  // shallower than the fit's, for the test's time
  detail::GeometryForest cells;
  for (int set = 0; set < 3; ++set) {
    std::vector<Sphere> start;
    for (int i = 0; i < 4 + 3 * set; ++i) {
      const double t = (i + 0.5) / (4 + 3 * set);
      start.push_back({b.min + t * (b.max - b.min), 0.12 * b.diagonal()});
    }
    const Aabb region{b.min, 0.5 * (b.min + b.max)};
    for (const Aabb* r : {static_cast<const Aabb*>(nullptr), &region}) {
      std::vector<Sphere> plain = start, kept = start;
      const detail::BoundStats a = detail::boundInterior(idx, &plain, kDepth, r);
      const detail::BoundStats c = detail::boundInterior(idx, &kept, kDepth, r, &cells);
      EXPECT_GT(a.enlarged, 0) << "set " << set;
      EXPECT_EQ(a.enlarged, c.enlarged);
      EXPECT_EQ(a.pieces, c.pieces);
      for (size_t i = 0; i < start.size(); ++i) EXPECT_EQ(plain[i].radius, kept[i].radius);
    }
  }
}

// What one sphere alone covers (soleCover) is the same asked for that sphere only, which skips
// the pieces that miss it, as asked for every sphere: the same points in the same order.
TEST(Bound, SoleCoverOfOneSphereIsItsListAmongAll) {
  const SolidIndex idx(test::robotLink());
  auto fit = fitSpheres(idx, fitPreset(8, FitQuality::kFast));
  ASSERT_TRUE(fit.ok()) << fit.error().message;
  // Smaller spheres, so that pieces straddle their boundaries and are split deep.
  std::vector<Sphere> spheres = fit->spheres;
  for (Sphere& s : spheres) s.radius *= 0.9;
  std::vector<Vec3> interior;
  for (const Sphere& s : spheres) interior.push_back(s.center);
  const double min_edge = 1e-3 * idx.bounds().diagonal();
  const auto all = detail::soleCover(idx, spheres, interior, min_edge);
  ASSERT_EQ(all.size(), spheres.size());
  size_t listed = 0;
  for (size_t i = 0; i < spheres.size(); ++i) {
    const auto one =
        detail::soleCover(idx, spheres, interior, min_edge, nullptr, static_cast<int>(i));
    ASSERT_EQ(one.size(), spheres.size());
    ASSERT_EQ(one[i].size(), all[i].size()) << i;
    for (size_t k = 0; k < all[i].size(); ++k) EXPECT_EQ(one[i][k], all[i][k]) << i << " " << k;
    listed += all[i].size();
  }
  EXPECT_GT(listed, 0u);
}

}  // namespace
}  // namespace sphereset

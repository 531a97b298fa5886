// The whole repair ladder with CGAL's union and wrapping, on the broken meshes of
// broken_meshes.hpp: the repair chosen, the solid's volume (closed form for the union, bounds
// for the wrap), and a fit whose spheres cover every original triangle, checked by brute
// force.
#include <gtest/gtest.h>

#include <limits>
#include <utility>

#include "broken_meshes.hpp"
#include "repair/canonical_order.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/repair_cgal.hpp"
#include "sphereset/solid_index.hpp"
#include "test_support.hpp"

namespace sphereset::test {
namespace {

Expected<RepairResult> repairAll(const Mesh& m, bool fill = true, double alpha = 0.0) {
  RepairOptions o;
  o.fill_cavities = fill;
  o.wrap_alpha = alpha;
  o.operations = cgalSolidOperations();
  return repairMesh(m, o, "mesh.off");
}

// The repaired solid is a clean solid, and a fit of n spheres covers it and the original.
void expectFitCoversOriginal(const RepairResult& r, int n = 8) {
  EXPECT_TRUE(diagnoseMesh(r.solid).isSolid());
  EXPECT_FALSE(findSelfIntersections(r.solid).any());
  const SolidIndex index(r.solid);
  FitOptions fo;
  fo.num_spheres = n;
  fo.max_iterations = 10;
  fo.original = &r.original;
  auto f = fitSpheres(index, fo);
  ASSERT_TRUE(f.ok()) << f.error().message;
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.original = &r.original;
  const EvalResult e = *evaluateSpheres(index, f->spheres, eo);
  EXPECT_TRUE(e.surface_covered);
  EXPECT_TRUE(e.interior_covered);
  EXPECT_TRUE(e.original_covered);
  expectPointsCovered(r.original, f->spheres);
}

// Every vertex of the original lies inside the repaired solid.
void expectContainsVertices(const RepairResult& r) {
  const SolidIndex index(r.solid);
  int64_t outside = 0;
  for (const Vec3& v : r.original.vertices) outside += index.classify(v) == Containment::kOutside;
  EXPECT_EQ(outside, 0);
}

TEST(RepairLadder, OverlappingCubesBecomeTheirUnion) {
  auto r = repairAll(overlappingCubes());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kUnion);
  ASSERT_EQ(r->shells.intersecting.size(), 1u);
  EXPECT_NEAR(signedVolume(r->solid), 1.71875, 1e-9);
  expectFitCoversOriginal(*r);
}

// CGAL numbers its output in an order that can depend on memory addresses; the repair
// renumbers it canonically, so the fit (which samples triangles in order) is reproducible.
TEST(RepairLadder, UnionAndWrapComeOutInCanonicalOrder) {
  for (const Mesh& m : {overlappingCubes(), bowTiePrism()}) {
    auto r = repairAll(m);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_TRUE(r->kind == RepairKind::kUnion || r->kind == RepairKind::kWrapped);
    const Mesh c = detail::canonicalOrder(r->solid);
    EXPECT_EQ(c.vertices, r->solid.vertices);
    EXPECT_EQ(c.triangles, r->solid.triangles);
  }
}

TEST(RepairLadder, FlippedFaceIsReorientedNotWrapped) {
  auto r = repairAll(boxWithFlippedFace());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kReoriented);
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);
  expectFitCoversOriginal(*r);
}

TEST(RepairLadder, NonManifoldEdgeIsWrappedTightly) {
  const Mesh m = cubesSharingAnEdge();
  ASSERT_EQ(diagnoseMesh(m).nonmanifold_edges, 1);
  auto r = repairAll(m);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kWrapped);
  // It holds both cubes, and lies within twice the offset of them (the wrap's facets are at
  // least the offset away and, where flat, about that), plus the edge's neighbourhood, which
  // a wrap with this alpha may fill up to the alpha-ball's reach.
  const double d = 2.0 * r->wrap_offset;
  EXPECT_GE(signedVolume(r->solid), 2.0);
  EXPECT_LE(signedVolume(r->solid),
            2.0 * std::pow(1.0 + 2.0 * d, 3) + 4.0 * r->wrap_alpha * r->wrap_alpha);
  // Closed with balanced edges: the input's volume (2) is defined, and the ratio reported.
  EXPECT_NEAR(r->volume_ratio, signedVolume(r->solid) / 2.0, 1e-12);
  expectContainsVertices(*r);
  expectFitCoversOriginal(*r);
}

TEST(RepairLadder, BowTiePrismIsWrappedAroundBothLobes) {
  auto r = repairAll(bowTiePrism());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kWrapped);
  EXPECT_TRUE(r->shells.intersections.any());
  ASSERT_EQ(r->shells.shells.size(), 1u);
  EXPECT_TRUE(r->shells.shells[0].self_intersecting);
  // The two lobes, 1/4 each, and at most a layer of twice the offset over the surface.
  const double area = surfaceArea(r->original);
  EXPECT_GE(signedVolume(r->solid), 0.5);
  EXPECT_LE(signedVolume(r->solid), 0.5 + 2.0 * r->wrap_offset * area * 1.5);
  expectContainsVertices(*r);
  expectFitCoversOriginal(*r);
}

TEST(RepairLadder, OpenSheetBecomesAThinSlab) {
  auto r = repairAll(openSheet());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kWrapped);
  EXPECT_GT(signedVolume(r->solid), 0.0);
  // A slab about twice the offset thick over the unit square, its rim rounded.
  const double t = 2.0 * r->wrap_offset;
  EXPECT_LE(signedVolume(r->solid), 2.0 * t * std::pow(1.0 + 2.0 * t, 2));
  expectContainsVertices(*r);
  expectFitCoversOriginal(*r);
}

TEST(RepairLadder, OpenBoxIsCappedOrWrappedAsAShellWhenCavitiesAreKept) {
  auto capped = repairAll(openBox(), true);
  ASSERT_TRUE(capped.ok()) << capped.error().message;
  EXPECT_EQ(capped->kind, RepairKind::kCapped);
  expectFitCoversOriginal(*capped);
  // A coarser alpha than the automatic one (still far below the 1 x 1 opening) keeps the
  // two-sided wrap small.
  auto shell = repairAll(openBox(), false, 0.1);
  ASSERT_TRUE(shell.ok()) << shell.error().message;
  EXPECT_EQ(shell->kind, RepairKind::kWrapped);
  // The wrap enters the open top when alpha is below its size: a thin shell, far less than
  // the box.
  EXPECT_LT(signedVolume(shell->solid), 0.2);
  expectFitCoversOriginal(*shell, 16);
}

TEST(RepairLadder, NestedAndDuplicatedNeedNoOperation) {
  auto r = repairAll(nestedCubes(false));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kUnion);
  EXPECT_EQ(r->shells_dropped, 1);
  expectFitCoversOriginal(*r);
  const Mesh dup = cubeWithDuplicatedFace();
  auto c = cleanMesh(dup.vertices, dup.triangles);
  ASSERT_TRUE(c.ok());
  auto d = repairAll(c->mesh);
  ASSERT_TRUE(d.ok()) << d.error().message;
  EXPECT_EQ(d->kind, RepairKind::kNone);
  expectFitCoversOriginal(*d);
}

TEST(RepairLadder, KeptCavityAndItsIslandSurviveTheUnion) {
  // Two overlapping outer cubes; in the part of the first the second does not reach (x < 0.5)
  // a cavity, and in the cavity an island cube.
  Mesh cavity = makeBox(Vec3::Constant(0.1), Vec3::Constant(0.4));
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);
  const Mesh island = makeBox(Vec3::Constant(0.2), Vec3::Constant(0.3));
  const Mesh m = joined(joined(overlappingCubes(), cavity), island);
  auto kept = repairAll(m, false);
  ASSERT_TRUE(kept.ok()) << kept.error().message;
  EXPECT_EQ(kept->kind, RepairKind::kUnion);
  EXPECT_EQ(kept->cavities_kept, 1);
  EXPECT_NEAR(signedVolume(kept->solid), 1.71875 - 0.027 + 0.001, 1e-9);
  auto filled = repairAll(m, true);
  ASSERT_TRUE(filled.ok()) << filled.error().message;
  EXPECT_EQ(filled->cavities_filled, 1);
  EXPECT_NEAR(signedVolume(filled->solid), 1.71875, 1e-9);
}

}  // namespace
}  // namespace sphereset::test

namespace sphereset {
namespace {

// The wrap's limits are checked before CGAL runs: these used to raise a floating-point signal
// inside GMP (alpha 1e200, offset 1e308, coordinates near 1e80) or run for minutes (offset 10 on
// a mesh of diagonal 1.4).
TEST(RepairLadder, WrapLimitsAreCheckedBeforeWrapping) {
  RepairOptions o;
  o.operations = cgalSolidOperations();
  const Mesh tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  struct Case {
    double alpha, offset, scale;
    ErrorCode code;
    const char* words;
  };
  const Case cases[] = {
      {1e6, 0.0, 1.0, ErrorCode::kInvalidArgument, "wrap_alpha 1e+06 is more than 100 times"},
      {0.0, 1e6, 1.0, ErrorCode::kInvalidArgument, "wrap_offset 1e+06 is more than 100 times"},
      {0.0, 10.0, 1.0, ErrorCode::kInvalidArgument, "would make about"},
      {0.0, 0.0, 1e80, ErrorCode::kInvalidData, "coordinates up to 1e+80 cannot be wrapped"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.words);
    Mesh m = tri;
    for (Vec3& v : m.vertices) v *= c.scale;
    o.wrap_alpha = c.alpha;
    o.wrap_offset = c.offset;
    test::expectError(repairMesh(m, o, "tri.off"), c.code, "tri.off: ", c.words);
  }
  // Beyond the option table's limits (repairOptionTable), whatever the mesh: refused as options.
  const std::pair<double, const char*> beyond[] = {
      {1e200, "wrap_alpha '1e+200': expected a number from 0 to 1e+30"},
      {std::numeric_limits<double>::quiet_NaN(),
       "wrap_alpha 'nan': expected a number from 0 to 1e+30"},
      {-1.0, "wrap_alpha '-1': expected a number from 0 to 1e+30"}};
  for (const auto& [alpha, message] : beyond) {
    o.wrap_alpha = alpha;
    o.wrap_offset = 0.0;
    const auto r = repairMesh(tri, o, "tri.off");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
    EXPECT_EQ(r.error().message, message);
  }
  // Within the limits the wrap runs.
  o.wrap_alpha = 0.0;
  o.wrap_offset = 0.0;
  EXPECT_TRUE(repairMesh(tri, o, "tri.off").ok());
}

}  // namespace
}  // namespace sphereset

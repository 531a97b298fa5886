// The repair ladder without the union and the wrapping (the MIT core alone): clean, welded,
// capped and nested meshes become solids exactly; meshes that need more are refused with a
// message that says why and what would help.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <utility>

#include "broken_meshes.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/solid_index.hpp"
#include "test_support.hpp"

namespace sphereset::test {
namespace {

Expected<RepairResult> repairCore(const Mesh& m, bool fill = true) {
  RepairOptions o;
  o.fill_cavities = fill;
  return repairMesh(m, o, "mesh.off");
}

TEST(Repair, CleanBoxIsUsedAsItIs) {
  auto r = repairCore(makeBox(Vec3::Zero(), Vec3::Ones()));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kNone);
  EXPECT_TRUE(r->notes.empty());
  EXPECT_EQ(r->solid.triangles.size(), 12u);
  EXPECT_NEAR(r->volume_ratio, 1.0, 1e-12);
}

TEST(Repair, DuplicatedFaceIsDroppedByTheLoader) {
  const Mesh m = cubeWithDuplicatedFace();
  auto c = cleanMesh(m.vertices, m.triangles);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->report.duplicate_dropped, 1);
  auto r = repairCore(c->mesh);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kNone);
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);
}

TEST(Repair, NestedShellWithTheSameOrientationIsDropped) {
  auto r = repairCore(nestedCubes(false));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kUnion);  // the union of the shells, without computing one
  EXPECT_EQ(r->shells_dropped, 1);
  EXPECT_EQ(r->solid.triangles.size(), 12u);
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);
  ASSERT_EQ(r->shells.shells.size(), 2u);
  EXPECT_TRUE(r->shells.intersecting.empty());
}

TEST(Repair, InwardNestedShellIsACavityFilledOrKept) {
  auto filled = repairCore(nestedCubes(true), true);
  ASSERT_TRUE(filled.ok()) << filled.error().message;
  EXPECT_EQ(filled->kind, RepairKind::kUnion);
  EXPECT_EQ(filled->cavities_filled, 1);
  EXPECT_NEAR(signedVolume(filled->solid), 1.0, 1e-12);
  auto kept = repairCore(nestedCubes(true), false);
  ASSERT_TRUE(kept.ok()) << kept.error().message;
  EXPECT_EQ(kept->kind, RepairKind::kNone);
  EXPECT_EQ(kept->cavities_kept, 1);
  EXPECT_EQ(kept->solid.triangles.size(), 24u);
  EXPECT_NEAR(signedVolume(kept->solid), 1.0 - 0.125, 1e-12);
  EXPECT_NEAR(kept->volume_ratio, 1.0, 1e-12);
}

TEST(Repair, InsideOutShellIsTurnedOutward) {
  Mesh m = makeBox(Vec3::Zero(), Vec3::Ones());
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  auto r = repairCore(m);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);
}

TEST(Repair, NearlyCoincidentCornersAreWeldedAutomatically) {
  // Each triangle stores its own corners, a few 1e-9 apart (as a float STL export would).
  const Mesh box = makeBox(Vec3::Zero(), Vec3::Ones());
  Mesh m;
  int k = 0;
  for (const Triangle& t : box.triangles) {
    Triangle nt;
    for (int c = 0; c < 3; ++c) {
      nt[c] = static_cast<int32_t>(m.vertices.size());
      m.vertices.push_back(box.vertices[t[c]] + Vec3::Constant(1e-9 * (k++ % 3)));
    }
    m.triangles.push_back(nt);
  }
  auto c = cleanMesh(m.vertices, m.triangles);
  ASSERT_TRUE(c.ok());
  EXPECT_FALSE(diagnoseMesh(c->mesh).closed);
  auto r = repairCore(c->mesh);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kWelded);
  EXPECT_GT(r->weld_tolerance, 0.0);
  EXPECT_LE(r->weld_tolerance, kAutoWeldRel * std::sqrt(3.0) * (1 + 1e-9));
  ASSERT_FALSE(r->notes.empty());
  EXPECT_NE(r->notes[0].find("welded"), std::string::npos);
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-7);
  // Corners 2e-6 of the diagonal apart do not close within the automatic limit (1e-6).
  Mesh far = m;
  const double step = 2e-6 * std::sqrt(3.0);
  for (size_t i = 0; i < far.vertices.size(); ++i)
    far.vertices[i] = box.vertices[box.triangles[i / 3][i % 3]] + Vec3::Constant(step * (i % 3));
  auto fc = cleanMesh(far.vertices, far.triangles);
  ASSERT_TRUE(fc.ok());
  auto fr = repairCore(fc->mesh);
  EXPECT_FALSE(fr.ok() && fr->kind == RepairKind::kWelded);
  if (fr.ok()) {
    EXPECT_EQ(fr->weld_tolerance, 0.0);
  }
  // With the repair off the tolerance is not tried.
  RepairOptions off;
  off.enabled = false;
  expectError(repairMesh(c->mesh, off, "mesh.off"), ErrorCode::kNotSolid, "mesh.off",
              "boundary edges");
}

TEST(Repair, FlippedFaceIsReorientedExactly) {
  const Mesh m = boxWithFlippedFace();
  EXPECT_GT(diagnoseMesh(m).misoriented_edges, 0);
  auto r = repairCore(m);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kReoriented);
  EXPECT_EQ(r->triangles_flipped, 1);
  EXPECT_TRUE(diagnoseMesh(r->solid).isSolid());
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);
}

TEST(Repair, ReorientationKeepsEveryTriangleAndFixesAShuffledSphere) {
  // Every other triangle of an icosphere flipped; the whole then inside out.
  Mesh m = makeIcosphere(1.0, 3);
  for (size_t t = 0; t < m.triangles.size(); t += 2)
    std::swap(m.triangles[t][1], m.triangles[t][2]);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  auto r = repairCore(m);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kReoriented);
  EXPECT_EQ(r->solid.triangles.size(), m.triangles.size());
  EXPECT_NEAR(signedVolume(r->solid), signedVolume(makeIcosphere(1.0, 3)), 1e-12);
}

TEST(Repair, OpenBoxIsCappedExactly) {
  auto r = repairCore(openBox());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kCapped);
  EXPECT_EQ(r->holes_capped, 1);
  EXPECT_TRUE(diagnoseMesh(r->solid).isSolid());
  EXPECT_NEAR(signedVolume(r->solid), 1.0, 1e-12);  // the fan lies in the missing face
  EXPECT_TRUE(std::isnan(r->volume_ratio));         // an open input has no volume
  EXPECT_EQ(r->original.triangles.size(), 10u);
}

TEST(Repair, FitOnACappedBoxCoversTheOriginalTriangles) {
  auto r = repairCore(openBox());
  ASSERT_TRUE(r.ok()) << r.error().message;
  const SolidIndex index(r->solid);
  FitOptions fo;
  fo.num_spheres = 6;
  fo.max_iterations = 10;
  fo.original = &r->original;
  auto f = fitSpheres(index, fo);
  ASSERT_TRUE(f.ok()) << f.error().message;
  expectCovers(index, f->spheres);
  expectPointsCovered(r->original, f->spheres);
}

TEST(Repair, ReorientationKeepsTheMajorityOrientationOfACavity) {
  // An inward nested cube (a cavity) with one face flipped: it stays a cavity.
  Mesh m = nestedCubes(true);
  std::swap(m.triangles[14][1], m.triangles[14][2]);
  auto r = repairCore(m, false);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->triangles_flipped, 1);
  EXPECT_EQ(r->cavities_kept, 1);
  EXPECT_NEAR(signedVolume(r->solid), 0.875, 1e-12);
}

// The fit on repaired solids (no union or wrap needed) covers solid and original.
void expectFitCovers(const RepairResult& r) {
  const SolidIndex index(r.solid);
  FitOptions fo;
  fo.num_spheres = 6;
  fo.max_iterations = 10;
  fo.original = &r.original;
  auto f = fitSpheres(index, fo);
  ASSERT_TRUE(f.ok()) << f.error().message;
  expectCovers(index, f->spheres);
  expectPointsCovered(r.original, f->spheres);
}

TEST(Repair, FitsOnExactRepairsCoverTheOriginal) {
  for (const Mesh& m : {boxWithFlippedFace(), nestedCubes(false), nestedCubes(true)}) {
    auto r = repairCore(m);
    ASSERT_TRUE(r.ok()) << r.error().message;
    expectFitCovers(*r);
  }
  // The duplicated face, as loaded (the copy dropped), and as given.
  const Mesh dup = cubeWithDuplicatedFace();
  auto c = cleanMesh(dup.vertices, dup.triangles);
  ASSERT_TRUE(c.ok());
  auto r = repairCore(c->mesh);
  ASSERT_TRUE(r.ok()) << r.error().message;
  expectFitCovers(*r);
  expectPointsCovered(dup, [&] {
    const SolidIndex index(r->solid);
    FitOptions fo;
    fo.num_spheres = 4;
    fo.max_iterations = 5;
    fo.original = &r->original;
    return fitSpheres(index, fo)->spheres;
  }());
}

TEST(Repair, SameResultForAnyThreadCount) {
  auto run = [](int threads) {
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, threads);
    const Mesh m =
        joined(openBox(), transformed(openBox(), Eigen::Matrix3d::Identity(), Vec3(3, 0, 0), 1.0));
    auto r = repairCore(m);
    EXPECT_TRUE(r.ok());
    const SolidIndex index(r->solid);
    FitOptions fo;
    fo.num_spheres = 8;
    fo.max_iterations = 10;
    fo.original = &r->original;
    return std::make_pair(r->solid.triangles, fitSpheres(index, fo)->spheres);
  };
  const auto [t1, s1] = run(1);
  const auto [t2, s2] = run(2);
  EXPECT_EQ(t1, t2);
  ASSERT_EQ(s1.size(), s2.size());
  for (size_t i = 0; i < s1.size(); ++i) {
    EXPECT_EQ(s1[i].center, s2[i].center);
    EXPECT_EQ(s1[i].radius, s2[i].radius);
  }
}

TEST(Repair, WhatNeedsTheUnionOrTheWrapIsRefusedWithoutThem) {
  expectError(repairCore(overlappingCubes()), ErrorCode::kNotSolid, "mesh.off",
              "1 pair of shells intersects; rebuild with SPHERESET_WITH_REPAIR=ON");
  expectError(repairCore(cubesSharingAnEdge()), ErrorCode::kNotSolid, "mesh.off",
              "1 non-manifold edge");
  expectError(repairCore(bowTiePrism()), ErrorCode::kNotSolid, "mesh.off",
              "intersecting triangle pair");
  expectError(repairCore(openSheet()), ErrorCode::kNotSolid, "mesh.off", "wrap it");
}

TEST(Repair, OffRefusesAnythingButASolid) {
  RepairOptions off;
  off.enabled = false;
  expectError(repairMesh(openBox(), off, "box.obj"), ErrorCode::kNotSolid, "box.obj",
              "4 boundary edges");
  auto ok = repairMesh(makeBox(Vec3::Zero(), Vec3::Ones()), off, "box.obj");
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->kind, RepairKind::kNone);
}

TEST(Repair, BadWrapParametersAreRefused) {
  RepairOptions o;
  o.wrap_alpha = std::nan("");
  auto r = repairMesh(openSheet(), o, "s.off");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
  EXPECT_EQ(r.error().message, "wrap_alpha 'nan': expected a number from 0 to 1e+30");
  // A weld tolerance that is not a number used to weld exactly, silently.
  o.wrap_alpha = 0.0;
  o.weld_tolerance = std::nan("");
  r = repairMesh(openSheet(), o, "s.off");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "weld_tolerance 'nan': expected a number from 0 to 1e+30");
}

}  // namespace
}  // namespace sphereset::test

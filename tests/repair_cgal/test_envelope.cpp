// The envelope (RepairOptions::fill_openings, envelope.cpp) on shapes with closed forms: a cup (a
// box open at the top), a tube open at both ends and a closed casing with a window are filled,
// their hollows inside; a tray wide open on top keeps its opening; the walls' volume is the
// closed form; the original triangles lie inside the envelope; a fit of the envelope covers
// them; E_r against the walls is reported.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/repair_cgal.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

Mesh boxes(const std::vector<std::pair<Vec3, Vec3>>& parts) {
  Mesh m;
  for (const auto& [lo, hi] : parts) m = test::joined(m, test::makeBox(lo, hi));
  return m;
}

// A 1 × 1 × 1 box open at the top, walls and floor `t` thick: five overlapping slabs, united by
// the repair.
Mesh cup(double t) {
  return boxes({{{0, 0, 0}, {1, 1, t}},
                {{0, 0, 0}, {t, 1, 1}},
                {{1 - t, 0, 0}, {1, 1, 1}},
                {{0, 0, 0}, {1, t, 1}},
                {{0, 1 - t, 0}, {1, 1, 1}}});
}

// The cup closed by a lid with a square window of side `w` in its middle.
Mesh casingWithWindow(double t, double w) {
  Mesh m = cup(t);
  const double a = (1 - w) / 2, b = (1 + w) / 2;
  return test::joined(m, boxes({{{0, 0, 1 - t}, {a, 1, 1}},
                                {{b, 0, 1 - t}, {1, 1, 1}},
                                {{0, 0, 1 - t}, {1, a, 1}},
                                {{0, b, 1 - t}, {1, 1, 1}}}));
}

// A tube along z, `n` sides, outer and inner circumradius R and r, from z = 0 to `length`: one
// closed shell (outer wall, inner wall facing the axis, two rings).
Mesh tube(double R, double r, double length, int n) {
  Mesh m;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    const Vec3 u(std::cos(a), std::sin(a), 0);
    m.vertices.push_back(R * u);                       // 4k: outer bottom
    m.vertices.push_back(R * u + Vec3(0, 0, length));  // 4k + 1: outer top
    m.vertices.push_back(r * u);                       // 4k + 2: inner bottom
    m.vertices.push_back(r * u + Vec3(0, 0, length));  // 4k + 3: inner top
  }
  for (int k = 0; k < n; ++k) {
    const int i = 4 * k, j = 4 * ((k + 1) % n);
    auto quad = [&](int p, int q, int s, int v) {
      m.triangles.push_back({p, q, s});
      m.triangles.push_back({p, s, v});
    };
    quad(i, j, j + 1, i + 1);          // outer wall, facing out
    quad(i + 2, i + 3, j + 3, j + 2);  // inner wall, facing the axis
    quad(i + 1, j + 1, j + 3, i + 3);  // top ring, facing +z
    quad(i, i + 2, j + 2, j);          // bottom ring, facing -z
  }
  return m;
}

RepairOptions envelopeOptions(double size) {
  RepairOptions o;
  o.operations = cgalSolidOperations();
  o.fill_openings = size;
  return o;
}

bool inside(const Mesh& solid, const Vec3& p) {
  return SolidIndex(solid).classify(p) == Containment::kInside;
}

// The envelope's checks shared by every shape: a clean solid holding the walls (every vertex of
// the input strictly inside), `hollow` inside it and not inside the walls, and a volume between
// the filled shape's (less a sliver at the openings) and the filled shape grown by the offset.
void expectFilled(const RepairResult& r, const Vec3& hollow, double filled_volume,
                  double walls_volume) {
  EXPECT_GT(r.fill_openings, 0.0);
  const MeshDiagnosis d = diagnoseMesh(r.solid);
  EXPECT_TRUE(d.isSolid());
  EXPECT_NEAR(signedVolume(r.walls), walls_volume, 1e-9 + 1e-3 * walls_volume);
  const SolidIndex envelope(r.solid);
  for (const Vec3& v : r.original.vertices)
    EXPECT_EQ(envelope.classify(v), Containment::kInside) << v.transpose();
  EXPECT_EQ(envelope.classify(hollow), Containment::kInside);
  EXPECT_FALSE(inside(r.walls, hollow));
  EXPECT_GT(d.volume, 0.97 * filled_volume);
  EXPECT_LT(d.volume, 1.06 * filled_volume);
  ASSERT_NE(originalTriangles(r), nullptr);
  EXPECT_EQ(envelopeWalls(r), &r.walls);
}

TEST(Envelope, CupIsFilledToItsRim) {
  const double t = 0.1;
  auto r = repairMesh(cup(t), envelopeOptions(kAutomatic), "cup");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->kind, RepairKind::kUnion);
  EXPECT_DOUBLE_EQ(r->fill_openings, 1.0);  // the bounding box's smallest extent
  expectFilled(*r, Vec3(0.5, 0.5, 0.5), 1.0, 1.0 - (1 - 2 * t) * (1 - 2 * t) * (1 - t));
}

TEST(Envelope, TubeIsFilledAlongItsLength) {
  const int n = 48;
  const double R = 0.5, r = 0.4, length = 2.0;
  const double polygon = n / 2.0 * std::sin(2 * std::numbers::pi / n);  // area / circumradius²
  auto res = repairMesh(tube(R, r, length, n), envelopeOptions(kAutomatic), "tube");
  ASSERT_TRUE(res.ok()) << res.error().message;
  EXPECT_EQ(res->kind, RepairKind::kNone);  // the walls were a clean solid already
  expectFilled(*res, Vec3(0, 0, 1), polygon * R * R * length, polygon * (R * R - r * r) * length);
  // Openings of the tube (0.8 wide) stay open for a smaller size.
  auto open = repairMesh(tube(R, r, length, n), envelopeOptions(0.4), "tube");
  ASSERT_TRUE(open.ok()) << open.error().message;
  EXPECT_FALSE(inside(open->solid, Vec3(0, 0, 1)));
}

TEST(Envelope, CasingWithAWindowIsFilled) {
  const double t = 0.1;
  auto r = repairMesh(casingWithWindow(t, 0.4), envelopeOptions(kAutomatic), "casing");
  ASSERT_TRUE(r.ok()) << r.error().message;
  const double inner = (1 - 2 * t) * (1 - 2 * t) * (1 - 2 * t);
  expectFilled(*r, Vec3(0.5, 0.5, 0.5), 1.0, 1.0 - inner - 0.4 * 0.4 * t);
}

TEST(Envelope, WideOpeningStaysOpenAndSmallSizeKeepsTheCup) {
  // A tray 0.3 deep: the automatic size is its depth, its 0.9-wide top stays open, and with no
  // hollow enclosed the walls stay the solid.
  auto tray = repairMesh(boxes({{{0, 0, 0}, {1, 1, 0.05}},
                                {{0, 0, 0}, {0.05, 1, 0.3}},
                                {{0.95, 0, 0}, {1, 1, 0.3}},
                                {{0, 0, 0}, {1, 0.05, 0.3}},
                                {{0, 0.95, 0}, {1, 1, 0.3}}}),
                         envelopeOptions(kAutomatic), "tray");
  ASSERT_TRUE(tray.ok()) << tray.error().message;
  EXPECT_EQ(tray->fill_openings, 0.0);
  EXPECT_FALSE(inside(tray->solid, Vec3(0.5, 0.5, 0.2)));
  auto tray_given = repairMesh(tray->original, envelopeOptions(0.3), "tray");
  ASSERT_TRUE(tray_given.ok()) << tray_given.error().message;
  EXPECT_EQ(tray_given->fill_openings, 0.3);
  EXPECT_FALSE(inside(tray_given->solid, Vec3(0.5, 0.5, 0.2)));
  // The cup's 0.8-wide opening stays open for a size of 0.3.
  auto cup_open = repairMesh(cup(0.1), envelopeOptions(0.3), "cup");
  ASSERT_TRUE(cup_open.ok()) << cup_open.error().message;
  EXPECT_FALSE(inside(cup_open->solid, Vec3(0.5, 0.5, 0.5)));
}

TEST(Envelope, AutomaticSizeKeepsTheWallsWhenThereIsNoHollow) {
  // An L-shaped solid: its envelope only rounds the inner corner (about 1.1 times its volume),
  // so the automatic size keeps the walls; a size given is applied.
  const Mesh ell = boxes({{{0, 0, 0}, {2, 1, 1}}, {{0, 0, 0}, {1, 2, 1}}});
  auto walls = repairMesh(ell, envelopeOptions(kAutomatic), "ell");
  ASSERT_TRUE(walls.ok()) << walls.error().message;
  EXPECT_EQ(walls->fill_openings, 0.0);
  EXPECT_TRUE(walls->walls.triangles.empty());
  EXPECT_NEAR(signedVolume(walls->solid), 3.0, 1e-9);
  EXPECT_EQ(envelopeWalls(*walls), nullptr);
  ASSERT_FALSE(walls->notes.empty());
  EXPECT_NE(walls->notes.back().find("no hollow behind openings narrower than 1"),
            std::string::npos)
      << walls->notes.back();
  auto given = repairMesh(ell, envelopeOptions(1.0), "ell");
  ASSERT_TRUE(given.ok()) << given.error().message;
  EXPECT_EQ(given->fill_openings, 1.0);
  EXPECT_GT(signedVolume(given->solid), 3.0);
  EXPECT_LT(signedVolume(given->solid), 1.5 * 3.0);
}

TEST(Envelope, FitOfTheEnvelopeCoversTheOriginalAndReportsEAgainstTheWalls) {
  auto r = repairMesh(cup(0.1), envelopeOptions(kAutomatic), "cup");
  ASSERT_TRUE(r.ok()) << r.error().message;
  const SolidIndex index(r->solid);
  FitOptions fo = fitPreset(8, FitQuality::kFast);
  fo.original = originalTriangles(*r);
  auto fit = fitSpheres(index, fo);
  ASSERT_TRUE(fit.ok()) << fit.error().message;
  auto ev = evaluateSpheres(index, fit->spheres,
                            fitCheckEvalOptions(1, originalTriangles(*r), envelopeWalls(*r)));
  ASSERT_TRUE(ev.ok()) << ev.error().message;
  EXPECT_TRUE(ev->surface_covered && ev->interior_covered && ev->original_covered);
  EXPECT_NEAR(ev->walls_volume, signedVolume(r->walls), 1e-12);
  // More outside the walls than outside the envelope, over a smaller volume.
  EXPECT_GT(ev->er_walls, ev->er_sum);
  // Without walls, the figures against the solid.
  auto plain = evaluateSpheres(index, fit->spheres, fitCheckEvalOptions(1));
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain->er_walls, plain->er_sum);
}

TEST(Envelope, RefusedWithoutTheWrappingOrForATinySize) {
  RepairOptions o = envelopeOptions(kAutomatic);
  o.operations = {};
  auto none = repairMesh(test::makeBox(Vec3::Zero(), Vec3::Ones()), o, "box");
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().code, ErrorCode::kNotSolid);
  EXPECT_NE(none.error().message.find("box: fill_openings needs the wrapping"), std::string::npos);
  auto tiny = repairMesh(cup(0.1), envelopeOptions(1e-6), "cup");
  ASSERT_FALSE(tiny.ok());
  EXPECT_EQ(tiny.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(tiny.error().message.find("cup: fill_openings 1e-06 is too small"), std::string::npos)
      << tiny.error().message;
}

}  // namespace
}  // namespace sphereset

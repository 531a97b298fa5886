// The incremental coverage certificate against the full evaluation: after every edit of random
// sequences (moves, growth, shrinking, additions, removals; gaps opened and closed), its
// summary equals evaluateSpheres' certificate fields exactly, and its uncovered triangles those
// of a certificate made afresh for the same set.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "sphereset/certificate.hpp"
#include "sphereset/cover.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/limits.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

// Spheres on a grid of cubes of side (largest extent / g) over the solid's bounds, each the
// ball about its cube grown by a tenth: together they cover the whole box, so the solid, with
// room for the pieces of the surface certificate where cubes meet, and not so much that a
// sphere can go without a gap opening where its centre is in the solid.
std::vector<Sphere> coveringGrid(const Aabb& b, int g) {
  const double side = (b.max - b.min).maxCoeff() / g;
  const double r = 0.5 * std::sqrt(3.0) * side * 1.1;
  int count[3];
  for (int a = 0; a < 3; ++a)
    count[a] = std::max(1, static_cast<int>(std::ceil((b.max[a] - b.min[a]) / side - 1e-9)));
  std::vector<Sphere> out;
  for (int z = 0; z < count[2]; ++z)
    for (int y = 0; y < count[1]; ++y)
      for (int x = 0; x < count[0]; ++x)
        out.push_back({b.min + side * Vec3(x + 0.5, y + 0.5, z + 0.5), r});
  return out;
}

EvalOptions certificateOnly(const CertificateOptions& co) {
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  eo.surface_max_depth = co.surface_max_depth;
  eo.interior_max_depth = co.interior_max_depth;
  eo.original = co.original;
  return eo;
}

// The summary equals the full evaluation's fields and a fresh certificate's triangle lists.
void expectSameAsFull(const SolidIndex& idx, const CoverageCertificate& cert,
                      const CertificateOptions& co, const std::string& step) {
  SCOPED_TRACE(step);
  const CertificateSummary& s = cert.summary();
  const auto full = evaluateSpheres(idx, cert.spheres(), certificateOnly(co));
  ASSERT_TRUE(full.ok()) << full.error().message;
  const EvalResult& e = *full;
  EXPECT_EQ(s.spheres, static_cast<int64_t>(cert.spheres().size()));
  EXPECT_EQ(s.volume, e.mesh_volume);
  EXPECT_EQ(s.bbox_diagonal, e.bbox_diagonal);
  EXPECT_EQ(s.er_sum, e.er_sum);
  EXPECT_EQ(s.outside_volume, e.outside_volume);
  EXPECT_EQ(s.surface_covered, e.surface_covered);
  EXPECT_EQ(s.max_surface_gap, e.max_surface_gap);
  EXPECT_EQ(s.surface_uncertified_area, e.surface_uncertified_area);
  EXPECT_EQ(static_cast<int64_t>(s.uncovered_triangles.size()), e.uncovered_triangles);
  EXPECT_EQ(s.original_covered, e.original_covered);
  EXPECT_EQ(s.max_original_gap, e.max_original_gap);
  EXPECT_EQ(static_cast<int64_t>(s.original_uncovered_triangles.size()),
            e.original_uncovered_triangles);
  EXPECT_EQ(s.interior_covered, e.interior_covered);
  EXPECT_EQ(s.max_interior_gap, e.max_interior_gap);
  EXPECT_EQ(s.interior_uncertified_cells, e.interior_uncertified_cells);
  EXPECT_EQ(s.covered, e.surface_covered && e.original_covered && e.interior_covered);
  EXPECT_EQ(s.max_gap, std::max({e.max_surface_gap, e.max_original_gap, e.max_interior_gap}));
  const auto fresh = makeCoverageCertificate(idx, cert.spheres(), co);
  ASSERT_TRUE(fresh.ok()) << fresh.error().message;
  EXPECT_EQ(s.uncovered_triangles, fresh->summary().uncovered_triangles);
  EXPECT_EQ(s.original_uncovered_triangles, fresh->summary().original_uncovered_triangles);
  EXPECT_EQ(s.cells, fresh->summary().cells);
}

// Random edits: each one applied to the certificate and to a plain copy of the set, then
// checked; every tenth starts again from `start`. Returns how many edits left the set covered,
// and not.
struct Seen {
  int covered = 0, uncovered = 0;
};
Seen randomEdits(const SolidIndex& idx, const std::vector<Sphere>& start,
                 const CertificateOptions& co, int edits, uint64_t seed) {
  Seen seen;
  auto made = makeCoverageCertificate(idx, start, co);
  EXPECT_TRUE(made.ok());
  if (!made.ok()) return seen;
  CoverageCertificate cert = std::move(*made);
  std::vector<Sphere> model = start;
  expectSameAsFull(idx, cert, co, "start");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Aabb& b = idx.bounds();
  const double diag = b.diagonal();
  for (int e = 0; e < edits; ++e) {
    if (e % 10 == 9) {  // the start again now and then: edits from a covering set
      EXPECT_TRUE(cert.setSpheres(start).ok());
      model = start;
    }
    const int n = static_cast<int>(model.size());
    const int i = static_cast<int>(u(rng) * n) % n;
    const int kind = static_cast<int>(u(rng) * 8);
    std::string what;
    Sphere s = model[i];
    if (kind == 0) {  // move
      s.center += 0.3 * s.radius * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      what = "move";
    } else if (kind == 1) {  // grow
      s.radius *= 1.0 + 0.5 * u(rng);
      what = "grow";
    } else if (kind == 2) {  // shrink: opens gaps
      s.radius *= 0.1 + 0.8 * u(rng);
      what = "shrink";
    } else if (kind == 7) {  // jump anywhere: a gap where it was, and far gaps' nearest sphere
      s.center = b.min + (b.max - b.min).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
      what = "jump";
    } else if (kind == 3) {  // back to the start's sphere: closes gaps
      s = start[i % start.size()];
      what = "restore";
    } else if (kind == 4 && n > 1) {
      EXPECT_TRUE(cert.removeSphere(i).ok()) << "remove";
      model.erase(model.begin() + i);
      what = "remove";
    } else {  // add: a start sphere back (closing) or a random one, at times of radius 0
      const bool copy = u(rng) < 0.5;
      const Sphere add =
          copy ? start[static_cast<size_t>(u(rng) * start.size()) % start.size()]
               : Sphere{b.min + (b.max - b.min).cwiseProduct(Vec3(u(rng), u(rng), u(rng))),
                        u(rng) < 0.2 ? 0.0 : 0.3 * diag * u(rng)};
      EXPECT_TRUE(cert.addSphere(add).ok()) << "add";
      model.push_back(add);
      what = "add";
    }
    if (what != "remove" && what != "add") {
      EXPECT_TRUE(cert.setSphere(i, s).ok()) << what;
      model[i] = s;
    }
    EXPECT_EQ(cert.spheres().size(), model.size());
    for (size_t k = 0; k < model.size() && k < cert.spheres().size(); ++k) {
      EXPECT_EQ(cert.spheres()[k].center, model[k].center);
      EXPECT_EQ(cert.spheres()[k].radius, model[k].radius);
    }
    expectSameAsFull(idx, cert, co,
                     "edit " + std::to_string(e) + " " + what + " of " + std::to_string(i));
    (cert.summary().covered ? seen.covered : seen.uncovered) += 1;
  }
  return seen;
}

CertificateOptions shallow() {
  CertificateOptions co;
  co.surface_max_depth = 6;
  co.interior_max_depth = 3;
  return co;
}

TEST(IncrementalCertificate, BoxEqualsFullEvaluationAfterEveryEdit) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3(1.0, 0.7, 0.5)));
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 2), shallow(), 40, 11);
  // The sequence went through covered and uncovered sets.
  EXPECT_GT(seen.covered, 0);
  EXPECT_GT(seen.uncovered, 0);
}

TEST(IncrementalCertificate, IcosphereEqualsFullEvaluationAtDefaultDepths) {
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 3), CertificateOptions{}, 25, 5);
  EXPECT_GT(seen.covered, 0);
  EXPECT_GT(seen.uncovered, 0);
}

TEST(IncrementalCertificate, TorusEqualsFullEvaluationAfterEveryEdit) {
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 24, 12));
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 4), shallow(), 40, 3);
  EXPECT_GT(seen.covered, 0);
  EXPECT_GT(seen.uncovered, 0);
}

TEST(IncrementalCertificate, RobotLinkEqualsFullEvaluationAfterEveryEdit) {
  const Mesh link = test::robotLink();
  ASSERT_FALSE(link.triangles.empty());
  const SolidIndex idx(link);
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 3), shallow(), 30, 7);
  EXPECT_GT(seen.covered + seen.uncovered, 0);
}

TEST(IncrementalCertificate, FarFromTheOriginEqualsFullEvaluation) {
  // Coordinates in the ten thousands and a small solid: the rounding margins of the proximity
  // tests scale with the coordinates, and the verdicts stay the full evaluation's.
  const Mesh far = test::transformed(test::makeTorus(1.0, 0.35, 24, 12),
                                     Eigen::Matrix3d::Identity(), Vec3(1.2e4, -3.1e3, 5.0e3), 0.5);
  const SolidIndex idx(far);
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 4), shallow(), 30, 29);
  EXPECT_GT(seen.covered, 0);
  EXPECT_GT(seen.uncovered, 0);
}

TEST(IncrementalCertificate, OriginalTrianglesEqualFullEvaluation) {
  // The solid a repair would have made, and "original" triangles that differ from it: a finer
  // sphere slightly larger than the solid, so that covering the solid does not cover them.
  const SolidIndex idx(test::makeIcosphere(1.0, 2));
  const Mesh original = test::makeIcosphere(1.08, 3);
  CertificateOptions co = shallow();
  co.original = &original;
  const Seen seen = randomEdits(idx, coveringGrid(idx.bounds(), 3), co, 40, 19);
  EXPECT_GT(seen.covered + seen.uncovered, 0);
  // A set that covers the solid but not the original: the original's verdict is its own.
  auto cert = makeCoverageCertificate(idx, {{Vec3::Zero(), 1.0 + 1e-9}}, co);
  ASSERT_TRUE(cert.ok());
  EXPECT_TRUE(cert->summary().surface_covered);
  EXPECT_FALSE(cert->summary().original_covered);
  EXPECT_EQ(cert->summary().original_uncovered_triangles.size(), original.triangles.size());
  EXPECT_EQ(cert->summary().original_triangles, static_cast<int64_t>(original.triangles.size()));
  expectSameAsFull(idx, *cert, co, "solid only");
}

TEST(IncrementalCertificate, SameSummaryOnOneThread) {
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 24, 12));
  std::vector<Sphere> set = coveringGrid(idx.bounds(), 3);
  auto run = [&] {
    auto cert = makeCoverageCertificate(idx, set, shallow());
    EXPECT_TRUE(cert.ok());
    // Spheres with their centres in the solid shrunk to points, the first removed: gaps.
    for (size_t i = 0; i < set.size(); ++i) {
      if (idx.classify(set[i].center) == Containment::kInside) {
        EXPECT_TRUE(cert->setSphere(static_cast<int>(i), {set[i].center, 0.0}).ok());
      }
    }
    EXPECT_TRUE(cert->removeSphere(0).ok());
    return cert->summary();
  };
  const CertificateSummary many = run();
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const CertificateSummary single = run();
  EXPECT_FALSE(many.covered);
  EXPECT_EQ(many.max_surface_gap, single.max_surface_gap);
  EXPECT_EQ(many.max_interior_gap, single.max_interior_gap);
  EXPECT_EQ(many.uncovered_triangles, single.uncovered_triangles);
  EXPECT_EQ(many.interior_uncertified_cells, single.interior_uncertified_cells);
  EXPECT_EQ(many.cells_rechecked, single.cells_rechecked);
  EXPECT_EQ(many.triangles_rechecked, single.triangles_rechecked);
}

TEST(IncrementalCertificate, SmallEditRechecksLittle) {
  const SolidIndex idx(test::makeIcosphere(1.0, 4));  // 5120 triangles
  const std::vector<Sphere> set = coveringGrid(idx.bounds(), 5);
  auto cert = makeCoverageCertificate(idx, set, CertificateOptions{});
  ASSERT_TRUE(cert.ok());
  const CertificateSummary& first = cert->summary();
  EXPECT_EQ(first.triangles_rechecked, first.triangles);  // the full certificate
  EXPECT_TRUE(first.covered);
  // One sphere of the grid, moved by a hundredth of its radius.
  Sphere s = set[31];
  s.center += Vec3(0.01, -0.005, 0.0) * s.radius;
  ASSERT_TRUE(cert->setSphere(31, s).ok());
  const CertificateSummary& after = cert->summary();
  EXPECT_GT(after.triangles_rechecked, 0);
  EXPECT_LT(after.triangles_rechecked * 8, after.triangles);
  EXPECT_GT(after.cells_rechecked, 0);
  EXPECT_LT(after.cells_rechecked * 8, after.cells);
  EXPECT_GE(after.seconds, 0.0);
  expectSameAsFull(idx, *cert, CertificateOptions{}, "small move");
}

// Several spheres changed at once (updateSpheres: moved, grown, shrunk, added at the end, dropped
// from the end), each batch certified once: the summary equals the full evaluation's after every
// batch, a small batch judges only part of the triangles, and a batch changing more than
// kFullUpdateShare of the set is certified in full.
TEST(IncrementalCertificate, BatchedEditsEqualFullEvaluation) {
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 24, 12));
  const std::vector<Sphere> start = coveringGrid(idx.bounds(), 4);
  const CertificateOptions co = shallow();
  auto made = makeCoverageCertificate(idx, start, co);
  ASSERT_TRUE(made.ok());
  CoverageCertificate cert = std::move(*made);
  std::vector<Sphere> model = start;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Aabb& b = idx.bounds();
  int partial = 0, covered = 0;
  for (int e = 0; e < 30; ++e) {
    if (e % 10 == 9) model = start;  // back to the covering set: most spheres change
    const int edits = 1 + static_cast<int>(u(rng) * 4);
    for (int k = 0; k < edits; ++k) {
      const size_t i = static_cast<size_t>(u(rng) * model.size()) % model.size();
      const double kind = u(rng);
      if (kind < 0.3) {
        model[i].center += 0.3 * model[i].radius * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      } else if (kind < 0.4) {
        model[i].radius *= 1.0 + 0.5 * u(rng);
      } else if (kind < 0.6) {  // shrink: opens gaps
        model[i].radius *= 0.05 + 0.5 * u(rng);
      } else if (kind < 0.7) {  // back to the start's sphere: closes gaps
        model[i] = start[i % start.size()];
      } else if (kind < 0.85 || model.size() < 3) {
        model.push_back({b.min + (b.max - b.min).cwiseProduct(Vec3(u(rng), u(rng), u(rng))),
                         0.2 * b.diagonal() * u(rng)});
      } else {
        model.pop_back();
      }
    }
    ASSERT_TRUE(cert.updateSpheres(model).ok());
    ASSERT_EQ(cert.spheres().size(), model.size());
    for (size_t k = 0; k < model.size(); ++k) {
      EXPECT_EQ(cert.spheres()[k].center, model[k].center);
      EXPECT_EQ(cert.spheres()[k].radius, model[k].radius);
    }
    expectSameAsFull(idx, cert, co, "batch " + std::to_string(e));
    const CertificateSummary& sm = cert.summary();
    partial += sm.triangles_rechecked < sm.triangles;
    covered += sm.covered;
  }
  EXPECT_GT(partial, 10);  // most batches are certified near their changes only
  EXPECT_GT(covered, 0);
  EXPECT_LT(covered, 30);
  // Every sphere moved: certified in full. The same set again: nothing judged.
  for (Sphere& sp : model) sp.center += Vec3(1e-3, 0.0, 0.0);
  ASSERT_TRUE(cert.updateSpheres(model).ok());
  EXPECT_EQ(cert.summary().triangles_rechecked, cert.summary().triangles);
  expectSameAsFull(idx, cert, co, "all moved");
  ASSERT_TRUE(cert.updateSpheres(model).ok());
  EXPECT_EQ(cert.summary().triangles_rechecked, 0);
  EXPECT_EQ(cert.summary().cells_rechecked, 0);
  // Refused as setSpheres refuses, the set left as it was.
  EXPECT_FALSE(cert.updateSpheres({}).ok());
  EXPECT_FALSE(cert.updateSpheres({{Vec3(NAN, 0.0, 0.0), 1.0}}).ok());
  EXPECT_EQ(cert.spheres().size(), model.size());
}

// The surface certificate's rule written plainly, every test over every sphere (the spheres
// already grown): a triangle held by one sphere is certified, else its vertices' and centroid's
// distance to the union gives a gap, and it is split in four (to half the depth once refuted).
void plainCover(const std::vector<Sphere>& sp, const Vec3& a, const Vec3& b, const Vec3& c,
                int depth, int max_depth, double* gap, double* area) {
  for (const Sphere& s : sp)
    if (s.contains(a) && s.contains(b) && s.contains(c)) return;
  double g = 0.0;
  for (const Vec3& p : {a, b, c, Vec3((a + b + c) / 3.0)}) {
    double best = std::numeric_limits<double>::infinity();
    for (const Sphere& s : sp) best = std::min(best, (p - s.center).norm() - s.radius);
    g = std::max(g, best);
  }
  *gap = std::max(*gap, g);
  if (g > 0.0 && depth >= max_depth / 2) return;
  if (depth >= max_depth) {
    *area += 0.5 * (b - a).cross(c - a).norm();
    return;
  }
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  plainCover(sp, a, ab, ca, depth + 1, max_depth, gap, area);
  plainCover(sp, ab, b, bc, depth + 1, max_depth, gap, area);
  plainCover(sp, ca, bc, c, depth + 1, max_depth, gap, area);
  plainCover(sp, ab, bc, ca, depth + 1, max_depth, gap, area);
}

TEST(IncrementalCertificate, SurfaceCertificateIsThePlainRule) {
  // The certificate's shortcuts (the sphere grid, the spheres near each triangle, each point's
  // distance computed once) change nothing: the same gaps, areas and triangles as the plain rule.
  const Mesh mesh = test::makeTorus(1.0, 0.35, 20, 10);
  const SolidIndex idx(mesh);
  const double diag = idx.bounds().diagonal();
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int uncovered_sets = 0;
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<Sphere> set = coveringGrid(idx.bounds(), 4);
    for (Sphere& s : set) s.radius *= 0.7 + 0.4 * u(rng);
    CertificateOptions co = shallow();
    auto cert = makeCoverageCertificate(idx, set, co);
    ASSERT_TRUE(cert.ok());
    std::vector<Sphere> grown = set;
    for (Sphere& s : grown) s.radius += kCoverageToleranceRel * diag;
    double max_gap = 0.0, area = 0.0;
    std::vector<int64_t> uncovered;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      double gap = 0.0, a = 0.0;
      const auto& tri = mesh.triangles[t];
      plainCover(grown, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]], 0,
                 co.surface_max_depth, &gap, &a);
      max_gap = std::max(max_gap, gap);
      area += a;
      if (gap > 0.0 || a > 0.0) uncovered.push_back(static_cast<int64_t>(t));
    }
    EXPECT_EQ(cert->summary().max_surface_gap, max_gap / diag);
    EXPECT_EQ(cert->summary().surface_uncertified_area, area);
    EXPECT_EQ(cert->summary().uncovered_triangles, uncovered);
    uncovered_sets += uncovered.empty() ? 0 : 1;
  }
  EXPECT_GT(uncovered_sets, 0);
}

TEST(IncrementalCertificate, RefusesBadInputsAndChangesNothing) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto expectRefusal = [](const Status& st, const std::string& words) {
    ASSERT_FALSE(st.ok()) << words;
    EXPECT_EQ(st.error().code, ErrorCode::kInvalidArgument);
    EXPECT_NE(st.error().message.find(words), std::string::npos) << st.error().message;
    EXPECT_EQ(st.error().message.find('\n'), std::string::npos);
  };
  auto made = [](const Expected<CoverageCertificate>& r) -> Status {
    return r.ok() ? Status{} : Status{r.error()};
  };
  expectRefusal(made(makeCoverageCertificate(idx, {})), "no spheres to evaluate");
  expectRefusal(made(makeCoverageCertificate(idx, {{Vec3::Zero(), 1.0}, {Vec3(nan, 0, 0), 1.0}})),
                "sphere 1: NaN or infinite value");
  expectRefusal(made(makeCoverageCertificate(idx, {{Vec3::Zero(), -1.0}})),
                "sphere 0: negative radius");
  expectRefusal(made(makeCoverageCertificate(
                    idx, std::vector<Sphere>(limits::kMaxSpheres + 1, {Vec3::Zero(), 1.0}))),
                "spheres must be from 1 to 1000000");
  CertificateOptions deep;
  deep.surface_max_depth = limits::kMaxSurfaceDepth + 1;
  expectRefusal(made(makeCoverageCertificate(idx, {{Vec3::Zero(), 1.0}}, deep)),
                "surface_max_depth");
  deep = {};
  deep.interior_max_depth = -1;
  expectRefusal(made(makeCoverageCertificate(idx, {{Vec3::Zero(), 1.0}}, deep)),
                "interior_max_depth");

  auto cert =
      makeCoverageCertificate(idx, {{Vec3::Constant(0.5), 0.5}, {Vec3::Constant(0.5), 1.0}});
  ASSERT_TRUE(cert.ok());
  const CertificateSummary before = cert->summary();
  EXPECT_TRUE(before.covered);
  expectRefusal(cert->setSphere(2, {Vec3::Zero(), 1.0}),
                "sphere index 2 is out of range (the set has 2 spheres)");
  expectRefusal(cert->setSphere(-1, {Vec3::Zero(), 1.0}), "sphere index -1 is out of range");
  expectRefusal(cert->setSphere(0, {Vec3::Zero(), inf}), "sphere 0: NaN or infinite value");
  expectRefusal(cert->setSphere(1, {Vec3(0, inf, 0), 1.0}), "sphere 1: NaN or infinite value");
  expectRefusal(cert->setSphere(1, {Vec3::Zero(), nan}), "sphere 1: NaN or infinite value");
  expectRefusal(cert->addSphere({Vec3::Zero(), -0.5}), "sphere 2: negative radius");
  expectRefusal(cert->removeSphere(5), "sphere index 5 is out of range");
  expectRefusal(cert->setSpheres({}), "no spheres to evaluate");
  expectRefusal(cert->setSpheres({{Vec3::Zero(), 1.0}, {Vec3::Zero(), nan}}),
                "sphere 1: NaN or infinite value");
  ASSERT_TRUE(cert->removeSphere(0).ok());
  expectRefusal(cert->removeSphere(0), "cannot remove sphere 0: no spheres to evaluate");
  // The refusals changed nothing: one sphere left, the larger one, still covering.
  ASSERT_EQ(cert->spheres().size(), 1u);
  EXPECT_EQ(cert->spheres()[0].radius, 1.0);
  EXPECT_TRUE(cert->summary().covered);
  EXPECT_EQ(cert->summary().outside_volume, std::vector<double>{before.outside_volume[1]});
}

TEST(IncrementalCertificate, CancelledEditLeavesTheSetAsBefore) {
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 24, 12));
  const std::vector<Sphere> set = coveringGrid(idx.bounds(), 3);
  const int mid = static_cast<int>(set.size() / 2);
  int polls = 0;
  bool cancel = false;
  CertificateOptions co = shallow();
  co.poll_interval = 0.0;
  co.poll = [&] {
    ++polls;
    if (cancel) throw std::runtime_error("cancelled");
  };
  auto cert = makeCoverageCertificate(idx, set, co);
  ASSERT_TRUE(cert.ok());
  EXPECT_GT(polls, 0);
  const CertificateSummary before = cert->summary();
  cancel = true;
  EXPECT_THROW((void)cert->setSphere(mid, {set[mid].center, 0.1}), std::runtime_error);
  EXPECT_THROW((void)cert->removeSphere(2), std::runtime_error);
  // A new set of another size, cancelled: the old set stays, one outside volume per sphere.
  std::vector<Sphere> more = set;
  more.push_back({set[0].center, 0.05});
  more.push_back({set[1].center, 0.05});
  EXPECT_THROW((void)cert->setSpheres(more), std::runtime_error);
  cancel = false;
  ASSERT_EQ(cert->spheres().size(), set.size());
  EXPECT_EQ(cert->spheres()[mid].radius, set[mid].radius);
  EXPECT_EQ(cert->summary().max_gap, before.max_gap);
  // The next edit certifies the set in full and agrees with the evaluation.
  ASSERT_TRUE(cert->setSphere(mid, {set[mid].center, 0.1}).ok());
  EXPECT_EQ(cert->summary().triangles_rechecked, cert->summary().triangles);
  // A batch of a few changes (certified near them, not in full), cancelled: the set and its
  // outside volumes as before, and the next batch certified in full.
  const std::vector<Sphere> kept = cert->spheres();
  const std::vector<double> kept_outside = cert->summary().outside_volume;
  std::vector<Sphere> batch = kept;
  batch[0].radius *= 0.5;
  batch.pop_back();
  batch.push_back({set[2].center, 0.05});
  cancel = true;
  EXPECT_THROW((void)cert->updateSpheres(batch), std::runtime_error);
  cancel = false;
  ASSERT_EQ(cert->spheres().size(), kept.size());
  for (size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(cert->spheres()[i].radius, kept[i].radius);
  EXPECT_EQ(cert->summary().outside_volume, kept_outside);
  ASSERT_TRUE(cert->updateSpheres(batch).ok());
  EXPECT_EQ(cert->summary().triangles_rechecked, cert->summary().triangles);
  co.poll = nullptr;
  expectSameAsFull(idx, *cert, co, "after a cancelled batch");
  // Uncancelled, the same kind of batch is certified near its changes only.
  batch[1].radius *= 0.5;
  ASSERT_TRUE(cert->updateSpheres(batch).ok());
  EXPECT_LT(cert->summary().triangles_rechecked, cert->summary().triangles);
  expectSameAsFull(idx, *cert, co, "a batch");
}

}  // namespace
}  // namespace sphereset

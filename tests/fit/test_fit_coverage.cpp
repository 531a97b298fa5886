// The fit's coverage checked independently of the machinery that built it: random points on
// every triangle and in the interior, each tested against every sphere by brute force. The
// bound and the evaluation share the sphere grid and the octree walk; this test shares
// neither (interior membership comes from the O(n) winding number, not the hierarchy).
#include <gtest/gtest.h>

#include <random>

#include "index/oracles.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/load.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

bool inSomeSphere(const std::vector<Sphere>& spheres, const Vec3& p, double tol) {
  for (const Sphere& s : spheres)
    if ((p - s.center).norm() <= s.radius + tol) return true;
  return false;
}

struct Counts {
  int64_t surface = 0, interior = 0, missed = 0;
};

// Every vertex and `per_triangle` uniform points on each triangle; `interior` uniform points
// of the bounding box kept when their winding number says they are inside.
Counts bruteForceCoverage(const SolidIndex& idx, const std::vector<Sphere>& spheres,
                          int per_triangle, int interior, uint64_t seed) {
  const Mesh& m = idx.mesh();
  const double tol = kCoverageToleranceRel * idx.bounds().diagonal();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Counts c;
  auto check = [&](const Vec3& p, int64_t* count) {
    ++*count;
    if (!inSomeSphere(spheres, p, tol)) {
      ++c.missed;
      ADD_FAILURE() << "uncovered point " << p.transpose();
    }
  };
  for (const Vec3& v : m.vertices) check(v, &c.surface);
  for (const Triangle& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &cc = m.vertices[t[2]];
    for (int k = 0; k < per_triangle; ++k) {
      double s = u(rng), w = u(rng);
      if (s + w > 1.0) s = 1.0 - s, w = 1.0 - w;
      check(a + s * (b - a) + w * (cc - a), &c.surface);
    }
  }
  const Aabb& box = idx.bounds();
  for (int k = 0; k < interior; ++k) {
    const Vec3 p = box.min + (box.max - box.min).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    if (windingNumber(idx, p) > 0.5) check(p, &c.interior);
  }
  return c;
}

void expectFitCovers(const Mesh& mesh, FitOptions o, int min_interior) {
  const SolidIndex idx(mesh);
  auto r = fitSpheres(idx, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->spheres.size(), static_cast<size_t>(o.num_spheres));
  const Counts c = bruteForceCoverage(idx, r->spheres, 40, 4000, o.seed + 17);
  EXPECT_EQ(c.missed, 0);
  EXPECT_GE(c.surface, 40 * static_cast<int64_t>(mesh.triangles.size()));
  EXPECT_GE(c.interior, min_interior);  // the interior was really sampled
}

TEST(FitCoverage, RobotLinkSurfaceAndInteriorByBruteForce) {
  FitOptions o;
  o.num_spheres = 8;
  o.target_points = 2000;
  expectFitCovers(test::robotLink(), o, 200);
}

TEST(FitCoverage, TorusWithDecimationByBruteForce) {
  FitOptions o;
  o.num_spheres = 12;
  o.target_points = 3000;
  o.decimation = 0.5;
  expectFitCovers(test::makeTorus(1.0, 0.35, 48, 24), o, 200);
}

// Long, flat triangles: the bound has to split them deeply.
TEST(FitCoverage, LongBoxByBruteForce) {
  FitOptions o;
  o.num_spheres = 6;
  o.target_points = 2000;
  expectFitCovers(test::makeBox(Vec3::Zero(), Vec3(20.0, 1.0, 0.5)), o, 50);
}

// The best preset's selection among its restarts' spheres (select.cpp), then its end passes.
TEST(FitCoverage, SelectionAmongRestartsByBruteForce) {
  FitOptions o = fitPreset(8, FitQuality::kBest);
  o.target_points = 2000;
  o.restarts = 3;
  expectFitCovers(test::robotLink(), o, 200);
  FitOptions t = fitPreset(10, FitQuality::kBest);
  t.target_points = 2000;
  t.restarts = 2;
  expectFitCovers(test::makeTorus(1.0, 0.35, 48, 24), t, 200);
}

TEST(FitCoverage, BaselinesByBruteForce) {
  for (FitMethod method : {FitMethod::kKMeans, FitMethod::kOctree}) {
    FitOptions o;
    o.num_spheres = 10;
    o.target_points = 2000;
    o.method = method;
    expectFitCovers(test::robotLink(), o, 200);
  }
}

TEST(FitCoverage, ExampleMeshByBruteForce) {
  auto m = loadMesh(test::examplePath("spot.obj"));
  ASSERT_TRUE(m.ok()) << m.error().message;
  FitOptions o;
  o.num_spheres = 16;
  o.seed = 3;
  expectFitCovers(m->mesh, o, 200);
}

}  // namespace
}  // namespace sphereset

// The certified protrusion (sphereProtrusion): closed forms on a cube (a ball half outside, a
// ball around it), a ball over a cavity whose farthest point is its centre and not its sphere,
// and a brute-force oracle on a non-convex link: dense points in every ball, their distance to
// the solid by every triangle and the winding number, never beyond the bound, with the witness
// at the distance the bound was certified from. Thread counts give the same answer. Asked for
// the union's figure only, the balls that cannot set it stay loose, their bounds still valid.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"

namespace sphereset {
namespace {

using test::joined, test::makeBox, test::makeTorus, test::robotLink;

// The closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Distance from p to the solid (0 inside): every triangle, and the winding number by solid
// angles (Van Oosterom and Strackee).
double bruteDistance(const Mesh& m, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity(), winding = 0.0;
  for (const Triangle& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    best = std::min(best, (p - closestOnTriangle(p, a, b, c)).norm());
    const Vec3 x = a - p, y = b - p, z = c - p;
    const double lx = x.norm(), ly = y.norm(), lz = z.norm();
    winding += 2.0 * std::atan2(x.dot(y.cross(z)),
                                lx * ly * lz + x.dot(y) * lz + y.dot(z) * lx + z.dot(x) * ly);
  }
  return std::fabs(winding / (4.0 * std::numbers::pi)) > 0.5 ? 0.0 : best;
}

ProtrusionResult run(const Mesh& mesh, const std::vector<Sphere>& spheres, double tol) {
  const SolidIndex index(mesh);
  ProtrusionOptions o;
  o.tolerance = tol;
  o.max_cells = 2000000;  // these tolerances are 10 times the default's, relative to the size
  auto r = sphereProtrusion(index, spheres, o);
  EXPECT_TRUE(r.ok());
  return r.ok() ? *r : ProtrusionResult{};
}

constexpr double kProtrusionTol = 1e-4;

TEST(Protrusion, ClosedFormsOnACube) {
  const Mesh cube = makeBox(Vec3::Zero(), Vec3::Ones());
  // A ball whose centre is 0.5 outside a face: its far point is 0.5 + r out.
  ProtrusionResult r = run(cube, {{Vec3(1.5, 0.5, 0.5), 0.8}}, kProtrusionTol);
  EXPECT_LE(r.lower, 1.3 + 1e-12);
  EXPECT_GE(r.upper, 1.3 - 1e-12);
  EXPECT_LE(r.upper - r.lower, kProtrusionTol);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(bruteDistance(cube, r.witness), r.lower, 1e-12);
  // A ball of radius 1 about the centre: farthest out along an axis, 1 - 0.5.
  r = run(cube, {{Vec3(0.5, 0.5, 0.5), 1.0}}, kProtrusionTol);
  EXPECT_LE(r.lower, 0.5 + 1e-12);
  EXPECT_GE(r.upper, 0.5 - 1e-12);
  EXPECT_LE(r.upper - r.lower, kProtrusionTol);
  // With the default cap of cells, the bound is looser but still holds.
  {
    ProtrusionOptions o;
    o.tolerance = kProtrusionTol;
    auto capped = sphereProtrusion(SolidIndex(cube), {{Vec3(0.5, 0.5, 0.5), 1.0}}, o);
    ASSERT_TRUE(capped.ok());
    EXPECT_GE(capped->upper, 0.5 - 1e-12);
    EXPECT_LE(capped->lower, 0.5 + 1e-12);
    EXPECT_FALSE(capped->converged);
    EXPECT_LE(capped->cells, 8 + o.max_cells);
  }
  // A ball inside: nothing out.
  r = run(cube, {{Vec3(0.5, 0.5, 0.5), 0.3}}, kProtrusionTol);
  EXPECT_EQ(r.lower, 0.0);
  EXPECT_LE(r.upper, kProtrusionTol);
}

TEST(Protrusion, ABallOverACavityProtrudesMostAtItsCentre) {
  // A cube [0, 3]³ with a cavity [1, 2]³ (inner walls facing in): the ball of radius 0.9 about
  // the cavity's centre has its sphere in the walls, and its centre 0.5 from them.
  Mesh inner = makeBox(Vec3::Ones(), Vec3::Constant(2.0));
  for (Triangle& t : inner.triangles) std::swap(t[1], t[2]);
  const Mesh hollow = joined(makeBox(Vec3::Zero(), Vec3::Constant(3.0)), inner);
  const ProtrusionResult r = run(hollow, {{Vec3::Constant(1.5), 0.9}}, kProtrusionTol);
  EXPECT_LE(r.lower, 0.5 + 1e-12);
  EXPECT_GE(r.upper, 0.5 - 1e-12);
  EXPECT_LE(r.upper - r.lower, kProtrusionTol);
  EXPECT_LT((r.witness - Vec3::Constant(1.5)).norm(), 2 * kProtrusionTol);
}

TEST(Protrusion, NeverBeyondTheBoundOnDenseSamplesOfAFittedSet) {
  const Mesh link = robotLink();
  const SolidIndex index(link);
  auto fit = fitSpheres(index, fitPreset(8, FitQuality::kFast));
  ASSERT_TRUE(fit.ok());
  const double tol = 1e-3 * index.bounds().diagonal();
  ProtrusionOptions po;
  po.tolerance = tol;
  auto r = sphereProtrusion(index, fit->spheres, po);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->converged);
  EXPECT_LE(r->upper - r->lower, tol);
  EXPECT_NEAR(bruteDistance(link, r->witness), r->lower, 1e-9);
  EXPECT_LE((r->witness - fit->spheres[r->sphere].center).norm(),
            fit->spheres[r->sphere].radius + 1e-12);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double sampled = 0.0;
  for (size_t i = 0; i < fit->spheres.size(); ++i) {
    const Sphere& s = fit->spheres[i];
    double own = 0.0;
    for (int k = 0; k < 1500; ++k) {
      const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
      const double rho =
          s.radius * (k % 3 == 0 ? 1.0 : std::cbrt(u(rng)));  // a third on the sphere
      own = std::max(own, bruteDistance(link, s.center + rho * dir));
    }
    EXPECT_LE(own, r->spheres[i].upper + 1e-12) << "sphere " << i;
    sampled = std::max(sampled, own);
  }
  EXPECT_LE(sampled, r->upper + 1e-12);
  EXPECT_GE(r->lower, sampled - tol);  // the search found at least what the samples did, less tol
}

TEST(Protrusion, OnlyTheUnionsFigureLeavesTheBallsThatCannotSetItLoose) {
  // union_only: every ball's bound still holds (at least what the full search found in it), the
  // union's is within the tolerance of its witness and of the full search's, and the balls that
  // cannot set it are searched less.
  const Mesh link = robotLink();
  const SolidIndex index(link);
  auto fit = fitSpheres(index, fitPreset(8, FitQuality::kFast));
  ASSERT_TRUE(fit.ok());
  ProtrusionOptions po;
  po.tolerance = 1e-3 * index.bounds().diagonal();
  auto full = sphereProtrusion(index, fit->spheres, po);
  ProtrusionOptions uo = po;
  uo.union_only = true;
  auto some = sphereProtrusion(index, fit->spheres, uo);
  ASSERT_TRUE(full.ok() && some.ok());
  ASSERT_TRUE(full->converged);
  EXPECT_TRUE(some->converged);
  EXPECT_LT(some->cells, full->cells);
  bool loose = false;  // some ball was left with more than the tolerance between its bounds
  for (const SphereProtrusionBound& b : some->spheres)
    loose = loose || b.upper > b.lower + po.tolerance;
  EXPECT_TRUE(loose);
  EXPECT_GE(some->upper, full->lower);
  EXPECT_LE(some->upper, some->lower + po.tolerance);
  EXPECT_LE(some->lower, full->upper);
  EXPECT_NEAR(bruteDistance(link, some->witness), some->lower, 1e-9);
  for (size_t i = 0; i < fit->spheres.size(); ++i) {
    EXPECT_GE(some->spheres[i].upper, full->spheres[i].lower) << "sphere " << i;
    EXPECT_LE(some->spheres[i].upper,
              std::max(some->spheres[i].lower + po.tolerance, some->lower) + 1e-12)
        << "sphere " << i;
  }
  // A figure known from elsewhere (here the full search's witness) settles every ball below it.
  uo.known = full->lower;
  auto known = sphereProtrusion(index, fit->spheres, uo);
  ASSERT_TRUE(known.ok());
  EXPECT_TRUE(known->converged);
  for (const SphereProtrusionBound& b : known->spheres)
    EXPECT_LE(b.upper, std::max(b.lower + po.tolerance, full->lower) + 1e-12);
  EXPECT_GE(known->upper, full->lower);
  EXPECT_LE(known->cells, some->cells);
}

TEST(Protrusion, SameAnswerOnAnyThreadCount) {
  const Mesh torus = makeTorus(1.0, 0.3, 32, 16);
  const std::vector<Sphere> spheres = {{Vec3(1, 0, 0), 0.5},
                                       {Vec3(0, 1, 0.2), 0.45},
                                       {Vec3(-0.8, -0.6, 0), 0.6},
                                       {Vec3::Zero(), 0.4}};
  ProtrusionResult one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = run(torus, spheres, kProtrusionTol);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = run(torus, spheres, kProtrusionTol);
  }
  EXPECT_EQ(one.upper, two.upper);
  EXPECT_EQ(one.lower, two.lower);
  EXPECT_EQ(one.witness, two.witness);
  // The ball in the hole protrudes most at its poles (sqrt(1 + 0.4²) - 0.3 from the true
  // torus, a little less from its polyhedron), not at its centre (0.7).
  const double pole = bruteDistance(torus, Vec3(0, 0, 0.4));
  EXPECT_GT(pole, 0.75);
  EXPECT_GE(one.spheres[3].upper, pole);
  EXPECT_GE(one.spheres[3].lower, pole - kProtrusionTol);
  EXPECT_NEAR(bruteDistance(torus, one.spheres[3].witness), one.spheres[3].lower, 1e-12);
}

TEST(Protrusion, BadOptionsAndSpheresAreRefused) {
  const SolidIndex index(makeBox(Vec3::Zero(), Vec3::Ones()));
  ProtrusionOptions o;
  EXPECT_EQ(sphereProtrusion(index, {{Vec3::Zero(), 1.0}}, o).error().code,
            ErrorCode::kInvalidArgument);  // tolerance 0
  o.tolerance = 1e-3;
  EXPECT_FALSE(sphereProtrusion(index, {{Vec3(NAN, 0, 0), 1.0}}, o).ok());
  EXPECT_FALSE(sphereProtrusion(index, {{Vec3::Zero(), -1.0}}, o).ok());
  o.known = -1.0;
  EXPECT_FALSE(sphereProtrusion(index, {{Vec3::Zero(), 1.0}}, o).ok());
  o.known = NAN;
  EXPECT_FALSE(sphereProtrusion(index, {{Vec3::Zero(), 1.0}}, o).ok());
  o.known = 0.0;
  o.max_cells = 0;
  EXPECT_FALSE(sphereProtrusion(index, {{Vec3::Zero(), 1.0}}, o).ok());
}

}  // namespace
}  // namespace sphereset

// Exact sphere outside volume: closed forms, Monte Carlo on real meshes, derivatives,
// invariances and the hierarchy against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "index/oracles.hpp"
#include "sphereset/load.hpp"
#include "sphereset/solid_index.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::kPi;
double ballVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

Mesh loadOrDie(const std::string& path) {
  auto m = loadMesh(path);
  EXPECT_TRUE(m.ok()) << (m.ok() ? "" : m.error().message);
  return m.ok() ? m->mesh : Mesh{};
}

TEST(OutsideVolume, SphereInsideCubeIsZero) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const OutsideVolume ov = idx.outsideVolume({Vec3::Constant(0.5), 0.5});
  EXPECT_NEAR(ov.volume, 0.0, 1e-14);
  EXPECT_EQ(ov.center, Containment::kInside);
  EXPECT_NEAR(idx.outsideVolume({Vec3(0.3, 0.4, 0.6), 0.25}).volume, 0.0, 1e-14);
}

TEST(OutsideVolume, CircumscribedSphereOfCube) {
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const double r = std::sqrt(3.0) / 2.0;
  const OutsideVolume ov = idx.outsideVolume({Vec3::Constant(0.5), r});
  EXPECT_NEAR(ov.volume, ballVolume(r) - 1.0, 1e-12);
}

TEST(OutsideVolume, SphereCentredOnAFaceOfALargeBoxIsHalfOutside) {
  const SolidIndex idx(test::makeBox(Vec3(-50, -50, -100), Vec3(50, 50, 0)));
  for (double r : {0.1, 1.0, 7.5}) {
    const OutsideVolume ov = idx.outsideVolume({Vec3(0.3, -0.2, 0.0), r});
    EXPECT_EQ(ov.center, Containment::kBoundary);
    EXPECT_NEAR(ov.volume, 0.5 * ballVolume(r), 1e-9 * ballVolume(r)) << r;
    EXPECT_NEAR(ov.d_radius, 2 * kPi * r * r, 1e-8 * r * r) << r;
  }
  // Centred on an edge of the box: three quarters outside; on a corner: seven eighths.
  EXPECT_NEAR(idx.outsideVolume({Vec3(50, 0, 0), 2.0}).volume, 0.75 * ballVolume(2.0),
              1e-9 * ballVolume(2.0));
  EXPECT_NEAR(idx.outsideVolume({Vec3(50, 50, 0), 2.0}).volume, 0.875 * ballVolume(2.0),
              1e-9 * ballVolume(2.0));
}

TEST(OutsideVolume, CapsAboveAndBelowAFace) {
  // Large box z <= 0; sphere centre at height d: the outside part is the ball minus (or plus)
  // a cap of height k = r - |d|, V_cap = π k² (r - k/3).
  const SolidIndex idx(test::makeBox(Vec3(-50, -50, -100), Vec3(50, 50, 0)));
  const double r = 1.5;
  for (double d : {-1.2, -0.5, -1e-9, 1e-9, 0.3, 1.4}) {
    const double k = r - std::abs(d);
    const double cap = kPi * k * k * (r - k / 3);
    const double expect = d > 0 ? ballVolume(r) - cap : cap;
    EXPECT_NEAR(idx.outsideVolume({Vec3(1, 2, d), r}).volume, expect, 1e-9) << d;
  }
  // Tangent from outside and inside.
  EXPECT_NEAR(idx.outsideVolume({Vec3(0, 0, r), r}).volume, ballVolume(r), 1e-12);
  EXPECT_NEAR(idx.outsideVolume({Vec3(0, 0, -r), r}).volume, 0.0, 1e-12);
}

TEST(OutsideVolume, SpheresFarLargerAndSmallerThanTheMesh) {
  const Mesh cube = test::makeBox(Vec3::Zero(), Vec3::Ones());
  const SolidIndex idx(cube);
  for (const Vec3& c : {Vec3(0.5, 0.5, 0.5), Vec3(0.1, 0.9, 0.2), Vec3(3, 0, 0)}) {
    const double R = 1e3;
    const OutsideVolume big = idx.outsideVolume({c, R});
    EXPECT_NEAR(big.volume / ballVolume(R), (ballVolume(R) - 1.0) / ballVolume(R), 1e-12);
    // Winding consistency: the sphere's whole surface is outside, Ω_out = 4π.
    EXPECT_NEAR(big.d_radius / (R * R), 4 * kPi, 1e-9);
  }
  // Tiny spheres inside, outside and centred on a face.
  const double r = 1e-7;
  EXPECT_NEAR(idx.outsideVolume({Vec3(0.5, 0.5, 0.5), r}).volume, 0.0, 1e-30);
  EXPECT_NEAR(idx.outsideVolume({Vec3(0.5, 0.5, 2.0), r}).volume, ballVolume(r), 1e-30);
  EXPECT_NEAR(idx.outsideVolume({Vec3(0.5, 0.5, 1.0), r}).volume / ballVolume(r), 0.5, 1e-6);
}

TEST(OutsideVolume, SixCapsOfABallAboutTheUnitCube) {
  // Centre 0.5, radius 0.55: six caps of height k = 0.05 stick out, one through each face,
  // and no two overlap (the edges are 0.707 from the centre).
  const SolidIndex idx(test::makeBox(Vec3::Zero(), Vec3::Ones()));
  const double r = 0.55, k = 0.05;
  const OutsideVolume ov = idx.outsideVolume({Vec3::Constant(0.5), r});
  EXPECT_NEAR(ov.volume, 6.0 * kPi * k * k * (r - k / 3.0), 1e-12);
  // dSOV/dr: the six caps' curved areas, 2 pi r k each.
  EXPECT_NEAR(ov.d_radius, 6.0 * 2.0 * kPi * r * k, 1e-12);
  EXPECT_LE(ov.gradient.norm(), 1e-12);  // symmetric
}

TEST(OutsideVolume, WindingConsistencyOnTorus) {
  // Σ sign(h) Ω over the triangles is 4π·[inside] when the sphere contains the mesh, so
  // dSOV/dr = 4π r² from any centre; and the generalised winding number is 0 or 1.
  const SolidIndex idx(test::makeTorus(1.0, 0.35, 48, 24));
  for (const Vec3& c : {Vec3(1.0, 0, 0), Vec3(0, 0, 0), Vec3(0.2, 1.0, 0.1), Vec3(2, 2, 2)}) {
    const OutsideVolume ov = idx.outsideVolume({c, 10.0});
    EXPECT_NEAR(ov.d_radius, 4 * kPi * 100.0, 1e-8);
    // The whole torus is inside the ball: the outside volume is the ball less the solid, a
    // value away from the clamps to [0, ball volume].
    EXPECT_NEAR(ov.volume, ballVolume(10.0) - signedVolume(idx.mesh()), 1e-10 * ballVolume(10.0));
    const double w = windingNumber(idx, c);
    EXPECT_NEAR(w, idx.classify(c) == Containment::kInside ? 1.0 : 0.0, 1e-9);
  }
}

struct McCase {
  std::string name;
  Mesh mesh;
};

std::vector<McCase> monteCarloMeshes() {
  return {{"torus", test::makeTorus(1.0, 0.35, 40, 20)},
          {"spot", loadOrDie(test::examplePath("spot.obj"))},
          {"fr3_link1", loadOrDie(test::dataPath("fr3_link1_collision.stl"))}};
}

TEST(OutsideVolume, MatchesSeededMonteCarloOnRealMeshes) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int inside_centres = 0, outside_centres = 0;
  for (const McCase& mc : monteCarloMeshes()) {
    const SolidIndex idx(mc.mesh);
    const Aabb box = idx.bounds();
    const double diag = box.diagonal();
    std::vector<Sphere> spheres;
    // Centres inside (surface samples pushed inwards are not needed: rejection on classify).
    while (spheres.size() < 10) {
      const Vec3 c =
          box.center() + 0.5 * (box.max - box.min).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      const Containment where = idx.classify(c);
      const bool want_inside = spheres.size() % 2 == 0;
      if ((where == Containment::kInside) != want_inside) continue;
      const double r = diag * (0.02 + 0.3 * (spheres.size() / 10.0));
      spheres.push_back({c, r});
      (want_inside ? inside_centres : outside_centres)++;
    }
    for (const Sphere& s : spheres) {
      const OutsideVolume ov = idx.outsideVolume(s);
      const int N = 20000;
      int outside = 0;
      for (int k = 0; k < N; ++k) {
        Vec3 u;
        do u = Vec3(U(rng), U(rng), U(rng));
        while (u.squaredNorm() > 1.0);
        outside += idx.classify(s.center + s.radius * u) == Containment::kOutside;
      }
      const double V = ballVolume(s.radius);
      const double p = static_cast<double>(outside) / N;
      const double est = p * V;
      const double se = V * std::sqrt(std::max(p * (1 - p), 1.0 / N) / N);
      EXPECT_LE(std::abs(ov.volume - est), 4.0 * se)
          << mc.name << " r=" << s.radius << " exact=" << ov.volume << " mc=" << est;
    }
  }
  EXPECT_GT(inside_centres, 0);
  EXPECT_GT(outside_centres, 0);
}

TEST(OutsideVolume, DerivativesMatchFiniteDifferences) {
  for (const McCase& mc : monteCarloMeshes()) {
    const SolidIndex idx(mc.mesh);
    const Aabb box = idx.bounds();
    const double diag = box.diagonal();
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> U(-0.5, 0.5);
    for (int k = 0; k < 6; ++k) {
      const Vec3 c = box.center() + (box.max - box.min).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      const double r = diag * (0.05 + 0.05 * k);
      const OutsideVolume ov = idx.outsideVolume({c, r});
      const double h = 1e-5 * diag;
      const double ddr =
          (idx.outsideVolume({c, r + h}).volume - idx.outsideVolume({c, r - h}).volume) / (2 * h);
      const double scale = r * r;  // derivatives are areas
      EXPECT_NEAR(ov.d_radius, ddr, 1e-5 * scale) << mc.name;
      for (int a = 0; a < 3; ++a) {
        Vec3 e = Vec3::Zero();
        e[a] = h;
        const double dc =
            (idx.outsideVolume({c + e, r}).volume - idx.outsideVolume({c - e, r}).volume) / (2 * h);
        EXPECT_NEAR(ov.gradient[a], dc, 1e-5 * scale) << mc.name << " axis " << a;
      }
    }
  }
}

TEST(OutsideVolume, InvariantUnderRigidMotionAndScaling) {
  const Mesh base = loadOrDie(test::dataPath("fr3_link1_collision.stl"));
  const SolidIndex idx0(base);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 t(12.5, -3.25, 100.0);
  const double diag = idx0.bounds().diagonal();
  std::vector<Sphere> probes = {{idx0.bounds().center(), 0.2 * diag},
                                {idx0.bounds().min, 0.3 * diag},
                                {base.vertices[7], 0.1 * diag}};
  for (double s : {1.0, 1e-3, 250.0}) {
    const SolidIndex idx(test::transformed(base, R, s * t, s));
    for (const Sphere& p : probes) {
      const double v0 = idx0.outsideVolume(p).volume;
      const double v1 = idx.outsideVolume({s * (R * p.center + t), s * p.radius}).volume;
      // Coordinates 300× the part's size cost about two digits, hence 1e-8 rather than 1e-10.
      EXPECT_NEAR(v1 / (s * s * s), v0, 1e-8 * ballVolume(p.radius)) << s;
    }
  }
}

TEST(OutsideVolume, HierarchyAgreesWithBruteForce) {
  for (const McCase& mc : monteCarloMeshes()) {
    const SolidIndex idx(mc.mesh);
    const Aabb box = idx.bounds();
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> U(-0.6, 0.6);
    for (int k = 0; k < 20; ++k) {
      const Vec3 c = box.center() + (box.max - box.min).cwiseProduct(Vec3(U(rng), U(rng), U(rng)));
      const Sphere s{c, box.diagonal() * (0.01 + 0.04 * k)};
      const OutsideVolume a = idx.outsideVolume(s), b = outsideVolumeBruteForce(idx, s);
      // Both derivatives are areas of at most the sphere's 4 pi r^2, summed over many triangles
      // in another order; 1e-12 of that area leaves room for the compiler's rounding choices.
      const double area = 4.0 * std::numbers::pi * s.radius * s.radius;
      EXPECT_NEAR(a.volume, b.volume, 1e-12 * ballVolume(s.radius));
      EXPECT_NEAR(a.d_radius, b.d_radius, 1e-12 * area);
      EXPECT_LE((a.gradient - b.gradient).norm(), 1e-12 * area);
    }
  }
}

TEST(OutsideVolume, MonotoneInRadius) {
  const SolidIndex idx(loadOrDie(test::examplePath("spot.obj")));
  const Vec3 c = idx.bounds().center() + Vec3(0.05, 0.1, -0.2);
  double prev = -1.0;
  for (int k = 1; k <= 40; ++k) {
    const double v = idx.outsideVolume({c, 0.04 * k}).volume;
    EXPECT_GE(v, prev - 1e-12);
    prev = v;
  }
}

}  // namespace
}  // namespace sphereset

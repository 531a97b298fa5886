// Private: the closed-form kernels one triangle at a time, and the index's queries done the
// slow, obvious way. They are the oracles of the tests and the baselines of the benchmarks;
// the library's own code uses the per-triangle kernels inside its accelerated queries.
#pragma once

#include <cstdint>
#include <vector>

#include "sphereset/solid_index.hpp"

namespace sphereset {

// Closed-form terms of one triangle t against the ball B(o, r); see outside_volume.hpp.
struct TriangleBallTerms {
  double h = 0.0;                   // signed distance of t's plane from o along t's outward normal
  double area = 0.0;                // A = area(t ∩ B)
  double solid_angle = 0.0;         // Ω = solid angle that t ∩ B subtends at o (unsigned, >= 0)
  bool center_on_triangle = false;  // o lies on t (within kOnPlaneRelTol): SOTV undefined
};

// The per-triangle closed form: triangle (a, b, c) counter-clockwise about its outward unit
// normal n, ball (o, r).
TriangleBallTerms triangleBallTerms(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                                    const Vec3& o, double r);

// Signed solid angle of triangle (a, b, c) seen from o (Van Oosterom–Strackee); positive when
// o lies behind the triangle (on the side opposite its counter-clockwise normal).
double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& o);

// SolidIndex::outsideVolume summed over every triangle, with no hierarchy.
OutsideVolume outsideVolumeBruteForce(const SolidIndex& index, const Sphere& ball);

// Generalised winding number Σ Ω_t / 4π over all triangles (O(n)); classify() falls back on it.
double windingNumber(const SolidIndex& index, const Vec3& p);

// Original indices of the triangles whose bounding boxes overlap the ball, sorted.
std::vector<int32_t> trianglesNearBall(const SolidIndex& index, const Sphere& ball);

}  // namespace sphereset

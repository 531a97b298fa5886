// A sphere: plain data.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "sphereset/mesh.hpp"
#include "sphereset/status.hpp"

namespace sphereset {

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  bool contains(const Vec3& p) const { return (p - center).squaredNorm() <= radius * radius; }
};

// Whether a computation can take `spheres` (one rule for the fit's bound, the evaluation and the
// incremental certificate): 1 to limits::kMaxSpheres spheres, each with a finite centre and a
// finite, non-negative radius. kInvalidArgument naming the first problem: "no spheres to WHAT"
// (`what`: "evaluate", "bound"), a count over the limit, "sphere I has a NaN, infinite or
// negative value".
Status checkSphereSet(std::span<const Sphere> spheres, const std::string& what);
// Its two parts: the count, and one sphere (`index` names it).
Status checkSphereCount(size_t count, const std::string& what);
Status checkSphereValues(const Sphere& s, size_t index);

// The smallest ball that contains every given ball entirely (exact up to rounding: a
// combinatorial pivoting method on support sets of at most four balls, no generic optimiser).
// Radius grows by a few ulps so that containment holds in floating point. Empty input gives
// a zero ball at the origin.
Sphere minimalEnclosingBall(std::span<const Sphere> balls);

}  // namespace sphereset

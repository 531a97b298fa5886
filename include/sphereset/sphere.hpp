// A sphere: plain data.
#pragma once

#include <span>

#include "sphereset/mesh.hpp"

namespace sphereset {

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
  bool contains(const Vec3& p) const { return (p - center).squaredNorm() <= radius * radius; }
};

// The smallest ball that contains every given ball entirely (exact up to rounding: a
// combinatorial pivoting method on support sets of at most four balls, no generic optimiser).
// Radius grows by a few ulps so that containment holds in floating point. Empty input gives
// a zero ball at the origin.
Sphere minimalEnclosingBall(std::span<const Sphere> balls);

}  // namespace sphereset

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

// The one rule for a sphere, at every door (files, queries, edits, Python, computations): a
// finite centre and a finite, non-negative radius, each value at most limits::kMaxCoordinate in
// magnitude (so that distances and volumes stay finite). An error with `code` naming `where`:
// "WHERE: NaN or infinite value", "WHERE: negative radius", "WHERE: a value beyond 1e+30 in
// magnitude (the coordinate limit)".
Status checkSphere(const std::string& where, const Sphere& s,
                   ErrorCode code = ErrorCode::kInvalidData);

// Whether a computation can take `spheres` (the fit's bound, the evaluation, the incremental
// certificate): 1 to limits::kMaxSpheres spheres, each passing checkSphere. kInvalidArgument
// naming the first problem: "no spheres to WHAT" (`what`: "evaluate", "bound"), a count over the
// limit, "sphere I: NaN or infinite value" (checkSphere's wording).
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

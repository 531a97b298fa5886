// The one rule for a set of spheres a computation takes (sphere.hpp): the fit's bound, the
// evaluation and the incremental certificate check their input through it.
#include <cmath>
#include <string>

#include "sphereset/limits.hpp"
#include "sphereset/sphere.hpp"

namespace sphereset {

Status checkSphereCount(size_t count, const std::string& what) {
  if (count == 0) return Error{ErrorCode::kInvalidArgument, "no spheres to " + what};
  return limits::checkRange("spheres", static_cast<double>(count), 1, limits::kMaxSpheres);
}

Status checkSphereValues(const Sphere& s, size_t index) {
  if (!s.center.allFinite() || !(s.radius >= 0.0) || !std::isfinite(s.radius))
    return Error{ErrorCode::kInvalidArgument,
                 "sphere " + std::to_string(index) + " has a NaN, infinite or negative value"};
  return {};
}

Status checkSphereSet(std::span<const Sphere> spheres, const std::string& what) {
  if (Status st = checkSphereCount(spheres.size(), what); !st) return st;
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st = checkSphereValues(spheres[i], i); !st) return st;
  return {};
}

}  // namespace sphereset

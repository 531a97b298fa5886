// The one rule for a sphere (sphere.hpp): every reader, query, edit and computation of the
// library checks spheres through checkSphere, so that a sphere one door accepts, every door
// accepts.
#include <cmath>
#include <string>

#include "sphereset/limits.hpp"
#include "sphereset/sphere.hpp"
#include "util/number_text.hpp"

namespace sphereset {

Status checkSphere(const std::string& where, const Sphere& s, ErrorCode code) {
  if (!s.center.allFinite() || !std::isfinite(s.radius))
    return Error{code, where + ": NaN or infinite value"};
  if (s.radius < 0.0) return Error{code, where + ": negative radius"};
  if (s.center.cwiseAbs().maxCoeff() > limits::kMaxCoordinate || s.radius > limits::kMaxCoordinate)
    return Error{code, where + ": a value beyond " + detail::numberText(limits::kMaxCoordinate) +
                           " in magnitude (the coordinate limit)"};
  return {};
}

Status checkSphereCount(size_t count, const std::string& what) {
  if (count == 0) return Error{ErrorCode::kInvalidArgument, "no spheres to " + what};
  return limits::checkRange("spheres", static_cast<double>(count), 1, limits::kMaxSpheres);
}

Status checkSphereValues(const Sphere& s, size_t index) {
  return checkSphere("sphere " + std::to_string(index), s, ErrorCode::kInvalidArgument);
}

Status checkSphereSet(std::span<const Sphere> spheres, const std::string& what) {
  if (Status st = checkSphereCount(spheres.size(), what); !st) return st;
  for (size_t i = 0; i < spheres.size(); ++i)
    if (Status st = checkSphereValues(spheres[i], i); !st) return st;
  return {};
}

}  // namespace sphereset

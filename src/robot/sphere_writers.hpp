// Private: what the robot writers with sphere collisions (URDF, MJCF) share.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// The spheres of each listed link, checked before any file is read: a link listed twice
// (kInvalidArgument), a sphere with a NaN, an infinite value or a negative radius
// (kInvalidData); messages start with `in_path`.
Expected<std::map<std::string, const std::vector<Sphere>*>> spheresByLink(
    const std::string& in_path, const std::vector<LinkSpheres>& spheres);

}  // namespace sphereset::detail

// Private: the lights of the shadow comparison.
#pragma once

#include <vector>

#include "sphereset/mesh.hpp"

namespace sphereset {

// Directions over the hemisphere about the unit vector `up`, each standing for the same solid
// angle (a deterministic spiral).
std::vector<Vec3> hemisphereDirections(int count, const Vec3& up);

}  // namespace sphereset

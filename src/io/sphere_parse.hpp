// Private: the sphere-file readers on a file's contents held in memory. The public readers
// (sphere_io.hpp) read the file and call these; the fuzzers call them directly. `name` stands
// for the file in error messages.
#pragma once

#include <string>
#include <vector>

#include "sphereset/sphere_io.hpp"

namespace sphereset::detail {

Expected<std::vector<Sphere>> parseSpheres(SphereFormat format, const std::string& text,
                                           const std::string& name);
Expected<SphereTree> parseSphereTree(SphereFormat format, const std::string& text,
                                     const std::string& name);

}  // namespace sphereset::detail

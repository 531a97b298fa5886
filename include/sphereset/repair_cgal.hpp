// The union and the wrapping of the repair (repair.hpp), by CGAL's corefinement booleans and
// 3D Alpha Wrapping. Part of the sphereset_repair library, which links GPL-licensed parts of
// CGAL: a program that uses it is bound by the GPL (see the README's licence section).
#pragma once

#include "sphereset/repair.hpp"

namespace sphereset {

SolidOperations cgalSolidOperations();

}  // namespace sphereset

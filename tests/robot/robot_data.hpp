// The synthetic robot of the robot tests (tests/data/robot/three_link.urdf) and its package.
#pragma once

#include <string>

#include "test_meshes.hpp"

namespace sphereset::test {

inline std::string robotDir() { return dataPath("robot"); }
inline std::string threeLinkUrdf() { return dataPath("robot/three_link.urdf"); }
inline std::string threeLinkStl() {
  return dataPath("robot/three_link_description/meshes/link.stl");
}

}  // namespace sphereset::test

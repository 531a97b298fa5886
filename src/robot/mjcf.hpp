// Private: MJCF robot descriptions read through MuJoCo (loadRobot of an ".xml" path), and what
// the MJCF writer shares with the reader.
#pragma once

#include <string>

#include "sphereset/robot.hpp"

namespace sphereset::detail {

// loadRobot for an MJCF (robot.hpp); without MuJoCo in the build, kUnreadable saying so.
Expected<Robot> loadMjcf(const std::string& path, const RobotLoadOptions& options);

// What sphereset refuses in an MJCF's text before MuJoCo reads it (limits.hpp): <composite>
// elements, a texture or height-field side beyond kMaxMjcfGridSide, and a file attribute naming
// something that exists but is not a regular file of at most kMaxMjcfFileBytes (relative names
// tried from `dir` and from the compiler's meshdir, texturedir and assetdir). kInvalidData
// naming `path`.
Status checkMjcfText(const std::string& path, const std::string& xml, const std::string& dir);

// The message of a build without MuJoCo, for `path`.
std::string noMujocoMessage(const std::string& path);

}  // namespace sphereset::detail

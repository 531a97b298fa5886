// A build without MuJoCo (SPHERESET_WITH_MUJOCO off): MJCF is refused with a message that says
// why (robot.hpp: mujocoAvailable).
#include "robot/mjcf.hpp"
#include "sphereset/robot.hpp"

namespace sphereset {

bool mujocoAvailable() { return false; }

namespace detail {

Expected<Robot> loadMjcf(const std::string& path, const RobotLoadOptions&) {
  return Error{ErrorCode::kUnreadable, noMujocoMessage(path)};
}

}  // namespace detail

Expected<std::string> formatSphereMjcf(const std::string&, const std::string& out_path,
                                       const std::vector<LinkSpheres>&,
                                       const std::vector<std::array<std::string, 2>>&,
                                       const RobotLoadOptions&) {
  return Error{ErrorCode::kUnreadable, detail::noMujocoMessage(out_path)};
}

Status writeSphereMjcf(const std::string&, const std::string& out_path,
                       const std::vector<LinkSpheres>&,
                       const std::vector<std::array<std::string, 2>>&, const RobotLoadOptions&) {
  return Error{ErrorCode::kUnreadable, detail::noMujocoMessage(out_path)};
}

}  // namespace sphereset

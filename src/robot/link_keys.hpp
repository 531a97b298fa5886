// The per-link rows of the robot table (link_spheres, link_padding, link_solid_for) are keyed
// by link name; a key that names no link of the robot is refused, with one message for all.
#pragma once
#include <algorithm>
#include <string>

#include "sphereset/robot.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// kInvalidArgument, prefixed by `name`, for the first key of `per_link` that is not a link of
// `robot`; `row` is the table row's name.
template <class Map>
Status checkLinkKeys(const Robot& robot, const Map& per_link, const char* row,
                     const std::string& name) {
  for (const auto& entry : per_link)
    if (std::none_of(robot.links.begin(), robot.links.end(),
                     [&](const RobotLink& l) { return l.name == entry.first; }))
      return Error{ErrorCode::kInvalidArgument,
                   name + ": " + row + " names '" + entry.first + "', not a link of " + robot.name};
  return {};
}

}  // namespace sphereset::detail

// The whole-robot fit's options as one table (robot_fit.hpp): the command line's flags of
// `sphereset robot` and the keywords of Python's fit_robot are made from it, and the library
// parses and checks what users type through it. Per-link rows are keyed by the link's name.
#include <algorithm>
#include <string>
#include <string_view>
#include <utility>

#include "robot/link_keys.hpp"
#include "sphereset/limits.hpp"
#include "sphereset/robot_fit.hpp"

namespace sphereset {
namespace {

constexpr double kNoLimit = std::numeric_limits<double>::max();
constexpr const char* kLinkSolids[] = {"envelope", "walls"};

constexpr OptionSpec kRobotOptions[] = {
    {"budget",
     "--budget",
     OptionType::kInteger,
     0,
     limits::kMaxSpheres,
     {},
     "0",
     "Spheres over the whole robot, sphere primitives included, split over the links by what "
     "lowers the total outside volume most (0: default_link_spheres per link)"},
    {"default_link_spheres",
     "--default-link-spheres",
     OptionType::kInteger,
     1,
     limits::kMaxSpheres,
     {},
     "8",
     "Spheres per link when no budget is given"},
    {"link_spheres",
     "--link-spheres",
     OptionType::kInteger,
     0,
     limits::kMaxSpheres,
     {},
     "none",
     "LINK=N: the link's count, fixed (0 skips the link); repeatable",
     "LINK"},
    {"padding",
     "--padding",
     OptionType::kReal,
     0,
     kNoLimit,
     {},
     "0",
     "Added to every radius (absolute units)"},
    {"link_padding",
     "--link-padding",
     OptionType::kReal,
     0,
     kNoLimit,
     {},
     "none",
     "LINK=R: the link's padding instead; repeatable",
     "LINK"},
    {"max_protrusion",
     "--max-protrusion",
     OptionType::kReal,
     0,
     limits::kMaxCoordinate,
     {},
     "none",
     "The certified protrusion of every fitted link's padded spheres at most this (a length "
     "above 0; with a trailing %, a percentage of each link's bounding-box diagonal): alone, "
     "each link's fewest spheres that meet it; with a budget, the split that keeps the worst "
     "link furthest under its limit",
     nullptr,
     nullptr,
     true,
     true},
    {"link_max_protrusion",
     "--link-max-protrusion",
     OptionType::kReal,
     0,
     limits::kMaxCoordinate,
     {},
     "none",
     "LINK=D: the link's protrusion limit instead of max_protrusion (above 0; D% of the "
     "link's diagonal); repeatable",
     "LINK",
     nullptr,
     true,
     true},
    {"link_solid", "--link-solid", OptionType::kChoice, 0, 0, kLinkSolids, "envelope",
     "envelope: each link's walls with the hollow behind openings up to fill_openings (auto: "
     "the link's smallest extent, where that encloses a hollow) inside, what a planner treats "
     "as the link; walls: the walls alone"},
    {"link_solid_for", "--link-solid-for", OptionType::kChoice, 0, 0, kLinkSolids, "none",
     "LINK=envelope|walls: the link's solid instead of link_solid (an envelope chosen so is "
     "kept even where it encloses no hollow); repeatable",
     "LINK"},
};

}  // namespace

std::span<const OptionSpec> robotFitOptionTable() { return kRobotOptions; }

Status setRobotFitOption(RobotFitOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kRobotOptions, "robot", name, text);
  if (!parsed) return parsed.error();
  const OptionValue& v = parsed->value;
  const std::string_view n = parsed->spec->name;
  // A link named twice in one keyed row used to keep the last value silently.
  const bool repeated =
      (n == "link_spheres" && o->link_spheres.count(v.key) > 0) ||
      (n == "link_padding" && o->link_padding.count(v.key) > 0) ||
      (n == "link_solid_for" && o->link_solid_for.count(v.key) > 0) ||
      (n == "link_max_protrusion" && (o->link_max_protrusion.count(v.key) > 0 ||
                                      o->link_max_protrusion_fraction.count(v.key) > 0));
  if (repeated)
    return Error{ErrorCode::kInvalidArgument,
                 std::string(n) + " '" + text + "': link '" + v.key + "' is given twice"};
  if (n == "budget") o->budget = static_cast<int>(v.integer);
  if (n == "default_link_spheres") o->default_link_spheres = static_cast<int>(v.integer);
  if (n == "link_spheres") o->link_spheres[v.key] = static_cast<int>(v.integer);
  if (n == "padding") o->padding = v.real;
  if (n == "link_padding") o->link_padding[v.key] = v.real;
  // A percent row's value is a fraction of the link's diagonal: one form per limit.
  if (n == "max_protrusion") {
    o->max_protrusion = v.length();
    o->max_protrusion_fraction = v.fraction();
  }
  if (n == "link_max_protrusion")
    (v.percent ? o->link_max_protrusion_fraction : o->link_max_protrusion)[v.key] =
        v.percent ? v.fraction() : v.length();
  const LinkSolid solid = v.choice == "walls" ? LinkSolid::kWalls : LinkSolid::kEnvelope;
  if (n == "link_solid") o->link_solid = solid;
  if (n == "link_solid_for") o->link_solid_for[v.key] = solid;
  return {};
}

namespace {

// The refusal of a fill_openings that no link would use.
Error noEnvelopeError(const RepairOptions& repair) {
  return Error{ErrorCode::kInvalidArgument,
               "every link's solid is its walls: fill_openings " +
                   (repair.fill_openings == kAutomatic ? std::string("auto")
                                                       : optionText(repair.fill_openings)) +
                   " asks for an envelope; give link_solid envelope, a link_solid_for "
                   "LINK=envelope or no fill_openings"};
}

bool isEnvelope(const std::pair<const std::string, LinkSolid>& entry) {
  return entry.second == LinkSolid::kEnvelope;
}

}  // namespace

Status checkRobotBestEffort(bool best_effort, const RobotFitOptions& o) {
  return checkBestEffort(best_effort, o.toleranceActive(), "max_protrusion, link_max_protrusion");
}

Status checkRobotFitOptions(const RobotFitOptions& o) {
  // Each number as its text, through the same parser as every front door's.
  const std::pair<const char*, double> values[] = {{"budget", o.budget},
                                                   {"default_link_spheres", o.default_link_spheres},
                                                   {"padding", o.padding}};
  for (const auto& [name, value] : values)
    if (Status st = checkTableValue(kRobotOptions, "robot", name, value); !st) return st;
  // max_protrusion 0 is the field's "none" (a user leaves the option out); any other value is
  // checked as the option's text would be.
  if (o.max_protrusion != 0.0)
    if (Status st = checkTableValue(kRobotOptions, "robot", "max_protrusion", o.max_protrusion);
        !st)
      return st;
  // The fractions as the percentages a user types ("5%").
  if (o.max_protrusion_fraction != 0.0)
    if (Status st = checkTableValue(kRobotOptions, "robot", "max_protrusion",
                                    100.0 * o.max_protrusion_fraction, {}, true);
        !st)
      return st;
  if (o.max_protrusion != 0.0 && o.max_protrusion_fraction != 0.0)
    return Error{ErrorCode::kInvalidArgument,
                 "max_protrusion is given both as a length and as a fraction: give one"};
  for (const auto& [link, count] : o.link_spheres)
    if (Status st = checkTableValue(kRobotOptions, "robot", "link_spheres", count, link); !st)
      return st;
  for (const auto& [link, padding] : o.link_padding)
    if (Status st = checkTableValue(kRobotOptions, "robot", "link_padding", padding, link); !st)
      return st;
  for (const auto& [link, limit] : o.link_max_protrusion) {
    if (Status st = checkTableValue(kRobotOptions, "robot", "link_max_protrusion", limit, link);
        !st)
      return st;
    if (o.link_spheres.contains(link))
      return Error{ErrorCode::kInvalidArgument, "link '" + link +
                                                    "' has both link_spheres and "
                                                    "link_max_protrusion: give one"};
  }
  for (const auto& [link, fraction] : o.link_max_protrusion_fraction) {
    if (Status st = checkTableValue(kRobotOptions, "robot", "link_max_protrusion", 100.0 * fraction,
                                    link, true);
        !st)
      return st;
    if (o.link_spheres.contains(link) || o.link_max_protrusion.contains(link))
      return Error{ErrorCode::kInvalidArgument,
                   "link '" + link + "' has both " +
                       (o.link_spheres.contains(link) ? "link_spheres" : "a length") +
                       " and a fraction as its link_max_protrusion: give one"};
  }
  for (const auto& [link, solid] : o.link_solid_for)
    if (auto v = parseTableOption(kRobotOptions, "robot", "link_solid_for",
                                  link + "=" + kLinkSolids[solid == LinkSolid::kWalls ? 1 : 0]);
        !v)
      return v.error();
  // Without the robot: walls for every link unless link_solid_for names an envelope.
  if (o.repair.fill_openings != 0.0 && o.link_solid == LinkSolid::kWalls &&
      std::none_of(o.link_solid_for.begin(), o.link_solid_for.end(), isEnvelope))
    return noEnvelopeError(o.repair);
  return {};
}

RepairOptions linkRepairOptions(const RepairOptions& repair, LinkSolid all,
                                const std::map<std::string, LinkSolid>& per_link,
                                const std::string& link) {
  RepairOptions out = repair;
  const auto it = per_link.find(link);
  if ((it != per_link.end() ? it->second : all) == LinkSolid::kWalls) {
    out.fill_openings = 0.0;
    return out;
  }
  if (out.fill_openings == 0.0) out.fill_openings = kAutomatic;
  out.keep_envelope = it != per_link.end();
  return out;
}

Status checkLinkSolids(const Robot& robot, const RepairOptions& repair, LinkSolid all,
                       const std::map<std::string, LinkSolid>& per_link, const std::string& name) {
  if (Status st = detail::checkLinkKeys(robot, per_link, "link_solid_for", name); !st) return st;
  const bool any_envelope = std::any_of(robot.links.begin(), robot.links.end(), [&](auto& l) {
    return linkRepairOptions(repair, all, per_link, l.name).fill_openings != 0.0;
  });
  if (repair.fill_openings != 0.0 && !any_envelope) {
    Error e = noEnvelopeError(repair);
    e.message = name + ": " + e.message;
    return e;
  }
  return {};
}

}  // namespace sphereset

// The evaluation's options as one table (evaluate.hpp): every front door's flags and keywords
// are made from it, and the library parses and checks what users type through it.
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

#include "sphereset/evaluate.hpp"
#include "sphereset/limits.hpp"

namespace sphereset {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

constexpr OptionSpec kEvalOptions[] = {
    {"seed", "--seed", OptionType::kUnsigned, 0, 0, {}, "1", "Seed for all sampling"},
    {"samples",
     "--samples",
     OptionType::kInteger,
     0,
     static_cast<double>(limits::kMaxUnionSamples),
     {},
     "200000",
     "Monte Carlo samples for the union's E_r"},
    {"segments",
     "--segments",
     OptionType::kInteger,
     0,
     static_cast<double>(limits::kMaxProximitySegments),
     {},
     "3000",
     "Segments for the proximity error"},
    {"up", "--up", OptionType::kChoice, 0, 0, kAxisNames, "y",
     "Up axis for the ground plane of the shadow comparison: x, y or z"},
    {"shadow_resolution",
     "--shadow-resolution",
     OptionType::kInteger,
     0,
     limits::kMaxShadowResolution,
     {},
     "48",
     "Ground-plane pixels per side for the shadow errors (0 skips them)"},
    {"shadow_lights",
     "--shadow-lights",
     OptionType::kInteger,
     1,
     limits::kMaxShadowLights,
     {},
     "64",
     "Directional lights over the upper hemisphere for the shadow errors"},
    {"surface_max_depth",
     "--surface-max-depth",
     OptionType::kInteger,
     0,
     limits::kMaxSurfaceDepth,
     {},
     "10",
     "Splits in four of a triangle by the surface certificate, at most"},
    {"interior_max_depth",
     "--interior-max-depth",
     OptionType::kInteger,
     0,
     limits::kMaxInteriorDepth,
     {},
     "5",
     "Octree levels below the 8x8x8 grid of the interior certificate, at most"},
    {"protrusion_tolerance",
     "--protrusion-tolerance",
     OptionType::kReal,
     0,
     1,
     {},
     "0.001",
     "Slack of the certified protrusion over its witness, a fraction of the bounding-box "
     "diagonal (0 skips the protrusion)"},
};

}  // namespace

std::span<const OptionSpec> evalOptionTable() { return kEvalOptions; }

Status setEvalOption(EvalOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kEvalOptions, "evaluation", name, text);
  if (!parsed) return parsed.error();
  const OptionValue* v = &parsed->value;
  const std::string_view n = parsed->spec->name;
  const auto integer = static_cast<int>(v->integer);  // within the row's int bounds
  if (n == "seed") o->seed = v->unsigned_integer;
  if (n == "samples") o->union_samples = v->integer;
  if (n == "segments") o->proximity_segments = integer;
  if (n == "up") o->up_axis = v->choice[0] - 'x';
  if (n == "shadow_resolution") o->shadow_resolution = integer;
  if (n == "shadow_lights") o->shadow_lights = integer;
  if (n == "surface_max_depth") o->surface_max_depth = integer;
  if (n == "interior_max_depth") o->interior_max_depth = integer;
  if (n == "protrusion_tolerance") o->protrusion_tolerance = v->real;
  return {};
}

Status checkEvalOptions(const EvalOptions& o) {
  // Each number as its text, through the same parser as every front door's.
  const std::pair<const char*, int64_t> values[] = {{"samples", o.union_samples},
                                                    {"segments", o.proximity_segments},
                                                    {"shadow_resolution", o.shadow_resolution},
                                                    {"shadow_lights", o.shadow_lights},
                                                    {"surface_max_depth", o.surface_max_depth},
                                                    {"interior_max_depth", o.interior_max_depth}};
  for (const auto& [name, value] : values)
    if (Status st = checkTableValue(kEvalOptions, "evaluation", name, static_cast<double>(value));
        !st)
      return st;
  if (Status st = checkTableValue(kEvalOptions, "evaluation", "protrusion_tolerance",
                                  o.protrusion_tolerance);
      !st)
    return st;
  if (Status st = limits::checkRange("poll_interval", o.poll_interval, 0.0, 3600.0); !st) return st;
  if (o.up_axis < 0 || o.up_axis > 2)
    return Error{ErrorCode::kInvalidArgument,
                 "up axis " + std::to_string(o.up_axis) + ": expected 0 (x), 1 (y) or 2 (z)"};
  return {};
}

}  // namespace sphereset

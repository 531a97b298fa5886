// The repair's options as one table (repair.hpp): the command line's flags, the Dask batch's
// flags and the Python keywords are made from it, and the library parses and checks what users
// type through it.
#include <charconv>
#include <limits>
#include <string>
#include <string_view>

#include "sphereset/limits.hpp"
#include "sphereset/repair.hpp"

namespace sphereset {
namespace {

constexpr const char* kRepairModes[] = {"auto", "off"};

constexpr OptionSpec kRepairOptions[] = {
    {"repair", "--repair", OptionType::kChoice, 0, 0, kRepairModes, "auto",
     "auto: make a solid of a broken mesh (weld, cap holes, unite overlapping shells, or wrap) "
     "and bound its original triangles too; off: refuse any mesh that is not a closed oriented "
     "manifold"},
    {"weld_tolerance",
     "--weld-tolerance",
     OptionType::kReal,
     0.0,
     limits::kMaxCoordinate,
     {},
     "automatic",
     "Merge vertices closer than this distance (automatic: exact duplicates; the repair then "
     "tries up to 1e-6 of the diagonal if that closes the mesh)"},
    {"wrap_alpha",
     "--wrap-alpha",
     OptionType::kReal,
     0.0,
     limits::kMaxCoordinate,
     {},
     "0",
     "Wrapping: openings narrower than about this are not entered (0: 1/50 of the diagonal)"},
    {"wrap_offset",
     "--wrap-offset",
     OptionType::kReal,
     0.0,
     limits::kMaxCoordinate,
     {},
     "0",
     "Wrapping: distance of the wrap outside the triangles (0: alpha/20)"},
    {"fill_openings",
     "--fill-openings",
     OptionType::kReal,
     0.0,
     limits::kMaxCoordinate,
     {},
     "0",
     "Envelope: close openings narrower than this length and count the hollow behind them as "
     "inside (auto: the smallest extent of the bounding box, kept only if it encloses a hollow; "
     "0: off, the walls as they are)",
     nullptr,
     "auto"},
};

}  // namespace

std::span<const OptionSpec> repairOptionTable() { return kRepairOptions; }

Status setRepairOption(RepairOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kRepairOptions, "repair", name, text);
  if (!parsed) return parsed.error();
  const OptionValue* v = &parsed->value;
  const std::string_view n = parsed->spec->name;
  if (n == "repair") o->enabled = v->choice == "auto";
  if (n == "weld_tolerance") o->weld_tolerance = v->real;
  if (n == "wrap_alpha") o->wrap_alpha = v->real;
  if (n == "wrap_offset") o->wrap_offset = v->real;
  if (n == "fill_openings") o->fill_openings = v->real;
  return {};
}

Status checkRepairOptions(const RepairOptions& o) {
  // Each number as its text, through the same parser as every front door's; a negative weld
  // tolerance is the automatic one.
  const std::pair<const char*, double> values[] = {
      {"weld_tolerance", o.weld_tolerance < 0.0 ? 0.0 : o.weld_tolerance},
      {"wrap_alpha", o.wrap_alpha},
      {"wrap_offset", o.wrap_offset},
      {"fill_openings", o.fill_openings}};
  for (const auto& [name, value] : values)
    if (Status st = checkTableValue(kRepairOptions, "repair", name, value); !st) return st;
  return {};
}

}  // namespace sphereset

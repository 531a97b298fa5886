// The animation's options as tables (animate.hpp): how centres follow the mesh, and the frame
// rate a clip is sampled at. The command line's flags of `sphereset animate` (and `render`'s
// --fps) and the Python keywords are made from them; the library parses and checks what users
// type through them.
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include "sphereset/animate.hpp"

namespace sphereset {
namespace {

constexpr const char* kWeightingNames[] = {"auto", "mvc", "bones"};

// Nearest rest vertices whose bone weights a centre averages: beyond a few dozen the average is
// the whole mesh's, and the weights' table grows with it.
constexpr int kMaxBoneNeighbours = 4096;
// Crossing triangle pairs counted per frame (the count stops there).
constexpr int64_t kMaxCrossings = 1000000000;

constexpr OptionSpec kAnimateOptions[] = {
    {"weighting", "--weighting", OptionType::kChoice, 0, 0, kWeightingNames, "auto",
     "Centres follow mean value coordinates of the rest mesh (mvc) or the bone weights of the "
     "surface near them (bones); auto: bones for skinned assets"},
    {"bone_neighbours",
     "--bone-neighbours",
     OptionType::kInteger,
     1,
     kMaxBoneNeighbours,
     {},
     "8",
     "bones: nearest rest vertices whose bone weights a centre averages"},
    {"max_crossings",
     "--max-crossings",
     OptionType::kInteger,
     0,
     static_cast<double>(kMaxCrossings),
     {},
     "1000",
     "Crossing triangle pairs counted per frame (0 skips the check)"},
};

constexpr OptionSpec kSkinnedLoadOptions[] = {
    {"fps",
     "--fps",
     OptionType::kReal,
     0,
     std::numeric_limits<double>::max(),
     {},
     "0",
     "Frames per second over the clip (0: the clip's keyframe times)"},
};

}  // namespace

const char* centreWeightingName(CentreWeighting w) { return kWeightingNames[static_cast<int>(w)]; }

std::span<const OptionSpec> animateOptionTable() { return kAnimateOptions; }

Status setAnimateOption(AnimateOptions* o, const std::string& name, const std::string& text) {
  auto parsed = parseTableOption(kAnimateOptions, "animation", name, text);
  if (!parsed) return parsed.error();
  const OptionValue& v = parsed->value;
  const std::string_view n = parsed->spec->name;
  if (n == "weighting")
    o->weighting = v.choice == "bones" ? CentreWeighting::kBones
                   : v.choice == "mvc" ? CentreWeighting::kMeanValue
                                       : CentreWeighting::kAuto;
  if (n == "bone_neighbours") o->bone_neighbours = static_cast<int>(v.integer);
  if (n == "max_crossings") o->max_crossings = v.integer;
  return {};
}

Status checkAnimateOptions(const AnimateOptions& o) {
  const std::pair<const char*, double> values[] = {
      {"bone_neighbours", o.bone_neighbours},
      {"max_crossings", static_cast<double>(o.max_crossings)}};
  for (const auto& [name, value] : values)
    if (Status st = checkTableValue(kAnimateOptions, "animation", name, value); !st) return st;
  return checkEvalOptions(o.eval);
}

std::span<const OptionSpec> skinnedLoadOptionTable() { return kSkinnedLoadOptions; }

Status setSkinnedLoadOption(SkinnedLoadOptions* o, const std::string& name,
                            const std::string& text) {
  auto parsed = parseTableOption(kSkinnedLoadOptions, "animation", name, text);
  if (!parsed) return parsed.error();
  o->fps = parsed->value.real;
  return {};
}

}  // namespace sphereset

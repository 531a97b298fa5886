// The link envelope (RepairOptions::fill_openings): the walls' solid with its openings up to a
// size closed and the hollow behind them filled. See envelope.cpp.
#pragma once
#include <string>

#include "sphereset/repair.hpp"
#include "sphereset/status.hpp"

namespace sphereset::detail {

// Replaces res->solid (the walls, as the repair ladder made them) by its envelope for
// o.fill_openings (an absolute size, or kAutomatic), keeping the walls in res->walls and the
// size used in res->fill_openings, with a note. With the automatic size, an envelope that encloses
// no hollow (its volume below kHollowVolumeRatio times the walls') is dropped and the walls stay
// the solid (res->fill_openings 0, a note says so), unless o.keep_envelope. Errors: the wrapping
// unavailable (kNotSolid), a size so small that the envelope would exceed the wrap's limits
// (kInvalidArgument).
Status closeOpenings(const RepairOptions& o, const std::string& name, RepairResult* res);

}  // namespace sphereset::detail

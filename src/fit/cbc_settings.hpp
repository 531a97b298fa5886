// Private: the options the fit's integer programs give CBC (select.cpp, optimal_radii.cpp).
#pragma once

#include <utility>

namespace sphereset::detail {

// CBC's options (its command-line names): plain branch and bound on the LP bound, no cuts,
// heuristics or strong branching. CBC's defaults took 30 to 70 s on 256 candidates and 5 700
// classes of the selection (fr3_link1, n = 64) for the same proven optimum that this finds in
// 2.5 s.
inline constexpr std::pair<const char*, const char*> kCbcSettings[] = {
    {"cuts", "off"}, {"heur", "off"}, {"strong", "0"}, {"trust", "0"}};

}  // namespace sphereset::detail

// The interactive page of `sphereset view`, built from web/ (three.js) into one HTML file and
// linked into the library as text (web/CMakeLists.txt generates its definition).
#pragma once

#include <string_view>

namespace sphereset::view_page {

// The page's HTML with its script inlined; empty when this build has no page (node and npm were
// not found when it was configured). Static data for a page without a server goes where the
// text kDataMarker stands (docs/view.md).
std::string_view html();
inline constexpr std::string_view kDataMarker = "<!--SPHERESET_DATA-->";

}  // namespace sphereset::view_page

// Private: JSON text from a document whose strings may hold file names that are not UTF-8.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace sphereset::detail {

// json.dump(indent) with invalid UTF-8 in strings replaced by U+FFFD instead of an exception
// (nlohmann's default throws type_error 316: a fit of "l\xff.stl" used to end in an internal
// error after the work was done).
template <class Json>
std::string jsonText(const Json& j, int indent = -1) {
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace sphereset::detail

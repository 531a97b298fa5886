// Private: the atomic write behind every output file of the library.
#pragma once

#include <string>

#include "sphereset/status.hpp"

namespace sphereset {

// Writes a whole file atomically (temporary file + rename). Used by every writer.
Status writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace sphereset

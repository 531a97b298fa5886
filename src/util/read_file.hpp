// Private: a whole file read into memory, for the readers that parse from memory, and the
// extension readers and writers choose a format by.
#pragma once

#include <string>

#include "sphereset/status.hpp"

namespace sphereset::detail {

// The file's bytes; kUnreadable, naming the file, when it cannot be opened or read.
Expected<std::string> readFileText(const std::string& path);

// The lower-case extension of a path, with its dot (".obj"; "" for none).
std::string extensionOf(const std::string& path);

}  // namespace sphereset::detail

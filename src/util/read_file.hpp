// Private: a whole file read into memory, for the readers that parse from memory.
#pragma once

#include <string>

#include "sphereset/status.hpp"

namespace sphereset::detail {

// The file's bytes; kUnreadable, naming the file, when it cannot be opened or read.
Expected<std::string> readFileText(const std::string& path);

}  // namespace sphereset::detail

// Private: the atomic write behind every output file of the library.
#pragma once

#include <string>

#include "sphereset/status.hpp"

namespace sphereset {

// Writes a whole file atomically and durably (temporary file, fsync, rename, fsync of the
// folder), through symbolic links, keeping an existing file's mode (a new one: 0666 less the
// umask). kWriteFailed naming `path`; the old file stays whole on any failure. Every writer.
Status writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace sphereset

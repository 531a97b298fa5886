// A whole file read into memory.
#include "util/read_file.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace sphereset::detail {

Expected<std::string> readFileText(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return Error{ErrorCode::kUnreadable, path + ": is a folder, not a file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::kUnreadable, path + ": cannot be opened for reading"};
  // Streams report errors of the underlying read (a folder, a device) by throwing from the
  // iterator in some cases; both ways end as kUnreadable.
  try {
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return Error{ErrorCode::kUnreadable, path + ": read error"};
    return text;
  } catch (const std::exception& e) {
    return Error{ErrorCode::kUnreadable, path + ": read error (" + e.what() + ")"};
  }
}

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace sphereset::detail

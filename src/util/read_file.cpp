// A whole file read into memory.
#include "util/read_file.hpp"

#include <fstream>
#include <iterator>

namespace sphereset::detail {

Expected<std::string> readFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::kUnreadable, path + ": cannot be opened for reading"};
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return Error{ErrorCode::kUnreadable, path + ": read error"};
  return text;
}

}  // namespace sphereset::detail

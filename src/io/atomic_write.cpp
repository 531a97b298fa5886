// Atomic file writes: every output of the library goes to a temporary file in the target's
// folder, which is then renamed over the target, so a failed write never leaves a partial file.
#include "io/atomic_write.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "sphereset/sphere_io.hpp"

namespace sphereset {

Status writeFileAtomically(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  std::string name = ".";
  name += target.filename().string();
  name += ".XXXXXX";
  const std::string tmpl = (dir / name).string();
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed, path + ": cannot create a file in '" + dir.string() +
                                              "' (" + std::strerror(errno) + ")"};
  const std::string tmp(buf.data());
  size_t done = 0;
  while (done < contents.size()) {
    const ssize_t w = ::write(fd, contents.data() + done, contents.size() - done);
    if (w <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      std::remove(tmp.c_str());
      return Error{ErrorCode::kWriteFailed, path + ": write failed (" + why + ")"};
    }
    done += static_cast<size_t>(w);
  }
  fchmod(fd, 0644);
  if (::close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + why + ")"};
  }
  return {};
}

}  // namespace sphereset

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
#include <string_view>
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

namespace {

namespace fs = std::filesystem;

// The input that `output` would overwrite, if any: the same file (hard or symbolic links
// included) when it exists, else the same normalised absolute path.
const std::string* sameFile(const fs::path& output, const std::vector<std::string>& inputs) {
  std::error_code ec;
  const fs::path out_abs = fs::weakly_canonical(fs::absolute(output, ec), ec);
  for (const std::string& in : inputs) {
    if (in.empty()) continue;
    std::error_code e1;
    if (fs::equivalent(output, in, e1)) return &in;
    std::error_code e2;
    const fs::path in_abs = fs::weakly_canonical(fs::absolute(in, e2), e2);
    if (!ec && !e2 && out_abs == in_abs) return &in;
  }
  return nullptr;
}

// Whether a new file can be made in `dir` (which exists): one is made and removed.
Status folderAcceptsFiles(const fs::path& dir, const std::string& what) {
  std::string tmpl = (dir / ".sphereset-check.XXXXXX").string();
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed, what + ": cannot create a file in '" + dir.string() +
                                              "' (" + std::strerror(errno) + ")"};
  ::close(fd);
  std::remove(buf.data());
  return {};
}

// What every output shares: a path is given, and it is none of the inputs. `kind` is "file" or
// "folder".
Status checkOutputIsNew(const std::string& output, const char* kind,
                        const std::vector<std::string>& inputs) {
  if (output.empty())
    return Error{ErrorCode::kInvalidArgument,
                 std::string("the output ") + (std::string_view(kind) == "file" ? "path" : kind) +
                     " is empty"};
  if (const std::string* in = sameFile(fs::path(output), inputs))
    return Error{ErrorCode::kInvalidArgument,
                 output + ": is the input " + *in + "; write the output to another " + kind};
  return {};
}

}  // namespace

Status checkOutputPath(const std::string& output, const std::vector<std::string>& inputs) {
  if (Status st = checkOutputIsNew(output, "file", inputs); !st) return st;
  const fs::path out(output);
  std::error_code ec;
  if (fs::is_directory(out, ec))
    return Error{ErrorCode::kInvalidArgument, output + ": is a folder; name a file"};
  fs::path dir = out.parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec))
    return Error{ErrorCode::kWriteFailed,
                 output + ": the folder '" + dir.string() + "' does not exist"};
  return folderAcceptsFiles(dir, output);
}

Status checkOutputFolder(const std::string& folder, const std::vector<std::string>& inputs) {
  if (Status st = checkOutputIsNew(folder, "folder", inputs); !st) return st;
  const fs::path out(folder);
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    return Error{ErrorCode::kInvalidArgument, folder + ": is a file, not a folder"};
  // The deepest part of the path that exists must be a folder that accepts files.
  fs::path existing = fs::absolute(out, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    return Error{ErrorCode::kWriteFailed, folder + ": '" + existing.string() + "' is not a folder"};
  return folderAcceptsFiles(existing, folder);
}

}  // namespace sphereset

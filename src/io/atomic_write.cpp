// Atomic, durable file writes: every output of the library goes to a temporary file in the
// target's folder, which is flushed to the disk (fsync) and then renamed over the target, and the
// folder is flushed so that the rename itself survives a power loss. A failed or interrupted
// write never leaves a partial or empty file: the old file stays whole until the rename.
//
// The saved file keeps what the user set on the old one: a symbolic link is written through (its
// final target is replaced, the link stays a link), an existing file keeps its permission bits,
// and a new file gets 0666 less the process's umask, as any program's new file does (the
// temporary file is created with those bits by open(2), so no umask call races other threads).
#include "io/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "sphereset/sphere_io.hpp"

namespace sphereset {
namespace {

// Links followed from the named path to the file a write replaces (the kernel's own limit for
// path resolution is 40).
constexpr int kMaxLinkHops = 40;
// Names tried for the temporary file before giving up (each is random; a clash is rare).
constexpr int kTemporaryNameAttempts = 100;
// Bits a new file gets before the umask (open(2)'s usual mode for data files).
constexpr mode_t kNewFileMode = 0666;

std::string why() { return std::strerror(errno); }

// The file a write to `path` replaces: `path` itself, or the final target of the symbolic links
// it names (relative targets resolved against the link's folder). A dangling link resolves to
// its missing target, which the write creates.
std::filesystem::path finalTarget(const std::filesystem::path& path, std::string* error) {
  namespace fs = std::filesystem;
  fs::path p = path;
  for (int hop = 0; hop < kMaxLinkHops; ++hop) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path next = fs::read_symlink(p, ec);
    if (ec) {
      *error = "cannot read the link (" + ec.message() + ")";
      return {};
    }
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  *error = "too many levels of symbolic links";
  return {};
}

// A new file in `dir` named after `base`, created exclusively with `mode` (less the umask).
int createTemporary(const std::filesystem::path& dir, const std::string& base, mode_t mode,
                    std::string* tmp) {
  std::random_device seed;
  std::mt19937_64 rng((static_cast<uint64_t>(seed()) << 32) ^ seed() ^
                      static_cast<uint64_t>(::getpid()));
  static constexpr char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    std::string name = "." + base + ".";
    for (int i = 0; i < 8; ++i) name += kChars[rng() % (sizeof kChars - 1)];
    *tmp = (dir / name).string();
    int fd;
    do {
      fd = ::open(tmp->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    } while (fd < 0 && errno == EINTR);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

// Every byte of `data` to `fd`, retrying short writes and EINTR.
bool writeAll(int fd, std::string_view data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t w = ::write(fd, data.data() + done, data.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      if (w == 0) errno = EIO;
      return false;
    }
    done += static_cast<size_t>(w);
  }
  return true;
}

int fsyncRetrying(int fd) {
  int rc;
  do rc = ::fsync(fd);
  while (rc != 0 && errno == EINTR);
  return rc;
}

// Flushes a folder's entries (the rename) to the disk. Some file systems refuse fsync on a
// folder (EINVAL): the rename is then as durable as they make it.
Status syncFolder(const std::filesystem::path& dir, const std::string& path) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return {};
  const int rc = fsyncRetrying(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0 && err != EINVAL && err != EROFS)
    return Error{
        ErrorCode::kWriteFailed,
        path + ": written, but its folder could not be flushed (" + std::strerror(err) + ")"};
  return {};
}

}  // namespace

Status writeFileAtomically(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  std::string link_error;
  const fs::path target = finalTarget(fs::path(path), &link_error);
  if (target.empty()) return Error{ErrorCode::kWriteFailed, path + ": " + link_error};
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  // An existing file keeps its permission bits; a new one gets kNewFileMode less the umask.
  struct stat old {};
  const bool exists = ::stat(target.c_str(), &old) == 0;
  if (exists && !S_ISREG(old.st_mode))
    return Error{ErrorCode::kWriteFailed, path + ": is not a regular file"};
  std::string tmp;
  const int fd = createTemporary(dir, target.filename().string(), kNewFileMode, &tmp);
  if (fd < 0)
    return Error{ErrorCode::kWriteFailed,
                 path + ": cannot create a file in '" + dir.string() + "' (" + why() + ")"};
  auto abandon = [&](const std::string& what) {
    const std::string reason = why();
    ::close(fd);
    ::unlink(tmp.c_str());
    return Error{ErrorCode::kWriteFailed, path + ": " + what + " (" + reason + ")"};
  };
  if (!writeAll(fd, contents)) return abandon("write failed");
  if (exists && ::fchmod(fd, old.st_mode & 07777) != 0)
    return abandon("cannot keep the file's permissions");
  if (fsyncRetrying(fd) != 0) return abandon("cannot flush the file to the disk");
  if (::close(fd) != 0) {
    const std::string reason = why();
    ::unlink(tmp.c_str());
    return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + reason + ")"};
  }
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    const std::string reason = why();
    ::unlink(tmp.c_str());
    return Error{ErrorCode::kWriteFailed, path + ": cannot write (" + reason + ")"};
  }
  return syncFolder(dir, path);
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

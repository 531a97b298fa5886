// Shared by the fuzz targets: the input as a string, and as a file with a given extension for
// the readers that only take paths (loadMesh through assimp).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace sphereset::fuzz {

inline std::string asString(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A file in a directory of its own (made once per process, removed at exit) rewritten with
// each input.
class InputFile {
 public:
  explicit InputFile(const std::string& extension) {
    char tmpl[] = "/tmp/sphereset_fuzz_XXXXXX";
    const char* dir = mkdtemp(tmpl);
    if (dir == nullptr) {
      std::perror("mkdtemp");
      std::abort();
    }
    dir_ = dir;
    path_ = dir_ + "/input" + extension;
  }
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  const std::string& write(const uint8_t* data, size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) std::abort();
    return path_;
  }

 private:
  std::string dir_;
  std::string path_;
};

// Stops the fuzzer on a broken invariant of the library (a crash to report, like any other).
inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
  }
}

}  // namespace sphereset::fuzz

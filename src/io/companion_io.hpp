// Private: assimp's file access for the readers of this library (loadMesh, loadAnimation).
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "io/smd_grammar.hpp"
#include "sphereset/status.hpp"
#include "util/read_file.hpp"

namespace sphereset::detail {

// Assimp's file access for one import. It records every file opened (LoadReport::files) and
// opens, besides the mesh itself, only the companions a format references for its geometry and
// materials (kCompanionExtensions, or the mesh's own stem); any other file a mesh names is
// "not found", so that a crafted mesh cannot make the loader read, and echo into an error,
// an unrelated file.
inline constexpr const char* kCompanionExtensions[] = {".bin", ".mtl"};

class CompanionIOSystem : public Assimp::DefaultIOSystem {
 public:
  explicit CompanionIOSystem(const std::string& mesh) : mesh_(mesh) {}
  bool Exists(const char* file) const override {
    return allowed(file) && Assimp::DefaultIOSystem::Exists(file);
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!allowed(file)) return nullptr;
    Assimp::IOStream* s = Assimp::DefaultIOSystem::Open(file, mode);
    if (s && std::find(files_.begin(), files_.end(), file) == files_.end()) files_.push_back(file);
    return s;
  }
  std::vector<std::string> files() const {
    std::vector<std::string> out{mesh_.string()};
    for (const std::string& f : files_) {
      std::error_code ec;
      if (!std::filesystem::equivalent(f, mesh_, ec)) out.push_back(f);
    }
    return out;
  }

 private:
  bool allowed(const char* file) const {
    const std::filesystem::path p(file);
    std::error_code ec;
    if (std::filesystem::equivalent(p, mesh_, ec)) return true;
    const std::string ext = extensionOf(file);
    for (const char* e : kCompanionExtensions)
      if (ext == e) return true;
    return p.stem() == mesh_.stem();
  }
  std::filesystem::path mesh_;
  std::vector<std::string> files_;
};

// Formats assimp reads as text only. Its text readers can loop for minutes on binary bytes (a
// NUL in an SMD node name: over 2 minutes) or read past their buffer on control characters
// (an SMD file with bytes 0x16 and 0x03: ASan, heap-buffer-overflow in strncmp), both found by
// fuzzing, so a control character other than whitespace in such a file is refused before
// assimp sees it.
inline constexpr const char* kTextOnlyExtensions[] = {
    ".smd", ".vta", ".obj", ".dae", ".gltf", ".ase", ".md5mesh", ".md5anim", ".nff", ".ac", ".x3d"};

// Whether a byte of a text file is binary data: a control character other than tab, line
// feed, carriage return and the old end-of-file mark 0x1a. Vertical tabs and form feeds count:
// assimp's parsers end a line at a form feed where a line-based check does not (an SMD file with
// one made assimp ask for 3.2 GB; found by fuzzing).
inline bool binaryByte(unsigned char c) {
  return c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != 0x1a;
}

// What must hold before assimp reads `path` (kUnreadable naming the file otherwise): no binary
// byte in a format of kTextOnlyExtensions ("binary data (byte 0x00 at offset N) in a text
// format"), and an SMD/VTA file that ends with a line break and follows its grammar
// (smd_grammar.hpp). A file that cannot be
// read passes: the reader says why.
inline Status checkBeforeAssimp(const std::string& path) {
  const std::string ext = extensionOf(path);
  if (std::find_if(std::begin(kTextOnlyExtensions), std::end(kTextOnlyExtensions),
                   [&](const char* e) { return ext == e; }) == std::end(kTextOnlyExtensions))
    return {};
  std::ifstream in(path, std::ios::binary);
  // SMD and VTA files are kept to check their grammar too, so that they are read once; the
  // others (an OBJ may be large) are only streamed.
  const bool smd = ext == ".smd" || ext == ".vta";
  std::string text;
  char buf[65536];
  int64_t offset = 0;
  while (in) {
    in.read(buf, sizeof buf);
    const std::streamsize got = in.gcount();
    for (std::streamsize i = 0; i < got; ++i)
      if (binaryByte(static_cast<unsigned char>(buf[i]))) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(buf[i]));
        return Error{ErrorCode::kUnreadable, path + ": binary data (byte " + hex + " at offset " +
                                                 std::to_string(offset + i) + ") in a text format"};
      }
    if (smd) text.append(buf, static_cast<size_t>(got));
    offset += got;
  }
  if (smd) {
    // assimp's SMD reader steps one byte past a keyword it matches ("end"), over the buffer's
    // terminating zero when the keyword is the file's last text (found by fuzzing: ASan,
    // heap-buffer-overflow in strncmp): the file must end with a line break.
    if (!text.empty() && text.back() != '\n')
      return Error{ErrorCode::kUnreadable, path + ": the last line does not end with a line break"};
    std::istringstream again(text);
    const std::string problem = smdProblem(again);
    if (!problem.empty()) return Error{ErrorCode::kUnreadable, path + ": " + problem};
  }
  return {};
}

}  // namespace sphereset::detail

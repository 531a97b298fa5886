// Private: assimp's file access for the readers of this library (loadMesh, loadAnimation).
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

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
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    for (const char* e : kCompanionExtensions)
      if (ext == e) return true;
    return p.stem() == mesh_.stem();
  }
  std::filesystem::path mesh_;
  std::vector<std::string> files_;
};

}  // namespace sphereset::detail

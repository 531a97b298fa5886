// The checks of an MJCF's text that come before MuJoCo reads it (mjcf.hpp): what MuJoCo 2.2.2
// would read without a bound (a <composite> of a million bodies, a 10⁵ × 10⁵ height field, a
// mesh "file" that is /dev/zero) is refused by name. Built with or without MuJoCo.
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "robot/mjcf.hpp"
#include "sphereset/limits.hpp"

namespace sphereset::detail {
namespace {

namespace fs = std::filesystem;

// The values of attribute `name` anywhere in `xml`, in double or single quotes.
std::vector<std::string> attributeValues(const std::string& xml, const std::string& name) {
  const std::regex re("[\\s]" + name + "\\s*=\\s*(\"([^\"]*)\"|'([^']*)')");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), re); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[2].matched ? (*it)[2].str() : (*it)[3].str());
  return out;
}

}  // namespace

std::string noMujocoMessage(const std::string& path) {
  return path +
         ": this build of sphereset reads no MJCF (it was built without MuJoCo: configure with "
         "-DSPHERESET_WITH_MUJOCO=ON and libmujoco-dev installed)";
}

Status checkMjcfText(const std::string& path, const std::string& xml, const std::string& dir) {
  if (xml.find("<composite") != std::string::npos)
    return Error{ErrorCode::kInvalidData,
                 path +
                     ": a <composite> element: composites are not read (write their bodies "
                     "out, e.g. with MuJoCo's mj_saveLastXML)"};
  for (const char* side : {"width", "height", "nrow", "ncol"})
    for (const std::string& v : attributeValues(xml, side)) {
      char* end = nullptr;
      const double n = std::strtod(v.c_str(), &end);
      if (end != v.c_str() && !(n <= limits::kMaxMjcfGridSide))
        return Error{ErrorCode::kInvalidData, path + ": " + side + "=\"" + v +
                                                  "\": textures and height fields are read up "
                                                  "to " +
                                                  std::to_string(limits::kMaxMjcfGridSide) +
                                                  " per side"};
    }
  std::vector<fs::path> bases = {fs::path(dir)};
  for (const char* folder : {"meshdir", "texturedir", "assetdir"})
    for (const std::string& v : attributeValues(xml, folder)) bases.push_back(fs::path(dir) / v);
  for (const std::string& file : attributeValues(xml, "file")) {
    std::vector<fs::path> candidates;
    if (fs::path(file).is_absolute())
      candidates.push_back(file);
    else
      for (const fs::path& b : bases) candidates.push_back(b / file);
    for (const fs::path& c : candidates) {
      std::error_code ec;
      const fs::file_status st = fs::status(c, ec);
      if (ec || !fs::exists(st)) continue;
      if (!fs::is_regular_file(st))
        return Error{ErrorCode::kInvalidData,
                     path + ": file=\"" + file + "\" names " + c.string() + ", not a file"};
      const auto bytes = fs::file_size(c, ec);
      if (!ec && bytes > static_cast<uintmax_t>(limits::kMaxMjcfFileBytes))
        return Error{ErrorCode::kInvalidData, path + ": file=\"" + file + "\" has " +
                                                  std::to_string(bytes) +
                                                  " bytes (files an MJCF names are read up to " +
                                                  std::to_string(limits::kMaxMjcfFileBytes) + ")"};
    }
  }
  return {};
}

}  // namespace sphereset::detail

// Fuzz target for one sphere-set format, chosen at compile time (SPHERESET_FUZZ_FORMAT):
// the reader on bytes in memory and, for the formats that keep every value (text, JSON,
// YAML), a write-then-read round trip that must give back the same spheres.
#include <set>
#include <string>

#include "fuzz_input.hpp"
#include "io/sphere_formats.hpp"
#include "util/utf8.hpp"

namespace {

using sphereset::Sphere;
using sphereset::SphereFormat;
using sphereset::fuzz::check;

constexpr SphereFormat kFormat = SphereFormat::SPHERESET_FUZZ_FORMAT;

bool same(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].center != b[i].center || a[i].radius != b[i].radius) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace d = sphereset::detail;
  const std::string text = sphereset::fuzz::asString(data, size);
  auto spheres = d::parseSpheres(kFormat, text, "fuzz");
  if (spheres && kFormat != SphereFormat::kSph) {
    auto back = d::parseSpheres(kFormat, sphereset::formatSpheres(kFormat, *spheres), "again");
    check(back.ok() && same(*spheres, *back), "a sphere set written and read back differs");
  }
  if (kFormat == SphereFormat::kYaml) {
    auto links = d::parseLinkSpheres(kFormat, text, "fuzz");
    // Names that are not UTF-8 are written repaired (U+FFFD for the bad bytes); two of them may
    // then coincide, and such a set is not expected to round-trip.
    std::set<std::string> repaired;
    if (links)
      for (const auto& l : *links) repaired.insert(d::validUtf8(l.link));
    if (links && repaired.size() == links->size()) {
      auto back = d::parseLinkSpheres(kFormat, sphereset::formatLinkSpheres(*links), "again");
      check(back.ok() && back->size() == links->size(), "links written and read back differ");
      for (size_t l = 0; l < links->size(); ++l)
        check((*back)[l].link == d::validUtf8((*links)[l].link) &&
                  same((*back)[l].spheres, (*links)[l].spheres),
              "a link written and read back differs");
    }
  }
  return 0;
}

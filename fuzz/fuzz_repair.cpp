// Fuzz target: the repair ladder's own steps (diagnosis of crossings and shells, welding,
// orientation, nested shells, hole capping) on an OFF mesh in memory. The union and the
// wrapping are CGAL's and not part of this build; meshes that need them are refused.
#include "fuzz_input.hpp"
#include "io/off_ply.hpp"
#include "sphereset/repair.hpp"

namespace {
// Larger meshes only repeat what small ones exercise, more slowly.
constexpr size_t kMaxTriangles = 2000;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto raw = sphereset::detail::parseOff(sphereset::fuzz::asString(data, size), "fuzz.off");
  if (!raw || raw->triangles.size() > kMaxTriangles) return 0;
  auto m = sphereset::cleanMesh(std::move(raw->vertices), std::move(raw->triangles));
  if (!m) return 0;
  for (bool fill : {true, false}) {
    sphereset::RepairOptions o;
    o.fill_cavities = fill;
    (void)sphereset::repairMesh(m->mesh, o, "fuzz.off");
  }
  return 0;
}

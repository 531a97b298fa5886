// Fuzz target: the PLY reader (ascii and binary) on bytes in memory, then the clean-up
// loadMesh applies.
#include "fuzz_input.hpp"
#include "io/off_ply.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto raw = sphereset::detail::parsePly(sphereset::fuzz::asString(data, size), "fuzz.ply");
  if (raw) (void)sphereset::cleanMesh(std::move(raw->vertices), std::move(raw->triangles));
  return 0;
}

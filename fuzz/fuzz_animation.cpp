// Fuzz target: loadAnimation on a Valve SMD file (a text format assimp reads with skeleton, skin
// and keyframes): the bind pose, the skin, the frame and bone caps of limits.hpp, and the
// clip's frames, at its keyframes or, when the first byte is odd, at a rate from it.
#include "fuzz_input.hpp"
#include "sphereset/animate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".smd");
  if (size == 0) return 0;
  sphereset::SkinnedLoadOptions o;
  if (data[0] % 2 == 1) o.fps = 1.0 + data[0];
  (void)sphereset::loadAnimation(file.write(data + 1, size - 1), o);
  return 0;
}

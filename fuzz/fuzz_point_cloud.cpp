// Fuzz target: readPointCloud on an .xyz file (one "x y z" per line, comments and blank lines
// skipped), then the obstacles made of the points it accepts.
#include "fuzz_input.hpp"
#include "sphereset/robot_query.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".xyz");
  auto points = sphereset::readPointCloud(file.write(data, size));
  if (points) (void)sphereset::makeObstacles(*points, "cloud.xyz");
  return 0;
}

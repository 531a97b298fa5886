// Fuzz target: loadMesh on a .obj file, read by assimp, then cleaned up and diagnosed.
#include "fuzz_input.hpp"
#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sphereset::fuzz::InputFile file(".obj");
  auto mesh = sphereset::loadMesh(file.write(data, size));
  if (mesh) (void)sphereset::diagnoseMesh(mesh->mesh);
  return 0;
}

// Helper of the CLI tests: reads a file the command line wrote, through the library's readers,
// and prints what it holds. `read_output spheres FILE` prints the number of spheres (a tree's
// leaves, after checking the tree's structure); `read_output mesh FILE` the number of
// triangles. A file that does not read gives one line on stderr and exit code 1.
#include <cstdio>
#include <string>

#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "sphereset/sphere_io.hpp"
#include "sphereset/sphere_tree.hpp"

namespace {

int failed(const sphereset::Error& e) {
  std::fprintf(stderr, "read_output: %s\n", e.message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sphereset;
  const std::string mode = argc == 3 ? argv[1] : "";
  if (mode != "spheres" && mode != "mesh") {
    std::fprintf(stderr, "usage: read_output spheres|mesh FILE\n");
    return 2;
  }
  const std::string path = argv[2];
  if (mode == "mesh") {
    auto m = loadMesh(path);
    if (!m) return failed(m.error());
    std::printf("%zu\n", m->mesh.triangles.size());
    return 0;
  }
  auto t = readSphereTree(path);
  if (!t) return failed(t.error());
  if (t->depth >= 2) {
    Status st = checkSphereTree(*t);
    if (!st) return failed(st.error());
  }
  std::printf("%zu\n", t->leaves().size());
  return 0;
}

// Hostile OFF and PLY files: headers that promise more data than the file holds, indices that
// are not integers. Each must give a one-line error naming the file, never an exception or
// undefined behaviour.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "sphereset/load.hpp"
#include "sphereset/mesh.hpp"
#include "test_meshes.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::expectError;

class MeshHostile : public test::TempDirTest {};

// The load fails with `code`, and the one-line message names the file and holds `words`.
TEST_F(MeshHostile, OffCountsBeyondTheFileAreRefusedWithoutReserving) {
  // 20 bytes that declare two billion vertices: nothing may be reserved for them.
  const std::string huge = write("huge.off", "OFF\n2000000000 1 0\n");
  expectError(loadMesh(huge), ErrorCode::kUnreadable, huge, "0 of 2000000000 vertices");
  const std::string faces =
      write("faces.off", "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expectError(loadMesh(faces), ErrorCode::kUnreadable, faces, "1 of 2000000000 faces");
}

// An ascii PLY triangle whose face indices are stored as `type` values.
std::string plyTriangle(const std::string& type, const std::string& face) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar " +
         type + " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" + face + "\n";
}

TEST_F(MeshHostile, PlyFloatIndicesMustBeIntegersInRange) {
  // Casting these to an integer would be undefined behaviour.
  const std::pair<const char*, const char*> cases[] = {
      {"3 0 1 nan", "index nan is not an integer"},
      {"3 0 1e30 2", "references vertex 1e+30 of 3"},
      {"3 -1e30 1 2", "references vertex -1e+30 of 3"},
      {"3 0 1 inf", "index inf is not an integer"},
      {"3 0 1.5 2", "index 1.5 is not an integer"},
  };
  for (const auto& [face, words] : cases) {
    const std::string p = write("f.ply", plyTriangle("double", face));
    expectError(loadMesh(p), ErrorCode::kInvalidData, p + ": face 0", words);
  }
  // Integral float indices are indices like any other.
  const std::string ok = write("ok.ply", plyTriangle("float", "3 0 1.0 2e0"));
  auto m = loadMesh(ok);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->mesh.triangles.size(), 1u);

  // The same in binary: a double index of 1e30.
  std::string b =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list uchar double vertex_indices\nend_header\n";
  const double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  b.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const double idx[3] = {0, 1, 1e30};
  b.push_back(3);
  b.append(reinterpret_cast<const char*>(idx), sizeof idx);
  const std::string bin = write("b.ply", b);
  expectError(loadMesh(bin), ErrorCode::kInvalidData, bin + ": face 0",
              "references vertex 1e+30 of 3");
}

TEST_F(MeshHostile, PlyListCountsMustBeCountsTheDataCanHold) {
  // A float list count of NaN, a negative one, a fraction and one beyond the data.
  for (const char* face : {"nan 0 1 2", "-3 0 1 2", "2.5 0 1 2", "1000000 0 1 2"}) {
    std::string text = plyTriangle("int", face);
    text.replace(text.find("list uchar"), 10, "list float");
    const std::string p = write("c.ply", text);
    expectError(loadMesh(p), ErrorCode::kUnreadable, p, "malformed list in element 'face'");
  }
  // Two billion vertices declared in a few bytes: a clear error, no reservation.
  const std::string huge =
      write("huge.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
            "property float y\nproperty float z\nend_header\n");
  expectError(loadMesh(huge), ErrorCode::kUnreadable, huge, "truncated data in element 'vertex'");
}

TEST_F(MeshHostile, PlyHeaderEndingAtTheLastByteHasNoData) {
  // No line break after end_header: the data starts at the end of the file, not one byte past
  // it (the ascii reader once parsed a number from beyond the buffer; AddressSanitizer shows it).
  for (const char* format : {"ascii", "binary_little_endian"}) {
    const std::string p =
        write("end.ply", std::string("ply\nformat ") + format +
                             " 1.0\nelement vertex 1\nproperty float x\n"
                             "property float y\nproperty float z\nend_header");
    expectError(loadMesh(p), ErrorCode::kUnreadable, p, "truncated data in element 'vertex'");
  }
}

// A mesh file may name other files. Only the companions its format needs are read (a glTF's
// .bin, an OBJ's .mtl), and they are listed in the report; any other file is missing to the
// loader (an OBJ naming /etc/passwd as its material library used to echo a line of it, and
// a tiny file named so made the mesh unreadable).
TEST_F(MeshHostile, OnlyCompanionFilesAreReadAndTheyAreListed) {
  const std::string gltf = write("tet.gltf", test::tetrahedronGltf("tet.bin"));
  write("tet.bin", test::tetrahedronBin(1.0f));
  auto m = loadMesh(gltf);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->mesh.triangles.size(), 4u);
  ASSERT_EQ(m->report.files.size(), 2u);
  EXPECT_EQ(m->report.files[0], gltf);
  EXPECT_EQ(std::filesystem::path(m->report.files[1]).filename(), "tet.bin");

  const std::string tiny = write("tiny.txt", "x\n");
  const std::string obj = write("evil.obj", "mtllib " + tiny +
                                                "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                                "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  auto o = loadMesh(obj);
  ASSERT_TRUE(o.ok()) << o.error().message;
  EXPECT_EQ(o->report.files, std::vector<std::string>{obj});
}

}  // namespace
}  // namespace sphereset

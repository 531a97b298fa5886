// Hostile OFF and PLY files: headers that promise more data than the file holds, indices that
// are not integers. Each must give a one-line error naming the file, never an exception or
// undefined behaviour.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sphereset/mesh.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;

class MeshHostile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("sphereset_hostile_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& contents) {
    const std::string p = (dir_ / name).string();
    std::ofstream(p, std::ios::binary) << contents;
    return p;
  }
  fs::path dir_;
};

// The load fails with `code`, and the one-line message names the file and holds `words`.
void expectError(const Expected<LoadedMesh>& m, ErrorCode code, const std::string& path,
                 const std::string& words) {
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().code, code) << m.error().message;
  EXPECT_NE(m.error().message.find(path), std::string::npos) << m.error().message;
  EXPECT_NE(m.error().message.find(words), std::string::npos) << m.error().message;
  EXPECT_EQ(m.error().message.find('\n'), std::string::npos) << m.error().message;
}

TEST_F(MeshHostile, OffCountsBeyondTheFileAreRefusedWithoutReserving) {
  // 20 bytes that declare two billion vertices: nothing may be reserved for them.
  const std::string huge = write("huge.off", "OFF\n2000000000 1 0\n");
  expectError(loadMesh(huge), ErrorCode::kUnreadable, huge, "0 of 2000000000 vertices");
  const std::string faces =
      write("faces.off", "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expectError(loadMesh(faces), ErrorCode::kUnreadable, faces, "1 of 2000000000 faces");
}

}  // namespace
}  // namespace sphereset

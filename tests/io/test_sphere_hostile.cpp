// Hostile sphere-set and sphere-tree files: numbers that do not fit the integers they stand
// for, layouts larger than the file. Each must give a one-line error naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sphereset/sphere_io.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using test::expectError;

class SphereHostile : public test::TempDirTest {};

std::string jsonTree(const std::string& branching, const std::string& depth,
                     const std::string& id) {
  return "{\"branching\": " + branching + ", \"depth\": " + depth + ", \"nodes\": [{\"id\": " + id +
         ", \"center\": [0, 0, 0], \"radius\": 1}]}";
}

TEST_F(SphereHostile, JsonTreeIntegersMustBeIntegersInRange) {
  // Converting 1e30 or NaN-like values to int would be undefined behaviour; a fraction or a
  // value beyond 32 bits must not be truncated or wrapped into a valid-looking one.
  const std::pair<std::string, std::string> cases[] = {
      {jsonTree("1e30", "1", "0"), "\"branching\""},
      {jsonTree("-1e30", "1", "0"), "\"branching\""},
      {jsonTree("4294967298", "1", "0"), "\"branching\""},
      {jsonTree("2.5", "1", "0"), "\"branching\""},
      {jsonTree("2", "1e300", "0"), "\"depth\""},
      {jsonTree("2", "1.5", "0"), "\"depth\""},
      {jsonTree("2", "1", "1e300"), "\"id\""},
      {jsonTree("2", "1", "0.5"), "\"id\""},
      {jsonTree("2", "1", "18446744073709551615"), "\"id\""},
  };
  for (const auto& [text, words] : cases) {
    const std::string p = write("t.json", text);
    expectError(readSphereTree(p), ErrorCode::kInvalidData, p, words);
  }
  // Integral values written as floats are integers.
  auto ok = readSphereTree(write("ok.json", jsonTree("2.0", "1", "0e0")));
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  EXPECT_EQ(ok->branching, 2);
  EXPECT_EQ(ok->nodes.size(), 3u);
}

TEST_F(SphereHostile, SphTreeLargerThanTheFileIsTruncated) {
  // 2^22 - 1 slots declared in six bytes.
  const std::string p = write("big.sph", "22 2\n");
  expectError(readSphereTree(p), ErrorCode::kInvalidData, p, "truncated after 0 of 4194303");
  const std::string q = write("huge.sph", "2000000000 1\n0 0 0 1\n");
  expectError(readSphereTree(q), ErrorCode::kInvalidData, q, "too large");
  const std::string r = write("over.sph", "99999999999 2\n0 0 0 1\n");
  expectError(readSphereTree(r), ErrorCode::kInvalidData, r, "levels branching");
}

// A 90-byte JSON tree used to make every reader allocate 2.1 GB (branching 67108863, depth 1)
// or 4.2 GB (branching 8191, depth 2): the layout is capped at SphereTree::kMaxSlots first.
TEST_F(SphereHostile, JsonTreeLayoutIsCappedBeforeAllocating) {
  for (const char* layout : {"67108863:1", "8191:2", "2048:2"}) {
    const std::string l = layout;
    const std::string p =
        write("wide.json", jsonTree(l.substr(0, l.find(':')), l.substr(l.find(':') + 1), "0"));
    expectError(readSphereTree(p), ErrorCode::kInvalidData, p, "too large");
  }
  EXPECT_TRUE(readSphereTree(write("ok.json", jsonTree("2047", "2", "0"))).ok());
}
}  // namespace
}  // namespace sphereset

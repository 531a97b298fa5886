// Helpers shared by the test suites: a fixture with a temporary folder of its own, the check of
// a library error, and the evaluation's coverage certificate alone.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "sphereset/evaluate.hpp"
#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"

namespace sphereset::test {

inline constexpr double kPi = std::numbers::pi;

// Spheres whose coordinates test a format's number round trip: a third, 1e-9, large values.
inline const std::vector<Sphere> kRoundTripSet = {{Vec3(0.1, -2.5, 3.0), 0.75},
                                                  {Vec3(1.0 / 3.0, 1e-9, -7.0), 1e-3},
                                                  {Vec3(100.0, 200.0, 300.0), 42.0}};

// A fresh folder for each test, named after the suite, the test and the process (so that two
// builds testing at once do not meet), removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("sphereset_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes `contents` byte for byte to a file of the folder and returns its path.
  std::string write(const std::string& name, const std::string& contents) const {
    std::ofstream(path(name), std::ios::binary) << contents;
    return path(name);
  }
  std::filesystem::path dir_;
};

// A file's whole text (empty when it cannot be read).
inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A path in the temporary folder that is this process's own (for tests without the fixture).
inline std::filesystem::path tempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("sphereset_" + std::to_string(::getpid()) + "_" + name);
}

// A failed call with the given code, one line that names `path` and contains `words`.
template <class T>
void expectError(const Expected<T>& r, ErrorCode code, const std::string& path,
                 const std::string& words) {
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, code) << r.error().message;
  EXPECT_NE(r.error().message.find(path), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << r.error().message;
}

// The evaluation's coverage certificates only (no Monte Carlo, proximity or shadows).
inline EvalResult coverageOnly(const SolidIndex& idx, const std::vector<Sphere>& spheres) {
  EvalOptions eo;
  eo.union_samples = 0;
  eo.proximity_segments = 0;
  eo.shadow_resolution = 0;
  return *evaluateSpheres(idx, spheres, eo);
}

inline void expectCovers(const SolidIndex& idx, const std::vector<Sphere>& spheres) {
  const EvalResult e = coverageOnly(idx, spheres);
  EXPECT_TRUE(e.surface_covered);
  EXPECT_TRUE(e.interior_covered);
}

}  // namespace sphereset::test

// Numbers read from text whatever the C locale: under a comma-decimal locale strtod stopped at
// the '.' of "0.5", so options and sphere files were refused or misread.
#include <gtest/gtest.h>
#include <unistd.h>

#include <clocale>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "sphereset/fit.hpp"
#include "sphereset/robot.hpp"
#include "sphereset/sphere_io.hpp"
#include "util/number_text.hpp"

namespace sphereset {
namespace {

TEST(NumberText, ParsesWholeNumbersOnly) {
  double v = 0.0;
  EXPECT_TRUE(detail::parseNumber("0.5", &v));
  EXPECT_EQ(v, 0.5);
  EXPECT_TRUE(detail::parseNumber("+2e3", &v));
  EXPECT_EQ(v, 2000.0);
  EXPECT_TRUE(detail::parseNumber("-1e-3", &v));
  EXPECT_EQ(v, -1e-3);
  EXPECT_TRUE(detail::parseNumber("nan", &v));
  EXPECT_TRUE(std::isnan(v));
  EXPECT_TRUE(detail::parseNumber("1e400", &v));
  EXPECT_EQ(v, HUGE_VAL);
  EXPECT_TRUE(detail::parseNumber("-1e400", &v));
  EXPECT_EQ(v, -HUGE_VAL);
  EXPECT_TRUE(detail::parseNumber("1e-400", &v));
  EXPECT_EQ(v, 0.0);
  for (const char* bad : {"", "0,5", "1.5x", " 1", "+-1", "+", "x"})
    EXPECT_FALSE(detail::parseNumber(bad, &v)) << bad;
}

// A comma-decimal locale for the length of a test (de_DE.UTF-8, made by scripts/setup.sh).
class CommaLocale {
 public:
  CommaLocale() {
    if (const char* old = std::setlocale(LC_ALL, nullptr)) old_ = old;
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8"})
      if (std::setlocale(LC_ALL, name) != nullptr) {
        active_ = true;
        break;
      }
  }
  ~CommaLocale() { std::setlocale(LC_ALL, old_.c_str()); }
  bool active() const { return active_; }

 private:
  std::string old_ = "C";
  bool active_ = false;
};

TEST(NumberText, OptionsAndFilesReadTheSameUnderACommaLocale) {
  CommaLocale comma;
  if (!comma.active()) GTEST_SKIP() << "no comma-decimal locale on this machine";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.1f", 0.5);
  ASSERT_EQ(std::string(buf), "0,5") << "the locale does not use a comma";
  FitRequest r;
  ASSERT_TRUE(setFitRequestOption(&r, "padding", "0.5").ok());
  EXPECT_EQ(r.padding, 0.5);
  const auto joints = parseJointValues("a=0.25,b=-1.5");
  ASSERT_TRUE(joints.ok()) << joints.error().message;
  EXPECT_EQ(joints->at("a"), 0.25);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("sphereset_comma_" + std::to_string(::getpid()) + ".txt"))
                               .string();
  std::ofstream(path) << "0.5 0.25 -1.5 0.125\n";
  const auto spheres = readSpheres(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(spheres.ok()) << spheres.error().message;
  ASSERT_EQ(spheres->size(), 1u);
  EXPECT_EQ((*spheres)[0].center.x(), 0.5);
  EXPECT_EQ((*spheres)[0].radius, 0.125);
}

TEST(NumberText, AJointNamedTwiceIsRefused) {
  const auto twice = parseJointValues("a=1,a=2");
  ASSERT_FALSE(twice.ok());
  EXPECT_EQ(twice.error().message, "joint 'a' is given twice");
  const auto bad = parseJointValues("a=1,b=x");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, "b=x: expected JOINT=VALUE (a number)");
}

}  // namespace
}  // namespace sphereset

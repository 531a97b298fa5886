// Every option table's setter and checker through the one shared prelude (parseTableOption): a
// name the table lacks is refused with the table's rows listed, a value outside its row with the
// row's range, whatever the table.
#include <gtest/gtest.h>

#include <string>

#include "sphereset/animate.hpp"
#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
#include "sphereset/robot_fit.hpp"
#include "sphereset/tree.hpp"

namespace sphereset {
namespace {

void expectRefused(const Status& st, const std::string& message) {
  ASSERT_FALSE(st.ok()) << message;
  EXPECT_EQ(st.error().code, ErrorCode::kInvalidArgument);
  EXPECT_EQ(st.error().message, message);
}

TEST(OptionTables, UnknownNamesListTheirTable) {
  FitRequest f;
  EvalOptions e;
  RepairOptions r;
  TreeOptions t;
  expectRefused(setFitRequestOption(&f, "spheres", "4"),
                "unknown fit option 'spheres' (expected n, quality, seed, points, iterations, "
                "restarts, decimation, padding, optimizer, init, method)");
  expectRefused(setEvalOption(&e, "lights", "4"),
                "unknown evaluation option 'lights' (expected seed, samples, segments, up, "
                "shadow_resolution, shadow_lights, surface_max_depth, interior_max_depth, "
                "protrusion_tolerance)");
  expectRefused(setRepairOption(&r, "weld", "0.1"),
                "unknown repair option 'weld' (expected repair, weld_tolerance, wrap_alpha, "
                "wrap_offset, fill_openings)");
  expectRefused(setTreeOption(&t, "branch", "4"),
                "unknown tree option 'branch' (expected branching, depth, parents)");
}

TEST(OptionTables, SettersAndCheckersShareTheRowsMessages) {
  TreeOptions t;
  expectRefused(setTreeOption(&t, "depth", "27"), "depth '27': expected an integer from 1 to 26");
  t.depth = 27;
  expectRefused(checkTreeOptions(t), "depth '27': expected an integer from 1 to 26");
  RepairOptions r;
  ASSERT_TRUE(setRepairOption(&r, "wrap_offset", "0.25").ok());
  EXPECT_EQ(r.wrap_offset, 0.25);
  r.wrap_offset = -0.5;
  expectRefused(checkRepairOptions(r), "wrap_offset '-0.5': expected a number from 0 to 1e+30");
  // A row's automatic word: read as kAutomatic, named in the expectation, and a struct holding
  // kAutomatic passes the checker.
  ASSERT_TRUE(setRepairOption(&r, "fill_openings", "auto").ok());
  EXPECT_EQ(r.fill_openings, kAutomatic);
  r.wrap_offset = 0.0;
  EXPECT_TRUE(checkRepairOptions(r).ok());
  expectRefused(setRepairOption(&r, "fill_openings", "-1"),
                "fill_openings '-1': expected a number from 0 to 1e+30 or auto");
  r.fill_openings = -2.0;
  expectRefused(checkRepairOptions(r),
                "fill_openings '-2': expected a number from 0 to 1e+30 or auto");
  FitRequest f;
  ASSERT_TRUE(setFitRequestOption(&f, "quality", "fast").ok());
  EXPECT_EQ(f.quality, FitQuality::kFast);
}

TEST(OptionTables, KeyedRowsTakeKeyEqualsValue) {
  RobotFitOptions o;
  ASSERT_TRUE(setRobotFitOption(&o, "link_spheres", "link1=4").ok());
  ASSERT_TRUE(setRobotFitOption(&o, "link_spheres", "a=b=0").ok());  // split at the last '='
  ASSERT_TRUE(setRobotFitOption(&o, "link_padding", "link1=0.5").ok());
  EXPECT_EQ(o.link_spheres.at("link1"), 4);
  EXPECT_EQ(o.link_spheres.at("a=b"), 0);
  EXPECT_EQ(o.link_padding.at("link1"), 0.5);
  expectRefused(setRobotFitOption(&o, "link_spheres", "link1"),
                "link_spheres 'link1': expected LINK=VALUE, VALUE an integer from 0 to 1000000");
  expectRefused(setRobotFitOption(&o, "link_spheres", "=3"),
                "link_spheres '=3': expected LINK=VALUE, VALUE an integer from 0 to 1000000");
  expectRefused(
      setRobotFitOption(&o, "link_spheres", "link1=2.5"),
      "link_spheres 'link1=2.5': expected LINK=VALUE, VALUE an integer from 0 to 1000000");
  // A link named twice used to keep the last value silently.
  expectRefused(setRobotFitOption(&o, "link_spheres", "link1=5"),
                "link_spheres 'link1=5': link 'link1' is given twice");
  EXPECT_EQ(o.link_spheres.at("link1"), 4);
  ASSERT_TRUE(setRobotFitOption(&o, "link_solid_for", "link1=walls").ok());
  expectRefused(setRobotFitOption(&o, "link_solid_for", "link1=envelope"),
                "link_solid_for 'link1=envelope': link 'link1' is given twice");
  o.link_solid_for.clear();
  EXPECT_TRUE(checkRobotFitOptions(o).ok());
  o.link_padding["l"] = -1.0;
  expectRefused(checkRobotFitOptions(o),
                "link_padding 'l=-1': expected LINK=VALUE, VALUE a finite number >= 0");
  RobotFitOptions big;
  big.budget = 10000000;  // an integer row's value is written as a user types it
  expectRefused(checkRobotFitOptions(big),
                "budget '10000000': expected an integer from 0 to 1000000");
}

// Limits and tolerances (0 would mean none) refuse 0 in their rows, whichever door: the setters'
// text and the checkers' structs get the row's message; a struct's 0 is the field's "none".
TEST(OptionTables, LimitRowsRefuseTheirLowerEnd) {
  RobotFitOptions o;
  expectRefused(
      setRobotFitOption(&o, "max_protrusion", "0"),
      "max_protrusion '0': expected a number above 0 and at most 1e+30, optionally followed "
      "by %");
  expectRefused(setRobotFitOption(&o, "link_max_protrusion", "l=-0"),
                "link_max_protrusion 'l=-0': expected LINK=VALUE, VALUE a number above 0 and at "
                "most 1e+30, optionally followed by %");
  ASSERT_TRUE(setRobotFitOption(&o, "max_protrusion", "1e-12").ok());
  EXPECT_EQ(o.max_protrusion, 1e-12);
  o.max_protrusion = 0.0;
  EXPECT_TRUE(checkRobotFitOptions(o).ok());
  o.max_protrusion = -1.0;
  expectRefused(
      checkRobotFitOptions(o),
      "max_protrusion '-1': expected a number above 0 and at most 1e+30, optionally followed "
      "by %");
  o.max_protrusion = 0.0;
  o.link_max_protrusion["l"] = 0.0;
  expectRefused(checkRobotFitOptions(o),
                "link_max_protrusion 'l=0': expected LINK=VALUE, VALUE a number above 0 and at "
                "most 1e+30, optionally followed by %");
  ToleranceOptions t;
  expectRefused(setToleranceOption(&t, "max_er", "nan"),
                "max_er 'nan': expected a number above 0 and at most 1000000");
  ASSERT_TRUE(setToleranceOption(&t, "max_er", "1e-9").ok());
  EXPECT_EQ(t.max_er, 1e-9);
}

// A percent row takes a number with or without a trailing '%' (the same bounds either way) and
// quotes the text as given when it refuses it; a row without it refuses the '%'.
TEST(OptionTables, PercentRowsTakeATrailingPercentSign) {
  constexpr OptionSpec row{"limit", "--limit", OptionType::kReal, 0,       50,   {},
                           "none",  "",        nullptr,           nullptr, true, true};
  auto percent = parseOption(row, "5%");
  ASSERT_TRUE(percent.ok());
  EXPECT_EQ(percent->real, 5.0);
  EXPECT_TRUE(percent->percent);
  auto plain = parseOption(row, "5");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain->percent);
  for (const char* bad : {"%", "5%%", "%5", "0%", "51%", "nan%", " 5%"}) {
    auto refused = parseOption(row, bad);
    ASSERT_FALSE(refused.ok()) << bad;
    EXPECT_EQ(refused.error().message,
              "limit '" + std::string(bad) +
                  "': expected a number above 0 and at most 50, optionally followed by %");
  }
  RobotFitOptions o;  // the robot's limit: a length, or a percentage of each link's diagonal
  ASSERT_TRUE(setRobotFitOption(&o, "max_protrusion", "5%").ok());
  EXPECT_EQ(o.max_protrusion, 0.0);
  EXPECT_DOUBLE_EQ(o.max_protrusion_fraction, 0.05);
  expectRefused(setRobotFitOption(&o, "max_protrusion", "5%%"),
                "max_protrusion '5%%': expected a number above 0 and at most 1e+30, optionally "
                "followed by %");
  // A struct's percentage, checked as the text a user would type.
  const OptionSpec table[] = {row};
  EXPECT_TRUE(checkTableValue(table, "test", "limit", 5.0, {}, true).ok());
  expectRefused(checkTableValue(table, "test", "limit", 60.0, {}, true),
                "limit '60%': expected a number above 0 and at most 50, optionally followed by %");
  const OptionSpec length_only[] = {
      {"limit", "--limit", OptionType::kReal, 0, 50, {}, "none", "", nullptr, nullptr, true}};
  expectRefused(checkTableValue(length_only, "test", "limit", 5.0, {}, true),
                "limit '5%': expected a number above 0 and at most 50");
}

TEST(OptionTables, LinkSolidForDecidesLinks) {
  RobotFitOptions o;
  ASSERT_TRUE(setRobotFitOption(&o, "link_solid", "walls").ok());
  ASSERT_TRUE(setRobotFitOption(&o, "link_solid_for", "link2=envelope").ok());
  ASSERT_TRUE(setRobotFitOption(&o, "link_solid_for", "link1=walls").ok());
  auto repairOf = [&](const char* link) {
    return linkRepairOptions(o.repair, o.link_solid, o.link_solid_for, link);
  };
  // link2's envelope, chosen for it, is kept whatever its volume; the others are walls.
  EXPECT_EQ(repairOf("link2").fill_openings, kAutomatic);
  EXPECT_TRUE(repairOf("link2").keep_envelope);
  EXPECT_EQ(repairOf("link1").fill_openings, 0.0);
  EXPECT_EQ(repairOf("base_link").fill_openings, 0.0);
  expectRefused(setRobotFitOption(&o, "link_solid_for", "link1=hollow"),
                "link_solid_for 'link1=hollow': expected LINK=VALUE, VALUE envelope or walls");
  expectRefused(setRobotFitOption(&o, "link_solid_for", "walls"),
                "link_solid_for 'walls': expected LINK=VALUE, VALUE envelope or walls");
  // A size applies to the envelopes: refused only when no link is one.
  o.repair.fill_openings = 0.1;
  EXPECT_TRUE(checkRobotFitOptions(o).ok());
  EXPECT_EQ(repairOf("link2").fill_openings, 0.1);
  EXPECT_EQ(repairOf("link1").fill_openings, 0.0);
  o.link_solid_for.erase("link2");
  expectRefused(checkRobotFitOptions(o),
                "every link's solid is its walls: fill_openings 0.1 asks for an envelope; give "
                "link_solid envelope, a link_solid_for LINK=envelope or no fill_openings");
  // The envelope for all links but not chosen for any: the hollow rule decides.
  o.link_solid = LinkSolid::kEnvelope;
  o.repair.fill_openings = 0.0;
  EXPECT_EQ(repairOf("base_link").fill_openings, kAutomatic);
  EXPECT_FALSE(repairOf("base_link").keep_envelope);
  o.link_solid_for[""] = LinkSolid::kWalls;  // set in code, not through the table
  expectRefused(checkRobotFitOptions(o),
                "link_solid_for '=walls': expected LINK=VALUE, VALUE envelope or walls");
}

TEST(OptionTables, AnimationRows) {
  AnimateOptions o;
  EXPECT_EQ(o.weighting, CentreWeighting::kAuto);
  ASSERT_TRUE(setAnimateOption(&o, "weighting", "bones").ok());
  EXPECT_EQ(o.weighting, CentreWeighting::kBones);
  EXPECT_STREQ(centreWeightingName(o.weighting), "bones");
  expectRefused(setAnimateOption(&o, "weighting", "nearest"),
                "weighting 'nearest': expected auto, mvc or bones");
  o.bone_neighbours = 0;
  expectRefused(checkAnimateOptions(o), "bone_neighbours '0': expected an integer from 1 to 4096");
  SkinnedLoadOptions so;
  ASSERT_TRUE(setSkinnedLoadOption(&so, "fps", "24").ok());
  EXPECT_EQ(so.fps, 24.0);
  expectRefused(setSkinnedLoadOption(&so, "fps", "inf"),
                "fps 'inf': expected a finite number >= 0");
}

}  // namespace
}  // namespace sphereset

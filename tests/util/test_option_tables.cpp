// Every option table's setter and checker through the one shared prelude (parseTableOption): a
// name the table lacks is refused with the table's rows listed, a value outside its row with the
// row's range, whatever the table.
#include <gtest/gtest.h>

#include <string>

#include "sphereset/evaluate.hpp"
#include "sphereset/fit.hpp"
#include "sphereset/repair.hpp"
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
                "shadow_resolution, shadow_lights, surface_max_depth, interior_max_depth)");
  expectRefused(setRepairOption(&r, "weld", "0.1"),
                "unknown repair option 'weld' (expected repair, weld_tolerance, wrap_alpha, "
                "wrap_offset)");
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
  FitRequest f;
  ASSERT_TRUE(setFitRequestOption(&f, "quality", "fast").ok());
  EXPECT_EQ(f.quality, FitQuality::kFast);
}

}  // namespace
}  // namespace sphereset

// Batch: listing, one item, report lines, resuming (batch.hpp).
#include <gtest/gtest.h>

#include "sphereset/batch.hpp"

namespace sphereset {
namespace {

TEST(BatchReport, StatusNames) { EXPECT_STREQ(batchStatusName(BatchStatus::kSkipped), "skipped"); }

}  // namespace
}  // namespace sphereset

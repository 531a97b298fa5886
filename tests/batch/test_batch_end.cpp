// How a batch run ends (batchEnd): the counts, the summary and the exit code every batch door
// gives (the command and python3 -m sphereset.batch), from the exit code table.
#include <gtest/gtest.h>

#include <string>

#include "sphereset/batch.hpp"
#include "sphereset/exit_codes.hpp"

namespace sphereset {
namespace {

BatchItemReport item(BatchStatus status, bool covered) {
  BatchItemReport r;
  r.status = status;
  r.covered = covered;
  return r;
}

TEST(BatchEnd, FailuresOutrankGapsAndASkippedItemKeepsItsCoverage) {
  BatchTotals t;
  EXPECT_EQ(batchEnd(t, "in", "out").exit_code, kExitOk);
  countBatchItem(item(BatchStatus::kOk, true), &t);
  countBatchItem(item(BatchStatus::kSkipped, true), &t);
  BatchEnd end = batchEnd(t, "in", "out");
  EXPECT_EQ(end.summary, "2 items: 1 fitted, 1 skipped, 0 failed");
  EXPECT_EQ(end.exit_code, kExitOk);
  EXPECT_EQ(end.message, "");
  // A resumed run ends as the first did: the skipped item's recorded coverage counts.
  countBatchItem(item(BatchStatus::kSkipped, false), &t);
  end = batchEnd(t, "in", "out");
  EXPECT_EQ(end.exit_code, kExitUncovered);
  EXPECT_EQ(end.message,
            "in: 1 of 3 items failed the coverage check (written anyway; see out/report.jsonl)");
  // A failed item is not also "uncovered", and a failure decides the code.
  countBatchItem(item(BatchStatus::kError, false), &t);
  EXPECT_EQ(t.uncovered, 1u);
  end = batchEnd(t, "in", "out");
  EXPECT_EQ(end.summary, "4 items: 1 fitted, 2 skipped, 1 failed");
  EXPECT_EQ(end.exit_code, kExitItemsFailed);
  EXPECT_EQ(end.message, "in: 1 of 4 items failed (see out/report.jsonl)");
}

TEST(BatchEnd, AMissedToleranceOutranksCoverageButNotAFailure) {
  // Items written with best_effort whose tolerance no count met: exit 10, below a failed item
  // (8) and above an uncovered one (7); a failed item is not also counted as unmet.
  BatchTotals t;
  countBatchItem(item(BatchStatus::kOk, false), &t);
  BatchItemReport unmet = item(BatchStatus::kSkipped, true);
  unmet.tolerance_met = false;
  countBatchItem(unmet, &t);
  EXPECT_EQ(t.unmet, 1u);
  BatchEnd end = batchEnd(t, "in", "out");
  EXPECT_EQ(end.exit_code, kExitToleranceNotMet);
  EXPECT_EQ(end.message,
            "in: 1 of 2 items missed their tolerance (the best count found written; see "
            "out/report.jsonl)");
  BatchItemReport failed = item(BatchStatus::kError, false);
  failed.tolerance_met = false;
  countBatchItem(failed, &t);
  EXPECT_EQ(t.unmet, 1u);
  end = batchEnd(t, "in", "out");
  EXPECT_EQ(end.exit_code, kExitItemsFailed);
  EXPECT_EQ(end.message,
            "in: 1 of 3 items failed, 1 more missed their tolerance (see out/report.jsonl)");
}

TEST(ExitCodes, OneCodePerErrorCode) {
  EXPECT_EQ(exitCodeFor(ErrorCode::kInvalidArgument), 2);
  EXPECT_EQ(exitCodeFor(ErrorCode::kUnreadable), 3);
  EXPECT_EQ(exitCodeFor(ErrorCode::kInvalidData), 4);
  EXPECT_EQ(exitCodeFor(ErrorCode::kNotSolid), 5);
  EXPECT_EQ(exitCodeFor(ErrorCode::kWriteFailed), 6);
}

}  // namespace
}  // namespace sphereset

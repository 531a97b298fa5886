// The batch's report (batch.hpp): one JSON line per item, round-tripped; report.jsonl written
// whole at the end of a run, the partial report beside it until then; one run per output folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "sphereset/batch.hpp"
#include "test_support.hpp"

namespace sphereset {
namespace {

using BatchReportTest = test::TempDirTest;

TEST(BatchReport, LineRoundTrips) {
  BatchItemReport r;
  r.mesh = "in/a \"b\".obj";
  r.output = "a.json";
  r.status = BatchStatus::kOk;
  r.num_spheres = 32;
  r.spheres = 32;
  r.er_sum = 0.125;
  r.er_union = 0.1;
  r.covered = true;
  r.repair = "welded";
  r.seconds = 1.5;
  r.fingerprint = "0123456789abcdef";
  const std::string line = reportLine(r);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line.rfind("{\"mesh\":", 0), 0u) << line;
  auto back = parseReportLine(line);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(reportLine(*back), line);
  EXPECT_EQ(back->mesh, r.mesh);
  EXPECT_EQ(back->repair, "welded");

  r.status = BatchStatus::kError;
  r.er_sum = std::nan("");
  r.error = "a.obj: no such file";
  const std::string bad = reportLine(r);
  EXPECT_NE(bad.find("\"er_sum\":null"), std::string::npos) << bad;
  back = parseReportLine(bad);
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(std::isnan(back->er_sum));
  EXPECT_EQ(back->status, BatchStatus::kError);
  EXPECT_EQ(back->error, r.error);

  EXPECT_FALSE(parseReportLine("{\"mesh\": 3}").ok());
  EXPECT_FALSE(parseReportLine("not json").ok());
}

TEST_F(BatchReportTest, ReportFileHoldsOneLinePerItemInOrder) {
  const std::string out = path("deep/out");
  BatchItemReport r;
  std::string first_run;
  {
    auto report = BatchReport::start(out);
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_EQ(test::readFile(batchPartialReportPath(out)), "");
    for (const char* name : {"first", "second"}) {
      r.mesh = name;
      ASSERT_TRUE(report->append(r).ok());
    }
    ASSERT_TRUE(report->finish().ok());
    first_run = test::readFile(batchReportPath(out));
  }
  EXPECT_EQ(first_run, reportLine([&] {
                         BatchItemReport a = r;
                         a.mesh = "first";
                         return a;
                       }()) +
                           "\n" + reportLine(r) + "\n");
  EXPECT_FALSE(std::filesystem::exists(batchPartialReportPath(out)));
  // A run that stops before finishing (killed, or an error) leaves the last whole report.
  {
    auto report = BatchReport::start(out);
    ASSERT_TRUE(report.ok());
    ASSERT_TRUE(report->append(r).ok());
  }
  EXPECT_EQ(test::readFile(batchReportPath(out)), first_run);
  EXPECT_EQ(test::readFile(batchPartialReportPath(out)), reportLine(r) + "\n");
}

// Two runs on one folder used to interleave report.jsonl and fit every item twice.
TEST_F(BatchReportTest, OneRunAtATimePerOutputFolder) {
  const std::string out = path("locked");
  auto first = BatchReport::start(out);
  ASSERT_TRUE(first.ok());
  auto second = BatchReport::start(out);
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.error().code, ErrorCode::kWriteFailed);
  EXPECT_NE(second.error().message.find("another batch run (pid " + std::to_string(::getpid())),
            std::string::npos)
      << second.error().message;
  ASSERT_TRUE(first->finish().ok());  // finishing releases the folder
  auto third = BatchReport::start(out);
  ASSERT_TRUE(third.ok());
  BatchReport moved = std::move(third).value();
  EXPECT_FALSE(BatchReport::start(out).ok());  // the moved-to report holds the lock
}

}  // namespace
}  // namespace sphereset

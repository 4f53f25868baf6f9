// What the analysis says about damaged test points: frames lost, the time the
// data cover, the longest gap, and when it refuses to report a delay.

#include "core/analysis/data_coverage.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "synthetic.h"

namespace fog::analysis {
namespace {

using testing::makeSynthetic;
using testing::SyntheticSpec;

// Removes table samples [from, from + count).
void dropTable(TestPointData& d, std::size_t from, std::size_t count) {
  d.table.erase(d.table.begin() + static_cast<std::ptrdiff_t>(from),
                d.table.begin() + static_cast<std::ptrdiff_t>(from + count));
}
// Removes IMU frames [from, from + count); the next frame says so, as the
// decoder's sequence gap would.
void dropImu(TestPointData& d, std::size_t from, std::size_t count) {
  d.imu.erase(d.imu.begin() + static_cast<std::ptrdiff_t>(from),
              d.imu.begin() + static_cast<std::ptrdiff_t>(from + count));
  d.imu[from].lostBefore += static_cast<std::uint32_t>(count);
}
// Removes both channels for [fromS, fromS + lengthS) of the record.
void outage(TestPointData& d, double fromS, double lengthS) {
  const double t0 = d.table.front().timeS + fromS, t1 = t0 + lengthS;
  std::size_t a = 0;
  while (d.table[a].timeS < t0) ++a;
  std::size_t b = a;
  while (d.table[b].timeS < t1) ++b;
  dropTable(d, a, b - a);
  a = 0;
  while (d.imu[a].timeS < t0) ++a;
  b = a;
  while (d.imu[b].timeS < t1) ++b;
  dropImu(d, a, b - a);
}

TEST(DataCoverage, CleanDataAreFullyCovered) {
  const auto c = measureCoverage(makeSynthetic(SyntheticSpec{}));
  EXPECT_EQ(c.lostTableFrames, 0u);
  EXPECT_EQ(c.lostImuFrames, 0u);
  EXPECT_EQ(c.missingS, 0.0);
  EXPECT_EQ(c.largestGapS, 0.0);
  EXPECT_NEAR(c.spanS, 20.0, 3e-3);
  EXPECT_EQ(c.coveredFraction(), 1.0);
  EXPECT_EQ(coverageRefusal(c, 1.0), "");
}

TEST(DataCoverage, CountsLostFramesAndTheLongestGap) {
  auto d = makeSynthetic(SyntheticSpec{});
  dropTable(d, 5000, 10);  // 10 ms
  for (std::size_t i = 0; i < 50; ++i) dropTable(d, 1000 + 200 * i, 1);
  dropImu(d, 2000, 5);     // 10 ms
  dropImu(d, 4000, 1);
  const auto c = measureCoverage(d);
  EXPECT_EQ(c.lostTableFrames, 60u);
  EXPECT_EQ(c.lostImuFrames, 6u);
  EXPECT_NEAR(c.largestGapS, 10e-3, 1e-6);
  EXPECT_NEAR(c.missingS, 60e-3, 1e-6);  // the worse channel: the table
  EXPECT_NEAR(c.coveredFraction(), 1.0 - 0.06 / c.spanS, 1e-9);
  EXPECT_EQ(coverageRefusal(c, 1.0), "");
}

TEST(DelayAnalysis, SaysHowATestPointWasAffectedAndStillMeasures) {
  SyntheticSpec s;
  auto d = makeSynthetic(s);
  const auto undamaged = analyzeTestPoint(d, BenchConstants{});
  ASSERT_TRUE(undamaged.isOk());
  for (std::size_t i = 0; i < 50; ++i) dropTable(d, 1000 + 300 * i, 1);
  dropTable(d, 9000, 10);
  dropImu(d, 2000, 5);
  d.health.duplicateFrames = 7;  // as the decoder reports them for this point
  d.health.checksumFailures = 3;
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ(r->lostTableFrames, 60u);
  EXPECT_EQ(r->lostImuFrames, 5u);
  EXPECT_NEAR(r->coveredS, r->durationS - 0.06, 1e-6);
  EXPECT_NEAR(r->largestGapS, 10e-3, 1e-6);
  // Lost data cost precision, not accuracy: the same lag as the undamaged
  // record within the damaged one's uncertainty. (Both sit 0.26 us from the
  // truth: noiseless samples commensurate with the swing quantise the same
  // way every period, an error no noise averages.)
  EXPECT_NEAR(r->lagMs, undamaged->lagMs, 3.0 * r->lagStdMs);
  EXPECT_NEAR(r->lagMs, s.lagS * 1e3, 3.0 * r->lagStdMs + 0.3e-3);

  DelayReport report;
  report.points.push_back(*r);
  const std::string text = formatReportText(report, {});
  EXPECT_NE(text.find("affected: 60 table and 5 IMU frames lost, 7 duplicated, 3 checksum failures"), std::string::npos)
      << text;
  EXPECT_NE(text.find("longest gap 10.0 ms"), std::string::npos) << text;
  const auto json = nlohmann::json::parse(formatReportJson(report, {}));
  const auto& a = json["test_points"][0]["affected"];
  EXPECT_EQ(a["lost_table_frames"], 60);
  EXPECT_EQ(a["lost_imu_frames"], 5);
  EXPECT_EQ(a["duplicate_frames"], 7);
  EXPECT_NEAR(a["time_covered"].get<double>(), 1.0 - 0.06 / r->durationS, 1e-9);
}

TEST(DelayAnalysis, RefusesAcrossAGapLongerThanAPeriod) {
  auto d = makeSynthetic(SyntheticSpec{});  // 1 Hz, 20 s
  outage(d, 8.0, 1.2);
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), StatusCode::kInsufficientData);
  EXPECT_NE(r.status().message().find("a gap of 1.20 s without data is longer than one swing period (1.00 s)"),
            std::string::npos)
      << r.status().message();
}

TEST(DelayAnalysis, AcceptsAGapShorterThanAPeriod) {
  SyntheticSpec s;
  auto d = makeSynthetic(s);
  outage(d, 8.0, 0.8);
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_NEAR(r->largestGapS, 0.8, 3e-3);
  EXPECT_NEAR(r->lagMs, s.lagS * 1e3, 3.0 * r->lagStdMs + 1e-6);
}

TEST(DelayAnalysis, RefusesWhenGapsLeaveUnderTwoPeriods) {
  SyntheticSpec s;
  s.durationS = 3.5;
  auto d = makeSynthetic(s);
  outage(d, 0.5, 0.9);
  outage(d, 2.0, 0.9);
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("swing periods once gaps are removed"), std::string::npos)
      << r.status().message();
  EXPECT_NE(r.status().message().find("a delay needs at least two whole periods"), std::string::npos);
}

TEST(DelayAnalysis, RefusesWhenMoreThanAFifthOfTheRecordIsMissing) {
  auto d = makeSynthetic(SyntheticSpec{});  // 20 s
  for (double at = 1.0; at < 18.0; at += 2.0) outage(d, at, 0.6);  // 9 x 0.6 s = 27 %
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_FALSE(r.isOk());
  EXPECT_TRUE(r.status().message().find("% of the record is missing") != std::string::npos &&
              r.status().message().find("at most 20 %") != std::string::npos)
      << r.status().message();
}

TEST(DelayAnalysis, ARefusedTestPointIsListedWithItsReason) {
  Recording rec;
  rec.pulseEquivalentDeg = 1.0;
  auto good = makeSynthetic(SyntheticSpec{});
  auto bad = makeSynthetic(SyntheticSpec{});
  bad.index = 1;
  outage(bad, 5.0, 2.0);
  rec.testPoints = {good, bad};
  auto report = analyzeRecording(rec, BenchConstants{});
  ASSERT_TRUE(report.isOk());
  ASSERT_EQ(report->points.size(), 1u);
  ASSERT_EQ(report->failedPoints.size(), 1u);
  EXPECT_EQ(report->failedPoints[0].rfind("test point 2: a gap of 2.00 s without data", 0), 0u)
      << report->failedPoints[0];
  const std::string text = formatReportText(*report, {});
  EXPECT_NE(text.find("no delay from test point 2"), std::string::npos) << text;
}

}  // namespace
}  // namespace fog::analysis

// Reading a stored result back as a record (core/session/stored_result.h):
// settings with gyro signs and limit, rows stored before them, damaged rows,
// and where this version's analysis departs from a record.

#include "core/session/stored_result.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace fog::session {
namespace {

using nlohmann::json;

// A report as formatReportJson writes it, reduced to what the record reads.
json reportWith(const std::string& verdict, double imuDelayMs, const std::string& pointVerdict) {
  return {{"verdict", verdict},
          {"verdict_reasons", {"test point 1: why"}},
          {"imu_delay_limit_ms", 0.8},
          {"constants", {{"table_read_delay_ms", 0.05}, {"board_delay_ms", 0.28}}},
          {"test_points",
           {{{"index", 0},
             {"verdict", pointVerdict},
             {"verdict_reasons", {"why"}},
             {"lag_ms", imuDelayMs - 0.05},
             {"imu_delay_ms", imuDelayMs},
             {"imu_delay_std_ms", 0.001}}}}};
}

TEST(StoredResult, SettingsCarryTheGyroSignsAndTheLimit) {
  BenchConstants c;
  c.gyroSign = {-1, 1, -1};
  c.boardDelayMs = 0.3;
  const session::StoredResult row{7, "2026-11-26T07:00:00Z", analysisSettingsJson(c, 0.5, "fogbench-cli analyze"),
                                  reportWith("invalid", 0.51, "invalid").dump(), true};
  const auto r = readStoredResult(row, {});
  ASSERT_TRUE(r.usable) << r.problem;
  EXPECT_TRUE(r.gyroSignStated);
  EXPECT_EQ(r.constants.gyroSign, (std::array<int, kAxisCount>{-1, 1, -1}));
  EXPECT_DOUBLE_EQ(r.constants.boardDelayMs, 0.3);
  // The report's own limit is the one its verdict used.
  EXPECT_DOUBLE_EQ(r.imuDelayLimitMs, 0.8);
  EXPECT_EQ(r.verdict, "invalid");
  EXPECT_EQ(r.analysedBy, "fogbench-cli analyze");
  ASSERT_NE(r.point(0), nullptr);
  EXPECT_EQ(r.point(0)->verdict, "invalid");
  EXPECT_EQ(r.point(1), nullptr);
}

TEST(StoredResult, TheAuditIsStoredAndReadBack) {
  const AnalysisAudit audit{"Li Wei", "operator", "fogbench-cli analyze", "fogbench-cli analyze s.fbs",
                            std::string(64, 'a')};
  const session::StoredResult row{3, "2026-11-29T05:00:00Z", analysisSettingsJson({}, 0.8, "fogbench-cli analyze", {}, &audit),
                                  reportWith("pass", 0.51, "pass").dump(), true};
  const auto r = readStoredResult(row, {});
  ASSERT_TRUE(r.usable) << r.problem;
  ASSERT_TRUE(r.audit.has_value());
  EXPECT_EQ(r.audit->who, "Li Wei");
  EXPECT_EQ(r.audit->whoSource, "operator");
  EXPECT_EQ(r.audit->command, "fogbench-cli analyze s.fbs");
  EXPECT_EQ(r.audit->inputSha256, std::string(64, 'a'));
  // Without an audit (an export's settings): no key at all.
  EXPECT_EQ(json::parse(analysisSettingsJson({}, 0.8, "x")).count("audit"), 0u);
}

TEST(StoredResult, ARowStoredBeforeTheAuditReadsNotRecorded) {
  // settings_json as fogbench wrote it before the audit trail.
  const json settings = {{"board_delay_ms", 0.28}, {"software_version", "0.8.0"}, {"analysed_by", "fogbench GUI"}};
  const session::StoredResult row{1, "2026-11-01T00:00:00Z", settings.dump(), reportWith("fail", 0.9, "fail").dump(),
                                  true};
  const auto r = readStoredResult(row, {});
  ASSERT_TRUE(r.usable) << r.problem;
  EXPECT_FALSE(r.audit.has_value());
  const auto lines = auditTrailLines({r});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("fogbench GUI (audit not recorded)"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("input not recorded"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("fogbench 0.8.0"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("| FAIL"), std::string::npos) << lines[0];
  // A damaged row says so, never a verdict.
  const session::StoredResult damaged{2, "2026-11-02T00:00:00Z", "{}", "{}", false};
  const auto dl = auditTrailLines({readStoredResult(damaged, {})});
  EXPECT_NE(dl[0].find("cannot be read: the stored result fails its checksum"), std::string::npos) << dl[0];
}

TEST(StoredResult, CommandLinesQuoteWhatASpaceWouldSplit) {
  const char* argv[] = {"/path/to/fogbench-cli", "analyze", "my run.fbs", "--operator", "O'Brien"};
  EXPECT_EQ(commandLineOf("fogbench-cli", 5, argv), "fogbench-cli analyze 'my run.fbs' --operator 'O'\\''Brien'");
}

TEST(StoredResult, TheGainToleranceIsStoredAndReadBack) {
  BenchConstants c;
  c.gainToleranceFraction = 0.025;
  const session::StoredResult row{2, "", analysisSettingsJson(c, 0.8, "test"), reportWith("pass", 0.51, "pass").dump(),
                                  true};
  BenchConstants fallback;
  fallback.gainToleranceFraction = 0.5;  // the session's: the row's own wins
  const auto r = readStoredResult(row, fallback);
  ASSERT_TRUE(r.usable);
  EXPECT_DOUBLE_EQ(r.constants.gainToleranceFraction, 0.025);
}

TEST(StoredResult, AnOlderRowReadsAsGyroSignPlusOneAndItsReportsLimit) {
  BenchConstants fallback;
  fallback.gyroSign = {-1, -1, -1};  // the session's or the GUI's: never an older row's
  json report = reportWith("pass", 0.51, "pass");
  report["imu_delay_limit_ms"] = 1.5;
  const session::StoredResult row{1, "", R"({"table_read_delay_ms":0.05,"software_version":"0.0.9"})", report.dump(),
                                  true};
  const auto r = readStoredResult(row, fallback);
  ASSERT_TRUE(r.usable);
  EXPECT_FALSE(r.gyroSignStated);
  EXPECT_EQ(r.constants.gyroSign, (std::array<int, kAxisCount>{1, 1, 1}));
  EXPECT_DOUBLE_EQ(r.imuDelayLimitMs, 1.5);
  EXPECT_EQ(r.softwareVersion, "0.0.9");
}

TEST(StoredResult, AnIncompleteRunKeepsItsReasonAndDataVerdict) {
  json report = reportWith("incomplete", 0.51, "pass");
  report["data_verdict"] = "pass";
  report["run"] = {{"complete", false},
                   {"incomplete_reason", "stopped by the operator after 3.5 s"},
                   {"recorded_s", 3.5},
                   {"planned_s", 61.3}};
  const auto r = readStoredResult({1, "", "{}", report.dump(), true}, {});
  EXPECT_EQ(r.verdict, "incomplete");
  EXPECT_EQ(r.dataVerdict, "pass");
  EXPECT_EQ(r.incompleteReason, "stopped by the operator after 3.5 s");
  EXPECT_DOUBLE_EQ(r.plannedS, 61.3);
}

TEST(StoredResult, AnOlderRowsSignsComeFromItsReport) {
  // `analyze --gyro-sign x=-1` before the settings kept the signs.
  json report = reportWith("invalid", 0.51, "invalid");
  report["test_points"][0]["axis"] = "x";
  report["test_points"][0]["gyro_sign"] = -1;
  const auto r = readStoredResult({1, "", R"({"table_read_delay_ms":0.05})", report.dump(), true}, {});
  EXPECT_TRUE(r.gyroSignStated);
  EXPECT_EQ(r.constants.gyroSign, (std::array<int, kAxisCount>{-1, 1, 1}));
}

TEST(StoredResult, DamagedRowsAreNotUsable) {
  EXPECT_FALSE(readStoredResult({1, "", "{}", reportWith("pass", 0.5, "pass").dump(), false}, {}).usable);
  EXPECT_FALSE(readStoredResult({1, "", "not json", reportWith("pass", 0.5, "pass").dump(), true}, {}).usable);
  EXPECT_FALSE(readStoredResult({1, "", "{}", "[1]", true}, {}).usable);
  std::vector<StoredResultRecord> records = {readStoredResult({1, "", "{}", "{}", true}, {}),
                                             readStoredResult({2, "", "{}", "{}", false}, {})};
  ASSERT_NE(newestUsable(records), nullptr);
  EXPECT_EQ(newestUsable(records)->id, 1);
}

TEST(StoredResult, DifferencesBeyondRoundingAreNamed) {
  analysis::DelayReport now;
  analysis::TestPointResult p;
  p.index = 0;
  p.imuDelayMs = 0.51;
  p.imuDelayStdMs = 0.001;
  now.points.push_back(p);
  const auto same = readStoredResult({1, "", "{}", reportWith("pass", 0.51 + 4e-7, "pass").dump(), true}, {});
  EXPECT_TRUE(differencesFromRecord(same, now).empty());
  const auto other = readStoredResult({1, "", "{}", reportWith("fail", 0.52, "fail").dump(), true}, {});
  const auto d = differencesFromRecord(other, now);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], "test point 1: IMU delay 0.5200 ms stored, 0.5100 ms by this version's analysis");
  EXPECT_EQ(d[1], "test point 1: fail stored, pass by this version's analysis");
}

}  // namespace
}  // namespace fog::session

namespace fog::session {
namespace {

// The decision rule's k is a stored setting: written into the settings'
// `decision_rule`, read back; the report's own k (what judged it) wins; a row
// stored before k was kept reads as k = 2, saying so.
TEST(StoredResult, TheCoverageFactorIsStoredAndReadBack) {
  const std::string settings = analysisSettingsJson(BenchConstants{}, 0.6, "fogbench-cli analyze", {}, nullptr, 3.0);
  const auto stored = nlohmann::json::parse(settings);
  EXPECT_EQ(stored["decision_rule"]["coverage_factor_k"].get<double>(), 3.0);
  EXPECT_EQ(stored["decision_rule"]["limit_ms"].get<double>(), 0.6);
  EXPECT_NE(stored["decision_rule"]["rule"].get<std::string>().find("k*sigma < limit"), std::string::npos);

  const auto r = readStoredResult({4, "", settings, reportWith("pass", 0.51, "pass").dump(), true}, {});
  ASSERT_TRUE(r.usable) << r.problem;
  EXPECT_TRUE(r.coverageKStated);
  EXPECT_EQ(r.coverageK, 3.0);
  EXPECT_EQ(decisionRuleProvenance(r), "");

  json report = reportWith("pass", 0.51, "pass");
  report["decision_rule"] = {{"coverage_factor_k", 2.5}};
  EXPECT_EQ(readStoredResult({5, "", settings, report.dump(), true}, {}).coverageK, 2.5);
}

TEST(StoredResult, ARowStoredBeforeKWasKeptReadsAsKTwoAndSaysSo) {
  const auto r = readStoredResult({1, "", R"({"imu_delay_limit_ms":0.8})", reportWith("pass", 0.51, "pass").dump(), true}, {});
  ASSERT_TRUE(r.usable);
  EXPECT_FALSE(r.coverageKStated);
  EXPECT_EQ(r.coverageK, 2.0);
  EXPECT_EQ(decisionRuleProvenance(r), "not stored: the rule of that version, k = 2");
  // A stored k the rule refuses (a hand-edited row) is not taken either.
  json bad = reportWith("pass", 0.51, "pass");
  bad["decision_rule"] = {{"coverage_factor_k", -4}};
  EXPECT_FALSE(readStoredResult({2, "", "{}", bad.dump(), true}, {}).coverageKStated);
}

}  // namespace
}  // namespace fog::session

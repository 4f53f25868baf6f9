// The verdict shown (core/session/shown_verdict.h): the one rule every view,
// command and export formats — a record's verdict as stored, a result not
// stored judged once, an incomplete run INCOMPLETE with its data's verdict
// beside it, and which delays are vouched for.

#include "core/session/shown_verdict.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/session/shown_csv.h"

namespace fog::session {
namespace {

using K = ShownVerdictKind;

analysis::TestPointResult point(int index, double imuDelayMs, double stdMs, bool checksPass = true) {
  analysis::TestPointResult p;
  p.index = index;
  p.imuDelayMs = imuDelayMs;
  p.imuDelayStdMs = stdMs;
  p.lagMs = imuDelayMs - 0.05;
  p.lagStdMs = stdMs;
  if (!checksPass) p.checks.push_back({"axis_sign", false, "the gyro turns against the table"});
  return p;
}

// Point 1 passes 0.8 (0.52 + 2 x 0.01), point 2 fails it (0.79 + 0.02),
// point 3 is invalid.
analysis::DelayReport threePoints() {
  analysis::DelayReport r;
  r.points = {point(0, 0.52, 0.01), point(1, 0.79, 0.01), point(2, 0.5155, 0.0002, false)};
  return r;
}

StoredResultRecord recordOf(const std::string& verdict, const std::vector<std::pair<int, std::string>>& points) {
  StoredResultRecord r;
  r.id = 3;
  r.usable = true;
  r.verdict = verdict;
  r.verdictReasons = {"as stored"};
  r.imuDelayLimitMs = 0.6;
  for (const auto& [index, v] : points) {
    StoredPointVerdict p;
    p.index = index;
    p.verdict = v;
    p.reasons = {"stored reason " + std::to_string(index)};
    p.lagMs = 0.1 * (index + 1);
    p.lagStdMs = 0.001;
    p.imuDelayMs = 0.2 * (index + 1);
    p.imuDelayStdMs = 0.002;
    r.points.push_back(p);
  }
  return r;
}

TEST(ShownVerdict, AResultNotStoredIsJudgedOnceWithTheLimit) {
  const auto report = threePoints();
  const ShownVerdict v = judgeShown(nullptr, &report, true, {}, 0.8);
  EXPECT_FALSE(v.stored);
  EXPECT_EQ(v.verdict, K::kInvalid);
  EXPECT_EQ(v.dataVerdict, K::kInvalid);
  ASSERT_EQ(v.points.size(), 3u);
  EXPECT_EQ(v.points[0].verdict, K::kPass);
  EXPECT_EQ(v.points[1].verdict, K::kFail);
  EXPECT_EQ(v.points[2].verdict, K::kInvalid);
  // PASS and FAIL are measurements; INVALID is refused, with why.
  EXPECT_TRUE(v.points[0].vouched());
  EXPECT_TRUE(v.points[1].vouched());
  EXPECT_FALSE(v.points[2].vouched());
  EXPECT_EQ(v.points[2].refusal(), "INVALID: the gyro turns against the table");
  EXPECT_EQ(v.points[0].refusal(), "");
  EXPECT_FALSE(v.allVouched());
  // A wider limit passes the second point: the limit is the caller's.
  const ShownVerdict wide = judgeShown(nullptr, &report, true, {}, 1.0);
  EXPECT_EQ(wide.points[1].verdict, K::kPass);
}

TEST(ShownVerdict, AStoredRecordIsShownAsStoredNeverReJudged) {
  const auto report = threePoints();  // this analysis would say pass, fail, invalid against 0.8
  const auto record = recordOf("pass", {{0, "pass"}, {1, "pass"}, {2, "pass"}});
  const ShownVerdict v = judgeShown(&record, &report, true, {}, 0.8);
  EXPECT_TRUE(v.stored);
  EXPECT_EQ(v.verdict, K::kPass);
  EXPECT_DOUBLE_EQ(v.limitMs, 0.6);  // the record's limit, not the caller's
  EXPECT_EQ(v.reasons, std::vector<std::string>{"as stored"});
  ASSERT_EQ(v.points.size(), 3u);
  for (const auto& p : v.points) {
    EXPECT_EQ(p.verdict, K::kPass) << p.index;
    EXPECT_TRUE(p.vouched());
    // The record's numbers, not this analysis'.
    EXPECT_DOUBLE_EQ(p.imuDelayMs, 0.2 * (p.index + 1));
    EXPECT_DOUBLE_EQ(p.lagStdMs, 0.001);
  }
}

TEST(ShownVerdict, APointTheRecordDoesNotStateIsRefused) {
  const auto report = threePoints();
  const auto record = recordOf("pass", {{0, "pass"}});
  const ShownVerdict v = judgeShown(&record, &report, true, {}, 0.8);
  ASSERT_EQ(v.points.size(), 3u);
  EXPECT_EQ(v.points[1].verdict, K::kNone);
  EXPECT_FALSE(v.points[1].vouched());
  EXPECT_EQ(v.points[1].refusal(), "no verdict: the stored result has no delay for this test point");
  // Without an analysis, the record's own points.
  const ShownVerdict alone = judgeShown(&record, nullptr, true, {}, 0.8);
  ASSERT_EQ(alone.points.size(), 1u);
  EXPECT_EQ(alone.points[0].verdict, K::kPass);
}

TEST(ShownVerdict, AnIncompleteRunIsIncompleteWithItsDataVerdictBeside) {
  const auto report = threePoints();
  const ShownVerdict v = judgeShown(nullptr, &report, false, "stopped by the operator", 0.8);
  EXPECT_EQ(v.verdict, K::kIncomplete);
  EXPECT_EQ(v.dataVerdict, K::kInvalid);
  EXPECT_EQ(v.incompleteReason, "stopped by the operator");
  for (const auto& p : v.points) {
    EXPECT_EQ(p.verdict, K::kIncomplete);
    EXPECT_FALSE(p.vouched()) << "no point of a run that stopped early passes";
  }
  EXPECT_EQ(v.points[0].dataVerdict, K::kPass);
  EXPECT_EQ(v.points[0].refusal(), "INCOMPLETE: the run stopped before its plan ended (its data give PASS)");

  // A stored incomplete record: the same, from what it stored.
  auto record = recordOf("incomplete", {{0, "pass"}});
  record.dataVerdict = "pass";
  record.incompleteReason = "the port vanished";
  const ShownVerdict stored = judgeShown(&record, nullptr, false, "ignored: the record states it", 0.8);
  EXPECT_EQ(stored.verdict, K::kIncomplete);
  EXPECT_EQ(stored.dataVerdict, K::kPass);
  EXPECT_EQ(stored.incompleteReason, "the port vanished");
  EXPECT_EQ(stored.points[0].verdict, K::kIncomplete);
  EXPECT_EQ(stored.points[0].dataVerdict, K::kPass);
}

TEST(ShownVerdict, WordsAndNamesRoundTrip) {
  for (auto k : {K::kPass, K::kFail, K::kInvalid, K::kIncomplete}) EXPECT_EQ(shownVerdictKind(shownVerdictName(k)), k);
  EXPECT_EQ(shownVerdictKind(""), K::kNone);
  EXPECT_EQ(shownVerdictKind("PASS"), K::kNone);  // the stored words are lower case
  EXPECT_STREQ(shownVerdictWord(K::kNone), "NO VERDICT");
  EXPECT_STREQ(shownVerdictWord(K::kInvalid), "INVALID");
}

TEST(ShownCsv, EveryDelayRowCarriesItsPointsVerdict) {
  const auto report = threePoints();
  const ShownVerdict v = judgeShown(nullptr, &report, true, {}, 0.8);
  const std::string csv = delayBreakdownCsv(report, v, "session S.fbs");
  EXPECT_NE(csv.find("# result verdict: INVALID (not stored, limit 0.8 ms)"), std::string::npos) << csv;
  EXPECT_NE(csv.find("test_point,axis,frequency_hz,quantity,value_ms,std_ms,verdict,vouched,reason\n"),
            std::string::npos);
  int rows = 0, refused = 0;
  std::size_t at = 0;
  while ((at = csv.find('\n', at)) != std::string::npos) {
    const std::size_t next = csv.find('\n', at + 1);
    const std::string line = csv.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    at += 1;
    if (line.empty() || line[0] == '#' || line.rfind("test_point", 0) == 0) continue;
    ++rows;
    if (line.find(",invalid,false,the gyro turns against the table") != std::string::npos) ++refused;
  }
  EXPECT_EQ(rows, 15);    // five quantities for each of three points
  EXPECT_EQ(refused, 5);  // every row of the invalid point says so
  EXPECT_EQ(csvField("a, \"b\""), "\"a, \"\"b\"\"\"");
  EXPECT_EQ(csvField("plain"), "plain");
}

// Text a person typed is never run by a spreadsheet as a formula: a field
// starting with = + - @ (or a tab, a carriage return) gets a single quote.
TEST(ShownCsv, TextThatLooksLikeAFormulaIsWrittenAsText) {
  EXPECT_EQ(csvTextField("=HYPERLINK(\"http://x\",\"y\")"), "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csvTextField("+L7"), "'+L7");
  EXPECT_EQ(csvTextField("-B1"), "'-B1");
  EXPECT_EQ(csvTextField("@ann"), "'@ann");
  EXPECT_EQ(csvTextField("\tcmd"), "'\tcmd");
  EXPECT_EQ(csvTextField("SN-0042"), "SN-0042");  // only a leading sign
  EXPECT_EQ(csvTextField(""), "");
  EXPECT_EQ(csvTextField("a, b"), "\"a, b\"");
}

// The shown verdict carries the rule's k: a record's own (never today's
// default), a result not stored the run's; each vouched point its risk.
TEST(ShownVerdict, CarriesTheRecordsKNotTodaysDefault) {
  StoredResultRecord record = recordOf("pass", {{0, "pass"}, {1, "invalid"}});
  record.coverageK = 3.0;
  record.coverageKStated = true;
  const ShownVerdict v = judgeShown(&record, nullptr, true, {}, 0.8, 2.0);
  EXPECT_EQ(v.coverageK, 3.0);
  EXPECT_EQ(v.ruleProvenance, "");
  EXPECT_NE(decisionRuleLine(v).find("(k = 3,"), std::string::npos) << decisionRuleLine(v);
  EXPECT_NE(decisionRuleLine(v).find("limit 0.6 ms"), std::string::npos) << decisionRuleLine(v);
  // Point 1: 0.2 ± 0.002 ms against 0.6 ms; point 2 is INVALID: no risk.
  EXPECT_NEAR(v.points[0].falseAcceptProbability, 0.5 * std::erfc(200.0 / std::sqrt(2.0)), 1e-300);
  EXPECT_NEAR(v.points[0].guardBandMs, 0.006, 1e-15);
  EXPECT_TRUE(std::isnan(v.points[1].falseAcceptProbability));

  StoredResultRecord older = recordOf("pass", {{0, "pass"}});
  const ShownVerdict o = judgeShown(&older, nullptr, true, {}, 0.8, 3.0);
  EXPECT_EQ(o.coverageK, 2.0);  // the rule of that version, not the 3 asked now
  EXPECT_NE(decisionRuleLine(o).find("(k not stored: the rule of that version, k = 2)"), std::string::npos)
      << decisionRuleLine(o);
}

TEST(ShownVerdict, AResultNotStoredIsJudgedWithTheRunsK) {
  const analysis::DelayReport report = threePoints();
  // Point 1: 0.52 + 3 × 0.01 = 0.55 < 0.6; point 2: 0.79 > 0.6.
  const ShownVerdict at3 = judgeShown(nullptr, &report, true, {}, 0.55, 3.0);
  EXPECT_EQ(at3.coverageK, 3.0);
  EXPECT_EQ(at3.points[0].verdict, K::kFail);  // 0.55 is not below 0.55
  const ShownVerdict at2 = judgeShown(nullptr, &report, true, {}, 0.55, 2.0);
  EXPECT_EQ(at2.points[0].verdict, K::kPass);  // 0.54 < 0.55
  EXPECT_NEAR(at2.points[0].falseAcceptProbability, 0.5 * std::erfc(3.0 / std::sqrt(2.0)), 1e-12);
  // Stopped early: nothing vouched, no risk.
  const ShownVerdict stopped = judgeShown(nullptr, &report, false, "stopped", 0.55, 2.0);
  EXPECT_TRUE(std::isnan(stopped.points[0].falseAcceptProbability));
}

}  // namespace
}  // namespace fog::session

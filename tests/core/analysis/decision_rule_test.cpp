// The decision rule and its risk (core/analysis/decision_rule.h) and the
// verdict's coverage factor k (verdict.h): the probabilities against the
// normal distribution's tabulated values, k changing a verdict, and the
// reports stating the rule.

#include "core/analysis/decision_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/analysis/report_writer.h"
#include "core/analysis/verdict.h"

namespace fog::analysis {
namespace {

// 1 − Φ(2) and 1 − Φ(3), tabulated (17 digits; e.g. Abramowitz & Stegun
// 26.2, or mpmath ncdf): independent of the code under test.
constexpr double kTailAt2 = 0.022750131948179207;
constexpr double kTailAt3 = 0.0013498980316300946;

TestPointResult pointAt(double imuDelayMs, double stdMs, bool checksPass = true) {
  TestPointResult p;
  p.imuDelayMs = imuDelayMs;
  p.imuDelayStdMs = stdMs;
  p.lagMs = imuDelayMs - 0.05;
  p.lagStdMs = stdMs;
  if (!checksPass) p.checks.push_back({"axis_sign", false, "the gyro turns against the table"});
  return p;
}

TEST(DecisionRule, TheMaximumFalseAcceptRiskIsTheNormalTailAtK) {
  EXPECT_NEAR(maxFalseAcceptProbability(2.0), 0.022750131948179, 1e-12);
  EXPECT_NEAR(maxFalseAcceptProbability(2.0), kTailAt2, 1e-15);
  EXPECT_NEAR(maxFalseAcceptProbability(3.0), kTailAt3, 1e-15);
  EXPECT_NEAR(standardNormalCdf(0.0), 0.5, 1e-16);
  EXPECT_NEAR(standardNormalCdf(-2.0), kTailAt2, 1e-15);
  EXPECT_NEAR(standardNormalCdf(2.0), 1.0 - kTailAt2, 1e-15);
  // Far in the tail erfc keeps the digits 1 − Φ would lose: 1 − Φ(10) ≈ 7.6e-24.
  EXPECT_NEAR(maxFalseAcceptProbability(10.0) / 7.619853024160527e-24, 1.0, 1e-12);
  EXPECT_EQ(probabilityText(maxFalseAcceptProbability(2.0)), "2.28 %");
  EXPECT_EQ(probabilityText(maxFalseAcceptProbability(3.0)), "0.135 %");
  // Far beyond the limit's reach the tail underflows to 0: never shown as "0 %".
  EXPECT_EQ(falseAcceptProbability(0.5, 1e-4, 0.8), 0.0);
  EXPECT_EQ(probabilityText(falseAcceptProbability(0.5, 1e-4, 0.8)), "< 1e-6 %");
  EXPECT_EQ(probabilityText(0.5), "50.0 %");
}

TEST(DecisionRule, APointJustAtTheBoundaryCarriesTheRulesMaximumRisk) {
  // d = limit − 2σ exactly (binary-exact numbers): P(true ≥ limit) = 1 − Φ(2).
  const double limit = 1.0, sigma = 0.125, d = limit - 2.0 * sigma;
  EXPECT_NEAR(falseAcceptProbability(d, sigma, limit), kTailAt2, 1e-15);
  EXPECT_NEAR(falseAcceptProbability(limit - 3.0 * sigma, sigma, limit), kTailAt3, 1e-15);
  EXPECT_NEAR(falseAcceptProbability(limit, sigma, limit), 0.5, 1e-16);
  // A delay above the limit: the complement.
  EXPECT_NEAR(falseAcceptProbability(limit + 2.0 * sigma, sigma, limit), 1.0 - kTailAt2, 1e-15);
  // And the verdict at the boundary: delay + 2σ = limit is not below it.
  const PointVerdict v = judgePoint(pointAt(d, sigma), limit, 2.0);
  EXPECT_EQ(v.verdict, Verdict::kFail);
  EXPECT_DOUBLE_EQ(v.guardBandMs, 0.25);
  EXPECT_NEAR(v.falseAcceptProbability, kTailAt2, 1e-15);
}

TEST(DecisionRule, ZeroSigmaIsCertainAndBadInputIsNotANumber) {
  EXPECT_EQ(falseAcceptProbability(0.7, 0.0, 0.8), 0.0);
  EXPECT_EQ(falseAcceptProbability(0.8, 0.0, 0.8), 1.0);
  EXPECT_EQ(falseAcceptProbability(0.9, 0.0, 0.8), 1.0);
  EXPECT_TRUE(std::isnan(falseAcceptProbability(0.7, -0.1, 0.8)));
  EXPECT_TRUE(std::isnan(falseAcceptProbability(std::nan(""), 0.1, 0.8)));
  EXPECT_TRUE(std::isnan(falseAcceptProbability(0.7, HUGE_VAL, 0.8)));
}

TEST(DecisionRule, KOutsideZeroToTenIsRefusedSayingWhy) {
  for (double bad : {0.0, -1.0, 10.5, std::nan(""), HUGE_VAL}) {
    const std::string why = coverageFactorProblem(bad);
    EXPECT_NE(why.find("coverage factor k"), std::string::npos) << bad;
  }
  for (double good : {0.5, 2.0, 3.0, 10.0}) EXPECT_EQ(coverageFactorProblem(good), "") << good;
}

TEST(DecisionRule, TheRuleIsStatedWithItsKAndRisk) {
  EXPECT_EQ(decisionRuleText(2.0),
            "PASS when IMU delay + k·σ < limit (k = 2, one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6 / "
            "ILAC-G8:09/2019); FAIL otherwise; INVALID when a validity check fails");
  EXPECT_NE(decisionRuleText(3.0).find("(k = 3,"), std::string::npos);
  EXPECT_NE(decisionRiskText(3.0).find("0.135 %"), std::string::npos);
}

TEST(Verdict, KChangesAVerdict) {
  // 0.55 + 2 × 0.1 = 0.75 < 0.8: PASS; 0.55 + 3 × 0.1 = 0.85 ≥ 0.8: FAIL.
  const TestPointResult p = pointAt(0.55, 0.1);
  const PointVerdict at2 = judgePoint(p, 0.8, 2.0), at3 = judgePoint(p, 0.8, 3.0);
  EXPECT_EQ(at2.verdict, Verdict::kPass);
  EXPECT_EQ(at3.verdict, Verdict::kFail);
  ASSERT_FALSE(at3.reasons.empty());
  EXPECT_NE(at3.reasons.front().find("+ 3σ = 0.8500 ms ≥ 0.8 ms limit"), std::string::npos) << at3.reasons.front();
  // The specific risk is the point's, whatever k: 1 − Φ(2.5).
  EXPECT_NEAR(at2.falseAcceptProbability, 0.5 * std::erfc(2.5 / std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(at2.falseAcceptProbability, 0.0062096653257761, 1e-12);
  EXPECT_DOUBLE_EQ(at2.falseAcceptProbability, at3.falseAcceptProbability);
  EXPECT_NEAR(at3.guardBandMs, 0.3, 1e-15);

  DelayReport report;
  report.points = {p};
  EXPECT_EQ(judgeReport(report, 0.8, 2.0).verdict, Verdict::kPass);
  const ReportVerdict strict = judgeReport(report, 0.8, 3.0);
  EXPECT_EQ(strict.verdict, Verdict::kFail);
  EXPECT_EQ(strict.coverageK, 3.0);
}

TEST(Verdict, AnInvalidPointCarriesNoRisk) {
  const PointVerdict v = judgePoint(pointAt(0.5, 0.01, false), 0.8, 2.0);
  EXPECT_EQ(v.verdict, Verdict::kInvalid);
  EXPECT_TRUE(std::isnan(v.falseAcceptProbability));
}

TEST(ReportWriter, BothReportsStateTheRuleAndEachVouchedPointsRisk) {
  DelayReport report;
  report.points = {pointAt(0.55, 0.1), pointAt(0.5, 0.01, false)};
  report.points[1].index = 1;
  ReportContext context;
  context.coverageK = 3.0;
  const std::string text = formatReportText(report, context);
  EXPECT_NE(text.find("decision rule: PASS when IMU delay + k·σ < limit (k = 3,"), std::string::npos) << text;
  EXPECT_NE(text.find("1 − Φ(k) = 0.135 %"), std::string::npos) << text;
  EXPECT_NE(text.find("guard band 3σ = 0.3 ms; probability that the true delay is at or above the limit: 0.621 %"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("no false-accept probability: the delay is refused (INVALID)"), std::string::npos) << text;

  const auto doc = nlohmann::json::parse(formatReportJson(report, context));
  EXPECT_EQ(doc["decision_rule"]["coverage_factor_k"].get<double>(), 3.0);
  EXPECT_EQ(doc["decision_rule"]["limit_ms"].get<double>(), 0.8);
  EXPECT_NEAR(doc["decision_rule"]["max_false_accept_probability"].get<double>(), kTailAt3, 1e-15);
  EXPECT_EQ(doc["verdict"], "invalid");  // point 2 is invalid
  const auto& tp = doc["test_points"];
  EXPECT_NEAR(tp[0]["false_accept_probability"].get<double>(), 0.0062096653257761, 1e-12);
  EXPECT_NEAR(tp[0]["guard_band_ms"].get<double>(), 0.3, 1e-15);
  EXPECT_TRUE(tp[1]["false_accept_probability"].is_null());
  EXPECT_TRUE(tp[1]["guard_band_ms"].is_null());
  EXPECT_NE(tp[1]["false_accept_note"].get<std::string>().find("refused"), std::string::npos);

  // An incomplete run vouches for no delay: no risk number either.
  context.incompleteReason = "stopped by the operator";
  const auto stopped = nlohmann::json::parse(formatReportJson(report, context));
  EXPECT_TRUE(stopped["test_points"][0]["false_accept_probability"].is_null());
}

}  // namespace
}  // namespace fog::analysis

// The standard frequency-response plan (issue 40, docs/method.md "The
// standard plan"): the one-third-octave grid 0.1 .. 10 Hz with amplitudes
// from the table's limits and whole-period dwells, and the per-point phase
// a certificate states (analysis::certifiedPhase: against the table's
// motion, U at k = 2 with the table read delay's uncertainty in the budget).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/analysis/frequency_response.h"
#include "core/analysis/theory.h"
#include "core/common/test_plan.h"
#include "core/common/units.h"
#include "core/table/table_controller.h"

namespace fog::analysis {
namespace {

// The grid: IEC 61260-1's base-10 bands k = -10 .. 10, nominal values within
// 1 % of the exact 10^(k/10) Hz, each an ISO 266 R10 preferred number.
TEST(StandardPlan, GridIsTheNominalOneThirdOctavesFromPointOneToTenHertz) {
  const std::vector<double> expected = {0.1, 0.125, 0.16, 0.2, 0.25, 0.315, 0.4, 0.5, 0.63, 0.8, 1.0,
                                        1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0, 10.0};
  ASSERT_EQ(thirdOctaveNominalHz(), expected);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const double exact = std::pow(10.0, (static_cast<double>(i) - 10.0) / 10.0);
    EXPECT_NEAR(expected[i] / exact, 1.0, 0.0096) << expected[i];
  }
  const auto plan = presetPlan("response-third-octave");
  ASSERT_TRUE(plan.isOk()) << plan.status().message();
  ASSERT_EQ(plan->points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(plan->points[i].frequencyHz, expected[i]);  // the nominal value itself
    EXPECT_EQ(plan->points[i].axis, Axis::kX);
  }
  EXPECT_NE(std::find(presetPlanNames().begin(), presetPlanNames().end(), "response-third-octave"),
            presetPlanNames().end());
}

// Amplitudes: the largest within 80 % of the angle, rate and acceleration
// limits (rounded down to 0.001 deg); dwell: whole periods, settle
// max(1 period, 1 s), record max(6 periods, 10 s); the plan passes the
// table's checks and every point reaches a phase resolution far below the
// 0.5 deg (k = 2) PTB states.
TEST(StandardPlan, AmplitudesAreTheTablesWithinTheMarginAndDwellsWholePeriods) {
  const TurntableLimits limits;
  const auto plan = thirdOctaveResponsePlan(limits);
  ASSERT_TRUE(plan.isOk()) << plan.status().message();
  EXPECT_TRUE(plan->validate(limits).isOk());
  table::TableLimits tableLimits;
  tableLimits.axes.fill(limits);
  EXPECT_TRUE(table::checkPlanAgainstLimits(*plan, tableLimits).isOk());
  const double margin = ResponsePlanOptions{}.limitMargin;
  ASSERT_EQ(margin, 0.8);
  double worstPhaseDeg = 0.0;
  for (const auto& p : plan->points) {
    const double f = p.frequencyHz, w = kTwoPi * f;
    const double allowed = std::min({margin * limits.maxAmplitudeDeg, margin * limits.maxRateDegPerS / w,
                                     margin * limits.maxAccelDegPerS2 / (w * w)});
    EXPECT_LE(p.amplitudeDeg, allowed + 1e-12) << f;
    EXPECT_GT(p.amplitudeDeg, allowed - 0.001) << f;  // the largest, to the rounding
    EXPECT_LE(w * p.amplitudeDeg, margin * limits.maxRateDegPerS + 1e-9) << f;
    EXPECT_LE(w * w * p.amplitudeDeg, margin * limits.maxAccelDegPerS2 + 1e-9) << f;
    const double periods = p.durationS * f, settle = p.settleS * f;
    EXPECT_NEAR(periods, std::round(periods), 1e-9) << f;
    EXPECT_NEAR(settle, std::round(settle), 1e-9) << f;
    EXPECT_GE(std::round(periods), 6.0) << f;
    EXPECT_GE(p.durationS, 10.0 - 1e-9) << f;
    EXPECT_GE(p.settleS, 1.0 - 1e-9) << f;
    EXPECT_EQ(std::round(settle), std::ceil(std::max(1.0, f) - 1e-9)) << f;
    PlannedTest t;
    t.frequencyHz = f;
    t.amplitudeDeg = p.amplitudeDeg;
    t.durationS = p.durationS;
    worstPhaseDeg = std::max(worstPhaseDeg, w * predictedLagStdS(t) * kDegPerRad);
  }
  const auto& first = plan->points.front();
  const auto& last = plan->points.back();
  EXPECT_EQ(first.amplitudeDeg, 36.0);  // 80 % of the 45-deg angle limit
  EXPECT_EQ(first.durationS, 60.0);     // 6 periods of 0.1 Hz
  EXPECT_EQ(first.settleS, 10.0);
  EXPECT_EQ(plan->points[11].amplitudeDeg, 36.0);  // 1.25 Hz: still the angle limit
  EXPECT_EQ(plan->points[12].amplitudeDeg, 23.747);  // 1.6 Hz: the acceleration's, 2400 / (2 pi 1.6)^2
  EXPECT_EQ(last.amplitudeDeg, 0.607);   // 2400 / (2 pi 10)^2 = 0.6079
  EXPECT_EQ(last.durationS, 10.0);
  EXPECT_EQ(last.settleS, 1.0);
  std::printf("  %zu points %.3g .. %.3g Hz, %.1f s in all, worst predicted phase sigma %.2e deg\n",
              plan->points.size(), first.frequencyHz, last.frequencyHz, plan->totalDurationS(), worstPhaseDeg);
  EXPECT_NEAR(plan->totalDurationS(), 454.41, 0.01);
  EXPECT_LE(worstPhaseDeg, 0.01);
}

// --axis: the same grid on another axis; a weaker table is refused, naming
// the frequency, rather than given a shorter grid; bad options are refused.
TEST(StandardPlan, AnotherAxisAndAWeakTable) {
  const auto y = responsePreset("response-third-octave", Axis::kY);
  ASSERT_TRUE(y.isOk()) << y.status().message();
  ASSERT_EQ(y->points.size(), 21u);
  for (const auto& p : y->points) EXPECT_EQ(p.axis, Axis::kY);
  EXPECT_TRUE(isResponsePreset("response-third-octave"));
  EXPECT_TRUE(isResponsePreset("response"));
  EXPECT_FALSE(isResponsePreset("paper"));
  EXPECT_FALSE(responsePreset("paper", Axis::kX).isOk());

  TurntableLimits weak;
  weak.maxAccelDegPerS2 = 1000.0;  // 0.8 * 1000 / (2 pi 10)^2 = 0.2 deg at 10 Hz, under 0.5
  const auto refused = thirdOctaveResponsePlan(weak);
  ASSERT_FALSE(refused.isOk());
  EXPECT_NE(refused.status().message().find("at 8 Hz"), std::string::npos) << refused.status().message();
  EXPECT_NE(refused.status().message().find("no frequency of it is dropped"), std::string::npos) << refused.status().message();
  TurntableLimits slow;
  slow.maxFrequencyHz = 5.0;
  const auto tooSlow = thirdOctaveResponsePlan(slow);
  ASSERT_FALSE(tooSlow.isOk());
  EXPECT_NE(tooSlow.status().message().find("at 6.3 Hz"), std::string::npos) << tooSlow.status().message();
  ResponsePlanOptions bad;
  bad.limitMargin = 1.5;
  EXPECT_FALSE(thirdOctaveResponsePlan(TurntableLimits{}, bad).isOk());
  // A smaller margin lowers every amplitude but keeps the grid (0.7: 0.532
  // deg at 10 Hz); 0.5 would leave 0.38 deg there, under the 0.5 a point needs.
  ResponsePlanOptions gentler;
  gentler.limitMargin = 0.7;
  const auto gentle = thirdOctaveResponsePlan(TurntableLimits{}, gentler);
  ASSERT_TRUE(gentle.isOk()) << gentle.status().message();
  EXPECT_EQ(gentle->points.front().amplitudeDeg, 31.5);
  EXPECT_EQ(gentle->points.back().frequencyHz, 10.0);
  EXPECT_EQ(gentle->points.back().amplitudeDeg, 0.531);
  gentler.limitMargin = 0.5;
  EXPECT_FALSE(thirdOctaveResponsePlan(TurntableLimits{}, gentler).isOk());
}

ResponsePoint point(double f, double lagMs, double lagStdMs) {
  ResponsePoint p;
  p.frequencyHz = f;
  p.magnitude = 1.0;
  p.magnitudeStd = 1e-5;
  p.lagMs = lagMs;
  p.lagStdMs = lagStdMs;
  p.phaseDeg = -360.0 * f * lagMs * 1e-3;
  p.phaseStdDeg = 360.0 * f * lagStdMs * 1e-3;
  return p;
}

// The certificate's phase against the closed form: phase - omega d, u the
// fit's and the read delay's in quadrature, U = 2u, and U in ms = U / omega
// = 2 sqrt(sigma_lag^2 + u_d^2).
TEST(StandardPlan, CertifiedPhaseCarriesTheReadDelayInItsBudget) {
  const ResponsePoint p = point(10.0, 0.5, 0.001);
  const CertifiedPhase c = certifiedPhase(p, 0.05, 0.01);
  EXPECT_EQ(c.coverageK, 2.0);
  EXPECT_NEAR(c.phaseDeg, -360.0 * 10.0 * 0.55e-3, 1e-12);  // -1.98 deg: the IMU delay's phase
  EXPECT_NEAR(c.fitStdDeg, 3.6e-3, 1e-15);
  EXPECT_NEAR(c.readDelayStdDeg, 3.6e-2, 1e-15);
  EXPECT_NEAR(c.standardDeg, std::hypot(3.6e-3, 3.6e-2), 1e-15);
  EXPECT_NEAR(c.expandedDeg, 2.0 * std::hypot(3.6e-3, 3.6e-2), 1e-15);
  EXPECT_NEAR(c.expandedMs, 2.0 * std::hypot(0.001, 0.01), 1e-15);
  // Not stated (0): only the fit's share.
  const CertifiedPhase exact = certifiedPhase(p, 0.05, 0.0);
  EXPECT_NEAR(exact.expandedDeg, 2.0 * 3.6e-3, 1e-15);
  EXPECT_NEAR(exact.expandedMs, 0.002, 1e-15);
  EXPECT_EQ(exact.readDelayStdDeg, 0.0);
  // At 0.1 Hz the same time uncertainty is 100 times fewer degrees.
  const CertifiedPhase slow = certifiedPhase(point(0.1, 0.5, 0.001), 0.05, 0.01);
  EXPECT_NEAR(slow.expandedMs, c.expandedMs, 1e-15);
  EXPECT_NEAR(slow.expandedDeg * 100.0, c.expandedDeg, 1e-14);
  // Wrapped as the point's phase: a lag near half a period stays within (-180, 180].
  const CertifiedPhase wrapped = certifiedPhase(point(10.0, 49.99, 0.001), 0.05, 0.0);
  EXPECT_NEAR(wrapped.phaseDeg, 360.0 - 360.0 * 10.0 * 50.04e-3, 1e-9);
}

// The response's text and JSON state it per point with the constants the
// analysis used (analyzeResponses takes them from the report).
TEST(StandardPlan, ResponseTextAndJsonStateTheExpandedPhaseUncertainty) {
  ResponseAnalysis r;
  r.tableReadDelayMs = 0.05;
  r.tableReadDelayStdMs = 0.01;
  r.points = {point(1.0, 0.5, 0.001), point(10.0, 0.5, 0.001)};
  r.groupDelayAtHz = 5.0;
  const std::string text = formatResponseText({r});
  EXPECT_NE(text.find("table read delay 0.05 ± 0.01 ms), expanded uncertainty U (k = 2)"), std::string::npos) << text;
  EXPECT_NE(text.find("U deg"), std::string::npos) << text;
  EXPECT_NE(text.find("   10.0000   -1.98000  7.24e-02  2.01e-02"), std::string::npos) << text;
  EXPECT_EQ(text.find("not stated"), std::string::npos) << text;
  const auto doc = nlohmann::json::parse(formatResponseJson({r}));
  const auto& axis = doc["responses"][0];
  EXPECT_EQ(axis["table_read_delay_std_ms"].get<double>(), 0.01);
  EXPECT_EQ(axis["coverage_factor"].get<double>(), 2.0);
  const auto& last = axis["points"][1];
  EXPECT_NEAR(last["phase_expanded_uncertainty_ms"].get<double>(), 2.0 * std::hypot(0.001, 0.01), 1e-15);
  EXPECT_NEAR(last["phase_expanded_uncertainty_deg"].get<double>(), 2.0 * std::hypot(3.6e-3, 3.6e-2), 1e-15);
  EXPECT_NEAR(last["phase_vs_table_motion_deg"].get<double>(), -1.98, 1e-12);
  EXPECT_EQ(last["coverage_factor"].get<double>(), 2.0);
  r.tableReadDelayStdMs = 0.0;
  EXPECT_NE(formatResponseText({r}).find("the table read delay's uncertainty is not stated"), std::string::npos);
}

}  // namespace
}  // namespace fog::analysis

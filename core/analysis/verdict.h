#pragma once
// The calibration verdict of a delay report: the one rule that the text and
// JSON reports, the GUI and the PDF all show.
//
// Per test point:
//   invalid: a validity check failed (validity.h): the delay is refused;
//   fail:    IMU delay + k sigma >= the limit (one-sided guarded acceptance,
//            coverage factor k, 2 by default, so a delay that is only
//            probably below the limit fails);
//   pass:    every check passed and IMU delay + k sigma < the limit.
// k is a stored setting of the result (decision_rule.h states the rule and
// its risk; a row stored before k was kept was judged with k = 2).
// The report: invalid when any test point is invalid or gave no delay, fail
// when any test point fails, pass only when every test point passes.

#include <string>
#include <vector>

#include "core/analysis/decision_rule.h"
#include "core/analysis/delay_analysis.h"

namespace fog::analysis {

enum class Verdict { kPass, kFail, kInvalid };

// "pass", "fail", "invalid" (the JSON report's values).
const char* verdictName(Verdict v);

// The default k (decision_rule.h kDefaultCoverageFactor); the rule's k is
// the result's setting, passed to judgePoint/judgeReport.
inline constexpr double kVerdictCoverageFactor = kDefaultCoverageFactor;

// Decimals (in ms) that show an uncertainty to two significant digits, and
// never fewer than the paper's four: 0.0015 -> 4, 0.00010 -> 5. The text
// report and the verdict's sentences write delays with it.
int decimalsFor(double stdMs);
inline constexpr double kDefaultImuDelayLimitMs = 0.8;

struct PointVerdict {
  int index = 0;  // test point index (0-based)
  Verdict verdict = Verdict::kInvalid;
  double upperMs = 0.0;  // IMU delay + k sigma
  double guardBandMs = 0.0;  // k sigma
  // PASS/FAIL points only (NaN for an INVALID one, whose delay is refused):
  // P(true delay >= limit | delay, sigma), decision_rule.h.
  double falseAcceptProbability = 0.0;
  // Why, in a sentence each: the failed checks' details, or the comparison
  // with the limit ("IMU delay 0.5158 ± 0.0015 ms; + 2σ = 0.5188 ms < 0.8 ms limit (margin 0.2812 ms)").
  std::vector<std::string> reasons;
};

struct ReportVerdict {
  Verdict verdict = Verdict::kInvalid;
  double limitMs = kDefaultImuDelayLimitMs;
  double coverageK = kDefaultCoverageFactor;  // the rule's k
  std::vector<std::string> reasons;  // "test point 2: ..." for every point that is not a pass
  std::vector<PointVerdict> points;  // one per analysed test point, report order
};

// `coverageK`: the rule's k (the result's setting; the caller checks it with
// coverageFactorProblem).
PointVerdict judgePoint(const TestPointResult& point, double imuDelayLimitMs,
                        double coverageK = kDefaultCoverageFactor);
ReportVerdict judgeReport(const DelayReport& report, double imuDelayLimitMs,
                          double coverageK = kDefaultCoverageFactor);

}  // namespace fog::analysis

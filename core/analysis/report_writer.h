#pragma once
// The delay report as a person reads it (plain text) and as a program reads
// it (JSON). Numbers in JSON are plain, locale-independent doubles.
//
// JSON layout: {"verdict": "pass"|"fail"|"invalid"|"incomplete", "verdict_reasons": [...],
//   "run": {"complete", "incomplete_reason", "recorded_s", "planned_s"} and
//   "data_verdict" (only for an incomplete run),
//   "imu_delay_limit_ms": ..., "decision_rule": {"rule", "coverage_factor_k",
//   "limit_ms", "max_false_accept_probability", "statement"}, "software": ..., "source": ..., "constants": {...},
//   "stream": {...}, "test_points": [{"axis", "frequency_hz", "amplitude_deg",
//   "table_fit": {"period_ms", "phase_ms", "amplitude_deg", ...},
//   "gyro_fit": {...}, "lag_ms", "lag_std_ms", "crlb_ms", "imu_delay_ms",
//   "gyro_delay_ms", "verdict", "verdict_reasons", "guard_band_ms",
//   "false_accept_probability" (null, with "false_accept_note", for a point
//   whose delay is refused), "checks": [{"id", "passed",
//   "detail"}], ...}], "frequency_consistency": [...], "failed_points": [...]}
// (docs/report.md lists every key.)

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/verdict.h"

namespace fog::analysis {

// What the analysis does not know about where the data came from.
struct ReportContext {
  std::string source;  // "simulator (seed 1)", "raw stream run.bin"
  // Known true lag per test point, by test point index (simulator only).
  std::vector<double> trueLagMs;
  // The acceptance limit of the verdict (verdict.h).
  double imuDelayLimitMs = kDefaultImuDelayLimitMs;
  // The decision rule's coverage factor k (decision_rule.h): PASS needs
  // IMU delay + k sigma < the limit.
  double coverageK = kDefaultCoverageFactor;
  // The run ended before its plan did (stopped by the operator, a vanished
  // port, a full disk, the memory budget): why; empty for a complete run or
  // data of unknown completeness. The report's verdict is then "incomplete",
  // whatever the recorded data give (that is still shown as data_verdict).
  std::string incompleteReason;
  double recordedS = 0.0;  // stream time the run recorded, s (0: unknown)
  double plannedS = 0.0;   // the plan's total time, s (0: unknown)
};

// "run stopped after 3.4 s of 62.3 s: <reason>" (the recorded and planned
// stream time when known; else the reason alone), or "" for a complete run.
std::string incompleteRunText(const ReportContext& context);

std::string formatReportText(const DelayReport& report, const ReportContext& context);
std::string formatReportJson(const DelayReport& report, const ReportContext& context);

}  // namespace fog::analysis

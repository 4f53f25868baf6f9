#pragma once
// The delay report as a person reads it (plain text) and as a program reads
// it (JSON). Numbers in JSON are plain, locale-independent doubles.
//
// JSON layout: {"verdict": "pass"|"fail"|"invalid", "verdict_reasons": [...],
//   "imu_delay_limit_ms": ..., "software": ..., "source": ..., "constants": {...},
//   "stream": {...}, "test_points": [{"axis", "frequency_hz", "amplitude_deg",
//   "table_fit": {"period_ms", "phase_ms", "amplitude_deg", ...},
//   "gyro_fit": {...}, "lag_ms", "lag_std_ms", "crlb_ms", "imu_delay_ms",
//   "gyro_delay_ms", "verdict", "verdict_reasons", "checks": [{"id", "passed",
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
};

std::string formatReportText(const DelayReport& report, const ReportContext& context);
std::string formatReportJson(const DelayReport& report, const ReportContext& context);

}  // namespace fog::analysis

#pragma once
// A stored result as a record: the settings that produced it and the verdict
// it gave, read back from the session's `result` row (settings_json and
// report_json, docs/sessions.md). Qt-free; the one parser the CLI (report,
// sessions) and the GUI (Results, Sessions, Compare, the PDF) share.
//
// The rule it serves (docs/report.md, "Stored results"): a stored result is
// a record, never a recomputation. Every view shows the verdict, its reasons
// and the limit exactly as stored; a different setting (constants, gyro
// signs, limit) is a new analysis stored as a new result. A view may
// re-analyse the data with the stored settings to draw plots and fits; when
// that re-analysis gives other numbers than the record it says so, and the
// verdict shown is still the stored one.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/verdict.h"
#include "core/session/session_file.h"

namespace fog::session {

// One test point's stored verdict.
struct StoredPointVerdict {
  int index = 0;                     // test point index (0-based)
  std::string verdict;               // "pass", "fail", "invalid"
  std::vector<std::string> reasons;  // as stored (English, core wording)
  double lagMs = 0.0, lagStdMs = 0.0;
  double imuDelayMs = 0.0, imuDelayStdMs = 0.0;
};

struct StoredResultRecord {
  std::int64_t id = 0;
  std::string createdUtc;
  // False: the row fails its checksum, or its settings or report do not
  // parse as JSON objects: it cannot be shown (`problem` says why).
  bool usable = false;
  std::string problem;

  // The settings (settings_json; for older rows, what the report states,
  // then `fallback`).
  std::string softwareVersion;  // "" when not stated
  std::string analysedBy;       // "acquisition", "fogbench GUI", "fogbench-cli analyze", ...
  BenchConstants constants;
  // The signs come from the settings, or, for a row stored before they were
  // kept there, from its report's per-point `gyro_sign` (the swing axes');
  // an axis neither states is +1. False: nothing stated any sign.
  bool gyroSignStated = false;
  double imuDelayLimitMs = analysis::kDefaultImuDelayLimitMs;
  bool limitStated = false;     // false: neither the settings nor the report state it
  // The decision rule's coverage factor k (decision_rule.h) the verdict was
  // judged with: the settings' or report's `decision_rule`; a row stored
  // before k was kept was judged with k = 2 (coverageKStated false).
  double coverageK = analysis::kDefaultCoverageFactor;
  bool coverageKStated = false;
  // What the import applied to make the recording (rate convention, swing
  // windows), as the settings state it; empty for a recorded session or a
  // row stored before the settings held it.
  ImportSettings imported;

  // The verdict (report_json): "pass", "fail", "invalid", "incomplete";
  // "" when the stored report states none (a very old row).
  std::string verdict;
  std::vector<std::string> verdictReasons;
  // An incomplete run: why it stopped, and what its recorded data gave.
  std::string incompleteReason;
  std::string dataVerdict;
  double recordedS = 0.0, plannedS = 0.0;
  std::vector<StoredPointVerdict> points;  // report order

  // The stored point of test point `index`, or null.
  const StoredPointVerdict* point(int index) const;
};

// Reads one stored result. Constants the row does not state come from
// `fallback` (the session's own bench constants). Never fails: a row that
// cannot be read is returned with usable = false and the reason.
StoredResultRecord readStoredResult(const session::StoredResult& stored, const BenchConstants& fallback);

std::vector<StoredResultRecord> readStoredResults(const std::vector<session::StoredResult>& stored,
                                                  const BenchConstants& fallback);

// Where the record's decision rule comes from, for every view that states
// it: "" when the record stores its k, else "not stored: the rule of that
// version, k = 2".
std::string decisionRuleProvenance(const StoredResultRecord& record);

// The newest usable record, or null.
const StoredResultRecord* newestUsable(const std::vector<StoredResultRecord>& records);

// Where this version's analysis of the same data with the record's settings
// departs from the record beyond rounding (IMU delay by more than 1e-6 ms,
// a point's verdict judged against the stored limit), one sentence each;
// empty when it agrees.
std::vector<std::string> differencesFromRecord(const StoredResultRecord& record, const analysis::DelayReport& now);

// The settings a stored result was produced with, as JSON (settings_json):
// the bench constants with the gyro signs, the acceptance limit, the
// software version, what produced it and, for an imported session, what the
// import applied (its rate convention and swing windows: `import`), and the
// decision rule (`decision_rule`: {"rule", "coverage_factor_k", "limit_ms"}).
std::string analysisSettingsJson(const BenchConstants& constants, double imuDelayLimitMs,
                                 const std::string& producedBy, const ImportSettings& imported = {},
                                 double coverageK = analysis::kDefaultCoverageFactor);

}  // namespace fog::session

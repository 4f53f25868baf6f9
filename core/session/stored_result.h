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

// Who analysed a session, with what, on which data: a stored result's audit
// trail entry (settings_json `audit`, docs/sessions.md). Stored result rows
// are append-only and checksummed, so the rows are the trail.
struct AnalysisAudit {
  std::string who;          // the operator named to the analysing command, else the login name
  std::string whoSource;    // "operator" (named) or "login" (the account the program ran as)
  std::string tool;         // "fogbench-cli analyze", "fogbench GUI Results", "acquisition", ...
  std::string command;      // the CLI's argument line, or the GUI view's name
  std::string inputSha256;  // SHA-256 (hex) of the session's raw byte stream analysed; "" not known
};

// The login name of the account this program runs as (getpwuid(geteuid())),
// else $USER, else "uid N".
std::string loginName();
// An audit entry: `who` is `operatorName` when one was named, else the
// login name, and `whoSource` says which.
AnalysisAudit makeAudit(const std::string& operatorName, std::string tool, std::string command,
                        std::string inputSha256);
// `program` and argv[1..] joined with spaces, an argument holding a space or
// a quote quoted ('...'): the command line as the audit states it
// ("fogbench-cli analyze s.fbs --board-delay-ms 0.2"; argv[0] is a path).
std::string commandLineOf(const std::string& program, int argc, const char* const* argv);

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
  // Who analysed it, with what, on which data; unset for a row stored before
  // the audit trail was kept ("not recorded").
  std::optional<AnalysisAudit> audit;

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
// audit entry (`audit`; left out when `audit` is null: an export's settings,
// which store nothing) and the decision rule (`decision_rule`: {"rule",
// "coverage_factor_k", "limit_ms"}).
std::string analysisSettingsJson(const BenchConstants& constants, double imuDelayLimitMs,
                                 const std::string& producedBy, const ImportSettings& imported = {},
                                 const AnalysisAudit* audit = nullptr,
                                 double coverageK = analysis::kDefaultCoverageFactor);

// The session's audit trail: one line per stored result, oldest first:
// "#2 2026-11-29T05:10:00Z by li (operator) fogbench-cli analyze [analyze
// s.fbs --board-delay-ms 0.2] | constants: table read 0.100 ± 0.010 ms,
// board 0.200 ± 0.010 ms, limit 1 ms, k 2 | fogbench 0.9.0 | input
// 3fa9c1d2e4b5 | PASS". A row that cannot be read says so; a row stored
// before the trail says "audit not recorded".
std::vector<std::string> auditTrailLines(const std::vector<StoredResultRecord>& records);

}  // namespace fog::session

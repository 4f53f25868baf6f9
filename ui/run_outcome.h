#pragma once
// Everything the result view shows about one analysed recording, whether it
// was just acquired or opened from a session file. Built off the GUI thread.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/model/simulator.h"
#include "ui/plot_data/test_point_traces.h"

namespace fog::session {
struct StoredResult;
}

namespace fog::ui {

// One analysis result stored in a session file (session::StoredResult), as
// far as the GUI chooses among them: when, by what, with which constants.
struct ResultRecord {
  std::int64_t id = 0;           // the session's result id (later results have larger ids)
  std::string createdUtc;        // when it was stored
  std::string softwareVersion;   // the fogbench version that stored it ("" when not stated)
  std::string analysedBy;        // "acquisition", "fogbench GUI", "fogbench-cli analyze", ...
  analysis::BenchConstants constants;
  // False: the row fails its checksum or its settings cannot be read; it
  // cannot be shown.
  bool usable = true;
  // The IMU delay the stored report gives per test point index (what the
  // version that stored it computed), to tell when this version's analysis
  // gives other numbers.
  std::vector<std::pair<int, double>> storedImuDelayMs;
};

// The session's results as records, oldest first. A constant a result's
// settings do not state (older files) is taken from `fallback` (the
// session's own bench constants).
std::vector<ResultRecord> resultRecords(const std::vector<session::StoredResult>& stored,
                                        const analysis::BenchConstants& fallback);
// The newest usable record, or null.
const ResultRecord* newestUsable(const std::vector<ResultRecord>& records);

struct RunOutcome {
  SessionInfo info;            // who, what, plan, bench constants
  std::string sessionPath;     // empty when the data was not recorded
  bool complete = true;        // false: stopped, or the source failed
  std::string incompleteReason;
  Recording recording;
  Result<analysis::DelayReport> report = Status(StatusCode::kInsufficientData, "not analysed");
  std::vector<TestPointTraces> traces;      // one per report point, same order (empty traces if none)
  std::vector<model::TestPointTruth> truth; // the simulator's, when it was the source
  std::string reportText;                   // formatReportText, or why there is no report
  // The session's stored results, oldest first (empty when not recorded),
  // and which of them `report` is (0: none; the report was computed from
  // the session's own constants because none is stored).
  std::vector<ResultRecord> results;
  std::int64_t shownResultId = 0;
  const ResultRecord* shownResult() const;
  // 1-based position of the shown result among `results` (0: none).
  int shownResultNumber() const;
};

// Analyses nothing: fills traces and report text for a recording whose report
// is already in `outcome.report`. `source` is the report's source line.
void completeOutcome(RunOutcome& outcome, const std::string& source);

}  // namespace fog::ui

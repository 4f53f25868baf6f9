#pragma once
// Everything the result view shows about one analysed recording, whether it
// was just acquired or opened from a session file. Built off the GUI thread.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/session/shown_verdict.h"
#include "core/session/stored_result.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/model/simulator.h"
#include "ui/plot_data/test_point_traces.h"

namespace fog::ui {

// One analysis result stored in a session file, as a record: the settings
// that produced it and the verdict it gave (core/session/stored_result.h, the
// parser the CLI shares). The GUI shows that verdict, never a re-judgement.
using ResultRecord = session::StoredResultRecord;

using session::newestUsable;

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
  // The frequency response of every axis with two or more passed points,
  // from `report` (analyzeResponses, the group delay at
  // kDefaultGroupDelayAtHz): what `fogbench-cli response` prints.
  std::vector<analysis::ResponseAnalysis> responses;
  // The limit a result not stored in a session is judged with (the run's
  // setting); a stored result's verdict and limit are its record's.
  double imuDelayLimitMs = analysis::kDefaultImuDelayLimitMs;
  double coverageK = analysis::kDefaultCoverageFactor;  // likewise the decision rule's k
  // The session's stored results, oldest first (empty when not recorded),
  // and which of them `report` is (0: none; the report was computed from
  // the session's own constants because none is stored).
  std::vector<ResultRecord> results;
  std::int64_t shownResultId = 0;
  const ResultRecord* shownResult() const;
  // Where `report` (this version's analysis with the shown result's
  // settings, for the plots) departs from the shown record beyond rounding
  // (session::differencesFromRecord); empty when it agrees or none is
  // shown. The verdict shown is the record's all the same.
  std::vector<std::string> differences;
  // 1-based position of the shown result among `results` (0: none).
  int shownResultNumber() const;
  // The verdict shown and each point's numbers with theirs (core's one rule,
  // session::judgeShown): the shown record's, else `report` judged with
  // `imuDelayLimitMs`; INCOMPLETE when the run stopped early.
  session::ShownVerdict shownVerdict() const;
};

// Analyses nothing: fills traces and report text for a recording whose report
// is already in `outcome.report`. `source` is the report's source line.
void completeOutcome(RunOutcome& outcome, const std::string& source);

}  // namespace fog::ui

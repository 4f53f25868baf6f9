#pragma once
// Everything the result view shows about one analysed recording, whether it
// was just acquired or opened from a session file. Built off the GUI thread.

#include <memory>
#include <string>
#include <vector>

#include "analysis/delay_analysis.h"
#include "common/recording.h"
#include "common/session_info.h"
#include "model/simulator.h"
#include "ui/test_point_traces.h"

namespace fog::ui {

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
};

// Analyses nothing: fills traces and report text for a recording whose report
// is already in `outcome.report`. `source` is the report's source line.
void completeOutcome(RunOutcome& outcome, const std::string& source);

}  // namespace fog::ui

#include "ui/run_outcome.h"

#include <algorithm>

#include "analysis/report_writer.h"

namespace fog::ui {

void completeOutcome(RunOutcome& outcome, const std::string& source) {
  outcome.traces.clear();
  if (!outcome.report) {
    outcome.reportText = "No delay was reported.\n\n" + outcome.report.status().message() + "\n";
    if (!outcome.complete) outcome.reportText += "\nThe run is incomplete: " + outcome.incompleteReason + "\n";
    return;
  }
  const auto& report = *outcome.report;
  const double scale = outcome.recording.pulseEquivalentDeg > 0.0 ? 1.0 : report.constants.pulseEquivalentDeg;
  for (const auto& point : report.points) {
    const auto& points = outcome.recording.testPoints;
    const auto data = std::find_if(points.begin(), points.end(),
                                   [&](const TestPointData& d) { return d.index == point.index; });
    Result<TestPointTraces> traces = data == points.end() ? Result<TestPointTraces>(insufficientData("no data"))
                                                          : makeTestPointTraces(*data, point, scale);
    if (traces) {
      outcome.traces.push_back(std::move(*traces));
    } else {
      TestPointTraces empty;  // keeps traces aligned with report.points
      empty.index = point.index;
      outcome.traces.push_back(std::move(empty));
    }
  }
  analysis::ReportContext context;
  context.source = source;
  // The report pairs trueLagMs with its points by position; a test point that
  // gave no delay is missing from report.points, so match by index.
  for (const auto& point : report.points) {
    const auto t = std::find_if(outcome.truth.begin(), outcome.truth.end(),
                                [&](const model::TestPointTruth& x) { return x.index == point.index; });
    if (t == outcome.truth.end()) break;
    context.trueLagMs.push_back(t->lagS * 1e3);
  }
  outcome.reportText = analysis::formatReportText(report, context);
  if (!outcome.complete) outcome.reportText = "INCOMPLETE RUN: " + outcome.incompleteReason + "\n\n" + outcome.reportText;
}

}  // namespace fog::ui

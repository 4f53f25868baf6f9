#include "ui/run_outcome.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "core/analysis/report_writer.h"

namespace fog::ui {

namespace {

std::string limitText(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

const ResultRecord* RunOutcome::shownResult() const {
  for (const auto& r : results)
    if (r.id == shownResultId && shownResultId != 0) return &r;
  return nullptr;
}

int RunOutcome::shownResultNumber() const {
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].id == shownResultId && shownResultId != 0) return static_cast<int>(i) + 1;
  return 0;
}

session::ShownVerdict RunOutcome::shownVerdict() const {
  return session::judgeShown(shownResult(), report ? &*report : nullptr, complete, incompleteReason, imuDelayLimitMs,
                             coverageK);
}

void completeOutcome(RunOutcome& outcome, const std::string& source) {
  outcome.traces.clear();
  outcome.responses.clear();
  if (!outcome.report) {
    outcome.reportText = "No delay was reported.\n\n" + outcome.report.status().message() + "\n";
    if (!outcome.complete) outcome.reportText += "\nThe run is incomplete: " + outcome.incompleteReason + "\n";
    return;
  }
  const auto& report = *outcome.report;
  for (const auto& point : report.points) {
    const auto& points = outcome.recording.testPoints;
    const auto data = std::find_if(points.begin(), points.end(),
                                   [&](const TestPointData& d) { return d.index == point.index; });
    Result<TestPointTraces> traces = data == points.end() ? Result<TestPointTraces>(insufficientData("no data"))
                                                          : makeTestPointTraces(*data, point);
    if (traces) {
      outcome.traces.push_back(std::move(*traces));
    } else {
      TestPointTraces empty;  // keeps traces aligned with report.points
      empty.index = point.index;
      outcome.traces.push_back(std::move(empty));
    }
  }
  outcome.responses = analysis::analyzeResponses(report);
  analysis::ReportContext context;
  context.source = source;
  const ResultRecord* shown = outcome.shownResult();
  context.imuDelayLimitMs = shown ? shown->imuDelayLimitMs : outcome.imuDelayLimitMs;
  context.coverageK = shown ? shown->coverageK : outcome.coverageK;
  if (!outcome.complete) context.incompleteReason = outcome.incompleteReason;
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
  if (shown) {
    // The record first: its verdict is the one that counts; the text below
    // is this version's analysis with the record's settings (for the plots).
    const session::ShownVerdict v = outcome.shownVerdict();
    std::string head = std::string("Stored verdict: ") + session::shownVerdictWord(v.verdict);
    if (v.verdict == session::ShownVerdictKind::kIncomplete)
      head += std::string(" (the data recorded give ") + session::shownVerdictWord(v.dataVerdict) + ")";
    head += ", against the stored limit of " + limitText(v.limitMs) + " ms\n";
    for (const auto& why : v.reasons) head += "  " + why + "\n";
    if (!outcome.differences.empty()) {
      head += "This version's analysis of the same data with the same settings differs from the stored result:\n";
      for (const auto& d : outcome.differences) head += "  " + d + "\n";
    }
    head += "\nThis version's analysis with the stored result's settings (plots and fits):\n";
    outcome.reportText = head + outcome.reportText;
  }
}

}  // namespace fog::ui

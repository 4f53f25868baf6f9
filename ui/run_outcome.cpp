#include "ui/run_outcome.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

#include "core/analysis/report_writer.h"
#include "core/session/session_file.h"

namespace fog::ui {

namespace {

QJsonObject objectOf(const std::string& json) {
  QJsonParseError error{};
  const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(json), &error);
  return error.error == QJsonParseError::NoError && doc.isObject() ? doc.object() : QJsonObject();
}

double numberOr(const QJsonObject& o, const char* key, double fallback) {
  const QJsonValue v = o.value(QLatin1String(key));
  return v.isDouble() ? v.toDouble() : fallback;
}

}  // namespace

std::vector<ResultRecord> resultRecords(const std::vector<session::StoredResult>& stored,
                                        const analysis::BenchConstants& fallback) {
  std::vector<ResultRecord> out;
  for (const auto& r : stored) {
    ResultRecord rec;
    rec.id = r.id;
    rec.createdUtc = r.createdUtc;
    const QJsonObject settings = objectOf(r.settingsJson);
    const QJsonObject report = objectOf(r.reportJson);
    const QJsonObject reported = report.value("constants").toObject();
    rec.usable = r.intact && !settings.isEmpty();
    rec.softwareVersion = settings.value("software_version").toString().toStdString();
    rec.analysedBy = settings.value("analysed_by").toString().toStdString();
    auto constant = [&](const char* key, double otherwise) {
      return numberOr(settings, key, numberOr(reported, key, otherwise));
    };
    rec.constants = fallback;
    rec.constants.tableReadDelayMs = constant("table_read_delay_ms", fallback.tableReadDelayMs);
    rec.constants.tableReadDelayStdMs = constant("table_read_delay_std_ms", fallback.tableReadDelayStdMs);
    rec.constants.boardDelayMs = constant("board_delay_ms", fallback.boardDelayMs);
    rec.constants.boardDelayStdMs = constant("board_delay_std_ms", fallback.boardDelayStdMs);
    rec.constants.pulseEquivalentDeg = constant("pulse_equivalent_deg", fallback.pulseEquivalentDeg);
    for (const QJsonValue& v : report.value("test_points").toArray()) {
      const QJsonObject tp = v.toObject();
      if (tp.value("index").isDouble() && tp.value("imu_delay_ms").isDouble())
        rec.storedImuDelayMs.emplace_back(tp.value("index").toInt(), tp.value("imu_delay_ms").toDouble());
    }
    out.push_back(std::move(rec));
  }
  return out;
}

const ResultRecord* newestUsable(const std::vector<ResultRecord>& records) {
  for (auto r = records.rbegin(); r != records.rend(); ++r)
    if (r->usable) return &*r;
  return nullptr;
}

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

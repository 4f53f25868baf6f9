#include "ui/data_export.h"

#include <QObject>
#include <QDir>
#include <QSaveFile>

#include "core/analysis/frequency_response.h"
#include "core/io/csv_export.h"
#include "core/io/hdf5_export.h"
#include "core/session/session_file.h"
#include "core/session/shown_csv.h"

namespace fog::ui {

namespace {

std::string num(double v) { return io::formatDouble(v); }

using session::oneLine;

}  // namespace

Status exportSessionData(const RunOutcome& outcome, const QString& dir) {
  const analysis::DelayReport* report = outcome.report ? &*outcome.report : nullptr;
  return io::exportCsv(QDir::toNativeSeparators(dir).toStdString(), outcome.info, outcome.recording, report, false);
}

Status exportSessionHdf5(const RunOutcome& outcome, const QString& path) {
  const std::string file = QDir::toNativeSeparators(path).toStdString();
  if (session::isSqliteFile(file))
    return invalidArgument(file + " is a session (or another database); a session is never overwritten: "
                           "choose another name");
  const analysis::DelayReport* report = outcome.report ? &*outcome.report : nullptr;
  const session::ShownVerdict verdict = outcome.shownVerdict();
  const io::Hdf5Extras extras = io::hdf5Extras(outcome.recording, report, outcome.info.bench);
  io::Hdf5ExportInput in;
  in.info = &outcome.info;
  in.recording = &outcome.recording;
  in.report = report;
  in.shown = &verdict;
  in.sessionPath = outcome.sessionPath;  // empty (no SHA-256) for a run without a session
  in.source = outcome.info.source;
  in.responses = &extras.responses;
  in.noise = &extras.noise;
  return io::exportHdf5(file, in, true);
}

std::string comparisonCsv(const std::vector<PointComparison>& rows, const analysis::DelayReport& a,
                          const analysis::DelayReport& b, const std::string& aName, const std::string& bName) {
  std::string t = "# fogbench comparison of the IMU delay (ms, 1 sigma): B - A\n";
  t += "# A: " + oneLine(aName) + "\n# B: " + oneLine(bName) + "\n";
  t += "# a delay whose verdict is not pass or fail is refused: no difference is taken with it\n";
  t += "test_point,axis,frequency_hz,amplitude_deg,a_imu_delay_ms,a_std_ms,a_verdict,b_imu_delay_ms,b_std_ms,"
       "b_verdict,difference_ms,difference_std_ms,significance,note\n";
  int n = 0;
  for (const auto& r : rows) {
    const analysis::TestPointResult& p = r.a ? a.points[*r.a] : b.points[*r.b];
    // The amplitude as Compare matches points by: the table's fitted one.
    t += std::to_string(++n) + "," + axisLabel(p.axis) + "," + num(p.nominalFrequencyHz) + "," +
         num(p.tableFit.amplitudeDeg) + ",";
    t += r.a ? num(r.aMs) + "," + num(r.aStdMs) + "," + session::shownVerdictName(r.aShown.verdict) : std::string(",,");
    t += ",";
    t += r.b ? num(r.bMs) + "," + num(r.bStdMs) + "," + session::shownVerdictName(r.bShown.verdict) : std::string(",,");
    t += ",";
    std::string note;
    if (r.comparable()) {
      t += num(r.differenceMs) + "," + num(r.differenceStdMs) + "," + num(r.significance);
    } else {
      t += ",,";
      note = !r.both()              ? std::string("tested in one session only")
             : !r.aShown.vouched() ? "not compared: A's delay is refused (" + r.aShown.refusal() + ")"
                                   : "not compared: B's delay is refused (" + r.bShown.refusal() + ")";
    }
    t += "," + session::csvField(note) + "\n";
  }
  return t;
}

QString writeTextFile(const QString& path, const std::string& text) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
    return QObject::tr("Cannot create %1: %2. Nothing was written; choose another folder.")
        .arg(QDir::toNativeSeparators(path), file.errorString());
  const auto size = static_cast<qint64>(text.size());
  if (file.write(text.data(), size) != size || !file.commit())
    return QObject::tr("Could not write all of %1 (%2; disk full?). Nothing was changed there; "
                       "free some space or choose another folder.")
        .arg(QDir::toNativeSeparators(path), file.errorString());
  return QString();
}

}  // namespace fog::ui

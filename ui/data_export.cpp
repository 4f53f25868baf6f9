#include "ui/data_export.h"

#include <QObject>
#include <QDir>
#include <QSaveFile>

#include "core/io/csv_export.h"

namespace fog::ui {

namespace {

std::string num(double v) { return io::formatDouble(v); }

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

Status exportSessionData(const RunOutcome& outcome, const QString& dir) {
  const analysis::DelayReport* report = outcome.report ? &*outcome.report : nullptr;
  return io::exportCsv(QDir::toNativeSeparators(dir).toStdString(), outcome.info, outcome.recording, report, false);
}

std::string delayRowsCsv(const analysis::DelayReport& report, const std::string& source) {
  std::string t = "# fogbench delay breakdown: measured lag + table read delay = IMU delay; "
                  "IMU delay - processing board delay = gyro's own delay; 1 sigma; ms\n";
  t += "# source: " + oneLine(source) + "\n";
  t += "test_point,axis,frequency_hz,quantity,value_ms,std_ms\n";
  const auto& c = report.constants;
  for (const auto& p : report.points) {
    const std::string head = std::to_string(p.index + 1) + "," + axisLabel(p.axis) + "," + num(p.nominalFrequencyHz) + ",";
    auto row = [&](const char* quantity, double value, double std) {
      t += head + quantity + "," + num(value) + "," + num(std) + "\n";
    };
    row("measured_lag", p.lagMs, p.lagStdMs);
    row("table_read_delay", c.tableReadDelayMs, c.tableReadDelayStdMs);
    row("imu_delay", p.imuDelayMs, p.imuDelayStdMs);
    row("processing_board_delay", c.boardDelayMs, c.boardDelayStdMs);
    row("gyro_delay", p.gyroDelayMs, p.gyroDelayStdMs);
  }
  return t;
}

std::string comparisonCsv(const std::vector<PointComparison>& rows, const analysis::DelayReport& a,
                          const analysis::DelayReport& b, const std::string& aName, const std::string& bName) {
  std::string t = "# fogbench comparison of the IMU delay (ms, 1 sigma): B - A\n";
  t += "# A: " + oneLine(aName) + "\n# B: " + oneLine(bName) + "\n";
  t += "test_point,axis,frequency_hz,amplitude_deg,a_imu_delay_ms,a_std_ms,b_imu_delay_ms,b_std_ms,difference_ms,"
       "difference_std_ms,significance\n";
  int n = 0;
  for (const auto& r : rows) {
    const analysis::TestPointResult& p = r.a ? a.points[*r.a] : b.points[*r.b];
    // The amplitude as Compare matches points by: the table's fitted one.
    t += std::to_string(++n) + "," + axisLabel(p.axis) + "," + num(p.nominalFrequencyHz) + "," +
         num(p.tableFit.amplitudeDeg) + ",";
    t += r.a ? num(r.aMs) + "," + num(r.aStdMs) : std::string(",");
    t += ",";
    t += r.b ? num(r.bMs) + "," + num(r.bStdMs) : std::string(",");
    t += ",";
    t += r.both() ? num(r.differenceMs) + "," + num(r.differenceStdMs) + "," + num(r.significance) : std::string(",,");
    t += "\n";
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

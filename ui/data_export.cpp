#include "ui/data_export.h"

#include <QObject>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <algorithm>
#include <cmath>

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

namespace {

// A number, or an empty cell when there is none.
std::string cell(double v) { return std::isfinite(v) ? num(v) : std::string(); }

std::string axisComment(const analysis::ResponseAnalysis& r) {
  return std::string("# ") + axisLabel(r.axis) + " axis";
}

}  // namespace

std::string responsePointsCsv(const std::vector<analysis::ResponseAnalysis>& responses, const std::string& source) {
  std::string t = "# fogbench frequency response: the points (gyro angle / table angle; std: 1 sigma)\n";
  t += "# source: " + oneLine(source) + "\n";
  t += "# phase_deg is against the stamped table angle (-omega lag); phase_vs_table_motion_deg against the table's "
       "motion (corrected by the table read delay), with its expanded uncertainty at coverage_factor, the read "
       "delay's uncertainty in the budget\n";
  for (const auto& r : responses) {
    t += axisComment(r) + ": table read delay " + num(r.tableReadDelayMs) + " ms, standard uncertainty " +
         num(r.tableReadDelayStdMs) + " ms" +
         (r.tableReadDelayStdMs > 0.0 ? std::string() : std::string(" (not stated: taken as exact)")) + "\n";
    for (const auto& left : r.leftOut)
      t += axisComment(r) + ": left out test point " + std::to_string(left.index + 1) + " (" +
           num(left.frequencyHz) + " Hz): " + oneLine(left.reason) + "\n";
  }
  t += "axis,test_point,frequency_hz,magnitude,magnitude_std,magnitude_db,magnitude_db_std,phase_deg,phase_std_deg,"
       "lag_ms,lag_std_ms,magnitude_phase_cov_deg,harmonic_fraction,phase_vs_table_motion_deg,"
       "phase_standard_uncertainty_deg,coverage_factor,phase_expanded_uncertainty_deg,"
       "phase_expanded_uncertainty_ms\n";
  for (const auto& r : responses)
    for (const auto& p : r.points) {
      const analysis::CertifiedPhase c = analysis::certifiedPhase(p, r);
      t += std::string(axisLabel(r.axis)) + "," + std::to_string(p.index + 1);
      for (double v : {p.frequencyHz, p.magnitude, p.magnitudeStd, p.magnitudeDb, p.magnitudeDbStd, p.phaseDeg,
                       p.phaseStdDeg, p.lagMs, p.lagStdMs, p.magnitudePhaseCovDeg, p.harmonicFraction, c.phaseDeg,
                       c.standardDeg, c.coverageK, c.expandedDeg, c.expandedMs})
        t += "," + cell(v);
      t += "\n";
    }
  return t;
}

std::string responseModelsCsv(const std::vector<analysis::ResponseAnalysis>& responses, const std::string& source) {
  std::string t = "# fogbench frequency response: the models fitted to the points (std: 1 sigma)\n";
  t += "# source: " + oneLine(source) + "\n";
  t += "# a model is adequate when p_value >= " + num(analysis::kModelAdequacyP) +
       "; only an adequate, admissible model is chosen\n";
  for (const auto& r : responses)
    t += axisComment(r) + ": " +
         (r.chosen >= 0 ? std::string("chosen ") + analysis::responseModelName(r.models[r.chosen].kind)
                        : oneLine(r.noModelReason)) +
         "\n";
  t += "axis,model,chosen,adequate,admissible,chi_square,dof,p_value,aic,bic,K,K_std,tau_ms,tau_ms_std,T_ms,T_ms_std,"
       "fn_hz,fn_hz_std,zeta,zeta_std,low_frequency_delay_ms,low_frequency_delay_std_ms,group_delay_at_hz,"
       "group_delay_ms,group_delay_std_ms,bandwidth_hz,bandwidth_std_hz,correlations,inadmissible,notes\n";
  auto yes = [](bool b) { return std::string(b ? "true" : "false"); };
  for (const auto& r : responses)
    for (std::size_t i = 0; i < r.models.size(); ++i) {
      const analysis::ResponseModelFit& m = r.models[i];
      t += std::string(axisLabel(r.axis)) + "," + analysis::responseModelName(m.kind) + "," +
           yes(static_cast<int>(i) == r.chosen) + "," + yes(m.adequate) + "," + yes(m.admissible()) + "," +
           cell(m.chiSquare) + "," + std::to_string(m.dof) + "," + cell(m.pValue) + "," + cell(m.aic) + "," +
           cell(m.bic);
      for (const char* name : {"K", "tau_ms", "T_ms", "fn_hz", "zeta"}) {
        const auto it = std::find_if(m.parameters.begin(), m.parameters.end(),
                                     [name](const analysis::ResponseParameter& p) { return p.name == name; });
        t += it == m.parameters.end() ? std::string(",,") : "," + cell(it->value) + "," + cell(it->stdDev);
      }
      t += "," + cell(m.lowFrequencyDelayMs.value) + "," + cell(m.lowFrequencyDelayMs.stdDev) + "," +
           cell(r.groupDelayAtHz) + "," + cell(m.groupDelayMs.value) + "," + cell(m.groupDelayMs.stdDev) + ",";
      t += m.bandwidthHz ? cell(m.bandwidthHz->value) + "," + cell(m.bandwidthHz->stdDev) : std::string(",");
      std::string correlations;
      for (int a = 0; a < m.correlation.rows(); ++a)
        for (int b = a + 1; b < m.correlation.cols(); ++b)
          if (a < static_cast<int>(m.parameters.size()) && b < static_cast<int>(m.parameters.size()))
            correlations += (correlations.empty() ? "" : "; ") + m.parameters[a].name + "/" + m.parameters[b].name +
                            " " + (std::isfinite(m.correlation(a, b)) ? num(m.correlation(a, b)) : "undefined");
      std::string inadmissible, notes;
      for (const auto& why : m.inadmissible) inadmissible += (inadmissible.empty() ? "" : "; ") + oneLine(why);
      for (const auto& n : m.notes) notes += (notes.empty() ? "" : "; ") + oneLine(n);
      t += "," + session::csvField(correlations) + "," + session::csvField(inadmissible) + "," +
           session::csvField(notes) + "\n";
    }
  return t;
}

QString responseModelsPath(const QString& pointsPath) {
  const QFileInfo info(pointsPath);
  const QString suffix = info.suffix().isEmpty() ? QStringLiteral("csv") : info.suffix();
  return info.dir().filePath(info.completeBaseName() + QStringLiteral("-models.") + suffix);
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

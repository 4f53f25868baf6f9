#pragma once
// Data out of the desktop bench as CSV, for a spreadsheet or a script:
//
//   exportSessionData   the shown session's data and the shown result's fits,
//                       residuals and report, exactly as `fogbench-cli export
//                       --csv DIR` writes them (io::exportCsv, docs/formats.md):
//                       into a new or empty folder, never over other files
//   exportSessionHdf5   the same and the shown result in one HDF5 file, as
//                       `fogbench-cli export --hdf5 FILE.h5` writes it
//                       (io::exportHdf5, docs/formats.md "HDF5 export")
//   (the delay table: session::delayBreakdownCsv, the core's, which the
//   CLI's export writes too)
//   comparisonCsv       Compare's rows: per test point A's and B's IMU delay
//                       with their verdicts, B − A, its σ and |B − A|/σ
//   responsePointsCsv   the frequency response's points (Results' Bode plot):
//                       per axis and point magnitude, phase and lag with
//                       their sigma, and the phase against the table's motion
//                       with its expanded uncertainty (k = 2)
//   responseModelsCsv   the models fitted to them, one row each
//   writeTextFile       writes a file whole or not at all
//
// Numbers are written as the core's exporter writes them (io::formatDouble:
// the shortest text that reads back to the same double); the CSVs start
// with '#' comment lines naming what they hold, then one header line.

#include <QString>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/common/status.h"
#include "ui/run_outcome.h"
#include "ui/session_compare.h"

namespace fog::ui {

// io::exportCsv of the outcome's recording with its report (when it has
// one) into `dir`, which must be new or empty (a file there is never
// replaced; the core's refusal says so).
Status exportSessionData(const RunOutcome& outcome, const QString& dir);

// io::exportHdf5 of the outcome (its report's constants, its shown verdict,
// the frequency response when it has one) into `path`. `path` may be
// replaced (the save dialog asked), but never when it is a session or other
// database (kInvalidArgument).
Status exportSessionHdf5(const RunOutcome& outcome, const QString& path);

// Columns (test_point: the row's number, 1-based; amplitude_deg: the table's
// fitted amplitude, as Compare matches points): test_point,axis,frequency_hz,amplitude_deg,a_imu_delay_ms,
// a_std_ms,a_verdict,b_imu_delay_ms,b_std_ms,b_verdict,difference_ms,
// difference_std_ms,significance,note; a test point tested in one session
// only has the other's cells empty; a row with a refused delay has no
// difference and a note saying why. aName/bName (the session files) go into
// the comment lines.
std::string comparisonCsv(const std::vector<PointComparison>& rows, const analysis::DelayReport& a,
                          const analysis::DelayReport& b, const std::string& aName, const std::string& bName);

// The response points of every axis (analysis::ResponseAnalysis::points, in
// frequency order), one row each. Columns: axis,test_point,frequency_hz,
// magnitude,magnitude_std,magnitude_db,magnitude_db_std,phase_deg,
// phase_std_deg,lag_ms,lag_std_ms,magnitude_phase_cov_deg,harmonic_fraction,
// phase_vs_table_motion_deg,phase_standard_uncertainty_deg,coverage_factor,
// phase_expanded_uncertainty_deg,phase_expanded_uncertainty_ms: the names
// and meanings of `fogbench-cli response --json` (docs/report.md); the
// comment lines give `source`, each axis' table read delay with its
// uncertainty, and the points left out and why.
std::string responsePointsCsv(const std::vector<analysis::ResponseAnalysis>& responses, const std::string& source);
// The models of every axis, one row each. Columns: axis,model,chosen,adequate,
// admissible,chi_square,dof,p_value,aic,bic,K,K_std,tau_ms,tau_ms_std,T_ms,
// T_ms_std,fn_hz,fn_hz_std,zeta,zeta_std,low_frequency_delay_ms,
// low_frequency_delay_std_ms,group_delay_at_hz,group_delay_ms,
// group_delay_std_ms,bandwidth_hz,bandwidth_std_hz,correlations,inadmissible,
// notes; a parameter the model does not have, and the pure delay's
// bandwidth, are empty; correlations "a/b r" for each pair, "; "-joined
// ("undefined" where the fit gives none: a parameter whose sigma is 0). The
// comment lines give `source`, the adequacy threshold and each axis' chosen
// model or why none is chosen.
std::string responseModelsCsv(const std::vector<analysis::ResponseAnalysis>& responses, const std::string& source);
// Where responsePointsCsv's companion goes when the points are written to
// `pointsPath`: beside it, "<name>-models.<suffix>" (suffix csv when it has none).
QString responseModelsPath(const QString& pointsPath);

// Writes `text` to `path` through a temporary file renamed over it at the
// end (QSaveFile): a write that fails (disk full, read-only folder) leaves
// any file already at `path` as it was and no partial file. Returns an
// empty string, or why not in the GUI's language (naming the path).
QString writeTextFile(const QString& path, const std::string& text);

}  // namespace fog::ui

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

// Writes `text` to `path` through a temporary file renamed over it at the
// end (QSaveFile): a write that fails (disk full, read-only folder) leaves
// any file already at `path` as it was and no partial file. Returns an
// empty string, or why not in the GUI's language (naming the path).
QString writeTextFile(const QString& path, const std::string& text);

}  // namespace fog::ui

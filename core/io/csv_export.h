#pragma once
// Export of a session in the CSV layout of docs/formats.md, readable back by
// csv_import and by any spreadsheet or script:
//   metadata.json   session info, bench constants, test points, stream health
//   table.csv       test_point,time_s,x_deg,y_deg,z_deg
//   gyro.csv        test_point,time_s,x_inc_deg,y_inc_deg,z_inc_deg,temperature_c,lost_before
// and, when an analysis report is given,
//   fits.csv        every fit of every test point, with standard errors
//   residuals_<N>.csv  per test point N (1-based): residuals of the
//                   4-parameter table and gyro fits
//   report.json     analysis::formatReportJson
//
// Numbers are written with std::to_chars: the shortest text that reads back
// to the same double (at most 17 significant digits), locale-independent.
// Gyro increments are written in degrees, as the recording holds them
// (protocol::RecordingBuilder); metadata.json states the recording's pulse
// equivalent and the session's gyro signs (bench.gyro_sign).
//
// The directory is created if needed. It must be empty, unless overwrite is
// set; even then it may hold only files of a previous export (the names
// above), which are removed first, so that no foreign file is ever replaced
// and no stale residuals file survives.
// Errors: kInvalidArgument (directory not empty, foreign files, a recording
// without gyro samples: no pulse equivalent), kIoError (cannot create or
// write).

#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

namespace fog::io {

// `delaysCsv`, when not empty, is written as delays.csv: the delay breakdown
// with the shown result's verdicts (session::delayBreakdownCsv), which this
// module cannot judge.
Status exportCsv(const std::string& dir, const SessionInfo& info, const Recording& rec,
                 const analysis::DelayReport* report, bool overwrite = false, const std::string& delaysCsv = {});

// The text the exporter writes for a double (std::to_chars, shortest
// round-trip form). Exposed so that converters and tests use the same rule.
std::string formatDouble(double v);

// metadata.json's text for this session and recording (the same text
// exportCsv writes; the HDF5 export stores it too). Errors as exportCsv's
// (no pulse equivalent, a negative test point index).
Result<std::string> exportMetadataJson(const SessionInfo& info, const Recording& rec);

// The residuals residuals_<N>.csv holds for one test point, in its row order:
// the table rows (time as recorded, angle - 4-parameter fit), then the gyro
// rows (time of the frame's end as recorded, increment - fitted increment).
struct ExportResiduals {
  std::vector<double> tableTimeS, tableResidualDeg;
  std::vector<double> gyroTimeS, gyroResidualDeg;
};
Result<ExportResiduals> exportResiduals(const TestPointData& data, const analysis::TestPointResult& point);

}  // namespace fog::io

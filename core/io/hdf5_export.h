#pragma once
// Export of a session as one HDF5 file (docs/formats.md, "HDF5 export"),
// written with the HDF5 C library. It holds the same doubles the CSV export
// (csv_export.h) prints, taken from the same sources, so that a reader finds
// them bit for bit:
//   /                       attributes format = "fogbench-hdf5",
//                           format_version = 1, session_sha256 (of the
//                           session file's bytes), session_file,
//                           fogbench_version, source
//   /metadata               attribute json: metadata.json's text
//   /result                 the shown result (session::judgeShown): verdict,
//                           data_verdict, stored, limit_ms, reasons,
//                           incomplete_reason; constants/; points/ (delays.csv's
//                           numbers with each point's verdict, vouched, reason)
//   /test_points/NN         NN = test point number (1-based, 2+ digits)
//       table/{time_s, angle_deg[N,3]}
//       gyro/{time_s, increment_deg[N,3], temperature_c, lost_before}
//       fits/{channel, model, <fits.csv's numeric columns>}    (analysis only)
//       residuals/{table_time_s, table_residual_deg, gyro_time_s, gyro_residual_deg}
//       period_track/{time_s, lag_ms, table_amplitude_deg}
//   /response/<x|y|z>       when given: the frequency response of an axis
//                           (analysis::analyzeResponses, as `response --json`)
//       points/, left_out/, models/<delay|first_order|second_order>/
//   /noise/segment_NN       when given: a static segment's gyro noise (as
//                           `noise --json`): scalars, allan/{tau_s, adev_deg_h,
//                           low_deg_h, high_deg_h, edf}, terms/<term>/{value,
//                           std (customary unit), value_si, std_si, tau_low_s,
//                           tau_high_s}
// Every dataset has a `unit` string attribute ("s", "deg", "ms", "Hz",
// "deg/s", "degC", "frames", "1" for dimensionless or a count, "" for text).
// A CSV cell that is empty (not a parameter of that fit) is NaN here.
//
// The file is built in memory (HDF5's core driver), written to a new
// `<path>.partial` (or `<path>.N.partial` when that name is taken: no file
// is truncated that the export did not create) in the same folder and
// renamed over `path` only when complete: a failed export leaves neither
// OUT.h5 nor the partial file.
// Errors (never an exception, never HDF5's own printing on stderr):
// kInvalidArgument (path exists and overwrite is false; path is a folder;
// a recording without gyro samples), kIoError (folder not writable, disk
// full, any HDF5 failure, with HDF5's own words).

#include <string>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/common/bench_constants.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"
#include "core/noise/gyro_noise.h"
#include "core/session/shown_verdict.h"

namespace fog::io {

struct Hdf5ExportInput {
  const SessionInfo* info = nullptr;            // required: as exportCsv's `info`
  const Recording* recording = nullptr;         // required
  const analysis::DelayReport* report = nullptr;  // null: samples only, no fits/result points
  const session::ShownVerdict* shown = nullptr;   // the shown result (null: none stated)
  const BenchConstants* constants = nullptr;    // the shown result's constants (null: report's, if any)
  std::string sessionPath;                      // the .fbs whose SHA-256 is stated (empty: none, "")
  std::string source;                           // the session's source line (as report.json's)
  // The frequency responses (analysis::analyzeResponses of `report`); null or
  // empty: no /response group.
  const std::vector<analysis::ResponseAnalysis>* responses = nullptr;
  // The static segments' gyro noise (noise::analyzeGyroNoise); null or
  // empty: no /noise group.
  const std::vector<noise::GyroNoiseReport>* noise = nullptr;
};

Status exportHdf5(const std::string& path, const Hdf5ExportInput& in, bool overwrite);

// What the export carries beyond the delay report, computed once here for
// the command line and the GUI alike: the frequency responses as `response`
// gives them (its default --at-hz), and the static segments' noise as
// `noise` gives it by default (`bench`'s latitude and IMU frame); each empty
// when the recording has none.
struct Hdf5Extras {
  std::vector<analysis::ResponseAnalysis> responses;
  std::vector<noise::GyroNoiseReport> noise;
};
Hdf5Extras hdf5Extras(const Recording& recording, const analysis::DelayReport* report, const BenchConstants& bench);


}  // namespace fog::io

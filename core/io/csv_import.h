#pragma once
// Import of data recorded on another bench (or exported by fogbench) from the
// CSV layout of docs/formats.md: metadata.json, table.csv, gyro.csv.
//
// Contract:
//  - The result is what the sampling-board decoder would have produced: a
//    fog::Recording that analysis::analyzeRecording accepts unchanged, and the
//    fog::SessionInfo written in metadata.json.
//  - Parsing is locale-independent ('.' decimal point, std::from_chars) and
//    exact: a number written with std::to_chars (as csv_export does) reads
//    back to the same double, so export -> import -> analysis reproduces the
//    original analysis bit for bit.
//  - Columns are found by header name, in any order; an unknown column is
//    refused (a typo must not silently drop data). Lines starting with '#'
//    and blank lines are skipped; CRLF line endings and a UTF-8 byte-order
//    mark are accepted.
//  - Errors name the file, the line (1-based, counting every physical line)
//    and the column, say what is wrong and what to do:
//      kIoError       a file is missing or unreadable
//      kCorruptData   any bad content: not a number, NaN/inf, time not
//                     increasing, missing/unknown/duplicate column, wrong
//                     number of values, empty file, bad metadata
//      kInvalidArgument  importCsvFiles was given the wrong set of files
//  - Nothing is read from the network and no file is written.

#include <cstdint>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/swing_windows.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

namespace fog::io {

// The largest file of an import read: a table CSV of 256 MiB is some 8
// million rows (2.2 h at 1 kHz); the text and the samples it becomes take
// about 0.7 GB at the peak (docs/reliability.md). A longer recording is
// split into several imports.
inline constexpr std::uint64_t kMaxImportFileBytes = 256ull << 20;

// What the user chooses for an import beside its files (the CLI's
// --rate-convention, --frame-period-ms and --segment; the GUI's import
// dialog). What it applied is in ImportedSession::info.imported.
struct ImportOptions {
  // How the gyro file's rates were sampled when the metadata does not say:
  // "frame_average" or "sample_at_stamp"; "" = as the metadata states. A
  // metadata that states another convention is refused: two answers.
  std::string gyroRateConvention;
  double gyroFramePeriodMs = 0.0;  // for "frame_average"; 0 = as the metadata states
  // How one continuous recording (one swing test point) is cut into test
  // points: "" keeps the files' test points; "auto" cuts it at the steady
  // swing windows it finds; "S-E,S-E" at the windows given (seconds).
  std::string segmentation;
};

struct ImportedSession {
  SessionInfo info;
  Recording recording;
  // Things the user should know that are not errors: axes absent from the
  // files (read as 0), test points without data, the files read.
  std::vector<std::string> notes;
  // The swing windows the recording was cut at (ImportOptions::segmentation),
  // one per test point, with what was measured in each; empty when not cut.
  std::vector<analysis::SwingWindow> windows;
};

// Reads <dir>/metadata.json, <dir>/table.csv and <dir>/gyro.csv. Other files
// in the directory (an export's fits.csv, residuals_*.csv, report.json) are
// ignored.
Result<ImportedSession> importCsvDirectory(const std::string& dir, const ImportOptions& options = {});

// The same from three explicitly named files in any order: the metadata is
// the one whose content starts with '{' (JSON); of the CSV files the gyro
// stream is the one whose header has an increment column (x_inc_deg,
// y_inc_deg or z_inc_deg), the table stream the one with an angle column
// (x_deg, y_deg or z_deg).
Result<ImportedSession> importCsvFiles(const std::vector<std::string>& paths, const ImportOptions& options = {});

// The same from the three files' texts (named metadata.json, table.csv and
// gyro.csv in messages): for programs that hold the data, and the fuzzer.
Result<ImportedSession> importCsvTexts(const std::string& metadataText, const std::string& tableText,
                                       const std::string& gyroText, const ImportOptions& options = {});

// A continuous recording (one swing test point, no test-point markers) cut
// into one test point per window (analysis/swing_windows.h); the plan
// follows. Fails when the import holds more than one test point.
Status splitIntoSwingWindows(ImportedSession& imported, const std::vector<analysis::SwingWindow>& windows);

}  // namespace fog::io

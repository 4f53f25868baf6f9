#pragma once
// Who, what and how of a recorded session: everything a reviewer needs months
// later besides the data itself. Stored in the session file's metadata,
// printed on the calibration report, filled by the CLI / GUI / importer.

#include <string>

#include "core/common/bench_constants.h"
#include "core/common/status.h"
#include "core/common/test_plan.h"

namespace fog {

// What an import of another bench's files applied to make the session's
// recording: part of every setting a result of it was produced with
// (docs/formats.md, "Import settings"). Empty for a recorded session.
struct ImportSettings {
  // How the gyro file's rates were turned into increments: "frame_average"
  // or "sample_at_stamp", with the IMU's frame period for the first;
  // "" when the file held increments.
  std::string gyroRateConvention;
  double gyroFramePeriodMs = 0.0;
  // How one continuous recording was cut into test points: "" not cut (the
  // files' own test points), else "auto: S-E,..." (found) or "given: S-E,..."
  // with the windows applied, in seconds on the recording's time axis.
  std::string segmentation;
  bool empty() const { return gyroRateConvention.empty() && segmentation.empty(); }
};

struct SessionInfo {
  std::string operatorName;
  std::string imuModel;
  std::string imuSerial;
  // The production lot the IMU belongs to and the bench (station) that
  // recorded the session: what the catalog groups results by (docs/catalog.md).
  std::string lot;
  std::string benchId;
  std::string source;           // "simulator, seed 1", "serial /dev/ttyUSB0 at 921600", "import run1/"
  std::string softwareVersion;  // FOG_VERSION of the program that recorded it
  std::string createdUtc;       // ISO 8601, e.g. "2026-11-22T02:45:00Z"
  std::string notes;            // free text
  BenchConstants bench;  // as set for the session
  TestPlan plan;
  ImportSettings imported;  // empty unless the session was imported
};

// The import settings as a JSON object ("" when empty: a recorded session),
// and back; "" reads as empty. Used by the session file and the stored
// results' settings (docs/sessions.md).
std::string importSettingsToJson(const ImportSettings& settings);
Result<ImportSettings> importSettingsFromJson(const std::string& text);

}  // namespace fog

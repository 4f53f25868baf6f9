#pragma once
// Who, what and how of a recorded session: everything a reviewer needs months
// later besides the data itself. Stored in the session file's metadata,
// printed on the calibration report, filled by the CLI / GUI / importer.

#include <string>

#include "core/common/test_plan.h"

namespace fog {

// Bench constants as set for the session. The breakdown uses the delays;
// the rest describe the chain that produced the data.
struct BenchSettings {
  double tableReadDelayMs = 0.05;
  double tableReadDelayStdMs = 0.0;
  double boardDelayMs = 0.28;  // IMU processing board, measured on the board
  double boardDelayStdMs = 0.0;
  double latitudeDeg = 40.0;
  double pulseEquivalentDeg = 5e-5;  // degrees per gyro pulse
  double counterHz = 10e6;           // sampling board's common counter
  int counterBits = 32;
};

struct SessionInfo {
  std::string operatorName;
  std::string imuModel;
  std::string imuSerial;
  std::string source;           // "simulator, seed 1", "serial /dev/ttyUSB0 at 921600", "import run1/"
  std::string softwareVersion;  // FOG_VERSION of the program that recorded it
  std::string createdUtc;       // ISO 8601, e.g. "2026-11-22T02:45:00Z"
  std::string notes;            // free text
  BenchSettings bench;
  TestPlan plan;
};

}  // namespace fog

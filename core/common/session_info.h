#pragma once
// Who, what and how of a recorded session: everything a reviewer needs months
// later besides the data itself. Stored in the session file's metadata,
// printed on the calibration report, filled by the CLI / GUI / importer.

#include <string>

#include "core/common/bench_constants.h"
#include "core/common/test_plan.h"

namespace fog {

struct SessionInfo {
  std::string operatorName;
  std::string imuModel;
  std::string imuSerial;
  std::string source;           // "simulator, seed 1", "serial /dev/ttyUSB0 at 921600", "import run1/"
  std::string softwareVersion;  // FOG_VERSION of the program that recorded it
  std::string createdUtc;       // ISO 8601, e.g. "2026-11-22T02:45:00Z"
  std::string notes;            // free text
  BenchConstants bench;  // as set for the session
  TestPlan plan;
};

}  // namespace fog

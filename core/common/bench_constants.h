#pragma once
// The bench's constants: measured elsewhere, set once per bench (GUI dialog,
// CLI options, import metadata) and stored with every session, so that an
// analysis of the session months later uses what the bench was set to.
// One type for every part of fogbench (analysis, diagnosis, noise, import /
// export, CLI, GUI): a constant means the same everywhere.

#include <array>

#include "core/common/imu_frame.h"
#include "core/common/test_plan.h"  // Axis, kAxisCount

namespace fog {

struct BenchConstants {
  // The breakdown's delays, with their standard uncertainties.
  double tableReadDelayMs = 0.05;
  double tableReadDelayStdMs = 0.0;
  double boardDelayMs = 0.28;  // IMU processing board, measured on the board
  double boardDelayStdMs = 0.0;
  double latitudeDeg = 40.0;
  // Degrees per gyro pulse, for a stream that does not state its own: the
  // stream's statement wins; 0 = not set, and a stream without a statement
  // is then refused (protocol::RecordingBuilder::finish). Never a guess: a
  // wrong pulse equivalent scales the gyro amplitude, not the delay, but
  // also every noise figure.
  double pulseEquivalentDeg = 0.0;
  double counterHz = 10e6;  // sampling board's common counter
  int counterBits = 32;
  // Sense of each gyro axis against the table's, as the user states it: -1
  // for a gyro axis mounted the other way round (its increments are negated
  // where they enter the analysis). A gyro that turns against the table
  // while its stated sign is +1 makes the test point invalid, never a
  // half-period lag. Sessions stored before the signs were kept read +1.
  std::array<int, kAxisCount> gyroSign{1, 1, 1};
  // Where the IMU's axes point at zero table angles (imu_frame.h): the
  // diagnosis' replay uses it and checks it against the data. Sessions
  // stored before it was kept read "not stated".
  ImuFrame imuFrame;
};

}  // namespace fog

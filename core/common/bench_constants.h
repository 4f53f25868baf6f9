#pragma once
// The bench's constants: measured elsewhere, set once per bench (GUI dialog,
// CLI options, import metadata) and stored with every session, so that an
// analysis of the session months later uses what the bench was set to.
// One type for every part of fogbench (analysis, diagnosis, noise, import /
// export, CLI, GUI): a constant means the same everywhere.

#include <array>
#include <string>
#include <vector>

#include "core/common/imu_frame.h"
#include "core/common/status.h"
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
  // The gyro's scale as the bench states it: the gyro/table amplitude ratio
  // of a test point, once the gyro's fitted dynamics are taken out, must lie
  // within 1 +- this fraction, or the point is invalid (the "gain" check,
  // docs/method.md "Validity checks"): a wrong pulse equivalent or frame
  // period scales every increment, never the delay, and passed unseen.
  // Sessions stored before it was kept read 1 %.
  double gainToleranceFraction = 0.01;
};

// The physical ranges of the bench constants, checked in one place for the
// command line (readConstants), the GUI's bench dialog and the importer's
// metadata (core/io/metadata.cpp): a value outside is a typo or a unit error
// (a board delay of 1e308 ms went into a stored PASS and a 300-digit gyro
// delay).
inline constexpr double kMaxBenchDelayMs = 1000.0;      // delays and their uncertainties: 0 .. 1 s
inline constexpr double kMinPulseEquivalentDeg = 1e-9;  // 0 = not set, else 1e-9 .. 1 deg per pulse
inline constexpr double kMaxPulseEquivalentDeg = 1.0;
inline constexpr double kMaxCounterHz = 1e12;           // the sampling board's counter: (0, 1 THz]
inline constexpr double kMinGainToleranceFraction = 1e-6;  // the scale tolerance: 1 ppm .. below 100 %
inline constexpr double kMaxGainToleranceFraction = 1.0;   // (exclusive)

// One constant out of its range: which one and what is wrong, in words that
// say what to do ("the processing-board delay (1e+308 ms) is beyond 1000 ms:
// ..."). The caller names it its own way (the CLI's option, the metadata's
// key, the dialog's field).
struct BenchConstantProblem {
  enum class Field {
    kTableReadDelay, kTableReadDelayStd, kBoardDelay, kBoardDelayStd, kLatitude, kPulseEquivalent,
    kCounterHz, kCounterBits, kGyroSign, kGainTolerance
  };
  Field field;
  std::string message;
};
// Every constant out of its range, in the order of the struct's fields.
std::vector<BenchConstantProblem> benchConstantProblems(const BenchConstants& constants);
// Ok, or kInvalidArgument with the first of benchConstantProblems().
Status checkBenchConstants(const BenchConstants& constants);
// The name of a constant as the command line takes it ("--board-delay-ms";
// empty for the counter and the latitude, which only the metadata and the
// GUI set) and as metadata and stored settings key it ("board_delay_ms").
const char* benchConstantOption(BenchConstantProblem::Field field);
const char* benchConstantKey(BenchConstantProblem::Field field);

}  // namespace fog

#pragma once
// Decoded sampling-board data, arranged per test point: what every source
// (simulator, serial board, replay, import) turns into before analysis.
//
// Times are seconds on the sampling board's common counter, measured from the
// first frame of the stream, so table and gyro samples share one time base.

#include <array>
#include <cstdint>
#include <vector>

#include "core/common/test_plan.h"

namespace fog {

// One turntable encoder reading, stamped when the board read it.
struct TableSample {
  double timeS = 0.0;
  std::array<double, kAxisCount> angleDeg{};
};

// One IMU frame: gyro angle increments since the previous IMU frame, stamped
// when the sampling board received the frame.
struct ImuSample {
  double timeS = 0.0;
  std::array<double, kAxisCount> incrementDeg{};
  double temperatureC = 0.0;
  // IMU frames lost (sequence gap) just before this one; their increments are
  // missing from the cumulative angle.
  std::uint32_t lostBefore = 0;
};

// Counters describing the integrity of a stream or of one test point.
struct StreamHealth {
  std::uint64_t tableFrames = 0;
  std::uint64_t imuFrames = 0;
  std::uint64_t statusFrames = 0;
  std::uint64_t checksumFailures = 0;
  std::uint64_t bytesSkipped = 0;     // garbage skipped while resynchronising
  std::uint64_t lostFrames = 0;       // by sequence gaps
  std::uint64_t duplicateFrames = 0;
  std::uint64_t outOfOrderFrames = 0; // stale sequence or time going backwards
  std::uint64_t counterWraps = 0;
};

struct TestPointData {
  int index = 0;  // position in the plan, from 0
  Axis axis = Axis::kX;
  double nominalFrequencyHz = 0.0;  // 0 when the source does not say
  double nominalAmplitudeDeg = 0.0; // 0 when the source does not say
  TestPointKind kind = TestPointKind::kSwing;  // kStatic: table at rest (gyro noise)
  std::vector<TableSample> table;
  std::vector<ImuSample> imu;
  // Frames and damage met while this test point was recorded (frames lost by
  // sequence gaps, duplicates, checksum failures, bytes skipped), from the
  // decoder; all zero when the source cannot tell (imported data, samples
  // stored in a session file, which keeps only the stream-wide counters).
  StreamHealth health;
};

struct Recording {
  double counterHz = 10e6;
  int counterBits = 32;
  double pulseEquivalentDeg = 0.0;
  std::vector<TestPointData> testPoints;
  StreamHealth health;
};

}  // namespace fog

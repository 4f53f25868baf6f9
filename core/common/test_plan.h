#pragma once
// The test plan: which axis swings, how, and for how long. Shared by the
// simulator (which executes it), the analysis (which labels its results) and
// the command line / GUI (which edit it).

#include <cstddef>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"

namespace fog {

enum class Axis { kX = 0, kY = 1, kZ = 2 };
inline constexpr int kAxisCount = 3;
const char* axisName(Axis axis);   // "x", "y", "z"
const char* axisLabel(Axis axis);  // "X", "Y", "Z": as reports print it
Result<Axis> parseAxis(std::string_view text);

// Mechanical limits of the turntable. Defaults describe a typical precision
// three-axis table; a plan outside them is refused before a run starts.
struct TurntableLimits {
  double maxAmplitudeDeg = 45.0;
  double maxFrequencyHz = 20.0;
  double maxRateDegPerS = 400.0;        // peak 2*pi*f*A
  double maxAccelDegPerS2 = 3000.0;     // peak (2*pi*f)^2*A
};

// A test point either swings its axis or holds the table at rest (a static
// segment, for gyro noise: bias, Earth rate and noise only; docs/noise.md).
enum class TestPointKind { kSwing = 0, kStatic = 1 };
const char* testPointKindName(TestPointKind kind);  // "swing", "static"

// One sinusoidal swing: angle = amplitude * sin(2*pi*f*(t - t_start) + startPhase);
// or, with kind == kStatic, the table at rest for settleS + durationS
// (frequency and amplitude 0; `axis` names the gyro of interest).
struct TestPoint {
  Axis axis = Axis::kX;
  double frequencyHz = 0.1;
  double amplitudeDeg = 10.0;
  double durationS = 294.0;  // recorded time after settling
  double settleS = 5.0;      // swing time before recording starts
  double startPhaseDeg = 0.0;
  TestPointKind kind = TestPointKind::kSwing;  // last, so positional initialisers stay valid

  bool isStatic() const { return kind == TestPointKind::kStatic; }
  // 0 for a static segment.
  double periodS() const { return isStatic() ? 0.0 : 1.0 / frequencyHz; }
  // A static segment: table at rest for durationS after settleS.
  static TestPoint staticSegment(Axis axis, double durationS, double settleS = 0.0);
  // Ok, or an error saying what is wrong and what to do.
  Status validate(const TurntableLimits& limits) const;
};

// Bounds of a plan (issue 15): every sample of a run is held in memory, so a
// plan is at most this long in total and has at most this many points.
inline constexpr std::size_t kMaxPlanPoints = 1000;
inline constexpr double kMaxPlanDurationS = 24.0 * 3600.0;

struct TestPlan {
  std::vector<TestPoint> points;
  double restBetweenS = 1.0;  // table at rest between test points

  // Ok, or the first problem ("test point 3: ...") and what to do.
  Status validate(const TurntableLimits& limits) const;
  double totalDurationS() const;

  // The paper's two conditions on the X axis: 0.1 Hz / 10 deg for 4.9 min and
  // 1 Hz / 3 deg.
  static TestPlan paperSlow();  // 0.1 Hz / 10 deg, 294 s
  static TestPlan paperFast();  // 1 Hz / 3 deg, 60 s
};

// JSON plan file: {"points":[{"axis":"x","frequency_hz":0.1,"amplitude_deg":10,
// "duration_s":294,"settle_s":5}], "rest_between_s":1}. Unknown keys are
// refused so that a typo is not silently ignored. A static segment is
// {"kind":"static","axis":"x","duration_s":600}; "kind" defaults to "swing"
// and is written only for static segments, so swing plans read and write as
// before.
Result<TestPlan> testPlanFromJson(std::string_view json);

// The named plans the command line and the GUI offer, in display order:
//   paper       the paper's two conditions on X: 0.1 Hz / 10 deg 294 s, then 1 Hz / 3 deg 60 s
//   paper-slow  0.1 Hz / 10 deg, 294 s
//   paper-fast  1 Hz / 3 deg, 60 s
//   quick       1 Hz / 3 deg, 20 s: a result in seconds
//   noise       10 minutes at rest on X (gyro noise), then the paper-fast swing
const std::vector<std::string>& presetPlanNames();
// kInvalidArgument naming the presets for an unknown name.
Result<TestPlan> presetPlan(std::string_view name);
std::string testPlanToJson(const TestPlan& plan);

}  // namespace fog

#pragma once
// The test plan: which axis swings, how, and for how long. Shared by the
// simulator (which executes it), the analysis (which labels its results) and
// the command line / GUI (which edit it).

#include <cstddef>
#include <cstdint>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/status.h"

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

// One sinusoidal swing of one axis about its position:
//   angle = position[axis] + amplitude * sin(2*pi*f*(t - t_start) + startPhase),
// the other axes holding their positions; or, with kind == kStatic, the table
// at rest at its position for settleS + durationS (frequency and amplitude 0;
// `axis` names the gyro of interest). Between points the table moves to the
// next point's position during the rest (TestPlan::restBetweenS), one axis
// after the other; after the last point it returns to zero.
struct TestPoint {
  Axis axis = Axis::kX;
  double frequencyHz = 0.1;
  double amplitudeDeg = 10.0;
  double durationS = 294.0;  // recorded time after settling
  double settleS = 5.0;      // swing time before recording starts
  double startPhaseDeg = 0.0;
  TestPointKind kind = TestPointKind::kSwing;  // after the scalars, so positional initialisers stay valid
  // Table angle of each axis for this point, deg (indexed by Axis): the swing
  // axis swings about its entry, the others hold theirs. Default: all zero.
  std::array<double, kAxisCount> positionDeg{};

  bool isStatic() const { return kind == TestPointKind::kStatic; }
  // 0 for a static segment.
  double periodS() const { return isStatic() ? 0.0 : 1.0 / frequencyHz; }
  // A static segment: table at rest for durationS after settleS.
  static TestPoint staticSegment(Axis axis, double durationS, double settleS = 0.0);
  // One thing wrong with the point: the field it is about and what to do.
  struct Problem {
    enum class Field { kPosition, kKind, kFrequency, kAmplitude, kDuration, kSettle, kStartPhase };
    Field field;
    std::string message;
  };
  // Every problem of the point, in the order of validate()'s checks (a plan
  // editor shows them all, each by its field).
  std::vector<Problem> problems(const TurntableLimits& limits) const;
  // Ok, or the first of problems(): what is wrong and what to do.
  Status validate(const TurntableLimits& limits) const;
};

// The fewest swing periods a delay rests on, one rule for the plan and the
// analysis: the plan refuses a point shorter (TestPoint::problems) and the
// analysis a record that covers fewer (delay_analysis, validity), in the
// same words (tooFewSwingPeriods). The plan counts a point's duration; the
// analysis the span of its samples plus one sample interval of each stream
// (N samples every dt span (N - 1) dt, and the first IMU frame only marks
// where the increments start), so that a point of exactly two planned
// periods is analysed.
inline constexpr double kMinSwingPeriods = 2.0;
// "" when `periods` reach kMinSwingPeriods (to rounding: 1e-9 of a period);
// otherwise why not, the words after the subject: "covers 1.99 swing
// periods, under two swing periods: a delay needs at least two whole
// periods" (the count rounded down to hundredths, never up to 2.00).
std::string tooFewSwingPeriods(double periods);

// Moves between test points are compared to within this (deg): the planned
// end of one point and the start of the next (or zero) that agree to it are
// the same place, and no rest is needed to move between them. Far below any
// table encoder's resolution (3.6e-3 arcsec), far above the rounding of
// position + amplitude * sin(2 pi f t + phase) over a 1-h plan at 20 Hz (an
// argument of 4.5e5 rad: a few 1e-9 deg; a whole-period swing's end read
// 7e-15 deg and refused a plan with rest_between_s 0).
inline constexpr double kMotionToleranceDeg = 1e-6;

// Largest table position, deg: the table's axes turn a full circle at most.
inline constexpr double kMaxPositionDeg = 360.0;

// Bounds of a plan (issue 15): every sample of a run is held in memory, so a
// plan is at most this long in total and has at most this many points.
//
// The memory budget of a run is 1 GB of address space (docs/reliability.md,
// "limits"): a run holds every decoded sample, and the analysis works on
// copies of them. Measured at the board's standard rates (table 1 kHz, IMU
// 500 Hz): `run --out` on a 1-h plan fits in 700 MB (`ulimit -v`) and
// 3 990 s still fit in 1 GB (peak RSS 569 MB); 90 min did not (std::bad_alloc,
// exit 134). The diagnosis of a 1-h session peaks at 918 MB RSS
// (docs/benchmarks.md). A plan is
// therefore at most 1 h in all, and a run at most kMaxRunSamples table + IMU
// samples: a simulated run at higher rates is refused beforehand when its
// plan would exceed that, and a live run (a board sending faster or longer
// than planned) ends there as incomplete, keeping what it recorded.
inline constexpr std::size_t kMaxPlanPoints = 1000;
inline constexpr double kMaxPlanDurationS = 3600.0;
inline constexpr std::uint64_t kMaxRunSamples = 6'000'000;  // 4 000 s at 1 kHz + 500 Hz

struct TestPlan {
  std::vector<TestPoint> points;
  double restBetweenS = 1.0;  // table at rest between test points

  // Ok, or the first problem ("test point 3: ...") and what to do. Also
  // checks the moves between points against the limits (each axis moves in
  // restBetweenS / (number of axes that move), with a raised-cosine profile;
  // an axis moves when its angles differ by more than kMotionToleranceDeg).
  Status validate(const TurntableLimits& limits) const;
  // Where the table starts point `index`: its position, with the swing axis
  // at position + amplitude * sin(startPhase) (index == points.size(): zero).
  std::array<double, kAxisCount> startAnglesDeg(std::size_t index) const;
  // Where the table is when point `index` ends (its swing axis mid-swing).
  std::array<double, kAxisCount> endAnglesDeg(std::size_t index) const;
  double totalDurationS() const;

  // The paper's two conditions on the X axis: 0.1 Hz / 10 deg for 4.9 min and
  // 1 Hz / 3 deg.
  static TestPlan paperSlow();  // 0.1 Hz / 10 deg, 294 s
  static TestPlan paperFast();  // 1 Hz / 3 deg, 60 s
};

// JSON plan file: {"points":[{"axis":"x","frequency_hz":0.1,"amplitude_deg":10,
// "duration_s":294,"settle_s":5,"position_deg":[0,0,30]}], "rest_between_s":1}
// ("position_deg" optional, written only when not zero). Unknown keys are
// refused so that a typo is not silently ignored. A static segment is
// {"kind":"static","axis":"x","duration_s":600}; "kind" defaults to "swing"
// and is written only for static segments, so swing plans read and write as
// before.
Result<TestPlan> testPlanFromJson(std::string_view json);

// A plan file (`run --plan`, the GUI's Open plan): a regular file of at most
// 16 MiB (a 1 000-point plan is some 200 kB), parsed by testPlanFromJson().
// Errors name the file.
Result<TestPlan> loadTestPlanFile(const std::string& path);

// The named plans the command line and the GUI offer, in display order:
//   paper       the paper's two conditions on X: 0.1 Hz / 10 deg 294 s, then 1 Hz / 3 deg 60 s
//   paper-slow  0.1 Hz / 10 deg, 294 s
//   paper-fast  1 Hz / 3 deg, 60 s
//   quick       1 Hz / 3 deg, 20 s: a result in seconds
//   noise       10 minutes at rest on X (gyro noise), then the paper-fast swing
//   response    a frequency response of X: responsePlan() for the default limits
//   response-third-octave
//               the standard frequency response of X: thirdOctaveResponsePlan()
//               for the default limits (21 one-third-octave frequencies 0.1 .. 10 Hz)
const std::vector<std::string>& presetPlanNames();
// kInvalidArgument naming the presets for an unknown name.
Result<TestPlan> presetPlan(std::string_view name);
std::string testPlanToJson(const TestPlan& plan);

// A frequency-response plan (issue 32, docs/method.md "Frequency response"):
// `frequencies` log-spaced frequencies from lowestHz up to the highest one at
// which the table still swings minAmplitudeDeg within limitMargin of its rate
// and acceleration limits (and its frequency limit). At each frequency the
// amplitude is the largest the margin allows, at most maxAmplitudeDeg; the
// dwell is whole periods: settle max(1 period, 1 s) rounded up to whole
// periods, then max(minPeriods, minDurationS) rounded up likewise. For the
// default limits: 0.05 .. 11.03 Hz, 10 deg down to 0.5 deg, 670 s in all.
// The phase resolution each point reaches (Cramer-Rao, the paper's gyro) is
// checked in tests/core/analysis/frequency_response_test.cpp: <= 0.01 deg.
struct ResponsePlanOptions {
  Axis axis = Axis::kX;
  double lowestHz = 0.05;
  int frequencies = 20;
  double maxAmplitudeDeg = 10.0;
  double minAmplitudeDeg = 0.5;
  double limitMargin = 0.8;
  double minPeriods = 6.0;  // the per-period track then has >= 5 periods (delay_analysis)
  double minDurationS = 10.0;
};
// kInvalidArgument when the options are out of range or the table cannot
// swing minAmplitudeDeg at lowestHz; the plan returned passes validate(limits).
Result<TestPlan> responsePlan(const TurntableLimits& limits, const ResponsePlanOptions& options = {});

// The standard frequency-response plan (issue 40, docs/method.md "The
// standard plan"): the one-third-octave grid 0.1 .. 10 Hz of the CCAUV.V-K3
// low-frequency key comparison, base-10 third octaves (IEC 61260-1: band k's
// exact mid-band frequency is 10^(k/10) Hz) swung at their nominal values
// (ISO 266's preferred numbers, as IEC 61260-1 labels the bands):
// thirdOctaveNominalHz(). The nominal values, not 10^(k/10), so that a
// session compares with another lab's and with another session at the same
// frequency (they differ by up to 0.95 %, at 0.16 and 1.6 Hz; Compare matches
// frequencies within 0.5 %). At each frequency the amplitude is the largest
// the table's limits allow within responsePlan's margin (limitMargin of the
// angle, rate and acceleration limits; the angle limit, not
// ResponsePlanOptions' 10 deg cap: a standard plan uses the whole table), and
// the dwell is responsePlan's: settle max(1 period, 1 s), record max(6
// periods, 10 s), both rounded up to whole periods. For the default limits:
// 36 deg up to 1.25 Hz, falling as 1/f^2 to 0.607 deg at 10 Hz; 454 s in all.
// Uses options.axis, limitMargin, minPeriods, minDurationS and
// minAmplitudeDeg (the grid is fixed: lowestHz, frequencies and
// maxAmplitudeDeg are not used). kInvalidArgument when the options are out
// of range, or for a table whose limits allow less than minAmplitudeDeg at a
// frequency of the grid or do not reach 10 Hz: it names the frequency and
// the limit; a frequency of the standard grid is never dropped.
Result<TestPlan> thirdOctaveResponsePlan(const TurntableLimits& limits, const ResponsePlanOptions& options = {});
// The 21 nominal one-third-octave frequencies 0.1 .. 10 Hz, in Hz, ascending:
// 0.1, 0.125, 0.16, 0.2, 0.25, 0.315, 0.4, 0.5, 0.63, 0.8, 1, 1.25, 1.6, 2,
// 2.5, 3.15, 4, 5, 6.3, 8, 10.
const std::vector<double>& thirdOctaveNominalHz();
// The names of the presets that are frequency responses of one axis (`run
// --preset NAME --axis y` makes that axis' plan): "response",
// "response-third-octave".
bool isResponsePreset(std::string_view name);
// The response preset `name` for `axis` (the default limits).
Result<TestPlan> responsePreset(std::string_view name, Axis axis);

}  // namespace fog

#pragma once
// The stream side of a table-driven run: watches the sampling board's table
// angles (board time) and decides, point by point, when the table really
// swings as planned and which stretch of the stream is the test point. Used
// by every driver that commands a table (remote, manual): the recording's
// test points come from here, so a board without test-point markers works.
//
// Swing check (docs/table-control.md, "Is the table doing what the plan
// says?"): over the last `checkPeriods` periods of the planned axis, a least-
// squares fit of centre + a sin(wt) + b cos(wt) at the planned frequency, and
// the same fit on each half of that window:
//   amplitude within amplitudeTolerance (relative) of the plan,
//   centre within centreToleranceDeg (+ 1 % of the amplitude) of the point's
//     position (TestPoint::positionDeg of the swing axis),
//   frequency within frequencyTolerance (relative; from the phase drift
//     between the two halves),
//   steady: RMS residual below steadyTolerance of the amplitude, and the two
//     halves' amplitudes within amplitudeDriftTolerance of it.
// A static point checks that the axis stays within restBandDeg for 1 s.
// Once the check passes, the point's window starts at the start of the
// checked stretch and ends durationS later.
//
// Thread-safety: addFrames()/addTableSamples()/failLink() are called by the
// acquisition thread, the PointRecorder methods by the plan runner's thread;
// a mutex guards the state. Not for use after the run: copy windows() out.

#include <deque>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/protocol/decoder.h"
#include "core/table/plan_runner.h"

namespace fog::table {

struct SwingCheckOptions {
  double checkPeriods = 2.0;
  double minCheckS = 1.0;              // the checked stretch is at least this long
  double amplitudeTolerance = 0.02;    // 2 %
  double centreToleranceDeg = 0.02;
  double frequencyTolerance = 0.005;   // 0.5 %
  double steadyTolerance = 0.02;       // RMS residual / amplitude
  // Amplitude of the second half minus the first's / planned amplitude: a
  // swing still ramping up (a manual table the operator just started) is
  // not yet steady, and a test point cut from its ramp would bias the delay.
  double amplitudeDriftTolerance = 0.005;
  double restBandDeg = 0.01;
};

// What a stretch of one axis's angle is, fitted at frequencyHz.
struct SwingFit {
  bool ok = false;           // enough samples
  double amplitudeDeg = 0.0, centreDeg = 0.0, frequencyHz = 0.0, rmsResidualDeg = 0.0;
  double amplitudeDriftDeg = 0.0;  // second half's amplitude minus the first's
  double startS = 0.0, endS = 0.0;
};
SwingFit fitSwing(std::span<const TableSample> samples, Axis axis, double frequencyHz);
// Empty when the fit matches the point within the tolerances; otherwise why
// not ("amplitude 2.71 deg, planned 3 deg").
std::string swingMismatch(const SwingFit& fit, const TestPoint& point, const SwingCheckOptions& options);

struct PointWindow {
  int index = 0;
  TestPoint point;
  double startS = 0.0, endS = 0.0;  // board time
  bool complete = false;            // the whole duration was recorded
};

class StreamPointRecorder : public PointRecorder {
 public:
  explicit StreamPointRecorder(SwingCheckOptions options = {}) : options_(options) {}

  // The runner's clock (plan seconds, the board's time scale). With it, a
  // point's check starts no earlier than the board time that matches
  // begin(): the host's time less the smallest offset (host time minus the
  // newest board time) seen so far, i.e. the stream as if it arrived with
  // its least delay. Without it, at the newest sample received, which is as
  // late as the stream (a burst delayed past the settle time then lets the
  // check reach back into the swing's ramp). Thread-safe; may be null.
  void setHostClock(RunnerClock* clock);

  // Acquisition side.
  void addFrames(std::span<const protocol::DecodedFrame> frames);
  void addTableSamples(std::span<const TableSample> samples);
  void failLink(const std::string& why);  // the board's stream ended / failed

  // Runner side.
  Status begin(int index, const TestPoint& point) override;
  RecorderProgress poll() override;
  void end(int index) override;
  Status health() override;
  bool streamShowsRest(Axis axis) override;

  std::vector<PointWindow> windows() const;
  double streamTimeS() const;

 private:
  void check();  // with the lock held

  SwingCheckOptions options_;
  mutable std::mutex mutex_;
  // Board time from frames (as RecordingBuilder: from the first frame's counter).
  bool haveFirst_ = false;
  std::int64_t firstTicks_ = 0;
  double counterHz_ = 10e6;
  double nowS_ = 0.0;
  RunnerClock* hostClock_ = nullptr;
  double leastOffsetS_ = 0.0;  // host time - newest board time, smallest seen
  bool haveOffset_ = false;
  std::string linkFailure_;

  enum class Phase { kIdle, kChecking, kRecording, kDone } phase_ = Phase::kIdle;
  int index_ = -1;
  TestPoint point_;
  double beganS_ = 0.0;
  double lastCheckS_ = -1.0;
  std::string lastMismatch_;
  std::deque<TableSample> buffer_;  // while checking: samples since begin
  std::vector<PointWindow> windows_;
};

// The recording cut into the windows' test points: every table and IMU
// sample of `whole` (all its test points, in time order) whose time falls in
// a window becomes a sample of that window's point (index, axis, nominal
// frequency and amplitude from the plan). Windows without samples are left out.
Recording segmentByWindows(const Recording& whole, const std::vector<PointWindow>& windows);

}  // namespace fog::table

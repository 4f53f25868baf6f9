#pragma once
// What the live plots show while a run is under way, computed from decoded
// frames as they arrive: the table angle and the integrated gyro angle of the
// axis that swings now, with the gyro's bias + Earth-rate trend removed on
// the fly, over a scrolling window; and where the run stands (test point,
// phase, board time).
//
// The trend is removed by a running least-squares fit of
//   gyro angle = a + b t + c sin(w t) + d cos(w t)
// over the current test point (w: the nominal swing frequency its STATUS
// frames announce; without one, a straight line), so the display is level
// from the first periods on, not only once the sinusoid has averaged out.
// It is for display only: the analysis fits the recording afterwards.
//
// Plain C++, no Qt; not thread-safe (the GUI thread owns one).

#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/common/test_plan.h"
#include "core/protocol/decoder.h"

namespace fog::acquisition {

class LiveTraces {
 public:
  // windowS: how much history the plots keep (board seconds).
  explicit LiveTraces(double windowS = 20.0);

  // The bench's pulse equivalent (degrees per pulse), for a stream that does
  // not state its own: the rule of protocol::RecordingBuilder. While neither
  // is known the gyro is not drawn (the recording would refuse it too).
  // Kept by clear().
  void setBenchPulseEquivalent(double degPerPulse) { benchPulseEquivalentDeg_ = degPerPulse; }

  void add(std::span<const protocol::DecodedFrame> frames);
  void clear();
  // Where the run stands as the host knows it (a table-driven run, whose
  // board need not send test-point markers): the same as a STATUS frame
  // naming test point `index` (0-based) on `axis` at `frequencyHz` in
  // `phase`. Markers the board does send agree with it.
  void follow(int index, Axis axis, double frequencyHz, protocol::TestPhase phase);

  struct Point {
    double timeS;
    double angleDeg;
  };
  // Within the last windowS of board time, oldest first.
  const std::deque<Point>& table() const { return table_; }
  // The integrated gyro angle with the current trend estimate removed.
  std::vector<Point> gyroDetrended() const;
  // The gyro's trend (bias + Earth rate), deg/s, for the number the operator
  // reads: fitted over the recording phase only (the settling swing ramps its
  // amplitude), and NaN until that holds two whole periods (two seconds
  // without a swing): over a part of a period a trend and the sinusoid are
  // not told apart, and early values read hundreds of deg/h.
  double gyroTrendDegPerS() const;

  int testPoint() const { return testPoint_; }  // -1 before a STATUS names one
  Axis axis() const { return axis_; }
  protocol::TestPhase phase() const { return phase_; }
  double nominalFrequencyHz() const { return frequencyHz_; }
  double streamTimeS() const { return streamTimeS_; }
  // Board time at which the current test point entered its recording phase;
  // negative while it has not.
  double recordingStartS() const { return recordingStartS_; }
  std::uint64_t framesSeen() const { return frames_; }

 private:
  void startTestPoint(int index, Axis axis, double frequencyHz);
  void trim();
  // A running least-squares fit of the gyro angle on basis(t).
  struct RunningFit {
    Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    std::size_t samples = 0;
    double firstS = 0.0, lastS = 0.0;
    void add(const Eigen::Vector4d& b, double angleDeg, double timeS);
  };
  // A fit's coefficients [a, b, c, d] (zeros when singular).
  Eigen::Vector4d solve(const RunningFit& fit) const;
  // The display's fit (the whole test point) solved.
  Eigen::Vector4d trend() const { return solve(fit_); }
  Eigen::Vector4d basis(double t) const;

  double windowS_;
  std::deque<Point> table_;
  std::deque<Point> gyro_;  // raw integrated angle

  bool haveFirst_ = false;
  std::int64_t firstTicks_ = 0;
  double counterHz_ = 10e6;
  double pulseEquivalentDeg_ = 0.0;       // the stream's latest statement
  double benchPulseEquivalentDeg_ = 0.0;  // 0 = not set
  double streamTimeS_ = 0.0;
  std::uint64_t frames_ = 0;

  int testPoint_ = -1;
  Axis axis_ = Axis::kX;
  protocol::TestPhase phase_ = protocol::TestPhase::kIdle;
  double frequencyHz_ = 0.0;
  double recordingStartS_ = -1.0;
  double pointStartS_ = 0.0;  // origin of the fit's time axis (conditioning)
  double gyroAngleDeg_ = 0.0;
  RunningFit fit_;           // the whole test point: levels the display from the first periods
  RunningFit recordingFit_;  // the recording phase: the trend shown as a number
};

}  // namespace fog::acquisition

#include "core/table/stream_recorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include <Eigen/Dense>

#include "core/common/units.h"

namespace fog::table {

namespace {

std::string num(double v, const char* f = "%.4g") {
  char b[48];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

struct HalfFit {
  bool ok = false;
  double a = 0, b = 0, c = 0, rss = 0;
  std::size_t n = 0;
};

HalfFit fit3(std::span<const TableSample> s, Axis axis, double w, double t0) {
  HalfFit h;
  if (s.size() < 8) return h;
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  const auto ax = static_cast<std::size_t>(axis);
  for (const auto& x : s) {
    const double t = x.timeS - t0;
    const Eigen::Vector3d b(std::sin(w * t), std::cos(w * t), 1.0);
    N += b * b.transpose();
    r += b * x.angleDeg[ax];
  }
  Eigen::LDLT<Eigen::Matrix3d> ldlt(N);
  if (ldlt.info() != Eigen::Success) return h;
  const Eigen::Vector3d p = ldlt.solve(r);
  if (!p.allFinite()) return h;
  double rss = 0.0;
  for (const auto& x : s) {
    const double t = x.timeS - t0;
    const double e = x.angleDeg[ax] - (p[0] * std::sin(w * t) + p[1] * std::cos(w * t) + p[2]);
    rss += e * e;
  }
  h.ok = true;
  h.a = p[0];
  h.b = p[1];
  h.c = p[2];
  h.rss = rss;
  h.n = s.size();
  return h;
}

}  // namespace

SwingFit fitSwing(std::span<const TableSample> samples, Axis axis, double frequencyHz) {
  SwingFit f;
  if (samples.size() < 16) return f;
  f.startS = samples.front().timeS;
  f.endS = samples.back().timeS;
  const auto ax = static_cast<std::size_t>(axis);
  if (!(frequencyHz > 0.0)) {
    // At rest: centre and spread.
    double lo = samples.front().angleDeg[ax], hi = lo, sum = 0.0;
    for (const auto& s : samples) {
      lo = std::min(lo, s.angleDeg[ax]);
      hi = std::max(hi, s.angleDeg[ax]);
      sum += s.angleDeg[ax];
    }
    f.ok = true;
    f.centreDeg = sum / static_cast<double>(samples.size());
    f.amplitudeDeg = 0.5 * (hi - lo);
    return f;
  }
  const double w = kTwoPi * frequencyHz;
  const double t0 = samples.front().timeS;
  const auto whole = fit3(samples, axis, w, t0);
  const std::size_t half = samples.size() / 2;
  const auto first = fit3(samples.subspan(0, half), axis, w, t0);
  const auto second = fit3(samples.subspan(half), axis, w, t0);
  if (!whole.ok || !first.ok || !second.ok) return f;
  f.ok = true;
  f.amplitudeDeg = std::hypot(whole.a, whole.b);
  f.centreDeg = whole.c;
  f.rmsResidualDeg = std::sqrt(whole.rss / static_cast<double>(whole.n));
  // A swing still ramping up (or dying away) has halves of different amplitude.
  const double a1 = std::hypot(first.a, first.b), a2 = std::hypot(second.a, second.b);
  f.amplitudeDriftDeg = a2 - a1;
  // A frequency error turns into a phase drift between the two halves.
  double dphi = std::atan2(second.b, second.a) - std::atan2(first.b, first.a);
  while (dphi > kPi) dphi -= kTwoPi;
  while (dphi <= -kPi) dphi += kTwoPi;
  const double dt = 0.5 * (f.endS - f.startS);
  f.frequencyHz = frequencyHz + (dt > 0.0 ? dphi / (kTwoPi * dt) : 0.0);
  return f;
}

std::string swingMismatch(const SwingFit& fit, const TestPoint& p, const SwingCheckOptions& o) {
  if (!fit.ok) return "too few table samples to check the motion";
  const double centre = p.positionDeg[static_cast<std::size_t>(p.axis)];
  if (p.isStatic()) {
    if (std::abs(fit.centreDeg - centre) > o.centreToleranceDeg)
      return std::string(axisLabel(p.axis)) + " rests at " + num(fit.centreDeg) + " deg, planned " + num(centre) + " deg";
    if (2.0 * fit.amplitudeDeg > o.restBandDeg)
      return std::string(axisLabel(p.axis)) + " moves " + num(2.0 * fit.amplitudeDeg) + " deg peak to peak; it should be at rest (within " +
             num(o.restBandDeg) + " deg)";
    return {};
  }
  const std::string ax = axisLabel(p.axis);
  if (std::abs(fit.frequencyHz - p.frequencyHz) > o.frequencyTolerance * p.frequencyHz)
    return ax + " swings at " + num(fit.frequencyHz, "%.5g") + " Hz, planned " + num(p.frequencyHz, "%.5g") +
           " Hz (tolerance " + num(o.frequencyTolerance * 100) + " %)";
  if (std::abs(fit.amplitudeDeg - p.amplitudeDeg) > o.amplitudeTolerance * p.amplitudeDeg)
    return ax + " amplitude " + num(fit.amplitudeDeg) + " deg, planned " + num(p.amplitudeDeg) + " deg (tolerance " +
           num(o.amplitudeTolerance * 100) + " %)";
  if (std::abs(fit.centreDeg - centre) > o.centreToleranceDeg + 0.01 * p.amplitudeDeg)
    return ax + " swings about " + num(fit.centreDeg) + " deg, planned " + num(centre) + " deg";
  if (std::abs(fit.amplitudeDriftDeg) > o.amplitudeDriftTolerance * p.amplitudeDeg)
    return ax + " amplitude is still changing (" + num(fit.amplitudeDriftDeg) + " deg between the two halves of the " +
           "checked stretch; tolerance " + num(o.amplitudeDriftTolerance * 100) + " %)";
  if (fit.rmsResidualDeg > o.steadyTolerance * p.amplitudeDeg)
    return ax + " is not a steady sinusoid yet (residual " + num(100.0 * fit.rmsResidualDeg / p.amplitudeDeg) +
           " % of the amplitude)";
  return {};
}

void StreamPointRecorder::addFrames(std::span<const protocol::DecodedFrame> frames) {
  std::vector<TableSample> table;
  {
    std::lock_guard lock(mutex_);
    for (const auto& d : frames) {
      if (!haveFirst_) {
        haveFirst_ = true;
        firstTicks_ = d.ticks;
      }
      if (const auto* s = std::get_if<protocol::StatusPayload>(&d.frame.payload)) {
        if (s->counterHz > 0) counterHz_ = s->counterHz;
      } else if (const auto* t = std::get_if<protocol::TablePayload>(&d.frame.payload)) {
        TableSample x;
        x.timeS = static_cast<double>(d.ticks - firstTicks_) / counterHz_;
        for (int a = 0; a < kAxisCount; ++a) x.angleDeg[static_cast<std::size_t>(a)] = t->angleMicroDeg[static_cast<std::size_t>(a)] * 1e-6;
        table.push_back(x);
      }
    }
  }
  addTableSamples(table);
}

void StreamPointRecorder::addTableSamples(std::span<const TableSample> samples) {
  std::lock_guard lock(mutex_);
  for (const auto& s : samples) {
    nowS_ = std::max(nowS_, s.timeS);
    buffer_.push_back(s);
    // Keep what a check or a rest test can need.
    const double keep =
        phase_ == Phase::kChecking
            ? std::max(options_.checkPeriods / std::max(point_.frequencyHz, 1e-3), options_.minCheckS) + 1.0
            : 2.0;
    while (!buffer_.empty() && buffer_.front().timeS < nowS_ - keep) buffer_.pop_front();
    check();  // at most every 0.1 s of board time while checking
  }
  if (hostClock_ && !samples.empty()) {
    const double offset = hostClock_->nowS() - nowS_;
    if (!haveOffset_ || offset < leastOffsetS_) leastOffsetS_ = offset;
    haveOffset_ = true;
  }
}

void StreamPointRecorder::setHostClock(RunnerClock* clock) {
  std::lock_guard lock(mutex_);
  hostClock_ = clock;
  haveOffset_ = false;
}

void StreamPointRecorder::check() {
  if (phase_ == Phase::kRecording) {
    auto& w = windows_.back();
    w.endS = std::min(nowS_, w.startS + point_.durationS);
    if (nowS_ >= w.startS + point_.durationS) {
      w.complete = true;
      phase_ = Phase::kDone;
    }
    return;
  }
  if (phase_ != Phase::kChecking || nowS_ - lastCheckS_ < 0.1) return;
  lastCheckS_ = nowS_;
  const double span = point_.isStatic()
                          ? options_.minCheckS
                          : std::max(options_.checkPeriods / point_.frequencyHz, options_.minCheckS);
  // Only samples after begin(), and a whole checked stretch of them.
  std::vector<TableSample> window;
  for (const auto& s : buffer_)
    if (s.timeS >= beganS_ && s.timeS >= nowS_ - span) window.push_back(s);
  if (window.empty() || window.back().timeS - window.front().timeS < 0.98 * span) {
    lastMismatch_ = "waiting for " + num(span) + " s of table data";
    return;
  }
  const auto fit = fitSwing(window, point_.axis, point_.isStatic() ? 0.0 : point_.frequencyHz);
  lastMismatch_ = swingMismatch(fit, point_, options_);
  if (!lastMismatch_.empty()) return;
  PointWindow w;
  w.index = index_;
  w.point = point_;
  w.startS = window.front().timeS;
  w.endS = nowS_;
  windows_.push_back(w);
  phase_ = Phase::kRecording;
  lastMismatch_ = point_.isStatic()
                      ? "at rest verified from board time " + num(w.startS, "%.3f") + " s"
                      : "swing verified from board time " + num(w.startS, "%.3f") + " s: " + num(fit.frequencyHz, "%.6g") +
                            " Hz, " + num(fit.amplitudeDeg, "%.5g") + " deg about " + num(fit.centreDeg, "%.3g") + " deg";
  buffer_.clear();
  check();
}

void StreamPointRecorder::failLink(const std::string& why) {
  std::lock_guard lock(mutex_);
  if (linkFailure_.empty()) linkFailure_ = why;
}

Status StreamPointRecorder::begin(int index, const TestPoint& point) {
  std::lock_guard lock(mutex_);
  if (!linkFailure_.empty()) return ioError("the board's stream ended: " + linkFailure_);
  index_ = index;
  point_ = point;
  beganS_ = nowS_;
  // The board time of this instant, as if the stream came with its least
  // delay; at most the settle time ahead of the newest sample, so a board
  // clock running slower than the host's (or an emulator at another
  // --speed) costs a point no more than that.
  if (hostClock_ && haveOffset_)
    beganS_ = std::clamp(hostClock_->nowS() - leastOffsetS_, nowS_, nowS_ + std::max(point.settleS, 0.0));
  lastCheckS_ = -1.0;
  lastMismatch_ = "checking the motion from board time " + num(beganS_, "%.3f") + " s";
  phase_ = Phase::kChecking;
  return Status::ok();
}

RecorderProgress StreamPointRecorder::poll() {
  std::lock_guard lock(mutex_);
  RecorderProgress p;
  p.done = phase_ == Phase::kDone;
  p.note = lastMismatch_;
  if (!p.done && !linkFailure_.empty()) p.failure = ioError("the board's stream ended: " + linkFailure_);
  return p;
}

void StreamPointRecorder::end(int index) {
  std::lock_guard lock(mutex_);
  if (index != index_) return;
  if (phase_ == Phase::kRecording) windows_.back().endS = nowS_;
  phase_ = Phase::kIdle;
  buffer_.clear();
}

Status StreamPointRecorder::health() {
  std::lock_guard lock(mutex_);
  if (!linkFailure_.empty()) return ioError("the board's stream ended: " + linkFailure_);
  return Status::ok();
}

bool StreamPointRecorder::streamShowsRest(Axis axis) {
  std::lock_guard lock(mutex_);
  if (buffer_.empty() || buffer_.back().timeS - buffer_.front().timeS < 0.9) return false;
  double lo = 1e300, hi = -1e300;
  const auto ax = static_cast<std::size_t>(axis);
  for (const auto& s : buffer_)
    if (s.timeS >= nowS_ - 1.0) {
      lo = std::min(lo, s.angleDeg[ax]);
      hi = std::max(hi, s.angleDeg[ax]);
    }
  return hi - lo <= options_.restBandDeg;
}

std::vector<PointWindow> StreamPointRecorder::windows() const {
  std::lock_guard lock(mutex_);
  return windows_;
}

double StreamPointRecorder::streamTimeS() const {
  std::lock_guard lock(mutex_);
  return nowS_;
}

Recording segmentByWindows(const Recording& whole, const std::vector<PointWindow>& windows) {
  Recording out;
  out.counterHz = whole.counterHz;
  out.counterBits = whole.counterBits;
  out.pulseEquivalentDeg = whole.pulseEquivalentDeg;
  out.health = whole.health;
  std::vector<TableSample> table;
  std::vector<ImuSample> imu;
  for (const auto& tp : whole.testPoints) {
    table.insert(table.end(), tp.table.begin(), tp.table.end());
    imu.insert(imu.end(), tp.imu.begin(), tp.imu.end());
  }
  auto byTime = [](const auto& a, const auto& b) { return a.timeS < b.timeS; };
  std::stable_sort(table.begin(), table.end(), byTime);
  std::stable_sort(imu.begin(), imu.end(), byTime);
  for (const auto& w : windows) {
    TestPointData tp;
    tp.index = w.index;
    tp.axis = w.point.axis;
    tp.kind = w.point.kind;
    tp.nominalFrequencyHz = w.point.isStatic() ? 0.0 : w.point.frequencyHz;
    tp.nominalAmplitudeDeg = w.point.isStatic() ? 0.0 : w.point.amplitudeDeg;
    auto in = [&](double t) { return t >= w.startS && t < w.endS; };
    for (const auto& s : table)
      if (in(s.timeS)) tp.table.push_back(s);
    for (const auto& s : imu)
      if (in(s.timeS)) tp.imu.push_back(s);
    if (!tp.table.empty() || !tp.imu.empty()) out.testPoints.push_back(std::move(tp));
  }
  return out;
}

}  // namespace fog::table

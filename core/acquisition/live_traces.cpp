#include "core/acquisition/live_traces.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

namespace fog::acquisition {

LiveTraces::LiveTraces(double windowS) : windowS_(windowS > 0.0 ? windowS : 20.0) {}

void LiveTraces::clear() {
  const double bench = benchPulseEquivalentDeg_;
  *this = LiveTraces(windowS_);
  benchPulseEquivalentDeg_ = bench;
}

void LiveTraces::startTestPoint(int index, Axis axis, double frequencyHz) {
  testPoint_ = index;
  axis_ = axis;
  frequencyHz_ = frequencyHz;
  recordingStartS_ = -1.0;
  pointStartS_ = streamTimeS_;
  gyroAngleDeg_ = 0.0;
  fit_ = RunningFit{};
  recordingFit_ = RunningFit{};
  table_.clear();
  gyro_.clear();
}

void LiveTraces::follow(int index, Axis axis, double frequencyHz, protocol::TestPhase phase) {
  if (index >= 0 && (index != testPoint_ || axis != axis_)) startTestPoint(index, axis, frequencyHz);
  if (phase == protocol::TestPhase::kRecording && phase_ != protocol::TestPhase::kRecording)
    recordingStartS_ = streamTimeS_;
  phase_ = phase;
}

Eigen::Vector4d LiveTraces::basis(double t) const {
  const double x = t - pointStartS_;
  if (!(frequencyHz_ > 0.0)) return {1.0, x, 0.0, 0.0};
  const double w = 2.0 * std::numbers::pi * frequencyHz_;
  return {1.0, x, std::sin(w * x), std::cos(w * x)};
}

void LiveTraces::add(std::span<const protocol::DecodedFrame> frames) {
  for (const auto& f : frames) {
    ++frames_;
    if (!haveFirst_) {
      haveFirst_ = true;
      firstTicks_ = f.ticks;
    }
    if (const auto* s = std::get_if<protocol::StatusPayload>(&f.frame.payload)) {
      if (s->counterHz > 0) counterHz_ = s->counterHz;
      if (std::isfinite(s->pulseEquivalentDeg) && s->pulseEquivalentDeg > 0) pulseEquivalentDeg_ = s->pulseEquivalentDeg;
    }
    streamTimeS_ = static_cast<double>(f.ticks - firstTicks_) / counterHz_;
    if (const auto* s = std::get_if<protocol::StatusPayload>(&f.frame.payload)) {
      const int index = s->testPoint == protocol::kNoTestPoint ? -1 : s->testPoint;
      if (index >= 0 && (index != testPoint_ || s->axis != static_cast<int>(axis_)) && s->axis < kAxisCount)
        startTestPoint(index, static_cast<Axis>(s->axis), s->nominalFrequencyMicroHz / 1e6);
      if (s->phase == protocol::TestPhase::kRecording && phase_ != protocol::TestPhase::kRecording)
        recordingStartS_ = streamTimeS_;
      phase_ = s->phase;
    } else if (const auto* t = std::get_if<protocol::TablePayload>(&f.frame.payload)) {
      table_.push_back({streamTimeS_, t->angleMicroDeg[static_cast<std::size_t>(axis_)] * 1e-6});
    } else if (const auto* g = std::get_if<protocol::ImuPayload>(&f.frame.payload)) {
      const double scale = pulseEquivalentDeg_ > 0.0 ? pulseEquivalentDeg_ : benchPulseEquivalentDeg_;
      if (!(std::isfinite(scale) && scale > 0.0)) continue;
      gyroAngleDeg_ += g->pulses[static_cast<std::size_t>(axis_)] * scale;
      gyro_.push_back({streamTimeS_, gyroAngleDeg_});
      const Eigen::Vector4d b = basis(streamTimeS_);
      fit_.add(b, gyroAngleDeg_, streamTimeS_);
      if (phase_ == protocol::TestPhase::kRecording) recordingFit_.add(b, gyroAngleDeg_, streamTimeS_);
    }
  }
  trim();
}

void LiveTraces::trim() {
  const double oldest = streamTimeS_ - windowS_;
  while (!table_.empty() && table_.front().timeS < oldest) table_.pop_front();
  while (!gyro_.empty() && gyro_.front().timeS < oldest) gyro_.pop_front();
}

void LiveTraces::RunningFit::add(const Eigen::Vector4d& b, double angleDeg, double timeS) {
  normal.noalias() += b * b.transpose();
  rhs.noalias() += b * angleDeg;
  if (samples++ == 0) firstS = timeS;
  lastS = timeS;
}

Eigen::Vector4d LiveTraces::solve(const RunningFit& fit) const {
  // A handful of samples before anything is subtracted.
  const bool sine = frequencyHz_ > 0.0;
  if (fit.samples < 8) return Eigen::Vector4d::Zero();
  if (!sine) {
    const Eigen::Matrix2d n = fit.normal.topLeftCorner<2, 2>();
    const Eigen::LDLT<Eigen::Matrix2d> ldlt(n);
    if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return Eigen::Vector4d::Zero();
    const Eigen::Vector2d ab = ldlt.solve(fit.rhs.head<2>());
    return {ab[0], ab[1], 0.0, 0.0};
  }
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(fit.normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return Eigen::Vector4d::Zero();
  return ldlt.solve(fit.rhs);
}

double LiveTraces::gyroTrendDegPerS() const {
  const double needS = frequencyHz_ > 0.0 ? 2.0 / frequencyHz_ : 2.0;
  if (recordingFit_.samples < 8 || recordingFit_.lastS - recordingFit_.firstS < needS)
    return std::numeric_limits<double>::quiet_NaN();
  return solve(recordingFit_)[1];
}

std::vector<LiveTraces::Point> LiveTraces::gyroDetrended() const {
  const Eigen::Vector4d c = trend();
  std::vector<Point> out;
  out.reserve(gyro_.size());
  for (const auto& p : gyro_) {
    const double x = p.timeS - pointStartS_;
    out.push_back({p.timeS, p.angleDeg - c[0] - c[1] * x});
  }
  return out;
}

}  // namespace fog::acquisition

#pragma once
// sin(w*(t_i - shift)) and cos(w*(t_i - shift)) along a time series whose
// steps repeat (sampling-board stamps: 1 ms table, 2 ms IMU), computed as the
// fits walk the data instead of one sincos call per sample: each sample is
// the one four places back rotated by w times their time difference (four
// interleaved chains keep the CPU's pipelines full). The rotation is
// re-derived whenever that difference changes by more than 1e-12 s, and the
// chains restart from exact sincos every 256 samples, so the error is at
// most that of a 0.1 ns timing error, far below anything measured
// (tests/core/analysis/sin_cos_series_test.cpp checks it, sample by sample
// and in the sums the fits build, over 10 h at 1 kHz and 1 h at 11 Hz).
//
// Streaming matters: the fits are limited by memory traffic, not arithmetic,
// so nothing per-sample is stored.

#include <cmath>
#include <cstddef>

namespace fog::analysis {

class SinCosStream {
 public:
  SinCosStream(double w, double shift) : w_(w), shift_(shift) {}

  // The next sample, at time t (samples must come in series order).
  void next(double t, double& s, double& c) {
    const std::size_t slot = i_ & (kChains - 1);
    if ((i_ & (kAnchorEvery - 1)) < kChains) {
      s = std::sin(w_ * (t - shift_));
      c = std::cos(w_ * (t - shift_));
    } else {
      const double d = t - t_[slot];
      if (!(std::abs(d - step_) <= kStepTolerance)) {
        step_ = d;
        rs_ = std::sin(w_ * d);
        rc_ = std::cos(w_ * d);
      }
      const double ps = s_[slot], pc = c_[slot];
      s = ps * rc_ + pc * rs_;
      c = pc * rc_ - ps * rs_;
    }
    t_[slot] = t;
    s_[slot] = s;
    c_[slot] = c;
    ++i_;
  }

 private:
  static constexpr std::size_t kChains = 4;
  static constexpr std::size_t kAnchorEvery = 256;
  static constexpr double kStepTolerance = 1e-12;
  double w_, shift_;
  std::size_t i_ = 0;
  double t_[kChains] = {}, s_[kChains] = {}, c_[kChains] = {};
  double step_ = NAN, rs_ = 0.0, rc_ = 1.0;
};

// The whole series at once, for code that needs it stored.
inline void sinCosSeries(const double* t, std::size_t n, double w, double shift, double* s, double* c) {
  SinCosStream stream(w, shift);
  for (std::size_t i = 0; i < n; ++i) stream.next(t[i], s[i], c[i]);
}

}  // namespace fog::analysis

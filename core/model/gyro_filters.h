#pragma once
// The gyro's output filters as stated constants of the nominal chain
// (docs/simulator.md, "Gyro output filters"): a first-order and a
// second-order (resonant) low-pass of the sensed rate and an averaging
// (boxcar) filter of the rate. Each works on the cumulative sensed angle
// given at increasing instants (filtering the angle and the rate are the same
// LTI operation); between two instants the angle is taken as a polynomial
// through the last samples (six for the first order, three for the others),
// and each filter is solved exactly for it, so no integration step biases a
// delay.
//
// Low-frequency group delay: first order T, second order 2 zeta / omega_n,
// boxcar T / 2. One object per simulator (not thread-safe).

#include <array>
#include <deque>
#include <optional>

#include "core/common/test_plan.h"

namespace fog::model {

struct FogParams;

using AxisAngles = std::array<double, kAxisCount>;

// The angle between the previous instant t1 and the current one t,
// x(s) = x1 + b s + q s^2 for s in [0, h], h = t - t1, through the samples
// at t0 (when there is one), t1 and t.
struct QuadraticSegment {
  double h = 0.0, x1 = 0.0, x = 0.0, b = 0.0, q = 0.0;  // x: the sample at t
  double at(double s) const { return x1 + (b + q * s) * s; }
  // Integral over [s0, s1] within [0, h].
  double integral(double s0, double s1) const;
};

// The last samples a filter needs: its quadratic segment for each axis.
class SampleHistory {
 public:
  // False for the first sample or one not after the last (at rest: the
  // caller restarts); otherwise the segments from the last sample to t.
  bool push(double t, const AxisAngles& x, std::array<QuadraticSegment, kAxisCount>& segments);
  int samples() const { return samples_; }
  double lastTimeS() const { return t1_; }

 private:
  int samples_ = 0;
  double t0_ = 0.0, t1_ = 0.0;
  AxisAngles x0_{}, x1_{};
};

// y' = (x - y) / T, solved exactly for the polynomial through the last six
// samples (of lower degree at the start) over the last interval: y(t1) =
// p(t1) + exp(-h/T) (y(t0) - p(t0)) with the particular solution p = sum
// over k of (-T)^k x^(k). The interpolation's error is of order (w h)^6 of
// the swing. (The quadratic through three that the other filters use left
// about (w h)^3 / 16: 1.6e-4 of the swing at 11 Hz with 2-ms samples, which
// a frequency response resolves: chi^2 1 268 on 13 dof for the first order
// of a 2-ms filter.) The diagnosis library's first_order_lag is this filter.
// Phase at omega: atan(omega T).
class FirstOrderFilter {
 public:
  explicit FirstOrderFilter(double timeConstantS) : tau_(timeConstantS) {}
  void apply(double t, AxisAngles& x);

 private:
  static constexpr int kNodes = 6;
  double tau_;
  int kept_ = 0;                  // samples kept: 1 .. kNodes - 1, newest first
  double time_[kNodes - 1] = {};  // their times
  AxisAngles x_[kNodes - 1]{}, y_{};
};

// y'' + 2 zeta omega_n y' + omega_n^2 y = omega_n^2 x, solved exactly for a
// quadratic x (particular solution p = x - (2 zeta / omega_n) x' +
// ((4 zeta^2 - 1) / omega_n^2) x'', the homogeneous rest by the 2x2 state
// transition). Phase at omega: atan2(2 zeta w / omega_n, 1 - (w / omega_n)^2).
class SecondOrderFilter {
 public:
  SecondOrderFilter(double naturalHz, double damping);
  void apply(double t, AxisAngles& x);

 private:
  double wn_, zeta_;
  SampleHistory history_;
  AxisAngles y_{}, dy_{};
};

// Y(t) = (1/T) integral of x over [t - T, t] (the rate averaged over T,
// integrated): the quadratic segments of the last T are kept. Before the
// first sample x holds its first value. A sinusoid of frequency f comes out
// delayed by T/2 and scaled by sinc(pi f T).
class BoxcarFilter {
 public:
  explicit BoxcarFilter(double lengthS) : length_(lengthS) {}
  void apply(double t, AxisAngles& x);

 private:
  struct Segment {
    double start = 0.0, end = 0.0;
    std::array<QuadraticSegment, kAxisCount> x{};
  };
  double length_;
  SampleHistory history_;
  AxisAngles first_{}, last_{};
  std::deque<Segment> segments_;
};

// The chain's rate filters in order: first order, second order, boxcar;
// those whose constant is 0 are left out.
class GyroFilters {
 public:
  explicit GyroFilters(const FogParams& fog);
  bool active() const { return first_ || second_ || boxcar_; }
  void apply(double t, AxisAngles& x);

 private:
  std::optional<FirstOrderFilter> first_;
  std::optional<SecondOrderFilter> second_;
  std::optional<BoxcarFilter> boxcar_;
};

}  // namespace fog::model

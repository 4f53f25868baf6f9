#include "core/model/gyro_filters.h"

#include <algorithm>
#include <cmath>

#include "core/common/units.h"
#include "core/model/sim_config.h"

namespace fog::model {

double QuadraticSegment::integral(double s0, double s1) const {
  return x1 * (s1 - s0) + b / 2.0 * (s1 * s1 - s0 * s0) + q / 3.0 * (s1 * s1 * s1 - s0 * s0 * s0);
}

bool SampleHistory::push(double t, const AxisAngles& x, std::array<QuadraticSegment, kAxisCount>& segments) {
  if (samples_ == 0 || !(t > t1_)) {
    samples_ = 1, t1_ = t, x1_ = x;
    return false;
  }
  const double h = t - t1_;
  for (int i = 0; i < kAxisCount; ++i) {
    double q = 0.0;
    if (samples_ >= 2) {
      const double g = t1_ - t0_;
      const double d1 = (x[i] - x1_[i]) / h, d0 = (x1_[i] - x0_[i]) / g;
      q = (d1 - d0) / (h + g);
    }
    const double b = (x[i] - x1_[i]) / h - q * h;
    segments[i] = QuadraticSegment{h, x1_[i], x[i], b, q};
  }
  t0_ = t1_, x0_ = x1_;
  t1_ = t, x1_ = x;
  samples_ = std::min(samples_ + 1, 2);
  return true;
}

void FirstOrderFilter::apply(double t, AxisAngles& x) {
  if (tau_ <= 0.0) return;
  if (kept_ == 0 || !(t > time_[0])) {
    if (kept_ == 0) y_ = x;  // at rest before the first sample
    kept_ = 1, time_[0] = t, x_[0] = x;
    x = y_;
    return;
  }
  const double h = t - time_[0];
  const double a = std::exp(-h / tau_);
  // Nodes in s = time - t1: the new sample at h, then the kept ones (0, ...).
  const int n = kept_ + 1;
  double s[kNodes];
  s[0] = h;
  for (int k = 1; k < n; ++k) s[k] = time_[k - 1] - time_[0];
  for (int i = 0; i < kAxisCount; ++i) {
    double v[kNodes];
    v[0] = x[i];
    for (int k = 1; k < n; ++k) v[k] = x_[k - 1][i];
    // Newton's divided differences, then the monomial coefficients m of p(s).
    for (int k = 1; k < n; ++k)
      for (int j = n - 1; j >= k; --j) v[j] = (v[j] - v[j - 1]) / (s[j] - s[j - k]);
    double m[kNodes] = {};
    for (int k = n - 1; k >= 0; --k) {  // m <- m (s - s_k) + v_k
      for (int j = kNodes - 1; j >= 1; --j) m[j] = m[j - 1] - s[k] * m[j];
      m[0] = -s[k] * m[0] + v[k];
    }
    // The particular solution of tau y' + y = p: sum over k of (-tau)^k p^(k).
    auto particular = [&](double at) {
      double d[kNodes];
      std::copy(m, m + kNodes, d);
      double sum = 0.0, weight = 1.0;
      for (int order = 0; order < n; ++order) {
        double value = 0.0;
        for (int j = n - 1 - order; j >= 0; --j) value = value * at + d[j];
        sum += weight * value;
        weight *= -tau_;
        for (int j = 0; j + 1 < kNodes; ++j) d[j] = static_cast<double>(j + 1) * d[j + 1];  // d <- d'
        d[kNodes - 1] = 0.0;
      }
      return sum;
    };
    y_[i] = particular(h) + a * (y_[i] - particular(0.0));
  }
  for (int k = kNodes - 2; k >= 1; --k) time_[k] = time_[k - 1], x_[k] = x_[k - 1];
  time_[0] = t, x_[0] = x;
  kept_ = std::min(kept_ + 1, kNodes - 1);
  x = y_;
}

SecondOrderFilter::SecondOrderFilter(double naturalHz, double damping) : wn_(kTwoPi * naturalHz), zeta_(damping) {}

void SecondOrderFilter::apply(double t, AxisAngles& x) {
  const bool first = history_.samples() == 0;
  std::array<QuadraticSegment, kAxisCount> seg;
  if (!history_.push(t, x, seg)) {
    if (first) y_ = x, dy_ = {};  // at rest before the first sample
    x = y_;
    return;
  }
  // State transition of (e, e') over h for e'' + 2 zeta wn e' + wn^2 e = 0:
  // exp(-zeta wn h) [C I + S (A + zeta wn I)], written with the decay folded
  // in so that a strongly damped filter does not overflow cosh.
  const double h = seg[0].h, zw = zeta_ * wn_, disc = zeta_ * zeta_ - 1.0;
  double c = 0.0, s = 0.0;  // decay * C, decay * S
  if (disc < 0.0) {
    const double wd = wn_ * std::sqrt(-disc), decay = std::exp(-zw * h);
    c = decay * std::cos(wd * h);
    s = decay * std::sin(wd * h) / wd;
  } else if (disc > 0.0) {
    const double wq = wn_ * std::sqrt(disc);
    const double e1 = std::exp((wq - zw) * h), e2 = std::exp(-(wq + zw) * h);
    c = 0.5 * (e1 + e2);
    s = (e1 - e2) / (2.0 * wq);
  } else {
    const double decay = std::exp(-zw * h);
    c = decay;
    s = decay * h;
  }
  const double f00 = c + s * zw, f01 = s, f10 = -s * wn_ * wn_, f11 = c - s * zw;
  const double c1 = 2.0 * zeta_ / wn_, c2 = (4.0 * zeta_ * zeta_ - 1.0) / (wn_ * wn_);
  for (int i = 0; i < kAxisCount; ++i) {
    const QuadraticSegment& q = seg[i];
    const double p0 = q.x1 - c1 * q.b + c2 * 2.0 * q.q, dp0 = q.b - c1 * 2.0 * q.q;
    const double slopeEnd = q.b + 2.0 * q.q * q.h;
    const double pEnd = q.x - c1 * slopeEnd + c2 * 2.0 * q.q, dpEnd = slopeEnd - c1 * 2.0 * q.q;
    const double e0 = y_[i] - p0, de0 = dy_[i] - dp0;
    y_[i] = pEnd + f00 * e0 + f01 * de0;
    dy_[i] = dpEnd + f10 * e0 + f11 * de0;
  }
  x = y_;
}

void BoxcarFilter::apply(double t, AxisAngles& x) {
  const bool first = history_.samples() == 0;
  Segment added;
  if (!history_.push(t, x, added.x)) {
    if (first) first_ = x, last_ = x;
    x = last_;
    return;
  }
  added.end = t;
  added.start = t - added.x[0].h;
  segments_.push_back(added);
  const double lo = t - length_;
  while (!segments_.empty() && segments_.front().end <= lo) segments_.pop_front();
  for (int i = 0; i < kAxisCount; ++i) {
    double sum = 0.0;
    // Before the first sample the angle held its first value.
    if (!segments_.empty() && segments_.front().start > lo) sum += (segments_.front().start - lo) * first_[i];
    for (const Segment& g : segments_) sum += g.x[i].integral(std::max(lo, g.start) - g.start, g.end - g.start);
    last_[i] = sum / length_;
  }
  x = last_;
}

GyroFilters::GyroFilters(const FogParams& fog) {
  if (fog.rateFilterTimeConstantS > 0.0) first_.emplace(fog.rateFilterTimeConstantS);
  if (fog.rateFilterNaturalHz > 0.0) second_.emplace(fog.rateFilterNaturalHz, fog.rateFilterDamping);
  if (fog.boxcarS > 0.0) boxcar_.emplace(fog.boxcarS);
}

void GyroFilters::apply(double t, AxisAngles& x) {
  if (first_) first_->apply(t, x);
  if (second_) second_->apply(t, x);
  if (boxcar_) boxcar_->apply(t, x);
}

}  // namespace fog::model

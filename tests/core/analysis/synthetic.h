#pragma once
// Test data made directly (not by the simulator): a swing seen by a table
// encoder and a gyro with a known lag, so the analysis can be checked against
// a truth that does not share the simulator's code.

#include <cmath>
#include <random>

#include "core/common/recording.h"
#include "core/common/units.h"

namespace fog::analysis::testing {

struct SyntheticSpec {
  double frequencyHz = 1.0;
  double amplitudeDeg = 3.0;
  double durationS = 20.0;
  double lagS = 0.4658e-3;
  double phaseRad = 0.3;
  double gain = 1.0;
  double trendDegPerS = 1e-4;
  double tableQuantumDeg = 1e-4;   // rounding of encoder readings (0 = none)
  double pulseEquivalentDeg = 5e-5; // gyro pulse quantisation (0 = none)
  double arwDegPerSqrtS = 0.0;
  double rateWalkDegPerS = 0.0;     // a bias that wanders (deg/s per sqrt(s)): noise slower than a period
  double startS = 3.0;
  unsigned seed = 1;
};

inline TestPointData makeSynthetic(const SyntheticSpec& s) {
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double w = kTwoPi * s.frequencyHz;
  auto motion = [&](double t) { return s.amplitudeDeg * std::sin(w * t + s.phaseRad); };
  TestPointData d;
  d.axis = Axis::kY;
  d.nominalFrequencyHz = s.frequencyHz;
  d.nominalAmplitudeDeg = s.amplitudeDeg;
  for (double t = s.startS; t < s.startS + s.durationS; t += 1e-3) {
    TableSample ts;
    ts.timeS = t;
    double y = motion(t);
    if (s.tableQuantumDeg > 0) y = std::round(y / s.tableQuantumDeg) * s.tableQuantumDeg;
    ts.angleDeg[1] = y;
    d.table.push_back(ts);
  }
  double arw = 0.0, bias = 0.0, biasAngle = 0.0, lastT = s.startS, lastSensed = 0.0;
  long long lastCount = 0;
  bool first = true;
  for (double t = s.startS + 0.3e-3; t < s.startS + s.durationS; t += 2e-3) {
    arw += s.arwDegPerSqrtS * std::sqrt(t - lastT) * normal(rng);
    biasAngle += bias * (t - lastT);
    if (s.rateWalkDegPerS > 0.0) bias += s.rateWalkDegPerS * std::sqrt(t - lastT) * normal(rng);
    lastT = t;
    const double sensed = s.gain * motion(t - s.lagS) + s.trendDegPerS * t + arw + biasAngle;
    double increment = sensed - lastSensed;
    if (s.pulseEquivalentDeg > 0) {
      const auto count = static_cast<long long>(std::floor(sensed / s.pulseEquivalentDeg));
      increment = static_cast<double>(count - lastCount) * s.pulseEquivalentDeg;
      lastCount = count;
    }
    lastSensed = sensed;
    ImuSample is;
    is.timeS = t;
    is.incrementDeg[1] = first ? 0.0 : increment;  // the first frame only starts integration
    first = false;
    d.imu.push_back(is);
  }
  return d;
}

}  // namespace fog::analysis::testing

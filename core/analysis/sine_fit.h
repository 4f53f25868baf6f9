#pragma once
// Sinusoid fits to one channel (IEEE Std 1057 style): a 3-parameter linear
// least-squares fit at a given frequency, then a 4-parameter fit with the
// frequency free, solved with Ceres. The gyro fits carry a trend term (bias +
// Earth rate) and work on the increments with the exact difference model,
// weighted by the channel's noise model (generalised least squares).
//
// Convention (the paper's): angle = A * sin(2*pi*(t - t0)/T) + offset, period
// T and phase t0 in ms on the session's time axis, t0 wrapped into (-T/2, T/2].
// A channel that lags has the larger t0.

#include <cstddef>

#include "core/analysis/channels.h"
#include "core/common/status.h"

namespace fog::analysis {

struct SineFit {
  double frequencyHz = 0.0, frequencyStdHz = 0.0;
  double periodMs = 0.0, periodStdMs = 0.0;
  double phaseMs = 0.0, phaseStdMs = 0.0;
  double amplitudeDeg = 0.0, amplitudeStdDeg = 0.0;
  double offsetDeg = 0.0;  // table: fitted; gyro: offset of the cumulative angle
  double trendDegPerS = 0.0, trendStdDegPerS = 0.0;  // gyro only
  double residualRmsDeg = 0.0;  // table: angle residuals; gyro: increment residuals
  double chiSquarePerDof = 0.0; // weighted residuals; ~1 when the noise model holds
  std::size_t samples = 0;
  int iterations = 0;  // 0 for a linear fit

  // The fit in the channel's own terms: a*sin(w*tau) + b*cos(w*tau) with tau
  // relative to the channel reference time.
  double a = 0.0, b = 0.0, omegaRadPerS = 0.0, referenceS = 0.0;
};

// 3-parameter fits at angular frequency omega (rad/s).
SineFit fitTableLinear(const TableChannel& table, double omegaRadPerS, double referenceS);
// weighted: use the channel's noise model (GLS); otherwise ordinary LS.
SineFit fitGyroLinear(const GyroChannel& gyro, double omegaRadPerS, double referenceS, bool weighted);

// 4-parameter fits (frequency free) with Ceres, started from a linear fit.
Result<SineFit> fitTableNonlinear(const TableChannel& table, const SineFit& start);
Result<SineFit> fitGyroNonlinear(const GyroChannel& gyro, const SineFit& start);

// Residuals of a fit: table angle residuals, or (unweighted) gyro increment residuals.
std::vector<double> tableResiduals(const TableChannel& table, const SineFit& fit);
std::vector<double> gyroIncrementResiduals(const GyroChannel& gyro, const SineFit& fit);
// What every gyro noise estimate starts from (channels.h), from the
// increment residuals of a fit, in one pass that stores no residual: the
// same numbers, to the bit, as
// incrementResidualSums(gyro, gyroIncrementResiduals(gyro, fit)).
IncrementResidualSums gyroIncrementResidualSums(const GyroChannel& gyro, const SineFit& fit);

// Wraps t (s) into (-period/2, period/2].
double wrapToHalfPeriod(double t, double period);

}  // namespace fog::analysis

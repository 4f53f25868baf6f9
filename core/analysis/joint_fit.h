#pragma once
// The joint fit: table and gyro share one swing frequency, and the delay is a
// parameter of the model, with its own standard error:
//
//   table(t) = a*sin(w*t) + b*cos(w*t) + c
//   gyro(t)  = g*(a*sin(w*(t - lag)) + b*cos(w*(t - lag))) + d*t
//
// (gyro fitted on its increments, whitened by its noise model; table
// weighted by its white noise). Parameters (w, a, b, c, g, lag, d).

#include "core/analysis/channels.h"
#include "core/analysis/sine_fit.h"
#include "core/common/status.h"

namespace fog::analysis {

struct JointFit {
  double frequencyHz = 0.0, frequencyStdHz = 0.0;
  double lagS = 0.0, lagStdS = 0.0;  // positive: gyro output behind the table
  double gain = 0.0, gainStd = 0.0;  // gyro amplitude / table amplitude
  // Correlation of gain and lag in the fit's covariance (frequency_response.h
  // turns it into the covariance of magnitude and phase).
  double gainLagCorrelation = 0.0;
  double trendDegPerS = 0.0, trendStdDegPerS = 0.0;
  double chiSquarePerDof = 0.0;
  int iterations = 0;
  // Model parameters, times relative to the channels' reference.
  double omegaRadPerS = 0.0, a = 0.0, b = 0.0, offsetDeg = 0.0;
};

// Starts from the separate 4-parameter fits of the two channels.
Result<JointFit> fitJoint(const Channels& channels, const SineFit& tableFit, const SineFit& gyroFit);

}  // namespace fog::analysis

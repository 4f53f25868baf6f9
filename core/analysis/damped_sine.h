#pragma once
// Lag of an exponentially decaying swing (a free pendulum, a table coasting
// down), where the steady-sinusoid fits are biased:
//
//   table(t) = exp(-lambda*t) * (a*sin(w*t) + b*cos(w*t)) + c
//   gyro(t)  = G * table(t - lag) without c, + trend*t
//
// The table is fitted with all five parameters (Levenberg-Marquardt); the
// gyro's increments are then fitted linearly at the table's (w, lambda) with
// the exact difference model, and the lag is the phase difference over w (a
// delayed decaying sinusoid is the same sinusoid times exp(lambda*lag)).
// Offered beside an "invalid" verdict for a swing that is not steady, never
// instead of it: whether the decay is the table's true motion is the
// operator's call.

#include <optional>

#include "core/analysis/channels.h"

namespace fog::analysis {

struct DampedSineLag {
  double lagMs = 0.0, lagStdMs = 0.0;
  double frequencyHz = 0.0;
  double decayTimeS = 0.0;  // 1/lambda; negative for a growing swing
  double tableResidualRmsDeg = 0.0;
  double gain = 0.0;  // gyro / table amplitude
};

// omegaStart, lambdaStart: starting values (rad/s, 1/s). Empty when the fit
// does not converge or the data cannot support it.
std::optional<DampedSineLag> fitDampedSineLag(const Channels& channels, double omegaStart, double lambdaStart);

}  // namespace fog::analysis

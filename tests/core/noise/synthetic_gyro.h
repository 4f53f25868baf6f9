#pragma once
// A gyro at rest with known noise, generated directly (no frames) so that a
// Monte Carlo over many seeds runs in seconds. The processes are the
// simulator's (core/model/simulator.cpp): angle random walk, a first-order
// Gauss-Markov bias wander started from its stationary distribution, and
// either white angle noise (IEEE 952 quantisation noise Q, white in the
// angle) or pulse quantisation of the cumulative angle with the remainder
// carried. The latter is white only when the angle moves by several pulses
// per frame; a gyro at rest dithers it far less (docs/noise.md).

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/model/random.h"

namespace fog::noise::testing {

struct SyntheticGyro {
  double intervalS = 2e-3;
  double biasDegPerS = 0.0;
  double arwDegPerSqrtS = 0.0;        // N
  double markovSigmaDegPerS = 0.0;    // Gauss-Markov standard deviation
  double markovCorrelationS = 100.0;
  double whiteAngleDeg = 0.0;         // Q: white noise on the cumulative angle (1 sigma)
  double pulseDeg = 0.0;              // 0: no pulse quantisation

  // Angle increments (deg) of n frames.
  std::vector<double> increments(std::size_t n, std::uint64_t seed) const {
    model::Random rng(seed);
    std::vector<double> out(n);
    const double decay = std::exp(-intervalS / markovCorrelationS);
    const double drive = markovSigmaDegPerS * std::sqrt(1.0 - decay * decay);
    double wander = markovSigmaDegPerS * rng.normal();
    double angle = 0.0, prev = 0.0;
    std::int64_t lastCount = 0;
    for (std::size_t k = 0; k < n; ++k) {
      // Exact integral of the Gauss-Markov rate over the frame is not needed
      // at the taus tested (>= 10 frames); the simulator uses the same rule.
      angle += biasDegPerS * intervalS + arwDegPerSqrtS * std::sqrt(intervalS) * rng.normal() + wander * intervalS;
      wander = wander * decay + drive * rng.normal();
      const double observed = angle + whiteAngleDeg * rng.normal();
      if (pulseDeg > 0.0) {
        const auto count = static_cast<std::int64_t>(std::floor(observed / pulseDeg));
        out[k] = static_cast<double>(count - lastCount) * pulseDeg;
        lastCount = count;
      } else {
        out[k] = observed - prev;
      }
      prev = observed;
    }
    return out;
  }
};

}  // namespace fog::noise::testing

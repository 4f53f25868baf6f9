#pragma once
// The Allan curve of a phase series and the IEEE Std 952 noise terms
// identified from it.
//
// Terms and their Allan variances (rate units r = phase units / s, e.g. deg/s;
// tau in s):
//   quantisation Q (phase units)             3 Q^2 / tau^2
//   angle random walk N (r sqrt(s))          N^2 / tau
//   bias instability B (r), flicker rate     (2 ln 2 / pi) B^2     (ADEV plateau 0.664 B)
//   rate random walk K (r / sqrt(s))         K^2 tau / 3
//   rate ramp R (r / s)                      R^2 tau^2 / 2
//   Markov (exponentially correlated) rate   (2 s^2 Tc / tau) [1 - Tc/(2 tau) (3 - 4 e^(-tau/Tc) + e^(-2 tau/Tc))]
//     of standard deviation s and correlation time Tc (IEEE 952 Annex C);
//     the simulator's bias instability is this process.
//
// Identification: a weighted least-squares fit of the sum of the terms'
// Allan variances to the measured one. Each variance is weighted by its
// inverse variance 2 model^2 / EDF (iterated, so the weights use the model,
// not the noisy measurement), coefficients are kept >= 0 (active set), the
// Markov correlation time is found on a logarithmic grid (variable
// projection: the rest is linear), and only terms whose coefficient is at
// least `minSignificance` standard errors from zero are reported (a Markov
// term also when dropping it raises chi^2 beyond the same tail probability
// for 2 degrees of freedom). With the curve's pulse known, the quantisation
// term has the shape of the pulse count of a slowly moving angle.
// Neighbouring taus of an overlapping Allan curve are strongly correlated,
// so the fit's covariance understates the uncertainties (by 2-4x, see
// docs/noise.md). The stated uncertainties are therefore delete-a-block
// jackknife estimates: the record is cut into blocks, each block's data
// left out in turn (every second difference that uses it), the fit repeated
// (same terms) and the spread of the replicates taken; where a second
// difference spans more than a block the replicates cannot see the
// variance, and each tau's spread there is raised to at least its 2 / EDF
// before the refit. The
// fit's covariance (scaled by chi^2/dof when above 1) is used only to decide
// which terms are significant, and when the curve has no replicates.
//
// Pure functions, thread-safe; no exceptions.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/noise/allan.h"

namespace fog::noise {

struct AllanPoint {
  double tauS = 0.0;
  std::size_t m = 0;            // averaging factor, tau = m * tau0
  double deviation = 0.0;       // overlapping Allan deviation, rate units
  std::size_t differences = 0;  // second differences averaged
  PowerLawNoise noise = PowerLawNoise::kWhiteFrequency;  // noise type the EDF assumes
  double edf = 0.0;
  Interval interval;            // at AllanCurve::confidence
  // Delete-a-block jackknife replicates: the Allan variance with block b's
  // data left out (every second difference using an increment of it),
  // rescaled to the spread of leaving out 1/blocks of the differences, so
  // that the delete-1 jackknife formula holds at every tau.
  std::vector<double> jackknifeVariance;
};

// The pulse quantisation of the phase, when known: the phase is
// pulseDeg * floor(angle / pulseDeg) of an angle advancing by stepDeg per
// tau0 on average (the mean increment, before it is removed). A gyro at rest
// moves a pulse only every few frames, so its quantisation error is a slow
// sawtooth, not white angle noise; with these the quantisation term takes the
// Allan variance of that sawtooth, dithered by the gyro's own noise
// (pulseQuantisationUnitVariance). pulseDeg = 0: white quantisation (IEEE 952).
struct PulseQuantisation {
  double pulseDeg = 0.0;
  double stepDeg = 0.0;
};

struct AllanCurve {
  double tau0S = 0.0;
  std::size_t phasePoints = 0;
  PulseQuantisation pulse;
  double confidence = kOneSigmaConfidence;
  std::vector<AllanPoint> points;
  // Per jackknife block b: how much the record's mean step per tau0 changes
  // when block b is left out (phase units). A pulse-quantised record's
  // quantisation shape depends steeply on its mean step, so each replicate
  // is fitted at its own (pulse.stepDeg + this).
  std::vector<double> jackknifeStepChange;
};

struct AllanOptions {
  int tausPerOctave = 2;      // tau steps of 2^(1/tausPerOctave)
  double maxTauFraction = 0.25;  // longest tau as a fraction of the record
  double confidence = kOneSigmaConfidence;
  int jackknifeBlocks = 16;   // 0: no jackknife (uncertainties from the fit's covariance)
};

// Overlapping Allan deviation at logarithmically spaced taus. EDFs and
// intervals assume the noise type of the curve's local slope; identifyNoise()
// refines them with the fitted model. Fails with kInsufficientData for fewer
// than 8 phase values.
Result<AllanCurve> overlappingAllanCurve(std::span<const double> phase, double tau0S, const AllanOptions& options = {});

enum class NoiseTermKind { kQuantisation, kAngleRandomWalk, kBiasInstability, kRateRandomWalk, kRateRamp, kMarkov };
inline constexpr int kNoiseTermKinds = 6;
const char* noiseTermName(NoiseTermKind kind);  // "quantisation", "angle random walk", ...
const char* noiseTermKey(NoiseTermKind kind);   // "quantisation", "angle_random_walk", ... (JSON)

struct NoiseTerm {
  NoiseTermKind kind = NoiseTermKind::kAngleRandomWalk;
  // In the units of the table above (phase units: Q; rate units * s^p: N, B, K, R; rate: Markov sigma).
  double value = 0.0, stdError = 0.0;
  double significance = 0.0;       // fitted coefficient / its standard error
  double tauLowS = 0.0, tauHighS = 0.0;  // taus where this term is >= 1/3 of the model variance
  double correlationTimeS = 0.0;   // Markov only: Tc and its chi^2 + 1 range on the grid
  double correlationTimeLowS = 0.0, correlationTimeHighS = 0.0;
};

struct NoiseModel {
  std::vector<NoiseTerm> terms;  // significant terms only, in NoiseTermKind order
  double chiSquare = 0.0;
  int dof = 0;
  double tau0S = 0.0;
  PulseQuantisation pulse;  // the curve's: shapes the quantisation term
  // Model Allan variance (rate units^2) at tau.
  double allanVariance(double tauS) const;
  const NoiseTerm* find(NoiseTermKind kind) const;
};

struct IdentifyOptions {
  double minSignificance = 2.0;  // report a term only when coefficient / std >= this
  bool allowMarkov = true;
  // Candidate terms; a term left out is never fitted (e.g. no rate ramp).
  bool allowed[kNoiseTermKinds] = {true, true, true, true, true, true};
  // Levenberg-Marquardt steps per pass; a fit still moving after them fails
  // with kNotConverged rather than reporting terms from a half-done fit.
  int maxIterations = 200;
};

// Fits the terms to `curve` and rewrites the curve's EDFs and intervals with
// the noise type the fitted model has at each tau. Fails with
// kInsufficientData when the curve has fewer than 3 points, kNotConverged
// when the final fit is still moving after options.maxIterations steps.
Result<NoiseModel> identifyNoise(AllanCurve& curve, const IdentifyOptions& options = {});

// Allan variance of a single term with value 1 (and correlation time tcS for
// Markov), so that model = sum value^2 * unitAllanVariance(...).
double unitAllanVariance(NoiseTermKind kind, double tauS, double tcS = 0.0);

// Allan variance per unit Q^2 (Q = pulse / sqrt 12) of the pulse quantisation
// error of an angle that advances by `step` pulses per tau0 on average, with
// Gaussian jitter: jitter1 and jitter2 are the variances (pulses^2) of the
// angle's change over tau and 2 tau from its noise. The quantisation error is
// the sawtooth e = frac(angle / pulse); with a random starting phase its
// autocovariance at a mean shift d and jitter variance v is
// R(d, v) = E[1/12 - f (1 - f) / 2], f = frac(d + N(0, v)), and
//   AVAR = 12 (3 R(0) - 4 R(step m, jitter1) + R(2 step m, jitter2)) / tau^2,
// uncorrelated with the noise itself (the random phase averages the cross
// term out). Large jitter: R -> 0 and this is 3 / tau^2, white quantisation.
double pulseQuantisationUnitVariance(double tauS, double tau0S, double step, double jitter1, double jitter2);

// Variance of the angle's change over lagS (phase units^2) due to a term of
// value 1: N^2 L (ARW), 2 s^2 Tc^2 (L/Tc - 1 + e^(-L/Tc)) (Markov), K^2 L^3/3
// (rate random walk), ~ L^2 x its Allan variance (flicker); 0 for Q and ramp.
double unitAngleVariance(NoiseTermKind kind, double lagS, double tcS = 0.0);

}  // namespace fog::noise

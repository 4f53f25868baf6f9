#pragma once
// Overlapping Allan deviation computed from a cumulative (phase) series, its
// equivalent degrees of freedom and chi-squared confidence intervals
// (NIST Special Publication 1065, sections 5.2.4 and 5.3).
//
// For a gyro, the phase is the cumulative angle (deg) and the "frequency" is
// the rate (deg/s): the Allan deviation of the rate at tau = m * tau0 is
//   sigma^2(tau) = sum_i (x[i+2m] - 2 x[i+m] + x[i])^2 / (2 tau^2 (N - 2m))
// over the N phase values x, which is the rate averaged over each tau without
// throwing any sample away. One pass over the data per tau: O(N) each.
//
// Pure functions, no state, thread-safe. Preconditions are stated per
// function; a violated one gives NaN, never a crash.

#include <cstddef>
#include <span>
#include <vector>

namespace fog::noise {

// Power-law noise types by the exponent alpha of the rate's power spectrum
// S(f) ~ f^alpha (SP 1065 Table 1), with their gyro names (IEEE Std 952).
enum class PowerLawNoise {
  kWhitePhase = 2,             // white angle: quantisation noise Q
  kFlickerPhase = 1,           // flicker angle
  kWhiteFrequency = 0,         // white rate: angle random walk N
  kFlickerFrequency = -1,      // flicker rate: bias instability B
  kRandomWalkFrequency = -2,   // random-walk rate: rate random walk K (also used for rate ramp)
};
const char* powerLawNoiseName(PowerLawNoise noise);  // "white angle", "white rate", ...

// x[0] = 0, x[k+1] = x[k] + (increments[k] - subtractPerStep): n increments give
// n + 1 phase values. Subtracting the mean increment keeps the sums small
// (the Allan variance is blind to a constant rate) and so keeps precision
// over tens of millions of samples.
std::vector<double> cumulativeSum(std::span<const double> increments, double subtractPerStep = 0.0);

// Allan variance at tau = m * tau0S from phase values (phase units / s)^2;
// overlapping (stride 1) or the classic non-overlapping estimator (stride m).
// Needs m >= 1, 2m < phase.size(), tau0S > 0. `differences` receives the
// number of second differences averaged.
double allanVariance(std::span<const double> phase, double tau0S, std::size_t m, bool overlapping,
                     std::size_t* differences = nullptr);

// Averaging factors m = 1, then steps of 2^(1/perOctave) rounded to distinct
// integers, up to maxFraction * (phasePoints - 1) (and always below half of it).
std::vector<std::size_t> averagingFactors(std::size_t phasePoints, int perOctave = 2, double maxFraction = 0.25);

// Equivalent degrees of freedom of the overlapping Allan variance for
// `phasePoints` phase values at averaging factor m: the simple approximations
// of SP 1065 Table 5 (Howe, Allan and Barnes 1981).
double edfOverlappingAllan(std::size_t phasePoints, std::size_t m, PowerLawNoise noise);

// Chi-squared distribution with a real number of degrees of freedom (> 0):
// the cumulative probability and its inverse (quantile, 0 < p < 1). The
// quantile is accurate to ~1e-10 relative; for dof > 1e5 it uses the
// Wilson-Hilferty cube-root approximation, whose error there is below 1e-9.
double chiSquareCdf(double x, double dof);
double chiSquareQuantile(double p, double dof);
// Standard normal quantile (Acklam's approximation refined by one Halley step).
double normalQuantile(double p);

// Two-sided confidence interval of a deviation estimated with `edf` degrees
// of freedom (SP 1065 eq. 45): sigma^2 * edf / chi2(1 - a/2) .. sigma^2 * edf / chi2(a/2).
struct Interval {
  double low = 0.0, high = 0.0;
};
Interval deviationInterval(double deviation, double edf, double confidence);

// The 1-sigma confidence level, erf(1/sqrt 2).
inline constexpr double kOneSigmaConfidence = 0.6826894921370859;

}  // namespace fog::noise

#pragma once
// Validity of a test point's delay: checks of the data against the model the
// delay rests on (a steady sinusoid seen by table and gyro on one clock, the
// gyro turning the same way as the table, a causal delay), and measures of
// the uncertainty that do not rest on the noise level fitted from the same
// residuals. A failed check makes the test point's verdict "invalid"
// (verdict.h): the bench refuses a number it cannot vouch for. Method and
// thresholds: docs/method.md, "Validity checks".
//
// Everything here is a pure function of the channels and the fits; no check
// changes the fits themselves.

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/channels.h"
#include "core/analysis/sample_passes.h"
#include "core/analysis/sine_fit.h"
#include "core/common/status.h"

namespace fog::analysis {

// One check of a test point. Ids are stable (the JSON report's "checks"):
// "axis_sign", "gain" (added by analyzeRecording, gain_check.h),
// "steady_sine", "clock_rate", "causal", "uncertainty_below_bound".
struct ValidityCheck {
  std::string id;
  bool passed = true;
  std::string detail;  // what was measured; when failed, what it means and what to do
  // false: the check could not be judged (its measure is meaningless, e.g.
  // timing on a swing that is not a steady sinusoid); it then neither passes
  // nor fails, and the detail says why.
  bool judged = true;
};

// Swing frequency of the table angle, for streams that do not state it and
// as a check of the plan: the peak of the periodogram of the (detrended,
// binned) angle, refined by a golden-section search of the least-squares
// periodogram (a sine-cosine-offset fit) within one bin. Unlike zero
// crossings armed at a fraction of the global peak-to-peak, it is not fooled
// by an amplitude that varies (decays, repeated excitations). Fails when the
// table did not move or the record holds fewer than two periods.
Result<double> estimateSwingFrequencyHz(const TableChannel& table);

// Angle residuals averaged over windows of windowS seconds: the smooth part
// of a misfit, from which white noise and quantisation average out. Returns
// the RMS of the window means (weighted by their sample counts). stream:
// whose samples the residual belongs to (its pass is counted there, as for
// the two functions below).
double smoothResidualRms(const std::vector<double>& timeS, const std::vector<double>& residual, double windowS,
                         SampleStream stream);

// Amplitude of the harmonics 2..5 of the fundamental in a residual (each
// fitted by linear least squares at k*omega), root-sum-square, in the
// residual's unit. One pass: the harmonics' sines and cosines come from the
// fundamental's by the angle-addition recurrence (rounding-level agreement
// with sin(k*w*t)).
double harmonicAmplitude(const std::vector<double>& timeS, const std::vector<double>& residual, double omegaRadPerS,
                         SampleStream stream);

// How much errors that repeat every swing period add to a phase estimate's
// variance: 2*sum_k (1 - k/n) rho_k over k = 1 .. K (rho_k > 0), rho_k the
// correlation one, two, ... periods apart (at the nearest sample) of the
// white error of variance whiteVariance in the residual. When stamps are
// commensurate with the swing (1 Hz at 1 kHz), quantisation errors repeat
// every period and do not average down; the variance then grows by
// (1 + this sum). About 0 for incommensurate stamps. rho_k is read from the
// residual's second differences (whose covariance one period apart is
// 6 * whiteVariance * rho_k), so neither an angle random walk (the gyro's
// cumulative angle; its second differences are uncorrelated beyond one
// sample) nor a smooth misfit (a table harmonic) counts as an error that
// repeats. One pass, all the lags' sums together.
double periodicResidualInflation(const std::vector<double>& residual, double samplesPerPeriod, double periods,
                                 double whiteVariance, SampleStream stream);

// Straight-line fit y = a + b*x with the standard error of b from the
// scatter about the line (needs 3 or more points).
struct LineFit {
  double intercept = 0.0, slope = 0.0, slopeStd = 0.0;
  double residualStd = 0.0;
  std::size_t points = 0;
};
std::optional<LineFit> fitLine(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace fog::analysis

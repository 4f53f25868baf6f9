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

// What errors that repeat every swing period add to the estimate of a
// sinusoid A sin(w t + theta) = a sin(w t) + b cos(w t) fitted to a series:
// the covariance of its relative amplitude dA/A and its phase dtheta. With
// stamps commensurate with the swing (20 Hz at 1 kHz: 50 samples a period)
// quantisation errors repeat every period and do not average down.
//
// A repeating error e moves the amplitude by its in-phase part (2/N) sum e
// sin(psi) and the phase by its quadrature part (2/(N A)) sum e cos(psi),
// psi = w t + theta. The fit absorbs exactly those projections, so they
// cannot be read from its residual (the folded residual's projection onto
// sin and cos is zero by construction); their variance can, from how much
// of each phase of the period repeats. The residual's second differences
// are folded by the swing's phase (B bins, one per sample of a period): D_j
// their sum over periods at bin j, S_j the sum of their squares. D_j^2 - S_j
// sums d d' over every pair of periods (every lag), 6 times the error's
// covariance one period apart at that phase for an error white within the
// period; weighted by sin^2(psi_j), cos^2(psi_j) and sin cos they give the
// added variance of the two projections and their covariance, 4 / (6 N^2
// A^2) sum_j w_j (D_j^2 - S_j). An error that repeats near the turning
// points moves the amplitude, one near the zero crossings the phase; one
// alike at every phase both equally (isotropic), and then this is the
// phase's 2 sum_k (1 - k/n) rho_k times the white variance, with every lag.
// With B even, the bins half a period apart count too (-D_j D_(j+B/2)):
// quantisation is odd about a grid point, so a swing about a centre on the
// grid repeats its error with the sign flipped every half period, which
// doubles what the fit carries.
//
// Not counted: an angle random walk (the gyro's cumulative angle; its
// second differences are uncorrelated beyond one sample) and smooth misfits
// (second differences shrink harmonic m by (m w dt)^4, and harmonics 0..5 of
// the period are taken out of the folded sums: a table harmonic repeats
// exactly but the fundamental's estimate is not biased by it; the white
// error's small share there is restored). About 0 for incommensurate stamps;
// clipped to a positive semi-definite matrix, but for the phase: an error
// that depends on the angle alone (quantisation) has no cos(psi) part where
// the swing reads its angles rising and falling alike, so where stamps drift
// slowly through it (a few ppm off the swing, or incommensurate) the phase
// errs less than the white model says. A negative phase fold is then kept,
// at its one-sided 69 % upper bound (half a sigma) and only with 8 or more
// degrees of freedom (phaseBelowWhite, validity.cpp), and the cross term is
// 0. One pass over the residual; timeS is the fit's time axis.
struct PeriodicErrorCovariance {
  double amplitude = 0.0;  // variance added to dA / A (1)
  double phase = 0.0;      // variance added to dtheta (rad^2); negative: removed from the white model's
  double cross = 0.0;      // their covariance (rad)
};
PeriodicErrorCovariance periodicErrorCovariance(const std::vector<double>& timeS, const std::vector<double>& residual,
                                                double omegaRadPerS, double a, double b, SampleStream stream);

// Straight-line fit y = a + b*x with the standard error of b from the
// scatter about the line (needs 3 or more points).
struct LineFit {
  double intercept = 0.0, slope = 0.0, slopeStd = 0.0;
  double residualStd = 0.0;
  std::size_t points = 0;
};
std::optional<LineFit> fitLine(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace fog::analysis

#pragma once
// Delay analysis of a recording (docs/method.md): per test point, the
// 3-parameter fits at the nominal frequency, the 4-parameter fits with the
// frequency free, the joint fit whose delay is a parameter, the Cramer-Rao
// bound for the measured noise, the per-period delay track and the delay
// breakdown, and the validity checks that decide whether the delay can be
// vouched for (validity.h, verdict.h); across test points, delay against
// frequency and whether it is consistent with a pure delay.
//
// Breakdown (the paper's): IMU delay = lag + table read delay;
// gyro's own delay = IMU delay - board delay.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/damped_sine.h"
#include "core/analysis/joint_fit.h"
#include "core/analysis/sine_fit.h"
#include "core/analysis/validity.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

namespace fog::analysis {

// Noise seen in the session, estimated from fit residuals.
struct NoiseEstimate {
  double tableNoiseDeg = 0.0;         // encoder white noise (1 sigma)
  double gyroQuantisationDeg = 0.0;   // white angle noise of the pulse output (1 sigma)
  double gyroArwDegPerSqrtH = 0.0;    // angle random walk (blocks of a twentieth of a period)
  // The gyro's noise near the swing frequency as a random walk (blocks of a
  // quarter period): what the fits are weighted with and the bound uses; it
  // includes slower noise (bias instability) that the ARW leaves out.
  double gyroSwingBandArwDegPerSqrtH = 0.0;
};

struct PeriodDelay {
  double timeS = 0.0;  // middle of the period, session time
  double lagMs = 0.0;
  double tableAmplitudeDeg = 0.0;  // the table's amplitude over this period
};

struct TestPointResult {
  int index = 0;
  Axis axis = Axis::kX;
  double nominalFrequencyHz = 0.0;
  double durationS = 0.0;
  double periods = 0.0;
  std::size_t tableSamples = 0, imuSamples = 0, lostImuFrames = 0;
  // How the stream's damage affected this test point (data_coverage.h):
  // table frames missing from the stamp grid, the time the data cover and the
  // longest stretch without data; the stream's counters met while the point
  // was recorded (zero when the source cannot tell).
  std::size_t lostTableFrames = 0;
  double coveredS = 0.0, largestGapS = 0.0;
  StreamHealth damage;

  SineFit tableNominal, gyroNominal;  // 3-parameter, at the nominal frequency
  SineFit tableFit, gyroFit;          // 4-parameter, frequency free
  JointFit joint;                     // shared frequency, delay as a parameter
  NoiseEstimate noise;

  // positive: gyro output lags the table. lagStdMs is the reported
  // uncertainty: the joint fit's, raised where the independent measures below
  // show it is too small (lagStdSource says which).
  double lagMs = 0.0, lagStdMs = 0.0;
  double fitLagStdMs = 0.0;        // the joint fit's standard error
  double periodicInflation = 0.0;  // variance added by errors that repeat every period (validity.h), / fit's;
                                   // negative when they cancel between periods (at most -0.9)
  double trackLagStdMs = 0.0;      // per-period scatter / sqrt(periods)
  // When errors that cancel between periods lowered lagStdMs (a negative
  // periodicInflation): the σ before, which uncertainty_below_bound judges
  // (the bound's white noise model does not see that cancelling); else 0.
  double lagStdBeforeCancellingMs = 0.0;
  std::string lagStdSource = "fit";  // "fit", "fit, with errors that repeat every period", "per-period scatter", ...
  double crlbMs = 0.0;                 // Cramer-Rao bound on the lag for the measured noise
  double stdOverCrlb = 0.0;
  double imuDelayMs = 0.0, imuDelayStdMs = 0.0;
  double gyroDelayMs = 0.0, gyroDelayStdMs = 0.0;
  // ISO 16063-15 style: gyro/table amplitude ratio and phase (deg) at this frequency.
  double magnitudeRatio = 0.0;
  double phaseDeg = 0.0;  // -omega lag: its uncertainty is omega lagStdMs
  // The ratio's reported uncertainty: the joint fit's standard error
  // (joint.gainStd) with the same allowance for errors that repeat every
  // period as the lag's (periodicErrorCovariance, validity.h: their
  // in-phase part moves the gain, their quadrature part the phase), and its
  // covariance with the lag (ratio x ms). periodicGainInflation: the
  // variance that allowance adds, as a fraction of the fit's.
  double gainStd = 0.0;
  double gainLagCovMs = 0.0;
  double periodicGainInflation = 0.0;

  std::vector<PeriodDelay> periodTrack;
  double periodMeanLagMs = 0.0, periodScatterMs = 0.0;

  // Model adequacy and timing, measured without the fitted noise level.
  int gyroSign = 1;                     // the sign applied to the increments (stated by the user)
  double rateErrorPpm = 0.0, rateErrorStdPpm = 0.0;  // gyro period / table period - 1
  double lagDriftPpm = 0.0, lagDriftStdPpm = 0.0;    // trend of the per-period lag (s/s)
  double tableMisfitFraction = 0.0;     // smooth table residual / amplitude
  double gyroMisfitFraction = 0.0;      // smooth cumulative gyro residual / amplitude
  double harmonicFraction = 0.0;        // harmonics 2..5 of the table / amplitude
  double amplitudeChangeFraction = 0.0; // change of the table amplitude over the record / amplitude
  std::optional<DampedSineLag> damped;  // offered when the amplitude decays smoothly
  std::vector<ValidityCheck> checks;    // any failed: the verdict is "invalid"

  std::vector<std::string> warnings;
};

// Delay against frequency on one axis.
struct FrequencyConsistency {
  Axis axis = Axis::kX;
  int points = 0;         // pooled: test points that passed every validity check
  int leftOutPoints = 0;  // on this axis but not pooled: a check failed (their delay is refused)
  double weightedLagMs = 0.0, weightedLagStdMs = 0.0;
  double chiSquare = 0.0;
  int dof = 0;
  double pValue = 1.0;
  bool consistentWithPureDelay = true;  // p >= 0.01
};

// A static segment of the recording (table at rest): no delay to measure; its
// gyro noise is analysed by fog::noise (fogbench-cli noise).
struct StaticSegment {
  int index = 0;
  Axis axis = Axis::kX;
  double durationS = 0.0;
  std::size_t imuSamples = 0;
};

struct DelayReport {
  std::vector<TestPointResult> points;
  std::vector<StaticSegment> staticSegments;  // skipped by the delay analysis, never failures
  std::vector<std::string> failedPoints;  // one line per test point that gave no delay, saying why
  std::vector<FrequencyConsistency> consistency;  // axes with two or more frequencies
  BenchConstants constants;
  StreamHealth health;
};

// The paper's breakdown of a measured lag into IMU and gyro delay, with
// uncertainties (lag and constants independent).
struct DelayBreakdown {
  double lagMs = 0.0, lagStdMs = 0.0;
  double imuDelayMs = 0.0, imuDelayStdMs = 0.0;
  double gyroDelayMs = 0.0, gyroDelayStdMs = 0.0;
};
DelayBreakdown delayBreakdown(double lagMs, double lagStdMs, const BenchConstants& constants);
// Lag from two fitted phases in the paper's convention (gyro t0 - table t0),
// wrapped into (-T/2, T/2].
double lagFromPhasesMs(double tablePhaseMs, double gyroPhaseMs, double periodMs);

// The increments are in degrees (protocol::RecordingBuilder); those of the
// swing axis are negated when constants.gyroSign says -1. Walks the samples
// a fixed number of times (sample_passes.h; SamplePasses in
// tests/core/analysis). Uses up to three threads: the fits split some passes
// over two, and when the plan states the frequency its check against the
// data runs beside them.
Result<TestPointResult> analyzeTestPoint(const TestPointData& data, const BenchConstants& constants);

// Analyses every swing test point; static segments are listed in
// staticSegments and not analysed. Fails only when no test point gives a
// delay (a recording of static segments only says so). Each point's checks
// are analyzeTestPoint's and the "gain" check (gain_check.h), which needs
// the axis' other points: the gyro's scale against
// constants.gainToleranceFraction once the axis' fitted dynamics are out.
Result<DelayReport> analyzeRecording(const Recording& recording, const BenchConstants& constants);

// True when no judged validity check of the point failed: its delay stands.
bool passedItsChecks(const TestPointResult& point);

// Per axis with two or more distinct frequencies among the points that passed
// their checks: the weighted lag and the chi^2 test of one pure delay. Points
// whose checks failed are left out and counted (leftOutPoints).
std::vector<FrequencyConsistency> frequencyConsistency(const std::vector<TestPointResult>& points);

// Asymptotic Cramer-Rao bound on the lag (s) for sinusoids of the given
// amplitudes over recordS seconds in the measured noise.
double lagCramerRaoBoundS(double omegaRadPerS, double recordS, double tableAmplitudeDeg,
                          double tableIntervalS, double tableNoiseDeg, double gyroAmplitudeDeg,
                          double gyroIntervalS, double gyroQuantisationVarDeg2,
                          double gyroArwVarDeg2PerS);

}  // namespace fog::analysis

#include "core/analysis/delay_analysis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <future>
#include <numeric>
#include <sstream>

#include "core/analysis/data_coverage.h"
#include "core/analysis/gain_check.h"
#include "core/analysis/least_squares.h"
#include "core/analysis/sample_passes.h"
#include "core/analysis/sin_cos_series.h"
#include "core/analysis/statistics.h"
#include "core/analysis/uncertainty_bound.h"
#include "core/common/units.h"

namespace fog::analysis {

namespace {

std::string fmt(double v, int precision = 4) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(precision);
  s << v;
  return s.str();
}

// Phase angle psi of a*sin + b*cos from the Gram matrix of
// [sin-like, cos-like, third regressor, y] over one window.
bool windowPhase(const NormalSums<4>& gram, std::size_t rows, double& psi, double& amplitude) {
  if (rows < 8) return false;
  Eigen::Matrix3d xtx;
  Eigen::Vector3d xty;
  for (int i = 0; i < 3; ++i) {
    xty[i] = gram.jtj[3][i];
    for (int j = 0; j <= i; ++j) xtx(i, j) = xtx(j, i) = gram.jtj[i][j];
  }
  const Eigen::Vector3d p = xtx.ldlt().solve(xty);
  psi = std::atan2(p[1], p[0]);
  amplitude = std::hypot(p[0], p[1]);
  return true;
}

// The per-period track's windows: whole periods at the track's frequency w
// from the first time both channels cover; none when the count is beyond
// reason (checked before the cast: a fit run from a wild start, a planned
// frequency of 1e300 Hz in fog_fuzz_analysis, gave 1e301 periods).
struct PeriodWindows {
  double first = 0.0, period = 0.0;
  int count = 0;
  double start(int j) const { return first + j * period; }
};
PeriodWindows periodWindows(const Channels& ch, double w) {
  const auto& tt = ch.table.timeS;
  const auto& g = ch.gyro;
  PeriodWindows out;
  out.period = kTwoPi / w;
  out.first = std::max(tt.front(), g.startS.front());
  const double last = std::min(tt.back(), g.endS.back());
  const double periods = std::floor((last - out.first) / out.period);
  if (periods >= 0.0 && periods <= static_cast<double>(tt.size())) out.count = static_cast<int>(periods);
  return out;
}

// The table's part of the track: the Gram matrix of [sin, cos, 1, angle]
// over each window [start, start + period), with its row count.
struct TablePeriodSums {
  std::vector<NormalSums<4>> gram;
  std::vector<std::size_t> rows;
};

// The 4-parameter table fit's residuals and, in the same pass (the same
// sines and cosines, at the fit's frequency, which the track uses), the
// track's table sums: the samples are assigned to windows as the track's
// own loop would (skip to a window's start, take samples before its end).
std::vector<double> tableResidualsAndPeriodSums(const TableChannel& table, const SineFit& f,
                                                const PeriodWindows& windows, TablePeriodSums& sums) {
  const auto& tt = table.timeS;
  const std::size_t n = tt.size();
  countPass(SampleStream::kTable);
  std::vector<double> r(n);
  sums.gram.assign(static_cast<std::size_t>(windows.count), NormalSums<4>{});
  sums.rows.assign(static_cast<std::size_t>(windows.count), 0);
  SinCosStream phase(f.omegaRadPerS, 0.0);
  int j = 0;
  bool inside = false;  // past window j's start
  double a = windows.start(0), b = a + windows.period;
  // Window j's sums are made in a local and stored when the window ends:
  // summed in the vector, every add was a load and a store (the compiler
  // cannot tell the sums from the residuals written beside them).
  NormalSums<4> window;
  std::size_t rows = 0;
  auto store = [&] {
    if (j >= windows.count) return;
    sums.gram[static_cast<std::size_t>(j)] = window;
    sums.rows[static_cast<std::size_t>(j)] = rows;
  };
  for (std::size_t i = 0; i < n; ++i) {
    double sn, cs;
    phase.next(tt[i], sn, cs);
    r[i] = table.angleDeg[i] - (f.a * sn + f.b * cs + f.offsetDeg);
    while (j < windows.count) {
      if (!inside) {
        if (tt[i] < a) break;  // before the window: skipped
        inside = true;
      }
      if (tt[i] < b) {
        const double v[4] = {sn, cs, 1.0, table.angleDeg[i]};
        window.add(v, 0.0);
        ++rows;
        break;
      }
      // Past the window's end: the next window looks at this sample.
      store();
      window = NormalSums<4>{};
      rows = 0;
      ++j;
      inside = false;
      a = windows.start(j);
      b = a + windows.period;
    }
  }
  store();
  return r;
}

// The per-period track from the table's sums and the gyro's increments.
// gyroTurnsAgainst: the gyro is in antiphase with the table (a reversed axis);
// its phase is then taken half a turn round, as in the joint fit.
std::vector<PeriodDelay> periodTrack(const Channels& ch, double w, double referenceS, bool gyroTurnsAgainst,
                                     const PeriodWindows& windows, const TablePeriodSums& tableSums) {
  std::vector<PeriodDelay> out;
  const double period = windows.period;
  const auto& g = ch.gyro;
  countPass(SampleStream::kGyro);
  GyroSinCosStream gyroPhase(g, w, 0.0);
  std::size_t k = 0;
  for (int j = 0; j < windows.count; ++j) {
    const double a = windows.start(j), b = a + period;
    // One small 3-parameter fit per channel and period, at the joint frequency.
    // The phase stream must see every sample in order, also those skipped.
    double s1, c1, s0, c0;
    NormalSums<4> gyro;
    for (; k < g.size() && g.startS[k] < a; ++k) gyroPhase.next(k, s1, c1, s0, c0);
    const std::size_t k0 = k;
    for (; k < g.size() && g.endS[k] <= b; ++k) {
      gyroPhase.next(k, s1, c1, s0, c0);
      const double v[4] = {s1 - s0, c1 - c0, g.endS[k] - g.startS[k], g.incrementDeg[k]};
      gyro.add(v, 0.0);
    }
    double psiT = 0.0, psiG = 0.0, ampT = 0.0, ampG = 0.0;
    const auto jj = static_cast<std::size_t>(j);
    if (windowPhase(tableSums.gram[jj], tableSums.rows[jj], psiT, ampT) && windowPhase(gyro, k - k0, psiG, ampG)) {
      if (gyroTurnsAgainst) psiG += kPi;
      out.push_back({referenceS + 0.5 * (a + b), wrapToHalfPeriod((psiT - psiG) / w, period) * 1e3, ampT});
    }
  }
  return out;
}

// What the stages of one test point's analysis hand each other, Ceres-style:
// each stage reads what earlier ones left here and adds its own, so that
// what a pass over the samples gave (the 4-parameter fits' residuals above
// all) is computed once and read by every later stage that needs it.
struct PointWork {
  PointWork(const TestPointData& d, const BenchConstants& c) : data(d), constants(c) {}
  const TestPointData& data;
  const BenchConstants& constants;
  Channels ch;
  TestPointResult r;
  DataCoverage coverage;      // what is missing from the samples
  double f0 = 0.0, w0 = 0.0;  // the frequency the fits start from (Hz, rad/s)
  SineFit gyroStart;          // unweighted 3-parameter gyro fit at the table's frequency
  double whiteRateVariance = 0.0;  // the gyro's q from blocks of a twentieth of a period (the bound's)
  bool gyroTurnsAgainst = false;
  // Residuals of the 4-parameter fits, one per sample: table angles, and the
  // cumulative gyro angle's (its offset removed).
  std::vector<double> tableResidual, gyroAngleResidual;
  // The per-period track's windows and table sums, taken with the table
  // residual (computeResiduals).
  PeriodWindows trackWindows;
  TablePeriodSums trackTableSums;
  // From the joint fit: the table's amplitude, its frequency (rad/s) and the
  // mean table sample interval.
  double amplitude = 0.0, w = 0.0, tableInterval = 0.0;
  // The per-period track as columns, and the lags' spread.
  std::vector<double> lags, times, amplitudes;
  MeanAndSpread spread;
  // The harmonics' amplitude in the table residual (steady_sine), started on
  // the second core as soon as the joint frequency is known.
  std::future<double> harmonics;
};

// Thresholds of the validity checks (docs/method.md, "Validity checks").
// None rests on the noise level fitted from the same residuals: misfits are
// compared with the amplitude, timing with significance from the data's own
// scatter.
constexpr double kClockPValue = 5.7e-7;      // periods, lag trend: two-sided, as 5 sigma of a normal
constexpr double kTableMisfitLimit = 0.01;   // smooth table residual / amplitude
constexpr double kGyroMisfitLimit = 0.05;    // smooth cumulative gyro residual / amplitude
constexpr double kHarmonicLimit = 0.02;      // harmonics 2..5 / amplitude
constexpr double kAmplitudeChangeLimit = 0.05;  // over the record, and > 5 sigma
constexpr double kCausalSignificance = 3.0;  // a negative IMU delay beyond 3 sigma

std::string percent(double fraction) { return fmt(100.0 * fraction, fraction < 0.001 ? 3 : 2) + " %"; }

// The validity checks, one function each, in the order the report lists
// them (clock_rate reads steady_sine's outcome). They read the fits and the
// residuals the earlier stages left in PointWork; none passes over the
// samples again except steady_sine's two residual measures (and, for a
// decaying swing, the damped-sine fit it offers).

void checkAxisSign(TestPointResult& r) {
  const std::string axis = axisLabel(r.axis);
  // The gyro turns with the table.
  {
    ValidityCheck c{"axis_sign", r.magnitudeRatio > 0.0, ""};
    const std::string ratio = fmt(r.magnitudeRatio, 4);
    if (c.passed) {
      c.detail = "the gyro turns with the table (gyro/table ratio " + ratio +
                 (r.gyroSign < 0 ? ", after the stated sign -1" : "") + ")";
    } else {
      c.detail = "the gyro's " + axis + " axis turns against the table (gyro/table ratio " + ratio +
                 (r.gyroSign < 0 ? " after the stated sign -1" : "") +
                 "): the axis is mounted the other way round or its sign convention differs from the table's; "
                 "the delay is refused (read as a normal axis it would be a half-period lag). " +
                 (r.gyroSign < 0 ? std::string("Check the stated sign: without it the gyro turns with the table")
                                 : std::string("If the IMU is mounted so, state it (metadata bench.gyro_sign {\"") +
                                       axisName(r.axis) + "\": -1}, or --gyro-sign " + axisName(r.axis) +
                                       "=-1) and analyse again");
    }
    r.checks.push_back(c);
  }
}

void checkSteadySine(PointWork& work) {
  TestPointResult& r = work.r;
  const Channels& ch = work.ch;
  const double w = r.joint.omegaRadPerS;
  const double periodS = kTwoPi / w;
  const double amplitude = work.amplitude;
  const auto& amplitudes = work.amplitudes;
  const auto& times = work.times;
  const auto& gyroAngleResidual = work.gyroAngleResidual;
  // A steady sinusoid: what the fits leave is noise, not shape.
  {
    const double windowS = std::max(periodS / 20.0, 3.0 * periodS / std::max(1.0, static_cast<double>(r.tableSamples) / r.periods));
    const auto& tableResidual = work.tableResidual;
    // The harmonics (a 9-column fit over every table sample) run on the
    // second core from the joint fit on (fitAndCheck), beside the uncertainty
    // and the smooth-residual checks.
    if (!work.harmonics.valid())
      work.harmonics = std::async(std::launch::deferred, [&] {
        return harmonicAmplitude(ch.table.timeS, tableResidual, w, SampleStream::kTable);
      });
    r.tableMisfitFraction = smoothResidualRms(ch.table.timeS, tableResidual, windowS, SampleStream::kTable) / amplitude;
    const bool gyroChecked = ch.gyro.lostFrames == 0;  // lost increments make steps in the cumulative angle
    if (gyroChecked)
      r.gyroMisfitFraction = smoothResidualRms(ch.gyro.endS, gyroAngleResidual, windowS, SampleStream::kGyro) /
                             (amplitude * std::abs(r.magnitudeRatio));
    r.harmonicFraction = work.harmonics.get() / amplitude;
    double amplitudeZ = 0.0;
    std::optional<LineFit> amplitudeLine;
    if (amplitudes.size() >= 3) amplitudeLine = fitLine(times, amplitudes);
    if (amplitudeLine) {
      r.amplitudeChangeFraction = amplitudeLine->slope * r.durationS / amplitude;
      amplitudeZ = amplitudeLine->slopeStd > 0.0 ? amplitudeLine->slope / amplitudeLine->slopeStd : 0.0;
    }
    std::vector<std::string> problems;
    if (r.tableMisfitFraction > kTableMisfitLimit)
      problems.push_back("the table's residual has a smooth part of " + percent(r.tableMisfitFraction) +
                         " of the amplitude (limit " + percent(kTableMisfitLimit) + ")");
    if (r.harmonicFraction > kHarmonicLimit)
      problems.push_back("harmonics 2-5 reach " + percent(r.harmonicFraction) + " of the amplitude (limit " +
                         percent(kHarmonicLimit) + ")");
    if (std::abs(r.amplitudeChangeFraction) > kAmplitudeChangeLimit && std::abs(amplitudeZ) > 5.0)
      problems.push_back("the amplitude " + std::string(r.amplitudeChangeFraction < 0 ? "decays" : "grows") + " by " +
                         percent(std::abs(r.amplitudeChangeFraction)) + " over the record (limit " +
                         percent(kAmplitudeChangeLimit) + ")");
    if (gyroChecked && r.gyroMisfitFraction > kGyroMisfitLimit)
      problems.push_back("the gyro angle's residual has a smooth part of " + percent(r.gyroMisfitFraction) +
                         " of its amplitude (limit " + percent(kGyroMisfitLimit) + ")");
    ValidityCheck c{"steady_sine", problems.empty(), ""};
    if (c.passed) {
      c.detail = "a steady sinusoid: smooth table residual " + percent(r.tableMisfitFraction) + ", harmonics " +
                 percent(r.harmonicFraction) + ", amplitude change " + percent(r.amplitudeChangeFraction) +
                 (gyroChecked ? ", smooth gyro residual " + percent(r.gyroMisfitFraction) : std::string()) +
                 " of the amplitude";
    } else {
      std::string joined;
      for (const auto& p : problems) joined += (joined.empty() ? "" : "; ") + p;
      c.detail = "not a steady sinusoid: " + joined +
                 ". The sine fits are biased by such a swing (the noise figures then describe the misfit, not "
                 "noise); the delay is refused. Check the table's servo and amplitude, and record a steady swing";
      // A smoothly decaying swing (free pendulum, table coasting down): the
      // lag of a damped-sine fit is offered beside the refusal.
      if (amplitudeLine && r.amplitudeChangeFraction < -kAmplitudeChangeLimit && r.magnitudeRatio > 0.0) {
        const double meanAmplitude = std::accumulate(amplitudes.begin(), amplitudes.end(), 0.0) /
                                     static_cast<double>(amplitudes.size());
        const double lambda = -amplitudeLine->slope / meanAmplitude;
        auto damped = fitDampedSineLag(ch, w, lambda);
        const double maxAmplitude = *std::max_element(amplitudes.begin(), amplitudes.end());
        if (damped && damped->tableResidualRmsDeg < kTableMisfitLimit * maxAmplitude) {
          r.damped = damped;
          c.detail += ". A damped sinusoid fits the table (decay time " + fmt(damped->decayTimeS, 1) +
                      " s, residual " + percent(damped->tableResidualRmsDeg / maxAmplitude) +
                      " of the amplitude): its lag is " + fmt(damped->lagMs, 4) + " ± " + fmt(damped->lagStdMs, 4) +
                      " ms, if the decay is the table's true motion";
        }
      }
    }
    r.checks.push_back(c);
  }
}

void checkClockRate(PointWork& work) {
  TestPointResult& r = work.r;
  const auto& lags = work.lags;
  const auto& times = work.times;
  // Table and gyro stamped on one clock at one rate: their periods agree and
  // the per-period lag has no trend. The period uncertainties are raised by
  // the same factor as the lag's when the noise model fell short.
  {
    // The fits' period uncertainties rest on the same noise model as the
    // lag's: raised by the factor the per-period scatter shows, if larger.
    const double honesty =
        r.fitLagStdMs > 0.0 ? std::max({1.0, r.lagStdMs / r.fitLagStdMs, r.trackLagStdMs / r.fitLagStdMs}) : 1.0;
    const double tp = r.tableFit.periodMs, gp = r.gyroFit.periodMs;
    r.rateErrorPpm = (gp / tp - 1.0) * 1e6;
    r.rateErrorStdPpm = honesty * std::hypot(r.tableFit.periodStdMs, r.gyroFit.periodStdMs) / tp * 1e6;
    const double zPeriod = r.rateErrorStdPpm > 0.0 ? r.rateErrorPpm / r.rateErrorStdPpm : 0.0;
    // With five or more periods the trend of the per-period lags decides: its
    // uncertainty comes from their own scatter, while the periods' rests on
    // the noise model (time-stamp errors that follow a slow pattern, such as
    // a bench reading held frames, made it 5 times too small). With fewer,
    // the periods decide.
    double zTrend = 0.0;
    bool trendJudged = false;
    if (lags.size() >= 5)
      if (auto line = fitLine(times, lags); line && line->slopeStd > 0.0) {
        r.lagDriftPpm = line->slope * 1e3;  // ms per s
        r.lagDriftStdPpm = line->slopeStd * 1e3;
        zTrend = line->slope / line->slopeStd;
        trendJudged = true;
      }
    // Significant: beyond 5 sigma (the trend's t statistic has n - 2 degrees
    // of freedom: with 6 periods |t| > 5 happens by chance once in 150
    // records). And it matters: over half the record the drift moves the lag
    // by more than the lag's uncertainty.
    const double ppm = trendJudged ? r.lagDriftPpm : r.rateErrorPpm;
    const double pValue = trendJudged ? studentTwoSidedP(zTrend, static_cast<int>(lags.size()) - 2)
                                      : std::erfc(std::abs(zPeriod) / std::sqrt(2.0));
    const double lagMoveMs = std::abs(ppm) * 1e-6 * 0.5 * r.durationS * 1e3;
    ValidityCheck c{"clock_rate", !(pValue < kClockPValue && lagMoveMs > r.lagStdMs), ""};
    // A swing that is not a steady sinusoid bends the per-period lags and the
    // fitted periods: their timing figures then say nothing about the clocks.
    const bool steady = r.checks.back().id == "steady_sine" && r.checks.back().passed;
    const std::string trend = "per-period lag drifts " + fmt(r.lagDriftPpm, 2) + " ± " + fmt(r.lagDriftStdPpm, 2) +
                              " ppm (" + fmt(zTrend, 1) + " σ)";
    const std::string periods = "periods differ by " + fmt(r.rateErrorPpm, 2) + " ± " + fmt(r.rateErrorStdPpm, 2) +
                                " ppm (" + fmt(zPeriod, 1) + " σ)";
    const std::string figures = trendJudged ? trend + "; " + periods + " (information)" : periods;
    if (!steady) {
      c.passed = true;
      c.judged = false;
      c.detail = "not judged: the swing is not a steady sinusoid (steady_sine), which moves the fitted periods and "
                 "the per-period lags; " + figures;
    } else if (c.passed) {
      c.detail = "table and gyro stamps keep one rate: " + figures;
    } else {
      c.detail = "the gyro's time stamps run " + fmt(std::abs(ppm), 1) + " ppm " + (ppm > 0 ? "fast" : "slow") +
                 " against the table's (" + figures +
                 "): the two streams are not stamped on one clock at one rate, so their phase difference is not a "
                 "delay. Stamp both with the sampling board's common counter (or correct the clock rate) and "
                 "record again";
    }
    r.checks.push_back(c);
  }
}

void checkCausal(TestPointResult& r) {
  // A causal delay: the gyro cannot report rotation before it happens.
  {
    const bool acausal = r.imuDelayMs + kCausalSignificance * r.imuDelayStdMs < 0.0;
    ValidityCheck c{"causal", !acausal, ""};
    c.detail = acausal ? "the IMU delay is negative (" + fmt(r.imuDelayMs, 4) + " ± " + fmt(r.imuDelayStdMs, 4) +
                             " ms): the gyro would report rotation before it happened. A stamping, sign or clock "
                             "problem: check the table read delay constant, that both streams share one clock, "
                             "and the gyro axis' sign"
                       : "the IMU delay is causal (" + fmt(r.imuDelayMs, 4) + " ms)";
    r.checks.push_back(c);
  }
}

// The validity checks of a point whose delay has been measured (validity.h).
void addValidityChecks(PointWork& work) {
  // The ratio shown beside the σ is of the numbers shown: the stated σ (the
  // fit's, or the per-period scatter's when that is honest), not the fit's
  // alone, which once read 1.26 beside a σ 6x below the bound.
  work.r.stdOverCrlb = work.r.crlbMs > 0.0 ? work.r.lagStdMs / work.r.crlbMs : 0.0;
  checkAxisSign(work.r);
  checkSteadySine(work);
  checkClockRate(work);
  checkCausal(work.r);
  work.r.checks.push_back(uncertaintyBelowBoundCheck(work.r));
}


}  // namespace

DelayBreakdown delayBreakdown(double lagMs, double lagStdMs, const BenchConstants& constants) {
  DelayBreakdown b;
  b.lagMs = lagMs;
  b.lagStdMs = lagStdMs;
  b.imuDelayMs = lagMs + constants.tableReadDelayMs;
  b.imuDelayStdMs = std::hypot(lagStdMs, constants.tableReadDelayStdMs);
  b.gyroDelayMs = b.imuDelayMs - constants.boardDelayMs;
  b.gyroDelayStdMs = std::hypot(b.imuDelayStdMs, constants.boardDelayStdMs);
  return b;
}

double lagFromPhasesMs(double tablePhaseMs, double gyroPhaseMs, double periodMs) {
  return wrapToHalfPeriod(gyroPhaseMs - tablePhaseMs, periodMs);
}

double lagCramerRaoBoundS(double w, double recordS, double tableAmplitudeDeg, double tableIntervalS,
                          double tableNoiseDeg, double gyroAmplitudeDeg, double gyroIntervalS,
                          double gyroQuantisationVarDeg2, double gyroArwVarDeg2PerS) {
  // One-sided angle-noise densities at the swing frequency (deg^2/Hz): white
  // noise sigma^2 sampled every dt gives 2*sigma^2*dt; an angle random walk of
  // rate variance q gives 2*q/w^2. Phase variance = S/(A^2*T); lag = phase/w.
  const double sTable = 2.0 * tableNoiseDeg * tableNoiseDeg * tableIntervalS;
  const double sGyro = 2.0 * gyroQuantisationVarDeg2 * gyroIntervalS + 2.0 * gyroArwVarDeg2PerS / (w * w);
  const double var = (sTable / (tableAmplitudeDeg * tableAmplitudeDeg) +
                      sGyro / (gyroAmplitudeDeg * gyroAmplitudeDeg)) /
                     (recordS * w * w);
  return std::sqrt(var);
}

namespace {

// What every later stage assumes of its input, checked once where the
// analysis starts: finite samples, times strictly increasing within each
// stream. The decoder and the importer give no other, but a session's stored
// samples may have been crafted, and a time out of order turned a bin index
// of the frequency estimate into an overflowed cast (fog_fuzz_analysis).
Status checkSamples(const TestPointData& data) {
  // The planned frequency starts the fits (beside the frequency check): one
  // beyond any swing would start them far from the data.
  if (!std::isfinite(data.nominalFrequencyHz) || data.nominalFrequencyHz < 0.0 || data.nominalFrequencyHz > 1000.0)
    return invalidArgument("the planned swing frequency (" + fmt(data.nominalFrequencyHz, 6) +
                           " Hz) is not within 0 .. 1000 Hz; check the plan or the metadata");
  countPass(SampleStream::kTable);
  countPass(SampleStream::kGyro);
  for (std::size_t i = 0; i < data.table.size(); ++i) {
    const auto& s = data.table[i];
    if (!std::isfinite(s.timeS) || (i > 0 && !(s.timeS > data.table[i - 1].timeS)))
      return corruptData("table sample " + std::to_string(i + 1) + ": its time (" + fmt(s.timeS, 6) +
                         " s) is not finite or not after the previous one; the recording is damaged");
    for (double a : s.angleDeg)
      if (!std::isfinite(a))
        return corruptData("table sample " + std::to_string(i + 1) + ": an angle is not finite; the recording is damaged");
  }
  // A test point longer than this is not one swing (plans stop at 1 h): its
  // span would overflow the frequency estimate's bins.
  constexpr double kMaxSpanS = 1e6;
  for (const auto& [name, span] :
       {std::pair{"table", data.table.empty() ? 0.0 : data.table.back().timeS - data.table.front().timeS},
        {"gyro", data.imu.empty() ? 0.0 : data.imu.back().timeS - data.imu.front().timeS}})
    if (!(span <= kMaxSpanS))
      return invalidArgument(std::string("the test point's ") + name + " samples span " + fmt(span, 6) +
                             " s; one test point is at most 1e6 s (11.6 days) long: check the time stamps");
  for (std::size_t i = 0; i < data.imu.size(); ++i) {
    const auto& s = data.imu[i];
    if (!std::isfinite(s.timeS) || (i > 0 && !(s.timeS > data.imu[i - 1].timeS)))
      return corruptData("gyro sample " + std::to_string(i + 1) + ": its time (" + fmt(s.timeS, 6) +
                         " s) is not finite or not after the previous one; the recording is damaged");
    for (double d : s.incrementDeg)
      if (!std::isfinite(d))
        return corruptData("gyro sample " + std::to_string(i + 1) +
                           ": an increment is not finite; the recording is damaged");
  }
  return Status::ok();
}

}  // namespace

namespace {

// The stages of analyzeTestPoint, in order. Each reads what the earlier ones
// left in PointWork; those that return a Status refuse the point with it.

// The channels, the samples' own checks and what is missing.
Status prepare(PointWork& work) {
  const TestPointData& data = work.data;
  const int sign = work.constants.gyroSign[static_cast<std::size_t>(data.axis)] < 0 ? -1 : 1;
  // The samples' own checks and what is missing read only the recording:
  // they run on the second core beside the channels. Coverage waits for the
  // checks (it assumes finite, increasing stamps), and the refusals come in
  // the order they did in series: the channels', then the checks'.
  DataCoverage coverageOfData;
  auto checked = std::async(std::launch::async, [&data, &coverageOfData] {
    Status s = checkSamples(data);
    if (s.isOk()) coverageOfData = measureCoverage(data);
    return s;
  });
  auto channels = makeChannels(data, sign);  // refuses too few samples
  const Status samplesChecked = checked.get();
  if (!channels) return channels.status();
  work.ch = std::move(*channels);
  FOG_RETURN_IF_ERROR(samplesChecked);
  Channels& ch = work.ch;
  TestPointResult& r = work.r;
  r.index = data.index;
  r.axis = data.axis;
  r.gyroSign = sign;
  r.durationS = ch.endS - ch.startS;
  r.tableSamples = ch.table.timeS.size();
  r.imuSamples = data.imu.size();
  r.lostImuFrames = ch.gyro.lostFrames;

  // What is missing, and whether the rest can still support a delay: checked
  // before the frequency is estimated from data a gap would distort.
  work.coverage = coverageOfData;
  const DataCoverage& coverage = work.coverage;
  r.lostTableFrames = coverage.lostTableFrames;
  r.coveredS = coverage.coveredS();
  r.largestGapS = coverage.largestGapS;
  r.damage = data.health;
  if (const double f = data.nominalFrequencyHz > 0.0 ? data.nominalFrequencyHz : 0.0; f > 0.0)
    if (auto why = coverageRefusal(coverage, f); !why.empty()) return insufficientData(why);
  return Status::ok();
}

// The swing periods a point's samples cover at f, counted as the plan counts
// its duration (kMinSwingPeriods, test_plan.h): their span plus one sample
// interval of each stream (N samples every dt span (N - 1) dt; the first
// IMU frame only marks where the increments start). A point of exactly two
// planned periods spans 1.998 at 1 Hz and is analysed.
double coveredPeriods(const PointWork& work, double f) {
  const auto& t = work.ch.table.timeS;
  const double tableInterval = t.size() > 1 ? (t.back() - t.front()) / static_cast<double>(t.size() - 1) : 0.0;
  return (work.r.durationS + tableInterval + work.ch.gyro.framePeriodS) * f;
}

// Nominal frequency: what the plan said, checked against the data
// (measuredHz: estimateSwingFrequencyHz of the table channel).
Status chooseFrequency(PointWork& work, const Result<double>& measuredHz) {
  const TestPointData& data = work.data;
  const DataCoverage& coverage = work.coverage;
  TestPointResult& r = work.r;
  if (!measuredHz) return measuredHz.status();
  const double measured = *measuredHz;
  double f0 = data.nominalFrequencyHz > 0.0 ? data.nominalFrequencyHz : measured;
  if (std::abs(measured / f0 - 1.0) > 0.01) {
    r.warnings.push_back("the table swung at " + fmt(measured, 5) + " Hz, not the planned " + fmt(f0, 5) +
                         " Hz; fitting from the measured frequency");
    f0 = measured;
  }
  r.nominalFrequencyHz = f0;
  r.periods = r.durationS * f0;
  if (!(data.nominalFrequencyHz > 0.0))
    if (auto why = coverageRefusal(coverage, f0); !why.empty()) return insufficientData(why);
  if (const std::string few = tooFewSwingPeriods(coveredPeriods(work, f0)); !few.empty())
    return insufficientData("the record " + few);  // analyzeRecording names the point
  const double w0 = kTwoPi * f0;
  work.f0 = f0;
  work.w0 = w0;
  return Status::ok();
}

// 1. The table: 3-parameter fit at the nominal frequency, then 4-parameter.
Status fitTable(PointWork& work) {
  Channels& ch = work.ch;
  TestPointResult& r = work.r;
  const double w0 = work.w0;
  r.tableNominal = fitTableLinear(ch.table, w0, ch.referenceS);
  ch.table.noiseDeg = std::max(r.tableNominal.residualRmsDeg, 1e-12);
  FOG_ASSIGN_OR_RETURN(auto table4, fitTableNonlinear(ch.table, r.tableNominal));
  ch.table.noiseDeg = std::max(table4.residualRmsDeg, 1e-12);
  // The table's noise is measured from these residuals, so against it the
  // fit's chi^2/dof is N/(N - 4) by construction (not the value against the
  // 3-parameter residual it was weighted with).
  table4.chiSquarePerDof = static_cast<double>(table4.samples) / static_cast<double>(table4.samples - 4);
  // Against the same noise, the nominal-frequency fit shows what a frequency
  // error costs (like the gyro's nominal fit, which is whitened).
  const double nominalRatio = r.tableNominal.residualRmsDeg / ch.table.noiseDeg;
  r.tableNominal.chiSquarePerDof = nominalRatio * nominalRatio * static_cast<double>(r.tableNominal.samples) /
                                   static_cast<double>(r.tableNominal.samples - 3);
  r.tableFit = table4;
  return Status::ok();
}

  // 2. The gyro's noise, from the residuals of a fit at the table's measured
  // frequency (at the nominal one, 8 ppm of error would dominate the slow
  // part of the residuals). Three views of it over blocks of frames:
  //  - the reported ARW (white rate noise alone), from second differences of
  //    block sums of a twentieth of a period (0.05 .. 1 s), where a slow bias
  //    wander cancels (over an hour, block sums alone read 0.0070 deg/sqrt(h)
  //    for 0.004, and a replay with that much noise hid nothing a lag could
  //    not explain): reported, and what the diagnosis replays with;
  //  - the block sums themselves at that length, the noise as the swing sees
  //    it, which the Cramer-Rao bound keeps (its accuracy checks,
  //    docs/accuracy.md, were measured against it);
  //  - the block sums over a quarter period (at least 0.05 s, at most an
  //    eighth of the record), which weight the fits: the lag is decided by
  //    the noise near the swing frequency, where a random walk that shorter
  //    blocks cannot see under pulse quantisation (0.0014 deg/sqrt(h) under
  //    1.2" pulses at 0.09 Hz) dominates and left the uncertainty 7 times too
  //    small.
void measureGyroNoise(PointWork& work) {
  Channels& ch = work.ch;
  TestPointResult& r = work.r;
  const double f0 = work.f0;
  const SineFit& table4 = r.tableFit;
  const SineFit gyroStart = fitGyroLinear(ch.gyro, table4.omegaRadPerS, ch.referenceS, false);
  const double blockS = std::clamp(0.05 / f0, 0.05, 1.0);
  // The start fit's residuals' sums, shared by all three, in one pass.
  const IncrementResidualSums sums = gyroIncrementResidualSums(ch.gyro, gyroStart);
  // The three views of the sums in one pass over them.
  const GyroNoiseViews views =
      gyroNoiseViews(ch.gyro, sums, blockS, std::clamp(0.25 / f0, 0.05, std::max(0.05, r.durationS / 8.0)));
  r.noise.gyroArwDegPerSqrtH = std::sqrt(views.whiteRateVarianceDeg2PerS) * 60.0;
  const double whiteRateVariance = views.swingBlocks.varianceDeg2PerS;
  // What estimateGyroNoise applies.
  ch.gyro.setNoise(views.weightBlocks.varianceDeg2PerS, sums.quantisationVarianceDeg2);
  ch.gyro.arwVarianceStdDeg2PerS = views.weightBlocks.stdDeg2PerS;
  work.gyroStart = gyroStart;
  work.whiteRateVariance = whiteRateVariance;
}

  // 3. The gyro: 3-parameter fit at the nominal frequency (beside, on the
  // second core), then 4-parameter.
Status fitGyro(PointWork& work) {
  Channels& ch = work.ch;
  TestPointResult& r = work.r;
  const double w0 = work.w0;
  auto gyroNominal = std::async(std::launch::async, [&] { return fitGyroLinear(ch.gyro, w0, ch.referenceS, true); });
  auto gyro4 = fitGyroNonlinear(ch.gyro, work.gyroStart);
  r.gyroNominal = gyroNominal.get();
  if (!gyro4) return gyro4.status();
  r.gyroFit = *gyro4;
  // A gyro in antiphase with the table turns against it (a reversed axis).
  const bool gyroTurnsAgainst =
      std::cos(std::atan2(r.tableFit.b, r.tableFit.a) - std::atan2(r.gyroFit.b, r.gyroFit.a)) < 0.0;
  work.gyroTurnsAgainst = gyroTurnsAgainst;
  return Status::ok();
}

// The 4-parameter fits' residuals, once each, for the uncertainty (errors
// that repeat every period) and the steady_sine check.
void computeResiduals(PointWork& work) {
  const Channels& ch = work.ch;
  TestPointResult& r = work.r;
  // The table's on the second core, beside the gyro's, with the per-period
  // track's table sums (at the table fit's frequency, as the residuals).
  work.trackWindows = periodWindows(ch, r.tableFit.omegaRadPerS);
  auto tableResidual = std::async(std::launch::async, [&ch, &r, &work] {
    return tableResidualsAndPeriodSums(ch.table, r.tableFit, work.trackWindows, work.trackTableSums);
  });
  // The cumulative gyro angle's offset (for plots that overlay the fit) and
  // its residuals, in one pass: the running sum of the increments, the fit
  // and their difference (the offset, their mean, is taken off after).
  countPass(SampleStream::kGyro, 2);  // the pass and the offset's removal
  const GyroChannel& g = ch.gyro;
  auto& residual = work.gyroAngleResidual;
  residual.resize(g.size());
  SinCosStream phase(r.gyroFit.omegaRadPerS, 0.0);
  double angle = 0.0, sum = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    double sn, cs;
    phase.next(g.endS[k], sn, cs);
    angle += g.incrementDeg[k];
    residual[k] = angle - (r.gyroFit.a * sn + r.gyroFit.b * cs + r.gyroFit.trendDegPerS * g.endS[k]);
    sum += residual[k];
  }
  r.gyroFit.offsetDeg = sum / static_cast<double>(g.size());
  for (auto& v : residual) v -= r.gyroFit.offsetDeg;
  work.tableResidual = tableResidual.get();
}

  // 4. Joint fit: one frequency, the delay as a parameter. The per-period
  // track needs only a frequency close to the swing's; it runs beside.
Status fitJointAndTrack(PointWork& work) {
  const Channels& ch = work.ch;
  TestPointResult& r = work.r;
  const double trackOmega = r.tableFit.omegaRadPerS;
  const bool gyroTurnsAgainst = work.gyroTurnsAgainst;
  auto track = std::async(std::launch::async,
                          [&] { return periodTrack(ch, trackOmega, ch.referenceS, gyroTurnsAgainst, work.trackWindows,
                                                   work.trackTableSums); });
  const double whiteRateVariance = work.whiteRateVariance;
  auto joint = fitJoint(ch, r.tableFit, r.gyroFit);
  r.periodTrack = track.get();
  if (!joint) return joint.status();
  r.joint = *joint;
  r.lagMs = joint->lagS * 1e3;
  r.fitLagStdMs = joint->lagStdS * 1e3;

  // Noise and the bound.
  r.noise.tableNoiseDeg = ch.table.noiseDeg;
  r.noise.gyroQuantisationDeg = std::sqrt(ch.gyro.quantisationVarianceDeg2);
  r.noise.gyroSwingBandArwDegPerSqrtH = std::sqrt(ch.gyro.arwVarianceDeg2PerS) * 60.0;
  const double tableInterval = r.durationS / static_cast<double>(std::max<std::size_t>(r.tableSamples - 1, 1));
  const double amplitude = std::hypot(joint->a, joint->b);
  const double w = joint->omegaRadPerS;
  // The bound for the white noise terms (encoder, pulse output, angle random
  // walk): std/CRLB above 1 is what slower noise (bias instability) costs.
  r.crlbMs = 1e3 * lagCramerRaoBoundS(w, r.durationS, amplitude, tableInterval, ch.table.noiseDeg,
                                      amplitude * std::abs(joint->gain), ch.gyro.framePeriodS,
                                      ch.gyro.quantisationVarianceDeg2, whiteRateVariance);
  work.tableInterval = tableInterval;
  work.amplitude = amplitude;
  work.w = w;

  // Per-period delays, as columns.
  for (const auto& p : r.periodTrack) {
    work.lags.push_back(p.lagMs);
    work.times.push_back(p.timeS);
    work.amplitudes.push_back(p.tableAmplitudeDeg);
  }
  work.spread = meanAndSpread(work.lags);
  r.periodMeanLagMs = work.spread.mean;
  r.periodScatterMs = work.spread.stdDev;
  return Status::ok();
}

  // 5. An honest uncertainty. (a) White-noise terms assume errors that
  // average down sample by sample; with stamps commensurate with the swing,
  // quantisation errors repeat every period and do not: what they add to
  // each channel's amplitude and phase is read from its residual
  // (periodicErrorCovariance) and added to the lag's, the phase's and the
  // gain's variance alike. (b) The per-period lags are independent
  // estimates whose scatter does not rest on the noise model (errors that
  // repeat every period do not scatter, so (a) is added to it): when it is
  // significantly larger than the fit's uncertainty and the lags hold noise
  // slower than a period (slowNoise) it is taken; with 20 or
  // more periods also when significantly smaller (time-stamp jitter, whose
  // errors follow the rate, makes the white-noise model pessimistic).
// Whether the per-period lags hold noise slower than a period (bias
// instability, a wandering clock): their means over blocks of about sqrt(n)
// periods then scatter more than the lags themselves imply, (b - 1) s_b^2 m /
// s^2 beyond chi^2(b - 1) at p < 1e-3. Without it a per-period scatter above
// the fit's is the periods' own estimator erring more than the whole
// record's fit does (quantisation within a period, which cancels between
// periods; 50 to 64 samples a period at 15.7 and 20 Hz read std(z) 0.5 with
// it): it is not the fit's uncertainty. With fewer than 5 blocks (under 25
// periods) nothing can tell, and the scatter is taken as before.
bool slowNoise(const std::vector<double>& lags) {
  const std::size_t n = lags.size();
  const auto m = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(n))));
  const std::size_t blocks = m > 0 ? n / m : 0;
  if (m < 2 || blocks < 5) return true;
  std::vector<double> means(blocks, 0.0);
  for (std::size_t b = 0; b < blocks; ++b) {
    for (std::size_t i = b * m; i < (b + 1) * m; ++i) means[b] += lags[i];
    means[b] /= static_cast<double>(m);
  }
  const double all = meanAndSpread(lags).stdDev, block = meanAndSpread(means).stdDev;
  if (!(all > 0.0)) return false;
  const int dof = static_cast<int>(blocks) - 1;
  const double x = static_cast<double>(dof) * block * block * static_cast<double>(m) / (all * all);
  return chiSquareSurvival(x, dof) < 1e-3;
}

void honestUncertainty(PointWork& work) {
  const Channels& ch = work.ch;
  TestPointResult& r = work.r;
  const JointFit* joint = &r.joint;
  const double w = work.w, amplitude = work.amplitude, tableInterval = work.tableInterval;
  const auto& lags = work.lags;
  const auto& spread = work.spread;
  // (a) Errors that repeat every period, per channel (validity.h): the
  // variance they add to the relative amplitude and the phase of each
  // channel's sinusoid, and the covariance. gain = A_gyro / A_table and
  // omega * lag = theta_table - theta_gyro, so the gain's relative variance
  // gets both channels' amplitude terms, omega * lag both phase terms, and
  // their covariance minus both cross terms. One allowance for gain, phase
  // and lag alike.
  const PeriodicErrorCovariance tableRepeats = periodicErrorCovariance(
      ch.table.timeS, work.tableResidual, r.tableFit.omegaRadPerS, r.tableFit.a, r.tableFit.b, SampleStream::kTable);
  const PeriodicErrorCovariance gyroRepeats = periodicErrorCovariance(
      ch.gyro.endS, work.gyroAngleResidual, r.gyroFit.omegaRadPerS, r.gyroFit.a, r.gyroFit.b, SampleStream::kGyro);
  const double addedLogGain = tableRepeats.amplitude + gyroRepeats.amplitude;
  const double addedPhaseRad2 = tableRepeats.phase + gyroRepeats.phase;
  const double addedCross = -(tableRepeats.cross + gyroRepeats.cross);  // cov(ln gain, omega lag), rad
  const double addedMs2 = 1e6 * addedPhaseRad2 / (w * w);
  r.periodicInflation = addedMs2 / (r.fitLagStdMs * r.fitLagStdMs);
  double baseMs = r.fitLagStdMs;
  if (r.periodicInflation > 0.1) r.lagStdSource = "fit, with errors that repeat every period";
  if (r.periodicInflation < -0.1) r.lagStdSource = "fit, less the errors that cancel between periods";
  if (lags.size() >= 5) {
    const auto n = static_cast<double>(lags.size());
    const int dof = static_cast<int>(lags.size()) - 1;
    r.trackLagStdMs = spread.stdDev / std::sqrt(n);
    // (n - 1) s^2 / (n sigma^2) is chi^2 with n - 1 dof when sigma is right.
    const double x = (n - 1.0) * r.trackLagStdMs * r.trackLagStdMs / (r.fitLagStdMs * r.fitLagStdMs);
    const bool larger = r.trackLagStdMs > r.fitLagStdMs && chiSquareSurvival(x, dof) < 1e-3 && slowNoise(lags);
    const bool smaller = lags.size() >= 20 && r.trackLagStdMs < r.fitLagStdMs && 1.0 - chiSquareSurvival(x, dof) < 1e-3;
    if (larger || smaller) {
      baseMs = r.trackLagStdMs;
      r.lagStdSource = r.periodicInflation > 0.1    ? "per-period scatter, with errors that repeat every period"
                       : r.periodicInflation < -0.1 ? "per-period scatter, less the errors that cancel between periods"
                                                    : "per-period scatter";
      r.warnings.push_back("the per-period lags scatter " + fmt(spread.stdDev, 4) + " ms, " +
                           (larger ? "more" : "less") +
                           " than the fit's noise model implies; the uncertainty rests on their scatter (" +
                           fmt(r.trackLagStdMs, 5) + " ms instead of " + fmt(r.fitLagStdMs, 5) + " ms)");
    }
  }
  if (lags.size() < 5 && ch.gyro.arwVarianceStdDeg2PerS > 0.0) {
    // Too few periods to check the noise model against the data: the
    // random walk, the part a short record estimates worst (under coarse
    // pulses 3x too low in 1 of 5 records of 3.8 periods), is taken at its
    // upper 2-sigma bound.
    const double q = ch.gyro.arwVarianceDeg2PerS, qHigh = q + 2.0 * ch.gyro.arwVarianceStdDeg2PerS;
    const double gyroAmp = amplitude * std::abs(joint->gain);
    auto bound = [&](double arw) {
      return lagCramerRaoBoundS(w, r.durationS, amplitude, tableInterval, ch.table.noiseDeg, gyroAmp,
                                ch.gyro.framePeriodS, ch.gyro.quantisationVarianceDeg2, arw);
    };
    const double factor = bound(qHigh) / bound(q);
    if (factor > 1.05) {
      baseMs *= factor;
      r.lagStdSource = "fit, random walk at its upper bound (fewer than 5 periods to check it)";
    }
  }
  // A negative allowance (errors that cancel between periods: the phase's
  // repeating part below the white model, validity.h) lowers the variance to
  // a tenth of its base at most: the white model overstates an error that
  // depends on the angle alone, but not by more than the fold can show.
  const double stdMs = std::sqrt(std::max(baseMs * baseMs + addedMs2, 0.1 * baseMs * baseMs));
  r.lagStdMs = stdMs;
  // The σ before, kept where lagStdSource names the cancelling (by the same test).
  if (r.periodicInflation < -0.1) r.lagStdBeforeCancellingMs = baseMs;
  // The gain: the joint fit's standard error with the same allowance, and
  // its covariance with the lag: the fit's correlation on the fit's part
  // (taken with the lag's base, the fit's or the per-period scatter's),
  // plus the repeating errors' own.
  const double gain = joint->gain;
  const double addedGain2 = gain * gain * addedLogGain;
  r.gainStd = std::sqrt(joint->gainStd * joint->gainStd + addedGain2);
  r.periodicGainInflation = joint->gainStd > 0.0 ? addedGain2 / (joint->gainStd * joint->gainStd) : 0.0;
  r.gainLagCovMs = joint->gainLagCorrelation * joint->gainStd * baseMs + 1e3 * gain * addedCross / w;
  // A lag variance lowered below its base keeps the pair a covariance matrix.
  const double most = r.gainStd * r.lagStdMs;
  r.gainLagCovMs = std::clamp(r.gainLagCovMs, -most, most);
}

// The breakdown into IMU and gyro delay, and the refusal of numbers the fits
// could not make finite.
Status breakDown(PointWork& work) {
  TestPointResult& r = work.r;
  const BenchConstants& constants = work.constants;
  const JointFit* joint = &r.joint;
  const double w = work.w;
  const DelayBreakdown breakdown = delayBreakdown(r.lagMs, r.lagStdMs, constants);
  r.imuDelayMs = breakdown.imuDelayMs;
  r.imuDelayStdMs = breakdown.imuDelayStdMs;
  r.gyroDelayMs = breakdown.gyroDelayMs;
  r.gyroDelayStdMs = breakdown.gyroDelayStdMs;
  r.magnitudeRatio = joint->gain;
  r.phaseDeg = -w * joint->lagS * kDegPerRad;

  // A number the fits could not make finite (a value near a double's range,
  // a degenerate record) is a refusal with its reason, never a result that a
  // verdict could pass: "± nan" compares false with every limit.
  for (const auto& [name, value] : {std::pair{"lag", r.lagMs}, {"lag uncertainty", r.lagStdMs},
                                    {"IMU delay", r.imuDelayMs}, {"Cramér–Rao bound", r.crlbMs},
                                    {"gyro/table amplitude ratio", r.magnitudeRatio}})
    if (!std::isfinite(value))
      return Status(StatusCode::kNotConverged,
                    std::string("the fits gave no finite ") + name + " (" + fmt(value, 4) +
                        "): the data hold values the sine model cannot fit; check the recording's units and values");
  if (r.lagStdMs < 0.0)
    return Status(StatusCode::kNotConverged, "the fits gave a negative lag uncertainty (" + fmt(r.lagStdMs, 4) +
                                                 " ms): the data are too degenerate for the noise model");
  return Status::ok();
}

// What the user should know about this result.
void addWarnings(PointWork& work) {
  TestPointResult& r = work.r;
  const TestPointData& data = work.data;
  const BenchConstants& constants = work.constants;
  const JointFit* joint = &r.joint;
  const double amplitude = work.amplitude;
  if (r.lostImuFrames > 0)
    r.warnings.push_back(std::to_string(r.lostImuFrames) + " IMU frames were lost; their increments are missing");
  if (r.lostTableFrames > 0)
    r.warnings.push_back(std::to_string(r.lostTableFrames) + " table frames were lost; the data cover " +
                         fmt(r.coveredS, 2) + " of " + fmt(r.durationS, 2) + " s (longest gap " +
                         fmt(r.largestGapS * 1e3, 1) + " ms)");
  if (joint->chiSquarePerDof > 2.0 || joint->chiSquarePerDof < 0.5)
    r.warnings.push_back("the residuals do not match the noise model (chi^2/dof = " +
                         fmt(joint->chiSquarePerDof, 2) + "); an unmodelled effect may be present");
  if (data.nominalAmplitudeDeg > 0.0 && std::abs(amplitude / data.nominalAmplitudeDeg - 1.0) > 0.05)
    r.warnings.push_back("the table swung " + fmt(amplitude, 3) + " deg, not the planned " +
                         fmt(data.nominalAmplitudeDeg, 3) + " deg");
  if (r.gyroDelayMs < 0.0 && r.imuDelayMs >= 0.0 && r.gyroDelayMs + 3.0 * r.gyroDelayStdMs < 0.0)
    r.warnings.push_back("the gyro's own delay is negative: the processing board delay (" +
                         fmt(constants.boardDelayMs, 4) + " ms) is larger than the IMU delay; check that constant");
}

// The stages from the fits on, once the frequency is chosen.
Result<TestPointResult> fitAndCheck(PointWork& work) {
  FOG_RETURN_IF_ERROR(fitTable(work));
  measureGyroNoise(work);
  FOG_RETURN_IF_ERROR(fitGyro(work));
  computeResiduals(work);
  FOG_RETURN_IF_ERROR(fitJointAndTrack(work));
  // The harmonics need only the table residual and the joint frequency: they
  // take the second core while this one does the uncertainty.
  work.harmonics = std::async(std::launch::async, [&table = work.ch.table, &residual = work.tableResidual,
                                                   w = work.r.joint.omegaRadPerS] {
    return harmonicAmplitude(table.timeS, residual, w, SampleStream::kTable);
  });
  honestUncertainty(work);
  FOG_RETURN_IF_ERROR(breakDown(work));
  addValidityChecks(work);
  addWarnings(work);
  return std::move(work.r);
}

}  // namespace

Result<TestPointResult> analyzeTestPoint(const TestPointData& data, const BenchConstants& constants) {
  PointWork work(data, constants);
  FOG_RETURN_IF_ERROR(prepare(work));
  const double planned = data.nominalFrequencyHz;
  if (!(planned > 0.0 && tooFewSwingPeriods(coveredPeriods(work, planned)).empty())) {
    FOG_RETURN_IF_ERROR(chooseFrequency(work, estimateSwingFrequencyHz(work.ch.table)));
    return fitAndCheck(work);
  }
  // The plan states the frequency, and the fits start from it unless the
  // table swung more than 1 % off it. The check (a 262 144-point FFT and 42
  // periodogram evaluations, the same for 1 min as for 5: two thirds of a
  // 1-min analysis) reads only the table's times and angles, so it runs on
  // the second core beside the fits. In the rare case it finds the plan off,
  // the point is analysed again, in order, from the measured frequency: the
  // result is the same as when the check runs first.
  auto measured = std::async(std::launch::async, [&table = work.ch.table] { return estimateSwingFrequencyHz(table); });
  const Status chosen = chooseFrequency(work, planned);  // as the check finds it within 1 %
  Result<TestPointResult> result = chosen.isOk() ? fitAndCheck(work) : Result<TestPointResult>(chosen);
  const Result<double> measuredHz = measured.get();
  if (!measuredHz) return measuredHz.status();  // the check's refusal comes first, as when it runs first
  if (std::abs(*measuredHz / planned - 1.0) > 0.01) {
    PointWork again(data, constants);
    FOG_RETURN_IF_ERROR(prepare(again));
    FOG_RETURN_IF_ERROR(chooseFrequency(again, measuredHz));
    return fitAndCheck(again);
  }
  return result;
}


bool passedItsChecks(const TestPointResult& point) {
  return std::none_of(point.checks.begin(), point.checks.end(),
                      [](const ValidityCheck& c) { return c.judged && !c.passed; });
}

std::vector<FrequencyConsistency> frequencyConsistency(const std::vector<TestPointResult>& points) {
  std::vector<FrequencyConsistency> out;
  for (int a = 0; a < kAxisCount; ++a) {
    // Only delays the analysis stands behind are pooled: a point whose
    // validity check failed has its lag refused, and pooling it would turn
    // refused numbers into a "consistent with a pure delay".
    std::vector<const TestPointResult*> onAxis;
    int leftOut = 0;
    for (const auto& p : points) {
      if (static_cast<int>(p.axis) != a) continue;
      if (p.lagStdMs > 0.0 && passedItsChecks(p)) onAxis.push_back(&p);
      else ++leftOut;
    }
    if (onAxis.size() < 2) continue;
    // Distinct frequencies only make a frequency test.
    bool distinct = false;
    for (const auto* p : onAxis)
      if (std::abs(p->nominalFrequencyHz / onAxis.front()->nominalFrequencyHz - 1.0) > 1e-3) distinct = true;
    if (!distinct) continue;
    FrequencyConsistency c;
    c.axis = static_cast<Axis>(a);
    c.points = static_cast<int>(onAxis.size());
    c.leftOutPoints = leftOut;
    double sw = 0.0, swx = 0.0;
    for (const auto* p : onAxis) {
      const double wgt = 1.0 / (p->lagStdMs * p->lagStdMs);
      sw += wgt;
      swx += wgt * p->lagMs;
    }
    c.weightedLagMs = swx / sw;
    c.weightedLagStdMs = std::sqrt(1.0 / sw);
    for (const auto* p : onAxis) c.chiSquare += std::pow((p->lagMs - c.weightedLagMs) / p->lagStdMs, 2);
    c.dof = c.points - 1;
    c.pValue = chiSquareSurvival(c.chiSquare, c.dof);
    c.consistentWithPureDelay = c.pValue >= 0.01;
    out.push_back(c);
  }
  return out;
}

Result<DelayReport> analyzeRecording(const Recording& recording, const BenchConstants& constants) {
  DelayReport report;
  report.constants = constants;
  report.health = recording.health;
  for (const auto& tp : recording.testPoints) {
    if (tp.kind == TestPointKind::kStatic) {
      StaticSegment s;
      s.index = tp.index;
      s.axis = tp.axis;
      s.imuSamples = tp.imu.size();
      s.durationS = tp.imu.size() > 1 ? tp.imu.back().timeS - tp.imu.front().timeS : 0.0;
      report.staticSegments.push_back(s);
      continue;
    }
    auto r = analyzeTestPoint(tp, constants);
    if (r) report.points.push_back(std::move(*r));
    else report.failedPoints.push_back("test point " + std::to_string(tp.index + 1) + ": " + r.status().message());
  }
  if (report.points.empty()) {
    if (report.failedPoints.empty() && !report.staticSegments.empty())
      return insufficientData("the recording holds only static segments (" +
                              std::to_string(report.staticSegments.size()) +
                              "): they measure gyro noise, not delay; use fogbench-cli noise");
    if (report.failedPoints.empty()) return insufficientData("the recording holds no test point");
    std::string why = report.failedPoints.front();
    return insufficientData("no test point gave a delay; " + why);
  }
  // The gyro's scale against the bench's tolerance, with the dynamics of
  // the axis' frequency response taken out (gain_check.h): before the
  // frequency test, which pools only points that pass it.
  addGainChecks(report, constants.gainToleranceFraction);
  report.consistency = frequencyConsistency(report.points);
  return report;
}

}  // namespace fog::analysis

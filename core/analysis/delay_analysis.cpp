#include "analysis/delay_analysis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <future>
#include <sstream>

#include "analysis/data_coverage.h"
#include "analysis/least_squares.h"
#include "analysis/sin_cos_series.h"
#include "analysis/statistics.h"
#include "common/units.h"

namespace fog::analysis {

BenchConstants benchConstantsOf(const BenchSettings& bench) {
  BenchConstants c;
  c.tableReadDelayMs = bench.tableReadDelayMs;
  c.tableReadDelayStdMs = bench.tableReadDelayStdMs;
  c.boardDelayMs = bench.boardDelayMs;
  c.boardDelayStdMs = bench.boardDelayStdMs;
  c.pulseEquivalentDeg = bench.pulseEquivalentDeg;
  return c;
}

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
bool windowPhase(const NormalSums<4>& gram, std::size_t rows, double& psi) {
  if (rows < 8) return false;
  Eigen::Matrix3d xtx;
  Eigen::Vector3d xty;
  for (int i = 0; i < 3; ++i) {
    xty[i] = gram.jtj[3][i];
    for (int j = 0; j <= i; ++j) xtx(i, j) = xtx(j, i) = gram.jtj[i][j];
  }
  const Eigen::Vector3d p = xtx.ldlt().solve(xty);
  psi = std::atan2(p[1], p[0]);
  return true;
}

std::vector<PeriodDelay> periodTrack(const Channels& ch, double w, double referenceS) {
  std::vector<PeriodDelay> out;
  const double period = kTwoPi / w;
  const auto& tt = ch.table.timeS;
  const auto& g = ch.gyro;
  SinCosStream tablePhase(w, 0.0);
  GyroSinCosStream gyroPhase(g, w, 0.0);
  const double first = std::max(tt.front(), g.startS.front());
  const double last = std::min(tt.back(), g.endS.back());
  const int count = static_cast<int>(std::floor((last - first) / period));
  std::size_t i = 0, k = 0;
  for (int j = 0; j < count; ++j) {
    const double a = first + j * period, b = a + period;
    // One small 3-parameter fit per channel and period, at the joint frequency.
    // The phase streams must see every sample in order, also those skipped.
    double sn, cs, s1, c1, s0, c0;
    for (; i < tt.size() && tt[i] < a; ++i) tablePhase.next(tt[i], sn, cs);
    NormalSums<4> table, gyro;
    const std::size_t i0 = i;
    for (; i < tt.size() && tt[i] < b; ++i) {
      double v[4] = {0.0, 0.0, 1.0, ch.table.angleDeg[i]};
      tablePhase.next(tt[i], v[0], v[1]);
      table.add(v, 0.0);
    }
    for (; k < g.size() && g.startS[k] < a; ++k) gyroPhase.next(k, s1, c1, s0, c0);
    const std::size_t k0 = k;
    for (; k < g.size() && g.endS[k] <= b; ++k) {
      gyroPhase.next(k, s1, c1, s0, c0);
      const double v[4] = {s1 - s0, c1 - c0, g.endS[k] - g.startS[k], g.incrementDeg[k]};
      gyro.add(v, 0.0);
    }
    double psiT = 0.0, psiG = 0.0;
    if (windowPhase(table, i - i0, psiT) && windowPhase(gyro, k - k0, psiG))
      out.push_back({referenceS + 0.5 * (a + b), wrapToHalfPeriod((psiT - psiG) / w, period) * 1e3});
  }
  return out;
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

Result<double> estimateSwingFrequencyHz(const TableChannel& table) {
  const auto& y = table.angleDeg;
  if (y.size() < 8) return insufficientData("too few table samples to find the swing frequency");
  const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  const double mid = 0.5 * (*lo + *hi), hysteresis = 0.25 * (*hi - *lo);
  if (!(hysteresis > 0.0)) return insufficientData("the table did not move on the swing axis");
  // Upward zero crossings of (y - mid), armed only after y went below -hysteresis.
  std::vector<double> crossings;
  bool armed = false;
  for (std::size_t i = 1; i < y.size(); ++i) {
    if (y[i] - mid < -hysteresis) armed = true;
    if (armed && y[i - 1] - mid < 0.0 && y[i] - mid >= 0.0) {
      const double f = (mid - y[i - 1]) / (y[i] - y[i - 1]);
      crossings.push_back(table.timeS[i - 1] + f * (table.timeS[i] - table.timeS[i - 1]));
      armed = false;
    }
  }
  if (crossings.size() < 3)
    return insufficientData("the table angle shows fewer than two whole swing periods");
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  return 1.0 / period;
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

Result<TestPointResult> analyzeTestPoint(const TestPointData& data, double incrementScale,
                                         const BenchConstants& constants) {
  auto channels = makeChannels(data, incrementScale);
  if (!channels) return channels.status();
  Channels& ch = *channels;
  TestPointResult r;
  r.index = data.index;
  r.axis = data.axis;
  r.durationS = ch.endS - ch.startS;
  r.tableSamples = ch.table.timeS.size();
  r.imuSamples = data.imu.size();
  r.lostImuFrames = ch.gyro.lostFrames;

  // What is missing, and whether the rest can still support a delay: checked
  // before the frequency is estimated from zero crossings a gap would hide.
  const DataCoverage coverage = measureCoverage(data);
  r.lostTableFrames = coverage.lostTableFrames;
  r.coveredS = coverage.coveredS();
  r.largestGapS = coverage.largestGapS;
  r.damage = data.health;
  if (const double f = data.nominalFrequencyHz > 0.0 ? data.nominalFrequencyHz : 0.0; f > 0.0)
    if (auto why = coverageRefusal(coverage, f); !why.empty()) return insufficientData(why);

  // Nominal frequency: what the plan said, checked against the data.
  auto measured = estimateSwingFrequencyHz(ch.table);
  if (!measured) return measured.status();
  double f0 = data.nominalFrequencyHz > 0.0 ? data.nominalFrequencyHz : *measured;
  if (std::abs(*measured / f0 - 1.0) > 0.01) {
    r.warnings.push_back("the table swung at " + fmt(*measured, 5) + " Hz, not the planned " + fmt(f0, 5) +
                         " Hz; fitting from the measured frequency");
    f0 = *measured;
  }
  r.nominalFrequencyHz = f0;
  r.periods = r.durationS * f0;
  if (!(data.nominalFrequencyHz > 0.0))
    if (auto why = coverageRefusal(coverage, f0); !why.empty()) return insufficientData(why);
  if (r.periods < 2.0)
    return insufficientData("test point " + std::to_string(data.index + 1) + " covers " + fmt(r.periods, 2) +
                            " swing periods; a delay needs at least two whole periods");
  const double w0 = kTwoPi * f0;

  // 1. The table: 3-parameter fit at the nominal frequency, then 4-parameter.
  r.tableNominal = fitTableLinear(ch.table, w0, ch.referenceS);
  ch.table.noiseDeg = std::max(r.tableNominal.residualRmsDeg, 1e-12);
  auto table4 = fitTableNonlinear(ch.table, r.tableNominal);
  if (!table4) return table4.status();
  ch.table.noiseDeg = std::max(table4->residualRmsDeg, 1e-12);
  // The table's noise is measured from these residuals, so against it the
  // fit's chi^2/dof is N/(N - 4) by construction (not the value against the
  // 3-parameter residual it was weighted with).
  table4->chiSquarePerDof = static_cast<double>(table4->samples) / static_cast<double>(table4->samples - 4);
  // Against the same noise, the nominal-frequency fit shows what a frequency
  // error costs (like the gyro's nominal fit, which is whitened).
  const double nominalRatio = r.tableNominal.residualRmsDeg / ch.table.noiseDeg;
  r.tableNominal.chiSquarePerDof = nominalRatio * nominalRatio * static_cast<double>(r.tableNominal.samples) /
                                   static_cast<double>(r.tableNominal.samples - 3);

  // 2. The gyro's noise, from the residuals of a fit at the table's measured
  // frequency (at the nominal one, 8 ppm of error would dominate the slow
  // part of the residuals). ARW is judged over blocks of a twentieth of a
  // period (0.05 .. 1 s): long enough to rise above pulse quantisation, short
  // enough for many blocks.
  const SineFit gyroStart = fitGyroLinear(ch.gyro, table4->omegaRadPerS, ch.referenceS, false);
  estimateGyroNoise(ch.gyro, gyroIncrementResiduals(ch.gyro, gyroStart), std::clamp(0.05 / f0, 0.05, 1.0));

  // 3. The gyro: 3-parameter fit at the nominal frequency (beside, on the
  // second core), then 4-parameter.
  auto gyroNominal = std::async(std::launch::async, [&] { return fitGyroLinear(ch.gyro, w0, ch.referenceS, true); });
  auto gyro4 = fitGyroNonlinear(ch.gyro, gyroStart);
  r.gyroNominal = gyroNominal.get();
  if (!gyro4) return gyro4.status();
  r.tableFit = *table4;
  r.gyroFit = *gyro4;
  // The cumulative gyro angle's offset, for plots that overlay the fit.
  {
    const auto angle = cumulativeGyroAngle(ch.gyro);
    std::vector<double> sn(angle.size()), cs(angle.size());
    sinCosSeries(ch.gyro.endS.data(), angle.size(), r.gyroFit.omegaRadPerS, 0.0, sn.data(), cs.data());
    double sum = 0.0;
    for (std::size_t k = 0; k < angle.size(); ++k)
      sum += angle[k] - (r.gyroFit.a * sn[k] + r.gyroFit.b * cs[k] + r.gyroFit.trendDegPerS * ch.gyro.endS[k]);
    r.gyroFit.offsetDeg = sum / static_cast<double>(angle.size());
  }

  // 4. Joint fit: one frequency, the delay as a parameter. The per-period
  // track needs only a frequency close to the swing's; it runs beside.
  auto track = std::async(std::launch::async, [&] { return periodTrack(ch, table4->omegaRadPerS, ch.referenceS); });
  auto joint = fitJoint(ch, r.tableFit, r.gyroFit);
  r.periodTrack = track.get();
  if (!joint) return joint.status();
  r.joint = *joint;
  r.lagMs = joint->lagS * 1e3;
  r.lagStdMs = joint->lagStdS * 1e3;

  // Noise and the bound.
  r.noise.tableNoiseDeg = ch.table.noiseDeg;
  r.noise.gyroQuantisationDeg = std::sqrt(ch.gyro.quantisationVarianceDeg2);
  r.noise.gyroArwDegPerSqrtH = std::sqrt(ch.gyro.arwVarianceDeg2PerS) * 60.0;
  const double tableInterval = r.durationS / static_cast<double>(std::max<std::size_t>(r.tableSamples - 1, 1));
  const double amplitude = std::hypot(joint->a, joint->b);
  r.crlbMs = 1e3 * lagCramerRaoBoundS(joint->omegaRadPerS, r.durationS, amplitude, tableInterval,
                                      ch.table.noiseDeg, amplitude * std::abs(joint->gain),
                                      ch.gyro.framePeriodS, ch.gyro.quantisationVarianceDeg2,
                                      ch.gyro.arwVarianceDeg2PerS);
  r.stdOverCrlb = r.crlbMs > 0.0 ? r.lagStdMs / r.crlbMs : 0.0;

  const DelayBreakdown breakdown = delayBreakdown(r.lagMs, r.lagStdMs, constants);
  r.imuDelayMs = breakdown.imuDelayMs;
  r.imuDelayStdMs = breakdown.imuDelayStdMs;
  r.gyroDelayMs = breakdown.gyroDelayMs;
  r.gyroDelayStdMs = breakdown.gyroDelayStdMs;
  r.magnitudeRatio = joint->gain;
  r.phaseDeg = -joint->omegaRadPerS * joint->lagS * kDegPerRad;

  // Per-period delays.
  std::vector<double> lags;
  for (const auto& p : r.periodTrack) lags.push_back(p.lagMs);
  const auto spread = meanAndSpread(lags);
  r.periodMeanLagMs = spread.mean;
  r.periodScatterMs = spread.stdDev;

  // What the user should know about this result.
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
  return r;
}

std::vector<FrequencyConsistency> frequencyConsistency(const std::vector<TestPointResult>& points) {
  std::vector<FrequencyConsistency> out;
  for (int a = 0; a < kAxisCount; ++a) {
    std::vector<const TestPointResult*> onAxis;
    for (const auto& p : points)
      if (static_cast<int>(p.axis) == a && p.lagStdMs > 0.0) onAxis.push_back(&p);
    if (onAxis.size() < 2) continue;
    // Distinct frequencies only make a frequency test.
    bool distinct = false;
    for (const auto* p : onAxis)
      if (std::abs(p->nominalFrequencyHz / onAxis.front()->nominalFrequencyHz - 1.0) > 1e-3) distinct = true;
    if (!distinct) continue;
    FrequencyConsistency c;
    c.axis = static_cast<Axis>(a);
    c.points = static_cast<int>(onAxis.size());
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
  double scale = 1.0;
  if (!(recording.pulseEquivalentDeg > 0.0)) {
    if (!(constants.pulseEquivalentDeg > 0.0))
      return invalidArgument("the stream does not state the gyro pulse equivalent; give it "
                             "(degrees per pulse) as a bench constant");
    scale = constants.pulseEquivalentDeg;
  }
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
    auto r = analyzeTestPoint(tp, scale, constants);
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
  report.consistency = frequencyConsistency(report.points);
  return report;
}

}  // namespace fog::analysis

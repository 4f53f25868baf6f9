#include "core/analysis/delay_analysis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/analysis/statistics.h"
#include "core/analysis/theory.h"
#include "synthetic.h"

namespace fog::analysis {
namespace {

using testing::makeSynthetic;
using testing::SyntheticSpec;

// The paper's X axis at 0.1 Hz / 10 deg: fitted phases -1865.3085 ms (table)
// and -1864.8427 ms (gyro), periods ~10000.08 ms.
TEST(DelayBreakdown, ReproducesPaperFromFittedPhases) {
  const double lag = lagFromPhasesMs(-1865.3085, -1864.8427, 10000.0837);
  EXPECT_NEAR(lag, 0.4658, 1e-9);
  const auto b = delayBreakdown(lag, 0.0, BenchConstants{});
  EXPECT_NEAR(b.imuDelayMs, 0.5158, 1e-9);
  EXPECT_NEAR(b.gyroDelayMs, 0.2358, 1e-9);
}

TEST(DelayBreakdown, WrapsLagAcrossThePeriodBoundary) {
  EXPECT_NEAR(lagFromPhasesMs(4999.9, -4999.8, 10000.0), 0.3, 1e-9);
  EXPECT_NEAR(lagFromPhasesMs(-4999.8, 4999.9, 10000.0), -0.3, 1e-9);
}

TEST(DelayBreakdown, PropagatesUncertainties) {
  BenchConstants c;
  c.tableReadDelayStdMs = 0.003;
  c.boardDelayStdMs = 0.004;
  const auto b = delayBreakdown(0.4, 0.012, c);
  EXPECT_NEAR(b.imuDelayStdMs, std::hypot(0.012, 0.003), 1e-12);
  EXPECT_NEAR(b.gyroDelayStdMs, std::sqrt(0.012 * 0.012 + 0.003 * 0.003 + 0.004 * 0.004), 1e-12);
}

TEST(Theory, PaperResolutionFigures) {
  // 0.5 deg/h over one period / (2*pi*f*A): 7.4 us at 1 Hz / 3 deg, ~0.2 ms at 0.1 Hz / 10 deg.
  EXPECT_NEAR(paperResolutionS(0.5, 1.0, 3.0) * 1e6, 7.4, 0.05);
  EXPECT_NEAR(paperResolutionS(0.5, 0.1, 10.0) * 1e3, 0.22, 0.005);
}

TEST(Theory, PaperBudgetStaysUnder0p8Ms) {
  const auto b = delayBudget(TheoryInputs{});
  EXPECT_NEAR(b.eigenPeriodUs, 3.34, 0.01);  // the paper's "about 3.4 us for 1000 m"
  EXPECT_LT(b.totalMaxMs, 0.8);
  EXPECT_GT(b.totalMaxMs, 0.7);
  EXPECT_NEAR(b.boardMaxMs, 0.25, 0.01);  // the paper's "board about 0.3 ms"
}

TEST(Statistics, ChiSquareSurvivalKnownValues) {
  EXPECT_NEAR(chiSquareSurvival(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chiSquareSurvival(9.210340, 2), 0.01, 1e-6);
  EXPECT_NEAR(chiSquareSurvival(18.307038, 10), 0.05, 1e-6);
  EXPECT_DOUBLE_EQ(chiSquareSurvival(0.0, 3), 1.0);
}

// The incomplete gamma functions the Allan-deviation intervals (non-integer
// EDF) and the chi-square tests share: P(1/2, x) = erf(sqrt x) on both sides
// of the series / continued-fraction split, P + Q = 1, and a far tail that
// keeps its relative precision (Q(1, x) = exp(-x)).
TEST(Statistics, RegularisedIncompleteGamma) {
  for (double x : {0.01, 0.7, 1.4, 3.0, 12.0})
    EXPECT_NEAR(regularisedGammaP(0.5, x), std::erf(std::sqrt(x)), 1e-13) << x;
  for (double a : {0.5, 2.75, 40.3, 5000.5})
    for (double x : {0.5 * a, a + 0.9, a + 1.1, 2.0 * a})
      EXPECT_NEAR(regularisedGammaP(a, x) + regularisedGammaQ(a, x), 1.0, 1e-12) << a << " " << x;
  EXPECT_NEAR(regularisedGammaQ(1.0, 50.0) / std::exp(-50.0), 1.0, 1e-10);
  EXPECT_DOUBLE_EQ(regularisedGammaP(3.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(regularisedGammaQ(3.0, -1.0), 1.0);
}

TEST(Statistics, StudentTTailsMatchTables) {
  EXPECT_NEAR(studentTwoSidedP(12.706, 1), 0.05, 1e-4);
  EXPECT_NEAR(studentTwoSidedP(2.776, 4), 0.05, 1e-4);
  EXPECT_NEAR(studentTwoSidedP(2.042, 30), 0.05, 1e-4);
  EXPECT_NEAR(studentTwoSidedP(5.0, 100000), std::erfc(5.0 / std::sqrt(2.0)), 1e-8);  // the normal's 5 sigma
  EXPECT_NEAR(studentTwoSidedP(0.0, 7), 1.0, 1e-12);
  EXPECT_NEAR(regularisedBeta(0.3, 2.0, 3.0), 0.3483, 1e-4);
}

// The counted median is the element nth_element gives, with few distinct
// intervals (counted) and with many (the fallback), in any order.
TEST(Statistics, MedianElementIsNthElements) {
  std::mt19937_64 rng(3);
  for (int distinct : {1, 2, 3, 9, 16, 17, 1000}) {
    for (std::size_t n : {1u, 2u, 5u, 1000u, 1001u}) {
      std::vector<double> v(n);
      for (auto& x : v) x = 1e-3 + 1e-9 * static_cast<double>(rng() % static_cast<unsigned>(distinct));
      std::vector<double> w = v;
      std::nth_element(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(n / 2), w.end());
      EXPECT_EQ(medianElement(v), w[n / 2]) << distinct << " distinct of " << n;
    }
  }
  std::vector<double> empty;
  EXPECT_EQ(medianElement(empty), 0.0);
}

TEST(SwingFrequency, EstimatedFromThePeriodogram) {
  SyntheticSpec s;
  s.frequencyHz = 0.37;
  s.durationS = 30.0;
  auto ch = makeChannels(makeSynthetic(s), 1.0);
  ASSERT_TRUE(ch.isOk());
  auto f = estimateSwingFrequencyHz(ch->table);
  ASSERT_TRUE(f.isOk()) << f.status().toString();
  EXPECT_NEAR(*f, 0.37, 0.37 * 1e-4);
}

TEST(DelayAnalysis, NoiselessDataGiveTheExactLag) {
  SyntheticSpec s;
  s.tableQuantumDeg = 0.0;
  s.pulseEquivalentDeg = 0.0;
  s.trendDegPerS = 2e-3;
  auto r = analyzeTestPoint(makeSynthetic(s), BenchConstants{});
  ASSERT_TRUE(r.isOk()) << r.status().toString();
  EXPECT_NEAR(r->lagMs, 0.4658, 1e-6);  // 1 ns
  EXPECT_NEAR(r->joint.trendDegPerS, 2e-3, 1e-9);
  EXPECT_NEAR(r->magnitudeRatio, 1.0, 1e-9);
}

TEST(DelayAnalysis, RecoversLagFrequencyAndAmplitudeUnderQuantisation) {
  SyntheticSpec s;
  s.frequencyHz = 1.0 * (1.0 - 8.37e-6);  // the table's rate error, as in the paper
  s.lagS = 0.5467e-3;
  auto data = makeSynthetic(s);
  data.nominalFrequencyHz = 1.0;
  auto r = analyzeTestPoint(data, BenchConstants{});
  ASSERT_TRUE(r.isOk()) << r.status().toString();
  EXPECT_NEAR(r->lagMs, 0.5467, 3.0 * r->lagStdMs + 1e-6);
  EXPECT_LT(r->lagStdMs, 1e-3);  // under 1 us with quantisation only
  EXPECT_NEAR(r->tableFit.frequencyHz, s.frequencyHz, 5.0 * r->tableFit.frequencyStdHz);
  EXPECT_NEAR(r->tableFit.periodMs, 1000.00837, 1e-4);
  EXPECT_NEAR(r->tableFit.amplitudeDeg, 3.0, 1e-5);
  EXPECT_NEAR(r->gyroFit.amplitudeDeg, 3.0, 1e-4);
  EXPECT_NEAR(r->imuDelayMs, r->lagMs + 0.05, 1e-12);
  EXPECT_NEAR(r->gyroDelayMs, r->lagMs + 0.05 - 0.28, 1e-12);
  // The per-period track scatters around the joint result.
  ASSERT_GE(r->periodTrack.size(), 18u);
  EXPECT_NEAR(r->periodMeanLagMs, r->lagMs, 3.0 * r->periodScatterMs / std::sqrt(18.0));
}

TEST(DelayAnalysis, PhaseFollowsThePaperConvention) {
  // angle = A*sin(w*t + 0.3) = A*sin(w*(t - t0)) with t0 = -0.3/w.
  SyntheticSpec s;
  s.frequencyHz = 0.5;
  s.durationS = 40.0;
  auto r = analyzeTestPoint(makeSynthetic(s), BenchConstants{});
  ASSERT_TRUE(r.isOk());
  const double t0 = -0.3 / (kTwoPi * 0.5);
  EXPECT_NEAR(r->tableFit.phaseMs, t0 * 1e3, 1e-3);
  EXPECT_NEAR(r->gyroFit.phaseMs - r->tableFit.phaseMs, 0.4658, 3e-3);
}

TEST(DelayAnalysis, RefusesUnderTwoPeriods) {
  SyntheticSpec s;
  s.frequencyHz = 0.1;
  s.durationS = 15.0;
  auto r = analyzeTestPoint(makeSynthetic(s), BenchConstants{});
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), StatusCode::kInsufficientData);
  EXPECT_NE(r.status().message().find("two whole"), std::string::npos) << r.status().message();
}

TEST(DelayAnalysis, RefusesTooFewSamples) {
  TestPointData d;
  d.table.resize(3);
  d.imu.resize(3);
  auto r = analyzeTestPoint(d, BenchConstants{});
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), StatusCode::kInsufficientData);
}

// A recording made before values were range-checked where they enter (or by
// another program) can hold a value whose square is not a double: the fits
// refuse it with a reason; an increment of 1e200 crashed the covariance
// (SIGSEGV in fillCovariance on an empty J^T J).
TEST(DelayAnalysis, AValueBeyondADoublesSquareIsRefusedNotCrashed) {
  for (const double extreme : {1e200, -1e300, 1e155}) {
    auto data = makeSynthetic(SyntheticSpec{});
    data.imu[data.imu.size() / 2].incrementDeg[1] = extreme;
    auto r = analyzeTestPoint(data, BenchConstants{});
    ASSERT_FALSE(r.isOk()) << extreme << ": lag " << r->lagMs << " ± " << r->lagStdMs;
    EXPECT_NE(r.status().message().find("fit"), std::string::npos) << r.status().message();  // which fit, and why
  }
  auto table = makeSynthetic(SyntheticSpec{});
  table.table[100].angleDeg[1] = 1e200;
  auto r = analyzeTestPoint(table, BenchConstants{});
  EXPECT_FALSE(r.isOk());
}

// A planned frequency beyond any swing starts the fits far from the data:
// 1e300 Hz gave 1e301 periods and an overflowed cast (fog_fuzz_analysis).
TEST(DelayAnalysis, APlannedFrequencyBeyondAnySwingIsRefused) {
  for (const double planned : {1e300, 2000.0, -1.0}) {
    auto data = makeSynthetic(SyntheticSpec{});
    data.nominalFrequencyHz = planned;
    auto r = analyzeTestPoint(data, BenchConstants{});
    ASSERT_FALSE(r.isOk()) << planned;
    EXPECT_NE(r.status().message().find("is not within 0 .. 1000 Hz"), std::string::npos) << r.status().message();
  }
}

// The delay-against-frequency test pools only points whose checks passed: 9
// refused pendulum episodes once read "weighted lag -21.87 ± 5.40 ms ...
// consistent with a pure delay".
TEST(DelayAnalysis, TheFrequencyTestPoolsOnlyPointsThatPassedTheirChecks) {
  std::vector<TestPointResult> points(3);
  const double f[] = {0.5, 1.0, 2.0}, lag[] = {0.5, 0.5, 30.0};
  for (int i = 0; i < 3; ++i) {
    points[i].index = i;
    points[i].axis = Axis::kX;
    points[i].nominalFrequencyHz = f[i];
    points[i].lagMs = lag[i];
    points[i].lagStdMs = 0.01;
    points[i].checks.push_back({"axis_sign", true, "ok"});
  }
  points[2].checks.push_back({"steady_sine", false, "not a steady sinusoid"});
  auto c = frequencyConsistency(points);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].points, 2);
  EXPECT_EQ(c[0].leftOutPoints, 1);
  EXPECT_NEAR(c[0].weightedLagMs, 0.5, 1e-12);
  EXPECT_TRUE(c[0].consistentWithPureDelay);
  // An unjudged check (n/a) does not leave a point out; with one point left no test is made.
  points[2].checks.back().judged = false;
  EXPECT_EQ(frequencyConsistency(points).at(0).points, 3);
  points[1].checks.push_back({"causal", false, "negative"});
  points[2].checks.back().judged = true;
  EXPECT_TRUE(frequencyConsistency(points).empty());
}

// A recording is in degrees (protocol::RecordingBuilder refuses a stream
// whose pulses it cannot convert): the bench's pulse equivalent never
// rescales it a second time.
TEST(DelayAnalysis, TheBenchPulseEquivalentNeverRescalesARecording) {
  Recording rec;
  rec.pulseEquivalentDeg = 5e-5;
  rec.testPoints.push_back(makeSynthetic(SyntheticSpec{}));
  BenchConstants unset, other;
  other.pulseEquivalentDeg = 0.25;
  auto a = analyzeRecording(rec, unset);
  auto b = analyzeRecording(rec, other);
  ASSERT_TRUE(a.isOk() && b.isOk());
  ASSERT_EQ(a->points.size(), 1u);
  ASSERT_EQ(b->points.size(), 1u);
  EXPECT_EQ(a->points[0].lagMs, b->points[0].lagMs);
  EXPECT_EQ(a->points[0].joint.gain, b->points[0].joint.gain);
}

// Monte Carlo: with angle random walk dominating, the reported standard
// error must match the scatter of the estimates, and the scatter must sit at
// the Cramer-Rao bound (the fit is efficient).
TEST(DelayAnalysis, StandardErrorMatchesMonteCarloScatterAndBound) {
  const int trials = 60;
  std::vector<double> lags, stds, bounds;
  for (int i = 0; i < trials; ++i) {
    SyntheticSpec s;
    s.durationS = 20.0;
    s.arwDegPerSqrtS = 0.02 / 60.0;
    s.seed = 1000u + static_cast<unsigned>(i);
    auto r = analyzeTestPoint(makeSynthetic(s), BenchConstants{});
    ASSERT_TRUE(r.isOk()) << r.status().toString();
    lags.push_back(r->lagMs);
    stds.push_back(r->lagStdMs);
    bounds.push_back(r->crlbMs);
  }
  const auto lag = meanAndSpread(lags);
  const auto sd = meanAndSpread(stds);
  const auto bound = meanAndSpread(bounds);
  // With 60 trials the scatter itself is known to ~9 % (1 sigma).
  EXPECT_NEAR(lag.mean, 0.4658, 3.0 * lag.stdOfMean);
  EXPECT_NEAR(sd.mean / lag.stdDev, 1.0, 0.25);
  EXPECT_LT(lag.stdDev / bound.mean, 1.3);
  EXPECT_NEAR(sd.mean / bound.mean, 1.0, 0.1);
}

// The frequency check runs beside the fits when the plan states the
// frequency (analyzeTestPoint); when it finds the table 5 % off the plan, the
// point is analysed again from the measured frequency: the same lag as when
// no frequency was planned, and a warning that says so.
TEST(DelayAnalysis, APlanOffByMoreThanOnePercentIsFittedFromTheMeasuredFrequency) {
  SyntheticSpec s;
  s.frequencyHz = 1.05;
  auto data = makeSynthetic(s);
  data.nominalFrequencyHz = 1.0;
  const auto planned = analyzeTestPoint(data, BenchConstants{});
  data.nominalFrequencyHz = 0.0;
  const auto unplanned = analyzeTestPoint(data, BenchConstants{});
  ASSERT_TRUE(planned.isOk()) << planned.status().toString();
  ASSERT_TRUE(unplanned.isOk()) << unplanned.status().toString();
  EXPECT_NEAR(planned->nominalFrequencyHz, 1.05, 1e-4);
  EXPECT_EQ(planned->nominalFrequencyHz, unplanned->nominalFrequencyHz);
  EXPECT_EQ(planned->lagMs, unplanned->lagMs);
  EXPECT_EQ(planned->lagStdMs, unplanned->lagStdMs);
  ASSERT_FALSE(planned->warnings.empty());
  EXPECT_NE(planned->warnings.front().find("not the planned 1.00000 Hz"), std::string::npos) << planned->warnings.front();
  EXPECT_EQ(planned->warnings.size(), unplanned->warnings.size() + 1);
}

}  // namespace
}  // namespace fog::analysis

// Each library effect does what its documentation says: injected at a known
// magnitude into the simulator, the feature (or analysis) estimator recovers
// it within a stated tolerance. Runs with and without the effect share a seed,
// so the noise cancels in the differences.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/common/units.h"
#include "core/diagnosis/effects.h"
#include "core/diagnosis/features.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis {
namespace {

TestPlan onePoint(Axis axis, double hz, double amp, double durationS) {
  TestPlan p;
  p.points.push_back({axis, hz, amp, durationS, 1.0, 0.0});
  return p;
}

Recording simulateWith(const TestPlan& plan, std::vector<std::unique_ptr<model::Effect>> effects = {}) {
  model::SimConfig c;
  c.seed = 5;
  auto run = model::simulate(c, plan, std::move(effects));
  EXPECT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  EXPECT_TRUE(rec.isOk());
  return *rec;
}

FeatureReference referenceFor(const TestPlan& plan) {
  FeatureReference r;
  for (const auto& p : plan.points)
    r.points.push_back({kTwoPi * p.frequencyHz * (1.0 - 8.37e-6), segmentsFor(p.durationS, p.frequencyHz),
                        static_cast<int>(p.axis)});
  return r;
}

// Mean over segments of one feature (by quantity and axis) of test point 0.
double feature(const FeatureSet& f, const std::string& quantity, int axis = -2, int segment = -1) {
  double s = 0;
  int n = 0;
  for (std::size_t i = 0; i < f.keys.size(); ++i)
    if (f.keys[i].point == 0 && quantityName(f.keys[i]) == quantity && (axis == -2 || f.keys[i].axis == axis) &&
        (segment < 0 || f.keys[i].segment == segment))
      s += f.values[i], ++n;
  EXPECT_GT(n, 0) << quantity;
  return s / n;
}

struct Pair {
  FeatureSet clean, with;
};
Pair features(const TestPlan& plan, EffectId id, std::vector<double> params) {
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeEffect(id, params));
  auto a = extractFeatures(simulateWith(plan), referenceFor(plan));
  auto b = extractFeatures(simulateWith(plan, std::move(e)), referenceFor(plan));
  EXPECT_TRUE(a.isOk() && b.isOk());
  return {*a, *b};
}

TEST(EffectLibrary, HasEveryRequiredEffectWithUnitsAndReferences) {
  EXPECT_EQ(effectLibrary().size(), static_cast<std::size_t>(kEffectCount));
  for (const auto& s : effectLibrary()) {
    EXPECT_EQ(effectSpec(s.id).name, s.name);
    EXPECT_EQ(*effectIdFromName(s.name), s.id);
    for (const auto& p : s.parameters) {
      EXPECT_FALSE(p.unit.empty()) << s.name;
      EXPECT_GT(p.reference, 0.0) << s.name;
    }
  }
  EXPECT_FALSE(effectIdFromName("warp_drive").isOk());
}

TEST(EffectLibrary, ZeroParametersLeaveTheStreamUnchanged) {
  const TestPlan plan = onePoint(Axis::kX, 1.0, 3.0, 4.0);
  model::SimConfig c;
  auto plain = model::simulate(c, plan);
  for (const auto& s : effectLibrary()) {
    std::vector<std::unique_ptr<model::Effect>> e;
    e.push_back(makeEffect(s.id, std::vector<double>(s.parameters.size(), 0.0)));
    auto with = model::simulate(c, plan, std::move(e));
    EXPECT_EQ(with->bytes, plain->bytes) << s.name;
  }
}

// Gyro/table gain - 1 = scale-factor error: 500 ppm within 2 ppm.
TEST(EffectSignature, ScaleFactorErrorIsAGain) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kScaleFactorError, {500.0});
  EXPECT_NEAR(feature(f.with, "gain") - feature(f.clean, "gain"), 500.0, 2.0);
}

// Asymmetry a = (K+ - K-) / Kbar (IEEE Std 528): the scale factor is
// 1 + a/2 for positive rates and 1 - a/2 for negative ones, which adds
// (a/2) * mean|rate| = (a/2) * (2/pi) * A * w to the trend: 20000 ppm at
// 1 Hz / 3 deg -> 432 deg/h, within 2 % (a factor 2 in the definition fails).
TEST(EffectSignature, ScaleFactorAsymmetryAddsATrendAndEvenHarmonics) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kScaleFactorAsymmetry, {20000.0});
  const double expected = 0.01 * (2.0 / kPi) * 3.0 * kTwoPi * kSecondsPerHour;
  EXPECT_NEAR(feature(f.with, "trend", 0) - feature(f.clean, "trend", 0), expected, 0.02 * expected);
  EXPECT_GT(std::abs(feature(f.with, "h2_in_phase", 0) - feature(f.clean, "h2_in_phase", 0)), 1000.0);
}

// IEEE Std 528's nonlinearity N over +-100 deg/s (largest deviation from the
// least-squares line, fraction of full scale) is a cubic term k (r/100)^2 r
// with k = N / 0.4. With r = R cos: gain + 3/4 k (R/100)^2 and, once
// integrated to an angle, a 3rd harmonic k/12 (R/100)^2; N = 4 % (k = 10 %)
// at R = 18.85 deg/s -> 2665 ppm gain (3 %) and 296 ppm at 3rd harmonic (5 %).
TEST(EffectSignature, ScaleFactorNonlinearityGivesAmplitudeDependentGainAndThirdHarmonic) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kScaleFactorNonlinearity, {4e4});
  const double r = 3.0 * kTwoPi / 100.0;
  EXPECT_NEAR(feature(f.with, "gain") - feature(f.clean, "gain"), 0.75 * 1e5 * r * r, 0.03 * 0.75 * 1e5 * r * r);
  const double h3 = std::hypot(feature(f.with, "h3_in_phase", 0) - feature(f.clean, "h3_in_phase", 0),
                               feature(f.with, "h3_quadrature", 0) - feature(f.clean, "h3_quadrature", 0));
  EXPECT_NEAR(h3, 1e5 / 12.0 * r * r, 0.05 * 1e5 / 12.0 * r * r);
}

// Misalignment m_yx and m_zx (gyro y / z sensing rotation about x): a swing
// about X shows in the other gyros in phase with it, m ppm (ppm = urad);
// the terms of axes that do not move show nothing.
TEST(EffectSignature, MisalignmentCouplesTheSwingIntoTheOtherAxes) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kMisalignment,
                          {700.0, 700.0, 1000.0, 700.0, -500.0, 700.0});
  const double expected[] = {0.0, 1000.0, -500.0};
  for (int a : {1, 2}) {
    EXPECT_NEAR(feature(f.with, "cross_in_phase", a) - feature(f.clean, "cross_in_phase", a), expected[a], 5.0);
    EXPECT_NEAR(feature(f.with, "cross_quadrature", a) - feature(f.clean, "cross_quadrature", a), 0.0, 5.0);
  }
}

// Each gyro's rate error is k times the specific force along it. A swing
// about X by theta turns gravity into Y (f_y = -g sin theta) and out of Z
// (f_z = -g cos theta); X sees none. Y's rate error -k sin(theta) integrates
// to an angle in quadrature with the swing, k (pi/180) / w relative to it
// (100 deg/h/g at 0.1 Hz / 10 deg: 772 ppm, within 3 %); Z's trend moves by
// -k (1 - A^2/4); X's delay does not move.
TEST(EffectSignature, GSensitivityActsAlongEachGyrosOwnSpecificForce) {
  const double w = kTwoPi * 0.1, k = 100.0, amp = 10.0 * kRadPerDeg;
  const double expectedPpm = k / kSecondsPerHour * kRadPerDeg / w * 1e6;
  const auto x = features(onePoint(Axis::kX, 0.1, 10.0, 40.0), EffectId::kGSensitivity, {k});
  EXPECT_NEAR(feature(x.with, "delay") - feature(x.clean, "delay"), 0.0, 0.05);
  EXPECT_NEAR(std::abs(feature(x.with, "cross_quadrature", 1) - feature(x.clean, "cross_quadrature", 1)), expectedPpm,
              0.03 * expectedPpm);
  EXPECT_NEAR(feature(x.with, "cross_in_phase", 1) - feature(x.clean, "cross_in_phase", 1), 0.0, 0.03 * expectedPpm);
  EXPECT_NEAR(feature(x.with, "trend", 2) - feature(x.clean, "trend", 2), -k * (1.0 - amp * amp / 4.0), 1.0);
}

// A continuous first-order lag of time constant tau delays a sinusoid of
// angular frequency w by atan(w tau) / w and scales it by 1 / sqrt(1 + (w tau)^2),
// however tau compares with the 2 ms frames: 0.3 ms -> 300.0 us (within
// 3 us) and 20 ms -> 19896 us (within 20 us), gain -7810 ppm.
// Issue 40: the library's 2-ms lag at the bench's own 2-ms gyro frames is a
// delay plus a first-order lag at the points' noise level, as generated. A
// quadratic between frames (the effect's first form) left 1.7e-4 of the
// swing at 11 Hz: chi^2 6 300 on 37 dof on the response preset, the first
// order refused, a negative delay "chosen". On a 10-frequency response plan
// (0.5 Hz .. the table's limit), seeds 1..20: the first order chosen with
// T within 3 sigma in at least 19, and never a rejected or unphysical model.
TEST(EffectSignature, TheLibrarysTwoMillisecondLagIsAFirstOrderResponse) {
  ResponsePlanOptions o;
  o.lowestHz = 0.5;
  o.frequencies = 10;
  o.minDurationS = 4.0;
  const TestPlan plan = *responsePlan(TurntableLimits{}, o);
  int right = 0;
  for (int seed = 1; seed <= 20; ++seed) {
    model::SimConfig c;
    c.seed = static_cast<std::uint64_t>(seed);
    std::vector<std::unique_ptr<model::Effect>> e;
    e.push_back(makeEffect(EffectId::kFirstOrderLag, {2.0}));
    auto run = model::simulate(c, plan, std::move(e));
    ASSERT_TRUE(run.isOk()) << run.status().message();
    auto rec = protocol::decodeRecording(run->bytes);
    ASSERT_TRUE(rec.isOk());
    auto report = analysis::analyzeRecording(*rec, BenchConstants{});
    ASSERT_TRUE(report.isOk()) << report.status().message();
    auto r = analysis::analyzeResponse(analysis::responsePoints(*report, Axis::kX), Axis::kX, 5.0);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    if (r->chosen < 0) {
      std::printf("  seed %d: %s\n", seed, r->noModelReason.c_str());
      continue;
    }
    const auto& chosen = r->models[static_cast<std::size_t>(r->chosen)];
    EXPECT_TRUE(chosen.eligible()) << "seed " << seed;
    double t = NAN, sigma = NAN;
    for (const auto& p : chosen.parameters)
      if (p.name == "T_ms") t = p.value, sigma = p.stdDev;
    std::printf("  seed %2d: %s, p %.3f, T %.6f ± %.2g ms (%+.2f σ)\n", seed,
                analysis::responseModelName(chosen.kind), chosen.pValue, t, sigma, (t - 2.0) / sigma);
    if (chosen.kind == analysis::ResponseModelKind::kFirstOrder && std::abs(t - 2.0) <= 3.0 * sigma) ++right;
  }
  EXPECT_GE(right, 19);
}

TEST(EffectSignature, FirstOrderLagIsTheContinuousFilter) {
  const double w = kTwoPi * 1.0;
  for (double tau : {0.3e-3, 20e-3}) {
    const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kFirstOrderLag, {tau * 1e3});
    const double expectedUs = std::atan(w * tau) / w * 1e6;
    EXPECT_NEAR(feature(f.with, "delay") - feature(f.clean, "delay"), expectedUs, std::max(3.0, 1e-3 * expectedUs))
        << "tau " << tau;
    const double expectedGainPpm = (1.0 / std::sqrt(1.0 + w * w * tau * tau) - 1.0) * 1e6;
    EXPECT_NEAR(feature(f.with, "gain") - feature(f.clean, "gain"), expectedGainPpm, 100.0) << "tau " << tau;
  }
}

// Bias ramp d deg/h per minute: segment trends grow by d * dt / 60 s.
TEST(EffectSignature, BiasDriftRampsTheTrendAcrossSegments) {
  const auto f = features(onePoint(Axis::kX, 0.1, 10.0, 60.0), EffectId::kBiasDrift, {6.0});
  const double first = feature(f.with, "trend", 0, 0) - feature(f.clean, "trend", 0, 0);
  const double last = feature(f.with, "trend", 0, 2) - feature(f.clean, "trend", 0, 2);
  EXPECT_NEAR(last - first, 6.0 * 40.0 / 60.0, 0.05);
}

// h3 is the 3rd harmonic relative to the fundamental at 10 deg, phase 0 at
// the fundamental's positive peak: 10 cos(chi) + 10 h3 cos(3 chi). With the
// fundamental as 10 sin(phi) (chi = phi - 90 deg) that is -10 h3 sin(3 phi):
// h3 = -1000 ppm is +1000 ppm in phase, in table and gyro alike (gyro -
// table: nothing).
TEST(EffectSignature, TableDistortionShowsInBothChannels) {
  const auto f = features(onePoint(Axis::kX, 0.1, 10.0, 40.0), EffectId::kTableHarmonicDistortion, {0.0, -1000.0});
  EXPECT_NEAR(feature(f.with, "h3_in_phase", -1) - feature(f.clean, "h3_in_phase", -1), 1000.0, 20.0);
  EXPECT_NEAR(feature(f.with, "h3_in_phase", 0) - feature(f.clean, "h3_in_phase", 0), 0.0, 5.0);
}

// h2 is the 2nd harmonic relative to the fundamental at 10 deg, phase 0 at
// the fundamental's positive peak: 10 cos(chi) + 10 h2 cos(2 chi). With the
// fundamental as 10 sin(phi), cos(2 chi) = -cos(2 phi): h2 = 1000 ppm is
// -1000 ppm in quadrature and nothing in phase; at 3 deg it is h2 (3 / 10)
// = 300 ppm (a static distortion of the angle).
TEST(EffectSignature, TableDistortionH2IsTheHarmonicRatioAtTenDegrees) {
  const auto f = features(onePoint(Axis::kX, 0.1, 10.0, 40.0), EffectId::kTableHarmonicDistortion, {1000.0, 0.0});
  EXPECT_NEAR(feature(f.with, "h2_quadrature", -1) - feature(f.clean, "h2_quadrature", -1), -1000.0, 20.0);
  EXPECT_NEAR(feature(f.with, "h2_in_phase", -1) - feature(f.clean, "h2_in_phase", -1), 0.0, 20.0);
  const auto g = features(onePoint(Axis::kX, 0.1, 3.0, 40.0), EffectId::kTableHarmonicDistortion, {1000.0, 0.0});
  EXPECT_NEAR(feature(g.with, "h2_quadrature", -1) - feature(g.clean, "h2_quadrature", -1), -300.0, 20.0);
}

// Encoder error es sin(2 pi theta / 10 deg) at 0.3 deg swing is nearly a
// table scale error 2 pi es / 10 deg: the gyro/table gain drops by that (5 %).
TEST(EffectSignature, EncoderCyclicErrorIsSeenByTheTableOnly) {
  const auto f = features(onePoint(Axis::kX, 1.0, 0.3, 20.0), EffectId::kEncoderCyclicError, {36.0, 0.0});
  const double scale = kTwoPi * 0.01 / 10.0;
  EXPECT_NEAR(feature(f.with, "gain") - feature(f.clean, "gain"), -scale * 1e6, 0.05 * scale * 1e6);
}

TEST(EffectSignature, TimestampJitterAddsTwiceItsVarianceToTheIntervals) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kTimestampJitter, {400.0});
  EXPECT_NEAR(feature(f.with, "imu_interval_var") - feature(f.clean, "imu_interval_var"), 800.0, 80.0);
}

TEST(EffectSignature, ClockDriftShowsInTheImuIntervalsAndTheDelayTrack) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kClockDrift, {50.0});
  EXPECT_NEAR(feature(f.with, "imu_interval") - feature(f.clean, "imu_interval"), 50.0, 0.5);
  // The IMU stamps fall behind by 50 ppm of session time: 15 s between the
  // first and last segment middles -> 750 us more delay.
  const double d0 = feature(f.with, "delay", -2, 0), d3 = feature(f.with, "delay", -2, 3);
  EXPECT_NEAR(d3 - d0, 50e-6 * 15.0 * 1e6, 10.0);
}

// 10 per mille over 10 000 frames: 100 +- 30 (3 sigma binomial).
TEST(EffectSignature, DroppedFramesAreCountedAsLost) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kDroppedFrames, {10.0});
  EXPECT_NEAR(feature(f.with, "imu_lost") * 4.0, 100.0, 30.0);
  EXPECT_EQ(feature(f.clean, "imu_lost"), 0.0);
}

// 10 deg latitude error at heading 0: the X (north) gyro's trend changes by
// 15.041 (cos 50 - cos 40) deg/h, the Z (down) gyro's by -15.041 (sin 50 - sin 40).
TEST(EffectSignature, EarthRateProjectionChangesTheTrends) {
  const auto f = features(onePoint(Axis::kX, 1.0, 3.0, 20.0), EffectId::kEarthRateProjection, {10.0, 0.0});
  const double c = kEarthRateDegPerH;
  EXPECT_NEAR(feature(f.with, "trend", 0) - feature(f.clean, "trend", 0),
              c * (std::cos(50 * kRadPerDeg) - std::cos(40 * kRadPerDeg)), 0.05);
  EXPECT_NEAR(feature(f.with, "trend", 2) - feature(f.clean, "trend", 2),
              -c * (std::sin(50 * kRadPerDeg) - std::sin(40 * kRadPerDeg)), 0.05);
}

TEST(TimingAudit, CountsGapsAndMeasuresIntervals) {
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeEffect(EffectId::kClockDrift, {20.0}));
  const Recording rec = simulateWith(onePoint(Axis::kX, 1.0, 3.0, 10.0), std::move(e));
  const TimingAudit a = auditTiming(rec, 1e-3, 2e-3);
  EXPECT_NEAR(a.imu.intervalMeanPpm, 20.0, 0.2);
  EXPECT_NEAR(a.table.intervalMeanPpm, 0.0, 0.2);
  EXPECT_EQ(a.imu.gaps, 0u);
  EXPECT_EQ(a.table.duplicates, 0u);
}

}  // namespace
}  // namespace fog::diagnosis

namespace fog::diagnosis {
namespace {

// The replays at one seed reuse the first replay's sums where their stamps
// and readings are its own (FeatureSums): every feature must be the one
// summing gives, bit for bit, whether the sums are reused (a gyro-only
// effect), partly reused (the encoder's readings changed, the stamps not)
// or not at all (the stamps moved).
TEST(FeatureSums, ReusedGiveTheFeaturesSummingGives) {
  const TestPlan plan = onePoint(Axis::kX, 1.0, 3.0, 12.0);
  FeatureSums sums;
  auto first = extractFeatures(simulateWith(plan), referenceFor(plan), ResidualView::kCompute, &sums);
  ASSERT_TRUE(first.isOk());
  for (auto [id, p] : {std::pair{EffectId::kScaleFactorError, std::vector<double>{1000.0}},
                       std::pair{EffectId::kEncoderCyclicError, std::vector<double>{1.0, 0.0}},
                       std::pair{EffectId::kTimestampJitter, std::vector<double>{100.0}}}) {
    std::vector<std::unique_ptr<model::Effect>> e;
    e.push_back(makeEffect(id, p));
    const Recording rec = simulateWith(plan, std::move(e));
    auto summed = extractFeatures(rec, referenceFor(plan));
    auto reused = extractFeatures(rec, referenceFor(plan), ResidualView::kCompute, nullptr, &sums);
    ASSERT_TRUE(summed.isOk() && reused.isOk());
    EXPECT_EQ(summed->values, reused->values) << effectSpec(id).name;
    EXPECT_EQ(summed->formalStd, reused->formalStd) << effectSpec(id).name;
    EXPECT_EQ(summed->spectra[0].gyroResidualDeg, reused->spectra[0].gyroResidualDeg) << effectSpec(id).name;
  }
}

}  // namespace
}  // namespace fog::diagnosis

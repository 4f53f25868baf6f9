// The gyro noise estimators of core/analysis/channels.h on residuals with a
// known truth: white rate noise (ARW), pulse quantisation of the cumulative
// angle (telescoping in the increments) and a slow Gauss-Markov bias wander.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/analysis/channels.h"
#include "core/analysis/sine_fit.h"
#include "core/common/units.h"
#include "synthetic.h"

namespace fog::analysis {
namespace {

struct Residuals {
  GyroChannel gyro;
  std::vector<double> r;
};

// n frames of period dt of a gyro swinging at 0.1 Hz / 10 deg (the swing
// moves the angle by many pulses per frame, so the quantisation errors are
// independent, as on the bench): increments of swing + white rate + wander
// angle, the cumulative angle quantised to `pulseDeg`, less the swing's own
// increments (what a fit's residuals are).
Residuals make(std::size_t n, double dt, double arwDegPerSqrtS, double pulseDeg, double wanderDegPerS, double tauS,
               unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Residuals out;
  out.gyro.framePeriodS = dt;
  out.gyro.continuesPrevious.assign(n, true);
  out.gyro.continuesPrevious[0] = false;
  const auto swing = [](double t) { return 10.0 * std::sin(2.0 * 3.14159265358979 * 0.1 * t); };
  double noise = 0.0, wander = wanderDegPerS * normal(rng), lastQuantised = 0.0;
  const double decay = std::exp(-dt / tauS);
  for (std::size_t k = 0; k < n; ++k) {
    noise += arwDegPerSqrtS * std::sqrt(dt) * normal(rng) + wander * dt;
    wander = wander * decay + wanderDegPerS * std::sqrt(1.0 - decay * decay) * normal(rng);
    const double t = static_cast<double>(k + 1) * dt;
    const double quantised = std::floor((swing(t) + noise) / pulseDeg) * pulseDeg;
    out.r.push_back(quantised - lastQuantised - (swing(t) - swing(t - dt)));
    lastQuantised = quantised;
  }
  out.r[0] = 0.0;  // the first increment starts from an unquantised 0
  return out;
}

constexpr double kArwDegPerSqrtH = 0.004;
constexpr double kArw = kArwDegPerSqrtH / 60.0;  // deg/sqrt(s)
constexpr double kPulse = 5e-5;                   // 0.18 arcsec

TEST(GyroNoise, WhiteRateVarianceRecoversTheArwAtAnyFramePeriod) {
  for (double dt : {0.002, 0.02}) {
    auto s = make(static_cast<std::size_t>(600.0 / dt), dt, kArw, kPulse, 0.0, 300.0, 3);
    const double arw = std::sqrt(estimateWhiteRateVariance(s.gyro, s.r, 0.5)) * 60.0;
    EXPECT_NEAR(arw, kArwDegPerSqrtH, 0.05 * kArwDegPerSqrtH) << "frame period " << dt;
  }
}

// An hour with a 0.5 deg/h bias wander of 300 s correlation: block sums take
// the wander for a random walk (the ARW 1.75x high here), their second
// differences do not.
TEST(GyroNoise, WhiteRateVarianceIgnoresASlowBiasWander) {
  auto s = make(1800000, 0.002, kArw, kPulse, 0.5 / 3600.0, 300.0, 5);
  const double arw = std::sqrt(estimateWhiteRateVariance(s.gyro, s.r, 0.5)) * 60.0;
  EXPECT_NEAR(arw, kArwDegPerSqrtH, 0.05 * kArwDegPerSqrtH);
  // The residuals of a fit take out the mean rate; the wander stays.
  double mean = 0.0;
  for (double v : s.r) mean += v / static_cast<double>(s.r.size());
  for (double& v : s.r) v -= mean;
  estimateGyroNoise(s.gyro, s.r, 0.5);
  const double blockArw = std::sqrt(s.gyro.arwVarianceDeg2PerS) * 60.0;
  EXPECT_GT(blockArw, 1.3 * kArwDegPerSqrtH) << "the block sums no longer see the wander: this test proves nothing";
  EXPECT_NEAR(std::sqrt(estimateWhiteRateVariance(s.gyro, s.r, 0.5)) * 60.0, arw, 1e-6);
}

// The one-pass forms measureGyroNoise uses give the same doubles as the
// passes they replace: the residual sums straight from a fit, and the three
// block views of them.
TEST(GyroNoise, OnePassSumsAndViewsEqualTheSeparatePasses) {
  testing::SyntheticSpec spec;
  spec.arwDegPerSqrtS = 2e-4;
  spec.durationS = 60.0;
  const auto data = testing::makeSynthetic(spec);
  auto ch = makeChannels(data, 1.0);
  ASSERT_TRUE(ch.isOk());
  const SineFit fit = fitGyroLinear(ch->gyro, kTwoPi * spec.frequencyHz, ch->referenceS, false);
  const IncrementResidualSums fused = gyroIncrementResidualSums(ch->gyro, fit);
  const IncrementResidualSums separate = incrementResidualSums(ch->gyro, gyroIncrementResiduals(ch->gyro, fit));
  EXPECT_EQ(fused.quantisationVarianceDeg2, separate.quantisationVarianceDeg2);
  ASSERT_EQ(fused.prefix.size(), separate.prefix.size());
  for (std::size_t k = 0; k < fused.prefix.size(); ++k) ASSERT_EQ(fused.prefix[k], separate.prefix[k]) << k;
  for (const auto& [blockS, weightS] : {std::pair{0.05, 0.25}, {0.25, 0.05}, {1.0, 7.5}}) {
    const GyroNoiseViews views = gyroNoiseViews(ch->gyro, separate, blockS, weightS);
    EXPECT_EQ(views.whiteRateVarianceDeg2PerS, estimateWhiteRateVariance(ch->gyro, separate, blockS));
    const BlockRateVariance swing = blockRateVariance(ch->gyro, separate, blockS);
    const BlockRateVariance weight = blockRateVariance(ch->gyro, separate, weightS);
    EXPECT_EQ(views.swingBlocks.varianceDeg2PerS, swing.varianceDeg2PerS);
    EXPECT_EQ(views.swingBlocks.stdDeg2PerS, swing.stdDeg2PerS);
    EXPECT_EQ(views.weightBlocks.varianceDeg2PerS, weight.varianceDeg2PerS);
    EXPECT_EQ(views.weightBlocks.stdDeg2PerS, weight.stdDeg2PerS);
  }
}

}  // namespace
}  // namespace fog::analysis

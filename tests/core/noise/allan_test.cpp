// Overlapping Allan deviation, EDF and chi-squared intervals against
// published reference values.

#include "core/noise/allan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace fog::noise {
namespace {

// The "NBS14" 1000-point test data set of NIST SP 1065 (Riley, Handbook of
// Frequency Stability Analysis, 2008), section 12.4 / Table 31: fractional
// frequency data from the portable generator n(i+1) = 16807 n(i) mod
// 2147483647, n(0) = 1234567890, x(i) = n(i) / 2147483647.
std::vector<double> nbs14Frequency() {
  std::vector<double> y(1000);
  std::uint64_t n = 1234567890;
  for (auto& v : y) {
    v = static_cast<double>(n) / 2147483647.0;
    n = (16807 * n) % 2147483647;
  }
  return y;
}

TEST(Nbs14, GeneratorMatchesThePublishedFirstValues) {
  // SP 1065 / Riley's test suite gives n(1), n(2), n(3).
  std::uint64_t n = 1234567890;
  const std::uint64_t expected[] = {395529916, 1209410747, 633705974};
  for (std::uint64_t e : expected) {
    n = (16807 * n) % 2147483647;
    EXPECT_EQ(n, e);
  }
}

// Reference deviations at tau = 1, 10, 100 (tau0 = 1) from NIST SP 1065
// Table 31 ("1000-point test suite"), also Riley's "The Calculation of Time
// Domain Frequency Stability", Table III: Allan deviation 2.922319e-01,
// 9.965736e-02, 3.897804e-02; overlapping Allan deviation 2.922319e-01,
// 9.159953e-02, 3.241343e-02. Required: at least 4 significant digits; all 7
// published digits are reproduced (relative error < 2e-7, the rounding of
// the published values).
TEST(Nbs14, OverlappingAllanDeviationReproducesAllPublishedDigitsOfSp1065) {
  const auto phase = cumulativeSum(nbs14Frequency());
  const double reference[] = {2.922319e-01, 9.159953e-02, 3.241343e-02};
  const std::size_t taus[] = {1, 10, 100};
  for (int i = 0; i < 3; ++i) {
    const double adev = std::sqrt(allanVariance(phase, 1.0, taus[i], true));
    EXPECT_NEAR(adev / reference[i], 1.0, 2e-7) << "tau " << taus[i] << ": " << adev;
  }
}

TEST(Nbs14, NonOverlappingAllanDeviationReproducesAllPublishedDigitsOfSp1065) {
  const auto phase = cumulativeSum(nbs14Frequency());
  const double reference[] = {2.922319e-01, 9.965736e-02, 3.897804e-02};
  const std::size_t taus[] = {1, 10, 100};
  for (int i = 0; i < 3; ++i) {
    const double adev = std::sqrt(allanVariance(phase, 1.0, taus[i], false));
    EXPECT_NEAR(adev / reference[i], 1.0, 2e-7) << "tau " << taus[i] << ": " << adev;
  }
}

TEST(Nbs14, RemovingTheMeanRateChangesNothing) {
  const auto y = nbs14Frequency();
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  const auto a = cumulativeSum(y), b = cumulativeSum(y, mean);
  for (std::size_t m : {1, 7, 100})
    EXPECT_NEAR(allanVariance(a, 1.0, m, true) / allanVariance(b, 1.0, m, true), 1.0, 1e-10);
}

TEST(AllanVariance, RefusesTausLongerThanHalfTheRecord) {
  const std::vector<double> phase(11, 0.0);
  EXPECT_TRUE(std::isnan(allanVariance(phase, 1.0, 6, true)));  // 2m must stay below 11
  EXPECT_TRUE(std::isnan(allanVariance(phase, 1.0, 0, true)));
  std::size_t count = 0;
  EXPECT_EQ(allanVariance(phase, 1.0, 4, true, &count), 0.0);
  EXPECT_EQ(count, 3u);  // 11 - 2 * 4 second differences
}

TEST(AveragingFactors, AreOctaveSpacedDistinctAndBounded) {
  const auto m = averagingFactors(1001, 1, 0.25);
  ASSERT_EQ(m.size(), 8u);  // 1 .. 128; 256 > 0.25 * 1000
  for (std::size_t i = 0; i < m.size(); ++i) EXPECT_EQ(m[i], std::size_t{1} << i);
  const auto fine = averagingFactors(100001, 2, 0.25);
  for (std::size_t i = 1; i < fine.size(); ++i) {
    EXPECT_GT(fine[i], fine[i - 1]);
    EXPECT_LE(static_cast<double>(fine[i]) / static_cast<double>(fine[i - 1]), 2.0 + 1e-12);
  }
  EXPECT_LE(fine.back(), 25000u);
}

// Reference quantiles (scipy.stats.chi2.ppf, also any statistics table),
// required to 1e-6 relative.
TEST(ChiSquare, QuantilesMatchTables) {
  EXPECT_NEAR(chiSquareQuantile(0.95, 1.0), 3.841458820694124, 3.9e-6);
  EXPECT_NEAR(chiSquareQuantile(0.05, 1.0), 0.003932140000019522, 4e-9);
  EXPECT_NEAR(chiSquareQuantile(0.975, 10.0), 20.48317735080739, 2e-5);
  EXPECT_NEAR(chiSquareQuantile(0.025, 10.0), 3.246972780236841, 3.3e-6);
  EXPECT_NEAR(chiSquareQuantile(0.5, 2.0), 2.0 * std::log(2.0), 1.4e-6);  // exponential median
  EXPECT_NEAR(chiSquareQuantile(0.9, 2.0), -2.0 * std::log(0.1), 4.6e-6);  // exponential: -2 ln(1 - p)
}

TEST(ChiSquare, QuantileInvertsTheCdfForRealDegreesOfFreedom) {
  for (double dof : {0.7, 1.5, 3.3, 17.2, 250.0, 9000.0})
    for (double p : {0.01, 0.1587, 0.5, 0.8413, 0.99}) EXPECT_NEAR(chiSquareCdf(chiSquareQuantile(p, dof), dof), p, 1e-9);
}

TEST(ChiSquare, WilsonHilfertyTakesOverSmoothlyAtLargeDof) {
  // Just below and above the switch at 1e5 the quantiles agree to 1e-9.
  const double below = chiSquareQuantile(0.8413, 99999.0) / 99999.0;
  const double above = chiSquareQuantile(0.8413, 100001.0) / 100001.0;
  EXPECT_NEAR(below, above, 1e-7);
}

TEST(NormalQuantile, MatchesKnownValues) {
  EXPECT_NEAR(normalQuantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(normalQuantile(0.8413447460685429), 1.0, 1e-12);
  EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(normalQuantile(1e-10), -6.361340902404056, 1e-9);
}

// SP 1065 Table 5 at N = 1001 phase points (1000 frequency points).
TEST(Edf, SimpleApproximationsOfSp1065) {
  const double n = 1001.0;
  EXPECT_NEAR(edfOverlappingAllan(1001, 10, PowerLawNoise::kWhiteFrequency),
              (3.0 * (n - 1.0) / 20.0 - 2.0 * (n - 2.0) / n) * 400.0 / 405.0, 1e-9);
  EXPECT_NEAR(edfOverlappingAllan(1001, 10, PowerLawNoise::kWhitePhase), (n + 1.0) * (n - 20.0) / (2.0 * (n - 10.0)),
              1e-9);
  EXPECT_NEAR(edfOverlappingAllan(1001, 10, PowerLawNoise::kFlickerFrequency), 5.0 * n * n / (40.0 * (n + 30.0)), 1e-9);
  // White-rate EDF falls as 1/m: about 1.5 N / m for m >> 1.
  EXPECT_NEAR(edfOverlappingAllan(100001, 100, PowerLawNoise::kWhiteFrequency) / (1.5 * 100000.0 / 100.0), 1.0, 2e-3);
  // Never below one difference.
  EXPECT_GE(edfOverlappingAllan(1001, 499, PowerLawNoise::kRandomWalkFrequency), 1.0);
}

TEST(DeviationInterval, IsTheChiSquaredIntervalOfSp1065Eq45) {
  // EDF 10, 90 %: sigma * sqrt(10 / chi2(0.95)) .. sigma * sqrt(10 / chi2(0.05)).
  const Interval i = deviationInterval(1.0, 10.0, 0.90);
  EXPECT_NEAR(i.low, std::sqrt(10.0 / 18.307038053275146), 1e-6);
  EXPECT_NEAR(i.high, std::sqrt(10.0 / 3.940299136119255), 1e-6);
}

}  // namespace
}  // namespace fog::noise

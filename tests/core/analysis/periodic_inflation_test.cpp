// periodicResidualInflation: what errors that repeat every swing period add
// to a phase estimate's variance, and what must not count as repeating.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/analysis/validity.h"

namespace fog::analysis {
namespace {

constexpr int kSamplesPerPeriod = 91;  // an 11-Hz swing at 1 kHz frames
constexpr int kPeriods = 200;
constexpr double kWhiteVariance = 1.0;

// 2 sum_(k=1..20) (1 - k/P): every lag correlated 1.
double fullyRepeating(double periods) {
  double s = 0.0;
  for (int k = 1; k <= 20; ++k) s += 2.0 * (1.0 - k / periods);
  return s;
}

double varianceOf(const std::vector<double>& x) {
  double m = 0.0, v = 0.0;
  for (double a : x) m += a;
  m /= static_cast<double>(x.size());
  for (double a : x) v += (a - m) * (a - m);
  return v / static_cast<double>(x.size());
}

// A random walk whose steps have the white error's variance: the gyro's
// cumulative angle under angle random walk. Its residual is correlated near
// 1 one period apart (0.99 here); it repeats nothing.
TEST(PeriodicInflation, AnAngleRandomWalkIsNotAnErrorThatRepeats) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  std::vector<double> r(kSamplesPerPeriod * kPeriods);
  double walk = 0.0;
  for (auto& v : r) {
    walk += n01(rng);
    v = walk + std::sqrt(kWhiteVariance) * n01(rng);
  }
  const double infl = periodicResidualInflation(r, kSamplesPerPeriod + 0.34, kPeriods, kWhiteVariance,
                                                SampleStream::kGyro);
  // Each rho is 0 +- 0.02 (18 000 second differences of variance 8 against 6): the positive ones' sum is
  // 0.06-0.24 (three draws); the residual's own correlation one, two, ... periods apart gave 32.
  EXPECT_LT(infl, 1.0);
  EXPECT_GE(infl, 0.0);
}

// A table harmonic the 4-parameter fit leaves (here the 2nd, 3 sigma of the
// white error) repeats exactly, but it is a misfit orthogonal to the
// fundamental, not noise that does not average down.
TEST(PeriodicInflation, ASmoothHarmonicMisfitIsNotAnErrorThatRepeats) {
  std::mt19937_64 rng(8);
  std::normal_distribution<double> n01;
  constexpr int kTableSamplesPerPeriod = 45;  // 11 Hz at 500 Hz
  std::vector<double> r(kTableSamplesPerPeriod * kPeriods);
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = 3.0 * std::sin(2.0 * 2.0 * M_PI * static_cast<double>(i) / (kTableSamplesPerPeriod + 0.4)) + n01(rng);
  const double infl = periodicResidualInflation(r, kTableSamplesPerPeriod + 0.4, kPeriods, kWhiteVariance,
                                                SampleStream::kTable);
  // (2 w dt)^4 = 0.0061 of 9/2 against 6: rho 0.005 per lag, 0.1-0.4 in all (three draws); the residual's
  // own correlation gave 31.
  EXPECT_LT(infl, 1.0);
}

// Stamps commensurate with the swing: the same white error every period, on
// top of a random walk. Every lag is correlated 1 and the variance grows by
// 2 sum (1 - k/P).
TEST(PeriodicInflation, AWhiteErrorThatRepeatsEveryPeriodCountsInFull) {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> n01;
  constexpr int kWhole = 500, kRepeats = 40;
  std::vector<double> once(kWhole);
  for (auto& v : once) v = n01(rng);
  std::vector<double> r(kWhole * kRepeats);
  double walk = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    walk += 0.5 * n01(rng);
    r[i] = walk + once[i % kWhole];
  }
  // The white error's variance as the bench's noise estimate states it: this record's.
  const double infl = periodicResidualInflation(r, kWhole, kRepeats, varianceOf(once), SampleStream::kGyro);
  EXPECT_NEAR(infl, fullyRepeating(kRepeats), 0.1 * fullyRepeating(kRepeats));
}

TEST(PeriodicInflation, NothingToJudgeIsNoInflation) {
  const std::vector<double> r(1000, 1.0);
  EXPECT_EQ(periodicResidualInflation(r, 50.0, 20.0, 0.0, SampleStream::kTable), 0.0);  // no white error stated
  EXPECT_EQ(periodicResidualInflation(r, 50.0, 1.5, 1.0, SampleStream::kTable), 0.0);  // under two periods
  EXPECT_EQ(periodicResidualInflation(std::vector<double>(10, 0.0), 2.0, 5.0, 1.0, SampleStream::kTable), 0.0);
}

}  // namespace
}  // namespace fog::analysis

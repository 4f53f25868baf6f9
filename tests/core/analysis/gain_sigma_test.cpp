// The gain's and the phase's stated sigma at a test point whose stamps are
// commensurate with the swing (issue 40): 20 Hz at 1 kHz table stamps, 50
// samples a period, where encoder quantisation repeats every period. Monte
// Carlo over swing phases and amplitudes on data made directly
// (synthetic.h), with a coarse encoder quantum (1e-4 deg: 570 quanta of
// swing) and a fine one (1e-8 deg): std(z) of the gain and of the phase
// within the band below, the gain's before the allowance for errors that
// repeat (the joint fit's alone) well outside it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/common/units.h"
#include "synthetic.h"

namespace fog::analysis {
namespace {

using testing::makeSynthetic;
using testing::SyntheticSpec;

struct Zs {
  std::vector<double> gain, gainFitOnly, phase;
};

double rms(const std::vector<double>& z) {
  double s = 0.0;
  for (double v : z) s += v * v;
  return std::sqrt(s / static_cast<double>(z.size()));
}

Zs monteCarlo(double quantumDeg, int trials) {
  std::mt19937_64 rng(2040);
  std::uniform_real_distribution<double> u01;
  Zs z;
  for (int i = 0; i < trials; ++i) {
    SyntheticSpec s;
    s.frequencyHz = 20.0;
    s.amplitudeDeg = 0.057 * (1.0 + 0.02 * u01(rng));
    s.durationS = 10.0;
    s.phaseRad = kTwoPi * u01(rng);
    s.tableQuantumDeg = quantumDeg;
    s.pulseEquivalentDeg = 5e-5;       // 0.18"
    s.arwDegPerSqrtS = 0.005 / 60.0;   // 0.005 deg/sqrt(h)
    s.seed = 500u + static_cast<unsigned>(i);
    auto r = analyzeTestPoint(makeSynthetic(s), BenchConstants{});
    EXPECT_TRUE(r.isOk()) << r.status().message();
    if (!r.isOk()) continue;
    z.gain.push_back((r->magnitudeRatio - s.gain) / r->gainStd);
    z.gainFitOnly.push_back((r->magnitudeRatio - s.gain) / r->joint.gainStd);
    // phase = -omega lag: its z is the lag's.
    z.phase.push_back((r->lagMs - s.lagS * 1e3) / r->lagStdMs);
    // The response point carries the same sigma and the covariance with the lag.
    DelayReport report;
    report.points.push_back(*r);
    const auto points = responsePoints(report, r->axis);
    if (points.size() == 1) {
      EXPECT_DOUBLE_EQ(points[0].magnitudeStd, r->gainStd);
      const double w = kTwoPi * points[0].frequencyHz;
      EXPECT_NEAR(points[0].magnitudePhaseCovDeg, -w * 1e-3 * kDegPerRad * r->gainLagCovMs,
                  1e-12 * std::abs(points[0].magnitudeStd * points[0].phaseStdDeg));
      EXPECT_LE(std::abs(points[0].magnitudePhaseCovDeg), points[0].magnitudeStd * points[0].phaseStdDeg * (1 + 1e-12));
    }
  }
  return z;
}

// The band for 40 trials: std(z) is known to about 0.11 (1 sigma) there.
constexpr int kTrials = 40;
constexpr double kLow = 0.7, kHigh = 1.3;

TEST(GainSigma, CoarseEncoderAtACommensuratePoint) {
  const Zs z = monteCarlo(1e-4, kTrials);
  std::printf("  1e-4 deg encoder: std(z) gain %.2f (joint fit's sigma alone %.2f), phase %.2f over %zu trials\n",
              rms(z.gain), rms(z.gainFitOnly), rms(z.phase), z.gain.size());
  EXPECT_GE(rms(z.gain), kLow);
  EXPECT_LE(rms(z.gain), kHigh);
  EXPECT_GE(rms(z.phase), kLow);
  EXPECT_LE(rms(z.phase), kHigh);
  EXPECT_GT(rms(z.gainFitOnly), 3.0);  // what the allowance is for
}

TEST(GainSigma, FineEncoderAtACommensuratePoint) {
  const Zs z = monteCarlo(1e-8, kTrials);
  std::printf("  1e-8 deg encoder: std(z) gain %.2f (joint fit's sigma alone %.2f), phase %.2f over %zu trials\n",
              rms(z.gain), rms(z.gainFitOnly), rms(z.phase), z.gain.size());
  EXPECT_GE(rms(z.gain), kLow);
  EXPECT_LE(rms(z.gain), kHigh);
  EXPECT_GE(rms(z.phase), kLow);
  EXPECT_LE(rms(z.phase), kHigh);
}

}  // namespace
}  // namespace fog::analysis

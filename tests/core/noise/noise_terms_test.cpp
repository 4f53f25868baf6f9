// Noise-term identification on gyros with known noise.

#include "core/noise/noise_terms.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "synthetic_gyro.h"

namespace fog::noise {
namespace {

// The simulator's default ARW (0.004 deg/sqrt(h)), a Gauss-Markov bias wander
// fast enough to show its whole hump in 20 minutes (5 deg/h, 10 s), and
// white angle noise equal to the quantisation of a 0.18" pulse (Q = p/sqrt 12).
testing::SyntheticGyro knownGyro() {
  testing::SyntheticGyro g;
  g.biasDegPerS = 1.0 / 3600.0;
  g.arwDegPerSqrtS = 0.004 / 60.0;
  g.markovSigmaDegPerS = 5.0 / 3600.0;
  g.markovCorrelationS = 10.0;
  g.whiteAngleDeg = 5e-5 / std::sqrt(12.0);
  return g;
}
constexpr std::size_t kFrames = 600000;  // 20 min at 500 Hz

struct Identified {
  AllanCurve curve;
  NoiseModel model;
};

// pulseDeg > 0: the increments are whole pulses and the fit is told so.
Identified identify(const std::vector<double>& increments, double intervalS, double pulseDeg = 0.0) {
  double mean = 0.0;
  for (double v : increments) mean += v;
  mean /= static_cast<double>(increments.size());
  const auto phase = cumulativeSum(increments, mean);
  auto curve = overlappingAllanCurve(phase, intervalS);
  EXPECT_TRUE(curve.isOk());
  if (pulseDeg > 0.0) curve->pulse = {pulseDeg, mean};
  auto model = identifyNoise(*curve);
  EXPECT_TRUE(model.isOk()) << model.status().message();
  return {*curve, *model};
}

double trueAllanVariance(const testing::SyntheticGyro& g, double tau) {
  return g.whiteAngleDeg * g.whiteAngleDeg * unitAllanVariance(NoiseTermKind::kQuantisation, tau) +
         g.arwDegPerSqrtS * g.arwDegPerSqrtS * unitAllanVariance(NoiseTermKind::kAngleRandomWalk, tau) +
         g.markovSigmaDegPerS * g.markovSigmaDegPerS *
             unitAllanVariance(NoiseTermKind::kMarkov, tau, g.markovCorrelationS);
}

TEST(NoiseTerms, RecoverAKnownGyroWithinTwiceTheStatedUncertainty) {
  const auto g = knownGyro();
  const auto r = identify(g.increments(kFrames, 1), g.intervalS);
  const NoiseTerm* q = r.model.find(NoiseTermKind::kQuantisation);
  const NoiseTerm* n = r.model.find(NoiseTermKind::kAngleRandomWalk);
  const NoiseTerm* m = r.model.find(NoiseTermKind::kMarkov);
  ASSERT_NE(q, nullptr);
  ASSERT_NE(n, nullptr);
  ASSERT_NE(m, nullptr);
  // Fixed seed; each truth inside value +- 2 stated standard errors (~95 %).
  EXPECT_NEAR(q->value, g.whiteAngleDeg, 2.0 * q->stdError);
  EXPECT_NEAR(n->value, g.arwDegPerSqrtS, 2.0 * n->stdError);
  EXPECT_NEAR(m->value, g.markovSigmaDegPerS, 2.0 * m->stdError);
  EXPECT_GT(m->correlationTimeHighS, m->correlationTimeLowS);
  EXPECT_NEAR(std::log(m->correlationTimeS / g.markovCorrelationS), 0.0,
              2.0 * std::log(m->correlationTimeHighS / m->correlationTimeS));
  // The terms sit where they should: Q at the shortest taus, the Markov hump
  // at the longest.
  EXPECT_EQ(q->tauLowS, r.curve.points.front().tauS);
  EXPECT_EQ(m->tauHighS, r.curve.points.back().tauS);
  EXPECT_LT(q->tauHighS, n->tauHighS);
}

TEST(NoiseTerms, WhiteRateAloneGivesOnlyAngleRandomWalk) {
  testing::SyntheticGyro g;
  g.arwDegPerSqrtS = 0.01 / 60.0;
  const auto r = identify(g.increments(200000, 7), g.intervalS);
  ASSERT_EQ(r.model.terms.size(), 1u);
  EXPECT_EQ(r.model.terms[0].kind, NoiseTermKind::kAngleRandomWalk);
  EXPECT_NEAR(r.model.terms[0].value, g.arwDegPerSqrtS, 2.0 * r.model.terms[0].stdError);
  EXPECT_LT(r.model.terms[0].stdError / r.model.terms[0].value, 0.01);  // 400 s of 500 Hz data
}

struct MonteCarlo {
  double ratio[3] = {};  // mean stated uncertainty / scatter: Q, N, Markov sigma
  // The same over the seeds whose model has exactly the true terms (Q, N,
  // Markov), and how many seeds took an extra term.
  double ratioTrueTerms[3] = {};
  int seedsWithExtraTerms = 0;
  double coverage = 0.0;
  double worstChi2PerDof = 0.0;
};

// Estimates over seeds: their mean, their scatter (sample standard
// deviation) and the mean of their stated uncertainties.
struct Spread {
  double mean = 0.0, scatter = 0.0, meanStated = 0.0;
  double ratio() const { return scatter > 0.0 ? meanStated / scatter : 0.0; }  // 0 for < 2 values
};
Spread spreadOf(const std::vector<double>& values, const std::vector<double>& stated) {
  Spread s;
  if (values.size() < 2) return s;
  const double n = static_cast<double>(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    s.mean += values[i] / n;
    s.meanStated += stated[i] / n;
  }
  double ss = 0.0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  s.scatter = std::sqrt(ss / (n - 1.0));
  return s;
}

// Over `seeds` seeds: the stated uncertainties against the scatter of the
// estimates (each mean unbiased within 3 standard errors of the mean), the
// coverage of the Allan-deviation intervals of the true curve, the worst
// chi^2/dof.
MonteCarlo monteCarlo(const testing::SyntheticGyro& g, int seeds, double pulseDeg) {
  const NoiseTermKind kinds[] = {NoiseTermKind::kQuantisation, NoiseTermKind::kAngleRandomWalk, NoiseTermKind::kMarkov};
  const double q = pulseDeg > 0.0 ? pulseDeg / std::sqrt(12.0) : g.whiteAngleDeg;
  const double truth[] = {q, g.arwDegPerSqrtS, g.markovSigmaDegPerS};
  std::vector<double> values[3], stated[3], trueValues[3], trueStated[3];
  std::size_t covered = 0, intervals = 0;
  MonteCarlo mc;
  for (int seed = 100; seed < 100 + seeds; ++seed) {
    const auto r = identify(g.increments(kFrames, static_cast<std::uint64_t>(seed)), g.intervalS, pulseDeg);
    mc.worstChi2PerDof = std::max(mc.worstChi2PerDof, r.model.chiSquare / std::max(1, r.model.dof));
    const bool trueTerms = r.model.terms.size() == 3;
    mc.seedsWithExtraTerms += trueTerms ? 0 : 1;
    for (int k = 0; k < 3; ++k) {
      const NoiseTerm* t = r.model.find(kinds[k]);
      EXPECT_NE(t, nullptr) << "seed " << seed << " lost " << noiseTermName(kinds[k]);
      if (!t) return mc;
      values[k].push_back(t->value);
      stated[k].push_back(t->stdError);
      if (trueTerms) {
        trueValues[k].push_back(t->value);
        trueStated[k].push_back(t->stdError);
      }
    }
    for (const auto& p : r.curve.points) {
      if (pulseDeg > 0.0) continue;  // the true curve of a pulse-quantised gyro depends on its noise: not tabulated
      const double dev = std::sqrt(trueAllanVariance(g, p.tauS));
      covered += p.interval.low <= dev && dev <= p.interval.high;
      ++intervals;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const Spread all = spreadOf(values[k], stated[k]);
    EXPECT_NEAR(all.mean, truth[k], 3.0 * all.scatter / std::sqrt(seeds)) << noiseTermName(kinds[k]);
    mc.ratio[k] = all.ratio();
    std::printf("%s: mean %.6g (truth %.6g), scatter %.4g, stated %.4g, stated/scatter %.3f\n", noiseTermName(kinds[k]),
                all.mean, truth[k], all.scatter, all.meanStated, mc.ratio[k]);
    mc.ratioTrueTerms[k] = spreadOf(trueValues[k], trueStated[k]).ratio();
  }
  std::printf("%d of %d seeds took an extra term; stated/scatter of the others: %.3f (Q), %.3f (N), %.3f (Markov)\n",
              mc.seedsWithExtraTerms, seeds, mc.ratioTrueTerms[0], mc.ratioTrueTerms[1], mc.ratioTrueTerms[2]);
  mc.coverage = intervals ? static_cast<double>(covered) / static_cast<double>(intervals) : 0.0;
  return mc;
}

// 50 seeds of white angle noise (IEEE 952 Q). The jackknife uncertainties
// against the true scatter: measured ratios in docs/noise.md; a factor-2 band
// is asserted. With 50 seeds the scatter itself is known to +-10 %. Over the
// seeds whose model has the true terms the stated uncertainties are the
// scatter's (Q 0.97, N 0.97, Markov sigma 0.89 measured; 0.85 over 250
// seeds; asserted 0.8 .. 1.25); the
// shortfall over all seeds is model selection: a seed that takes a flicker
// or ramp term of its own (5 of 50) moves N by up to 3 % (6 times a typical
// stated error), which no uncertainty of a fixed set of terms can state.
TEST(NoiseTerms, StatedUncertaintyAgreesWithMonteCarloScatter) {
  const auto mc = monteCarlo(knownGyro(), 50, 0.0);
  const char* keys[] = {"quantisation", "angle_random_walk", "markov"};
  for (int k = 0; k < 3; ++k) {
    RecordProperty(std::string(keys[k]) + "_stated_over_scatter", std::to_string(mc.ratio[k]));
    RecordProperty(std::string(keys[k]) + "_stated_over_scatter_true_terms", std::to_string(mc.ratioTrueTerms[k]));
    EXPECT_GT(mc.ratio[k], 0.5) << keys[k];
    EXPECT_LT(mc.ratio[k], 2.0) << keys[k];
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(mc.ratioTrueTerms[k], 0.8) << keys[k];
    EXPECT_LT(mc.ratioTrueTerms[k], 1.25) << keys[k];
  }
  EXPECT_LE(mc.seedsWithExtraTerms, 8);
  // 1-sigma (68.3 %) intervals: pooled coverage over ~1600 intervals (binomial
  // std 1.2 %); neighbouring taus are correlated, so a +-10 % band.
  RecordProperty("interval_coverage", std::to_string(mc.coverage));
  EXPECT_GT(mc.coverage, 0.583);
  EXPECT_LT(mc.coverage, 0.783);
}

// A gyro at rest whose output is pulse counts (0.18" pulse, 11.7 deg/h of
// bias + Earth rate, as the X gyro of `run --preset noise`), so the angle
// crosses a pulse only every ~8 frames and the quantisation error is a
// dithered sawtooth, not white. Told the pulse, the fit recovers Q = pulse /
// sqrt 12, N and the Markov sigma without bias over 50 seeds (checked in
// monteCarlo). Here the 5 deg/h / 10 s wander swings the pulse rate by +-40 %,
// so the short-tau Allan points vary with the wander far more than the
// white-phase EDF (~1e5) says: chi^2/dof is 2-14 (the white model: hundreds);
// the bench's own 0.5 deg/h wander fits with chi^2/dof < 1 (gyro_noise_test).
// The wander also moves each jackknife block's mean pulse rate, and the
// quantisation shape depends steeply on it: each replicate is fitted at its
// own mean step (AllanCurve::jackknifeStepChange). Fitted at the record's
// instead, the stated Q and N were 7.6 and 4.3 times the scatter; now 1.24,
// 0.96 and 0.89 (Markov), asserted within a factor 2.
TEST(NoiseTerms, PulseQuantisedGyroAtRestFitsAndRecoversItsTerms) {
  auto g = knownGyro();
  g.whiteAngleDeg = 0.0;
  g.pulseDeg = 5e-5;
  g.biasDegPerS = 11.7 / 3600.0;
  const auto mc = monteCarlo(g, 50, g.pulseDeg);
  RecordProperty("worst_chi2_per_dof", std::to_string(mc.worstChi2PerDof));
  EXPECT_LT(mc.worstChi2PerDof, 20.0);
  const char* keys[] = {"quantisation", "angle_random_walk", "markov"};
  for (int k = 0; k < 3; ++k) {
    RecordProperty(std::string(keys[k]) + "_stated_over_scatter", std::to_string(mc.ratio[k]));
    EXPECT_GT(mc.ratio[k], 0.5) << keys[k];
    EXPECT_LT(mc.ratio[k], 2.0) << keys[k];
  }
  // Told nothing of the pulse, the same data do not fit (white quantisation).
  const auto white = identify(g.increments(kFrames, 100), g.intervalS);
  std::printf("white quantisation model: chi^2 %.1f for %d dof\n", white.model.chiSquare, white.model.dof);
  EXPECT_GT(white.model.chiSquare / white.model.dof, 5.0 * mc.worstChi2PerDof);
}

// The jackknife replicates of each Allan variance against the Monte Carlo
// scatter of that variance, for a white rate (angle random walk) over 400
// seeds, wherever a block holds a whole second difference (2 tau up to the
// block length). Measured: 0.80-1.07 of the scatter (lowest at 2 tau = one
// block). Leaving out only the differences that start in a block, as a
// jackknife of independent blocks would, keeps those overlapping it: 0.70
// and 0.77 at 2 tau = 1 and 0.7 blocks, and worse beyond (docs/noise.md).
// The Monte Carlo variance itself is known to +-7 % (400 seeds).
TEST(NoiseTerms, JackknifeReplicatesSeeTheScatterOfEachAllanVariance) {
  testing::SyntheticGyro g;
  g.arwDegPerSqrtS = 0.004 / 60.0;
  constexpr std::size_t kSamples = 16384;
  constexpr int kSeeds = 400;
  const AllanOptions options;  // 16 blocks
  std::vector<std::vector<double>> logs;     // per tau: ln(avar) of each seed
  std::vector<double> replicateSpread;       // per tau: sum of the jackknife variances of ln(avar)
  AllanCurve first;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const auto phase = cumulativeSum(g.increments(kSamples, static_cast<std::uint64_t>(seed)));
    auto curve = overlappingAllanCurve(phase, g.intervalS, options);
    ASSERT_TRUE(curve.isOk());
    if (seed == 1) {
      first = *curve;
      logs.resize(first.points.size());
      replicateSpread.assign(first.points.size(), 0.0);
    }
    for (std::size_t i = 0; i < curve->points.size(); ++i) {
      const auto& p = curve->points[i];
      const double full = std::log(p.deviation * p.deviation);
      logs[i].push_back(full);
      double squares = 0.0;
      for (double v : p.jackknifeVariance) squares += (std::log(v) - full) * (std::log(v) - full);
      replicateSpread[i] += squares * (options.jackknifeBlocks - 1.0) / options.jackknifeBlocks / kSeeds;
    }
  }
  const double blockLength = static_cast<double>(kSamples) / options.jackknifeBlocks;
  int checked = 0;
  for (std::size_t i = 0; i < first.points.size(); ++i) {
    const auto& p = first.points[i];
    if (p.jackknifeVariance.empty() || 2.0 * static_cast<double>(p.m) > blockLength) continue;
    double mean = 0.0, scatter = 0.0;
    for (double v : logs[i]) mean += v / kSeeds;
    for (double v : logs[i]) scatter += (v - mean) * (v - mean) / (kSeeds - 1);
    const double ratio = replicateSpread[i] / scatter;
    std::printf("m %5zu  2 tau / block %.3f  replicate spread / scatter %.3f\n", p.m,
                2.0 * static_cast<double>(p.m) / blockLength, ratio);
    EXPECT_GT(ratio, 0.75) << "m " << p.m;
    EXPECT_LT(ratio, 1.25) << "m " << p.m;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST(NoiseTerms, RefusesTooShortACurve) {
  AllanCurve curve;
  curve.points.resize(2);
  EXPECT_EQ(identifyNoise(curve).status().code(), StatusCode::kInsufficientData);
  const std::vector<double> phase(5, 0.0);
  EXPECT_EQ(overlappingAllanCurve(phase, 1.0).status().code(), StatusCode::kInsufficientData);
}

TEST(NoiseTerms, UnitVariancesHaveTheIeee952Shapes) {
  EXPECT_DOUBLE_EQ(unitAllanVariance(NoiseTermKind::kQuantisation, 2.0), 0.75);
  EXPECT_DOUBLE_EQ(unitAllanVariance(NoiseTermKind::kAngleRandomWalk, 4.0), 0.25);
  EXPECT_NEAR(std::sqrt(unitAllanVariance(NoiseTermKind::kBiasInstability, 9.0)), 0.6643, 1e-4);
  EXPECT_DOUBLE_EQ(unitAllanVariance(NoiseTermKind::kRateRandomWalk, 3.0), 1.0);
  EXPECT_DOUBLE_EQ(unitAllanVariance(NoiseTermKind::kRateRamp, 2.0), 2.0);
  // Markov: white rate 2 sigma^2 Tc / tau far above Tc, rate random walk
  // 2 sigma^2 tau / (3 Tc) far below; continuous across the series switch.
  EXPECT_NEAR(unitAllanVariance(NoiseTermKind::kMarkov, 1e4, 1.0) * 1e4 / 2.0, 1.0, 2e-4);
  EXPECT_NEAR(unitAllanVariance(NoiseTermKind::kMarkov, 1e-5, 1.0) / (2e-5 / 3.0), 1.0, 1e-4);
  EXPECT_NEAR(unitAllanVariance(NoiseTermKind::kMarkov, 0.999e-3, 1.0) / unitAllanVariance(NoiseTermKind::kMarkov, 1.001e-3, 1.0),
              0.998, 1e-5);
}

// A fit cut off before it settles is an error with its code, not a model:
// one Levenberg-Marquardt step cannot reach the minimum from the linear start.
TEST(NoiseTerms, AFitStoppedBeforeItConvergesIsReportedAsNotConverged) {
  const auto g = knownGyro();
  const auto increments = g.increments(kFrames / 10, 3);
  double mean = 0.0;
  for (double v : increments) mean += v;
  mean /= static_cast<double>(increments.size());
  auto curve = overlappingAllanCurve(cumulativeSum(increments, mean), g.intervalS);
  ASSERT_TRUE(curve.isOk());
  IdentifyOptions cutShort;
  cutShort.maxIterations = 1;
  const auto stopped = identifyNoise(*curve, cutShort);
  ASSERT_FALSE(stopped.isOk());
  EXPECT_EQ(stopped.status().code(), StatusCode::kNotConverged);
  EXPECT_NE(stopped.status().message().find("record longer"), std::string::npos);
  EXPECT_TRUE(identifyNoise(*curve).isOk());  // the same curve with the default budget
}

}  // namespace
}  // namespace fog::noise

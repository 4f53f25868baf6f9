// The stated σ against the Cramér–Rao bound (check uncertainty_below_bound).

#include <gtest/gtest.h>

#include "core/analysis/uncertainty_bound.h"

namespace fog::analysis {
namespace {

TestPointResult pointWith(double stdMs, double crlbMs, const char* source, std::size_t periods) {
  TestPointResult p;
  p.lagStdMs = stdMs;
  p.crlbMs = crlbMs;
  p.lagStdSource = source;
  p.periodTrack.resize(periods);
  p.tableSamples = 60000;
  p.imuSamples = 30000;
  return p;
}

TEST(UncertaintyBelowBound, TheAllowanceFollowsTheDegreesOfFreedomOfSigma) {
  // The chi2 0.1 % quantiles by Wilson-Hilferty, nu (1 - 2/(9 nu) - 3.0902 sqrt(2/(9 nu)))^3:
  // 10^5 dof: sqrt(q / nu) = 0.9931, so 0.4 of the bound nearly.
  EXPECT_NEAR(smallestStdOverBound(100000), 0.4 * 0.9931, 0.001);
  // 29 periods: q = 10.91, sqrt(10.91 / 29) = 0.613.
  EXPECT_NEAR(smallestStdOverBound(29), 0.4 * 0.6133, 0.002);
  // 2 periods cannot vouch for anything: a scatter of 3 periods reads low by chance.
  EXPECT_LT(smallestStdOverBound(2), 0.02);
}

// The point: a per-period scatter 6x below the bound, shown beside
// "σ/CRLB 1.26" (the fit's ratio). It fails, and says by how much.
TEST(UncertaintyBelowBound, ASigmaSixTimesBelowTheBoundFails) {
  auto p = pointWith(0.0003, 0.0018, "per-period scatter", 30);
  const auto c = uncertaintyBelowBoundCheck(p);
  EXPECT_TRUE(c.judged);
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.detail.find("is 0.17 of the Cramér–Rao bound 0.0018 ms (per-period scatter, 29 degrees of freedom; "
                          "at least 0.25 expected)"),
            std::string::npos)
      << c.detail;
  EXPECT_EQ(c.id, "uncertainty_below_bound");
}

// Errors that cancel between periods lowered σ below the bound: the bound's
// white noise model cannot see them, so the σ before is judged, and both
// are said. A σ already below the bound before them still fails.
TEST(UncertaintyBelowBound, ErrorsThatCancelBetweenPeriodsAreJudgedBeforeThem) {
  auto p = pointWith(0.3e-3, 1e-3, "fit, less the errors that cancel between periods", 200);
  p.lagStdBeforeCancellingMs = 0.9e-3;
  const auto c = uncertaintyBelowBoundCheck(p);
  EXPECT_TRUE(c.passed) << c.detail;
  EXPECT_NE(c.detail.find("σ 0.0003 ms is 0.30 of the Cramér–Rao bound 0.001 ms; before the errors that cancel "
                          "between periods, which the bound's white noise does not see, 0.0009 ms, 0.90 of it (fit, "
                          "less the errors that cancel between periods, 89992 degrees of freedom"),
            std::string::npos)
      << c.detail;
  p.lagStdBeforeCancellingMs = 0.33e-3;
  EXPECT_FALSE(uncertaintyBelowBoundCheck(p).passed);
}

TEST(UncertaintyBelowBound, WhatTheIndependentMonteCarloSawPasses) {
  // The lowest σ/CRLB of 197 independent sessions with right z-scores: 0.54.
  EXPECT_TRUE(uncertaintyBelowBoundCheck(pointWith(0.54e-3, 1e-3, "fit", 14)).passed);
  EXPECT_TRUE(uncertaintyBelowBoundCheck(pointWith(1.3e-3, 1e-3, "fit", 14)).passed);
  // A fit σ a third of the bound does not.
  EXPECT_FALSE(uncertaintyBelowBoundCheck(pointWith(0.33e-3, 1e-3, "fit", 14)).passed);
}

TEST(UncertaintyBelowBound, AnUnknownBoundIsNotJudged) {
  const auto c = uncertaintyBelowBoundCheck(pointWith(0.001, 0.0, "fit", 10));
  EXPECT_FALSE(c.judged);
}

}  // namespace
}  // namespace fog::analysis

#pragma once
// Small statistics helpers the analysis needs.

#include <vector>

namespace fog::analysis {

// Probability that a chi-square variable with dof degrees of freedom exceeds x.
double chiSquareSurvival(double x, int dof);

// Regularised incomplete gamma functions P(a, x) and Q(a, x) = 1 - P(a, x),
// a > 0 (not only half-integers): each from its series below a + 1 and
// Lentz's continued fraction above, so that the small one of the two keeps
// its relative precision. x <= 0 gives P = 0, Q = 1.
double regularisedGammaP(double a, double x);
double regularisedGammaQ(double a, double x);

struct MeanAndSpread {
  double mean = 0.0;
  double stdDev = 0.0;      // sample standard deviation (n - 1)
  double stdOfMean = 0.0;   // stdDev / sqrt(n)
  std::size_t count = 0;
};
MeanAndSpread meanAndSpread(const std::vector<double>& values);

}  // namespace fog::analysis

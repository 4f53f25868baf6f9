#pragma once
// Small statistics helpers the analysis needs.

#include <vector>

namespace fog::analysis {

// Probability that a chi-square variable with dof degrees of freedom exceeds x.
double chiSquareSurvival(double x, int dof);

// Probability that |T| >= |t| for Student's t with dof degrees of freedom
// (two-sided), from the regularised incomplete beta function.
double studentTwoSidedP(double t, int dof);
// Regularised incomplete beta I_x(a, b), a, b > 0, x in [0, 1] (Lentz's
// continued fraction on the side where it converges fast).
double regularisedBeta(double x, double a, double b);

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

// The element std::nth_element puts at position size/2 (0 for an empty
// vector): the median of sample intervals. Stamps on a counter give a few
// distinct intervals, which are counted in one pass instead of partially
// sorting hundreds of thousands of them; any other series (more than 16
// distinct values, NaN) falls back to nth_element, so the result is the
// same element either way. May reorder v.
double medianElement(std::vector<double>& v);

}  // namespace fog::analysis

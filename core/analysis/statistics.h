#pragma once
// Small statistics helpers the analysis needs.

#include <vector>

namespace fog::analysis {

// Probability that a chi-square variable with dof degrees of freedom exceeds x.
double chiSquareSurvival(double x, int dof);

struct MeanAndSpread {
  double mean = 0.0;
  double stdDev = 0.0;      // sample standard deviation (n - 1)
  double stdOfMean = 0.0;   // stdDev / sqrt(n)
  std::size_t count = 0;
};
MeanAndSpread meanAndSpread(const std::vector<double>& values);

}  // namespace fog::analysis

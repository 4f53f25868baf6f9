#include "analysis/statistics.h"

#include <cmath>

namespace fog::analysis {

namespace {
// Regularised lower incomplete gamma P(s, x) by its series (x < s + 1).
double gammaSeries(double s, double x) {
  double term = 1.0 / s, sum = term;
  for (int n = 1; n < 1000; ++n) {
    term *= x / (s + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + s * std::log(x) - std::lgamma(s));
}
// Regularised upper incomplete gamma Q(s, x) by Lentz's continued fraction (x >= s + 1).
double gammaContinuedFraction(double s, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - s, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - s);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + s * std::log(x) - std::lgamma(s)) * h;
}
}  // namespace

double chiSquareSurvival(double x, int dof) {
  if (dof <= 0) return 1.0;
  if (x <= 0.0) return 1.0;
  const double s = 0.5 * dof, h = 0.5 * x;
  return h < s + 1.0 ? 1.0 - gammaSeries(s, h) : gammaContinuedFraction(s, h);
}

MeanAndSpread meanAndSpread(const std::vector<double>& v) {
  MeanAndSpread m;
  m.count = v.size();
  if (v.empty()) return m;
  for (double x : v) m.mean += x;
  m.mean /= static_cast<double>(v.size());
  if (v.size() < 2) return m;
  double ss = 0.0;
  for (double x : v) ss += (x - m.mean) * (x - m.mean);
  m.stdDev = std::sqrt(ss / static_cast<double>(v.size() - 1));
  m.stdOfMean = m.stdDev / std::sqrt(static_cast<double>(v.size()));
  return m;
}

}  // namespace fog::analysis

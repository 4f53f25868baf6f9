#include "core/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace fog::analysis {

namespace {
// Regularised lower incomplete gamma P(a, x) by its series (x < a + 1). The
// iteration limit allows the large, non-integer degrees of freedom of Allan
// deviations at short averaging times (the series needs ~sqrt(a) terms).
double gammaSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-16) break;
  }
  return std::min(1.0, sum * std::exp(a * std::log(x) - x - std::lgamma(a)));
}
// Regularised upper incomplete gamma Q(a, x) by Lentz's continued fraction
// (x >= a + 1).
double gammaContinuedFraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::min(1.0, std::exp(a * std::log(x) - x - std::lgamma(a)) * h);
}
}  // namespace

double regularisedGammaP(double a, double x) {
  if (x <= 0.0) return 0.0;
  return x < a + 1.0 ? gammaSeries(a, x) : std::max(0.0, 1.0 - gammaContinuedFraction(a, x));
}

double regularisedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  return x < a + 1.0 ? std::max(0.0, 1.0 - gammaSeries(a, x)) : gammaContinuedFraction(a, x);
}

double chiSquareSurvival(double x, int dof) {
  if (dof <= 0) return 1.0;
  return regularisedGammaQ(0.5 * dof, 0.5 * x);
}

namespace {
// Continued fraction of I_x(a, b) (modified Lentz), valid for x < (a+1)/(a+b+2).
double betaFraction(double x, double a, double b) {
  constexpr double kTiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    d = std::abs(d) < kTiny ? 1.0 / kTiny : 1.0 / d;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    d = std::abs(d) < kTiny ? 1.0 / kTiny : 1.0 / d;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return h;
}
}  // namespace

double regularisedBeta(double x, double a, double b) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double lnFront = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(lnFront) * betaFraction(x, a, b) / a;
  return 1.0 - std::exp(lnFront) * betaFraction(1.0 - x, b, a) / b;
}

double studentTwoSidedP(double t, int dof) {
  if (dof <= 0 || !std::isfinite(t)) return std::isfinite(t) ? 1.0 : 0.0;
  const double v = dof;
  return regularisedBeta(v / (v + t * t), 0.5 * v, 0.5);
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

double medianElement(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const std::size_t middle = v.size() / 2;
  // Distinct values and how often each occurs, compared bit for bit (a NaN
  // is never equal to itself, so it overflows the table and goes the
  // general way). Stamps alternate among a few intervals: the value last
  // seen is tried first.
  constexpr std::size_t kDistinct = 16;
  double value[kDistinct];
  std::uint64_t bits[kDistinct];
  std::size_t count[kDistinct] = {};
  std::size_t distinct = 0, last = 0;
  bool few = true;
  for (double x : v) {
    if (x != x) {
      few = false;
      break;
    }
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    if (distinct == 0 || bits[last] != b) {
      std::size_t j = 0;
      while (j < distinct && bits[j] != b) ++j;
      if (j == distinct) {
        if (distinct == kDistinct) {
          few = false;
          break;
        }
        value[distinct] = x;
        bits[distinct++] = b;
      }
      last = j;
    }
    ++count[last];
  }
  if (few) {
    std::size_t order[kDistinct];
    for (std::size_t j = 0; j < distinct; ++j) order[j] = j;
    // -0 before +0, as a strict weak order on the distinct values.
    std::sort(order, order + distinct, [&](std::size_t a, std::size_t b) {
      return value[a] < value[b] || (value[a] == value[b] && std::signbit(value[a]) && !std::signbit(value[b]));
    });
    std::size_t seen = 0;
    for (std::size_t j = 0; j < distinct; ++j) {
      seen += count[order[j]];
      if (seen > middle) return value[order[j]];
    }
  }
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(middle), v.end());
  return v[middle];
}

}  // namespace fog::analysis

#include "core/noise/allan.h"

#include "core/analysis/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fog::noise {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double wilsonHilferty(double p, double dof) {
  const double z = normalQuantile(p);
  const double k = 2.0 / (9.0 * dof);
  const double c = 1.0 - k + z * std::sqrt(k);
  return dof * std::max(c, 0.0) * c * c;
}
}  // namespace

const char* powerLawNoiseName(PowerLawNoise noise) {
  switch (noise) {
    case PowerLawNoise::kWhitePhase: return "white angle";
    case PowerLawNoise::kFlickerPhase: return "flicker angle";
    case PowerLawNoise::kWhiteFrequency: return "white rate";
    case PowerLawNoise::kFlickerFrequency: return "flicker rate";
    case PowerLawNoise::kRandomWalkFrequency: return "random-walk rate";
  }
  return "?";
}

std::vector<double> cumulativeSum(std::span<const double> increments, double subtractPerStep) {
  std::vector<double> x(increments.size() + 1);
  double sum = 0.0;
  x[0] = 0.0;
  for (std::size_t k = 0; k < increments.size(); ++k) {
    sum += increments[k] - subtractPerStep;
    x[k + 1] = sum;
  }
  return x;
}

double allanVariance(std::span<const double> phase, double tau0S, std::size_t m, bool overlapping,
                     std::size_t* differences) {
  const std::size_t n = phase.size();
  if (differences) *differences = 0;
  if (m < 1 || 2 * m >= n || !(tau0S > 0.0)) return kNaN;
  const double* x = phase.data();
  const std::size_t last = n - 2 * m;  // second differences start at 0 .. last - 1
  const std::size_t stride = overlapping ? 1 : m;
  std::size_t count = 0;
  double s0 = 0.0;
  if (stride == 1) {
    // Four independent accumulators let the compiler keep several additions
    // in flight; this loop is the whole cost of an Allan deviation.
    double s1 = 0.0, s2 = 0.0, s3 = 0.0;
    const double* a = x;
    const double* b = x + m;
    const double* c = x + 2 * m;
    std::size_t i = 0;
    for (; i + 4 <= last; i += 4) {
      const double d0 = c[i] - 2.0 * b[i] + a[i];
      const double d1 = c[i + 1] - 2.0 * b[i + 1] + a[i + 1];
      const double d2 = c[i + 2] - 2.0 * b[i + 2] + a[i + 2];
      const double d3 = c[i + 3] - 2.0 * b[i + 3] + a[i + 3];
      s0 += d0 * d0;
      s1 += d1 * d1;
      s2 += d2 * d2;
      s3 += d3 * d3;
    }
    for (; i < last; ++i) {
      const double d = c[i] - 2.0 * b[i] + a[i];
      s0 += d * d;
    }
    s0 += s1 + s2 + s3;
    count = last;
  } else {
    for (std::size_t i = 0; i < last; i += stride) {
      const double d = x[i + 2 * m] - 2.0 * x[i + m] + x[i];
      s0 += d * d;
      ++count;
    }
  }
  if (differences) *differences = count;
  const double tau = static_cast<double>(m) * tau0S;
  return s0 / (2.0 * tau * tau * static_cast<double>(count));
}

std::vector<std::size_t> averagingFactors(std::size_t phasePoints, int perOctave, double maxFraction) {
  std::vector<std::size_t> out;
  if (phasePoints < 3 || perOctave < 1) return out;
  const double span = static_cast<double>(phasePoints - 1);
  const std::size_t maxM = std::min(static_cast<std::size_t>(std::floor(maxFraction * span)), (phasePoints - 1) / 2);
  const double step = std::pow(2.0, 1.0 / perOctave);
  for (int k = 0;; ++k) {
    const auto m = static_cast<std::size_t>(std::llround(std::pow(step, k)));
    if (m > maxM || m < 1) break;
    if (out.empty() || m > out.back()) out.push_back(m);
  }
  return out;
}

double edfOverlappingAllan(std::size_t phasePoints, std::size_t mm, PowerLawNoise noise) {
  const double n = static_cast<double>(phasePoints);
  const double m = static_cast<double>(mm);
  if (mm < 1 || 2 * mm >= phasePoints) return kNaN;
  double edf = kNaN;
  switch (noise) {
    case PowerLawNoise::kWhitePhase:
      edf = (n + 1.0) * (n - 2.0 * m) / (2.0 * (n - m));
      break;
    case PowerLawNoise::kFlickerPhase:
      edf = std::exp(std::sqrt(std::log((n - 1.0) / (2.0 * m)) * std::log((2.0 * m + 1.0) * (n - 1.0) / 4.0)));
      break;
    case PowerLawNoise::kWhiteFrequency:
      edf = (3.0 * (n - 1.0) / (2.0 * m) - 2.0 * (n - 2.0) / n) * 4.0 * m * m / (4.0 * m * m + 5.0);
      break;
    case PowerLawNoise::kFlickerFrequency:
      edf = mm == 1 ? 2.0 * (n - 2.0) / (2.3 * n - 4.9) : 5.0 * n * n / (4.0 * m * (n + 3.0 * m));
      break;
    case PowerLawNoise::kRandomWalkFrequency:
      edf = (n - 2.0) / (m * (n - 3.0) * (n - 3.0)) * ((n - 1.0) * (n - 1.0) - 3.0 * m * (n - 1.0) + 4.0 * m * m);
      break;
  }
  // The approximations can dip below 1 at the longest taus; one degree of
  // freedom (a single difference) is the honest floor.
  return std::isfinite(edf) ? std::max(edf, 1.0) : kNaN;
}

double chiSquareCdf(double x, double dof) {
  if (!(dof > 0.0) || std::isnan(x)) return kNaN;
  return analysis::regularisedGammaP(0.5 * dof, 0.5 * x);
}

double normalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0)) return kNaN;
  // Acklam's rational approximation (relative error < 1.2e-9) ...
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01,  -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  const double lo = 0.02425;
  double x;
  if (p < lo) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - lo) {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log(1.0 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  // ... and one Halley step on the exact CDF, 0.5 erfc(-x / sqrt 2).
  const double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
  const double u = e * std::sqrt(2.0 * 3.14159265358979323846) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

double chiSquareQuantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0)) return kNaN;
  if (dof > 1e5) return wilsonHilferty(p, dof);
  // Bracket around the Wilson-Hilferty start, then bisection in log x: the
  // CDF is monotone, so this cannot fail, and 200 halvings reach double precision.
  double guess = wilsonHilferty(p, dof);
  if (!(guess > 0.0)) guess = dof * 1e-3;
  double lo = guess, hi = guess;
  while (chiSquareCdf(lo, dof) > p && lo > 1e-300) lo *= 0.5;
  while (chiSquareCdf(hi, dof) < p && hi < 1e300) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = std::sqrt(lo * hi) > 0.0 ? 0.5 * (lo + hi) : hi;
    if (chiSquareCdf(mid, dof) < p) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

Interval deviationInterval(double deviation, double edf, double confidence) {
  Interval out{kNaN, kNaN};
  if (!(edf > 0.0) || !(confidence > 0.0 && confidence < 1.0) || !std::isfinite(deviation)) return out;
  const double tail = 0.5 * (1.0 - confidence);
  const double chiLow = chiSquareQuantile(tail, edf);
  const double chiHigh = chiSquareQuantile(1.0 - tail, edf);
  out.low = deviation * std::sqrt(edf / chiHigh);
  out.high = deviation * std::sqrt(edf / chiLow);
  return out;
}

}  // namespace fog::noise

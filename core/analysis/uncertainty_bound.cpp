#include "core/analysis/uncertainty_bound.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/analysis/statistics.h"
#include "core/common/text.h"

namespace fog::analysis {

namespace {

// The x with P(χ²(ν) > x) = 1 - p: bisection on the survival function.
double chiSquareQuantile(double p, int dof) {
  double lo = 0.0, hi = std::max(10.0, 10.0 * dof);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (1.0 - chiSquareSurvival(mid, dof) < p) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

int lagStdDegreesOfFreedom(const TestPointResult& point) {
  if (point.lagStdSource.rfind("per-period scatter", 0) == 0)
    return std::max(1, static_cast<int>(point.periodTrack.size()) - 1);
  // The fit's σ scales with its residuals: table and gyro samples less the
  // joint fit's parameters. Capped: beyond ~10^4 the quantile is 1 to 3 %.
  const auto samples = static_cast<long long>(point.tableSamples + point.imuSamples);
  return static_cast<int>(std::clamp(samples - 8, 1LL, 100000LL));
}

double smallestStdOverBound(int dof) {
  return kBoundModelFactor * std::sqrt(chiSquareQuantile(0.001, dof) / static_cast<double>(dof));
}

ValidityCheck uncertaintyBelowBoundCheck(const TestPointResult& point) {
  ValidityCheck c;
  c.id = "uncertainty_below_bound";
  if (!(point.crlbMs > 0.0)) {
    c.judged = false;
    c.detail = "not judged: the Cramér–Rao bound of this session's noise is not known";
    return c;
  }
  const int dof = lagStdDegreesOfFreedom(point);
  const double ratio = point.lagStdMs / point.crlbMs, least = smallestStdOverBound(dof);
  const std::string tail = " (" + point.lagStdSource + ", " + std::to_string(dof) +
                           " degrees of freedom; at least " + fixed(least, 2) + " expected)";
  std::string measured = "σ " + printfNumber("%.2g", point.lagStdMs) + " ms is " + fixed(ratio, 2) +
                         " of the Cramér–Rao bound " + printfNumber("%.2g", point.crlbMs) + " ms";
  if (point.lagStdBeforeCancellingMs > 0.0) {
    // The bound's noise model is white: it cannot see errors that cancel
    // between periods (quantisation read rising and falling alike), which
    // the data showed. The σ before they lowered it is what it judges.
    const double before = point.lagStdBeforeCancellingMs / point.crlbMs;
    c.passed = before >= least;
    measured += "; before the errors that cancel between periods, which the bound's white noise does not see, " +
                printfNumber("%.2g", point.lagStdBeforeCancellingMs) + " ms, " + fixed(before, 2) + " of it" + tail;
  } else {
    c.passed = ratio >= least;
    measured += tail;
  }
  c.detail = c.passed ? measured
                      : "the stated uncertainty is below what the noise allows: " + measured +
                            ". No estimate of the lag scatters less than the bound; the σ is understated and the "
                            "delay is not vouched for. Record more periods, or check the noise model (docs/method.md)";
  return c;
}

bool sigmaBelowBound(const TestPointResult& point) {
  return std::any_of(point.checks.begin(), point.checks.end(), [](const ValidityCheck& c) {
    return c.id == "uncertainty_below_bound" && c.judged && !c.passed;
  });
}

}  // namespace fog::analysis

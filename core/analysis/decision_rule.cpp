#include "core/analysis/decision_rule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fog::analysis {

namespace {

std::string printed(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::string coverageFactorProblem(double k) {
  if (std::isfinite(k) && k > 0.0 && k <= kMaxCoverageFactor) return {};
  return "the coverage factor k must be a finite number in (0, 10] (k·σ is the guard band below the limit; "
         "2 is the default), not " + printed("%g", k);
}

double standardNormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double maxFalseAcceptProbability(double k) { return 0.5 * std::erfc(k / std::sqrt(2.0)); }

double falseAcceptProbability(double d, double sigma, double limit) {
  if (!std::isfinite(d) || !std::isfinite(sigma) || !std::isfinite(limit) || sigma < 0.0)
    return std::numeric_limits<double>::quiet_NaN();
  if (sigma == 0.0) return d >= limit ? 1.0 : 0.0;
  // 1 − Φ(z) = erfc(z/√2)/2, without the cancellation of 1 − Φ.
  return 0.5 * std::erfc((limit - d) / (sigma * std::sqrt(2.0)));
}

std::string coverageFactorText(double k) { return printed("%g", k); }

std::string probabilityText(double p) {
  if (!std::isfinite(p)) return "not defined";
  const double percent = 100.0 * p;
  // A Gaussian tail is never 0: a double that underflowed (beyond ~37σ) is
  // as true a "< 1e-6 %" as any other tiny risk.
  if (percent < 1e-6) return "< 1e-6 %";
  if (percent >= 99.9999 && p < 1.0) return "> 99.9999 %";
  // Three significant digits below 10 %, one decimal above.
  if (percent >= 10.0) return printed("%.1f", percent) + " %";
  const int decimals = std::max(2, 2 - static_cast<int>(std::floor(std::log10(percent))));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f %%", std::min(decimals, 8), percent);
  return buf;
}

std::string decisionRuleText(double k) {
  return "PASS when IMU delay + k·σ < limit (k = " + coverageFactorText(k) +
         ", one-sided guarded acceptance, ISO/IEC 17025:2017 §7.8.6 / ILAC-G8:09/2019); FAIL otherwise; "
         "INVALID when a validity check fails";
}

std::string decisionRiskText(double k) {
  return "maximum probability of false accept 1 − Φ(k) = " + probabilityText(maxFalseAcceptProbability(k)) +
         " (a delay measured just at the acceptance boundary, with a Gaussian error of the stated σ)";
}

std::string decisionRuleStatement(double k, double limitMs) {
  std::string s = "decision rule: " + decisionRuleText(k) + "; " + decisionRiskText(k);
  if (limitMs > 0.0) s += "; limit " + printed("%g", limitMs) + " ms";
  return s;
}

}  // namespace fog::analysis

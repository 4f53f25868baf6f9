#include "core/analysis/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/common/text.h"

namespace fog::analysis {

namespace {

// The limit as the user wrote it: 0.8, not 0.8000.
std::string limitText(double v) { return printfNumber("%g", v); }

}  // namespace

int decimalsFor(double stdMs) {
  if (!(stdMs > 0.0)) return 4;
  return std::clamp(1 - static_cast<int>(std::floor(std::log10(stdMs))), 4, 7);
}

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "pass";
    case Verdict::kFail: return "fail";
    case Verdict::kInvalid: return "invalid";
  }
  return "invalid";
}

PointVerdict judgePoint(const TestPointResult& p, double limitMs, double k) {
  PointVerdict v;
  v.index = p.index;
  v.guardBandMs = guardBandMs(k, p.imuDelayStdMs);
  v.upperMs = p.imuDelayMs + v.guardBandMs;
  v.falseAcceptProbability = std::numeric_limits<double>::quiet_NaN();
  for (const auto& c : p.checks)
    if (c.judged && !c.passed) v.reasons.push_back(c.detail);
  if (!std::isfinite(p.imuDelayMs) || !std::isfinite(p.imuDelayStdMs))
    v.reasons.push_back("the delay or its uncertainty is not a finite number");
  if (!v.reasons.empty()) {
    v.verdict = Verdict::kInvalid;
    return v;
  }
  const int d = decimalsFor(p.imuDelayStdMs);
  const bool pass = v.upperMs < limitMs;
  v.verdict = pass ? Verdict::kPass : Verdict::kFail;
  v.falseAcceptProbability = falseAcceptProbability(p.imuDelayMs, p.imuDelayStdMs, limitMs);
  v.reasons.push_back("IMU delay " + fixed(p.imuDelayMs, d) + " ± " + fixed(p.imuDelayStdMs, d) + " ms; + " +
                      coverageFactorText(k) + "σ = " +
                      fixed(v.upperMs, d) + " ms " + (pass ? "<" : "≥") + " " + limitText(limitMs) + " ms limit (" +
                      (pass ? "margin " : "over by ") + fixed(std::abs(limitMs - v.upperMs), d) + " ms)");
  return v;
}

ReportVerdict judgeReport(const DelayReport& report, double limitMs, double k) {
  ReportVerdict r;
  r.limitMs = limitMs;
  r.coverageK = k;
  int invalid = 0, failed = 0;
  for (const auto& p : report.points) {
    PointVerdict v = judgePoint(p, limitMs, k);
    if (v.verdict != Verdict::kPass)
      for (const auto& why : v.reasons) r.reasons.push_back("test point " + std::to_string(p.index + 1) + ": " + why);
    invalid += v.verdict == Verdict::kInvalid;
    failed += v.verdict == Verdict::kFail;
    r.points.push_back(std::move(v));
  }
  for (const auto& why : report.failedPoints) r.reasons.push_back(why + " (no delay)");
  if (report.points.empty()) r.reasons.push_back("no test point gave a delay");
  if (invalid > 0 || !report.failedPoints.empty() || report.points.empty()) r.verdict = Verdict::kInvalid;
  else if (failed > 0) r.verdict = Verdict::kFail;
  else r.verdict = Verdict::kPass;
  if (r.verdict == Verdict::kPass)
    r.reasons.push_back("every test point passed its validity checks and its IMU delay + " +
                        coverageFactorText(k) + "σ is below the " + limitText(limitMs) + " ms limit");
  return r;
}

}  // namespace fog::analysis

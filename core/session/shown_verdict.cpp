#include "core/session/shown_verdict.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/verdict.h"

namespace fog::session {

namespace {

ShownVerdictKind kindOf(analysis::Verdict v) {
  switch (v) {
    case analysis::Verdict::kPass: return ShownVerdictKind::kPass;
    case analysis::Verdict::kFail: return ShownVerdictKind::kFail;
    case analysis::Verdict::kInvalid: return ShownVerdictKind::kInvalid;
  }
  return ShownVerdictKind::kNone;
}

// A point with this analysis' numbers (a record's are its own).
ShownPoint withNumbersOf(const analysis::TestPointResult& a) {
  ShownPoint p;
  p.index = a.index;
  p.lagMs = a.lagMs;
  p.lagStdMs = a.lagStdMs;
  p.imuDelayMs = a.imuDelayMs;
  p.imuDelayStdMs = a.imuDelayStdMs;
  return p;
}

// A point's specific risk from its shown numbers and the shown rule; only a
// vouched point has one (a refused delay carries no number).
void withRisk(ShownPoint& p, const ShownVerdict& v) {
  const bool vouched = p.vouched() && v.verdict != ShownVerdictKind::kIncomplete;
  p.guardBandMs = vouched ? analysis::guardBandMs(v.coverageK, p.imuDelayStdMs) : NAN;
  p.falseAcceptProbability = vouched ? analysis::falseAcceptProbability(p.imuDelayMs, p.imuDelayStdMs, v.limitMs) : NAN;
}

// An INCOMPLETE result: no point of it passes; each keeps its data's verdict.
void markIncomplete(ShownVerdict& v, const std::string& why) {
  v.dataVerdict = v.verdict;
  v.verdict = ShownVerdictKind::kIncomplete;
  v.incompleteReason = why;
  for (auto& p : v.points) {
    p.verdict = ShownVerdictKind::kIncomplete;
    p.falseAcceptProbability = p.guardBandMs = NAN;
  }
}

ShownVerdict fromRecord(const StoredResultRecord& r, const analysis::DelayReport* report) {
  ShownVerdict v;
  v.stored = true;
  v.limitMs = r.imuDelayLimitMs;
  v.coverageK = r.coverageK;
  v.ruleProvenance = decisionRuleProvenance(r);
  v.verdict = shownVerdictKind(r.verdict);
  v.dataVerdict = v.verdict == ShownVerdictKind::kIncomplete ? shownVerdictKind(r.dataVerdict) : v.verdict;
  v.reasons = r.verdictReasons;
  if (v.verdict == ShownVerdictKind::kIncomplete) v.incompleteReason = r.incompleteReason;
  auto fromStored = [&](const StoredPointVerdict& s) {
    ShownPoint p;
    p.index = s.index;
    p.dataVerdict = shownVerdictKind(s.verdict);
    p.verdict = v.verdict == ShownVerdictKind::kIncomplete ? ShownVerdictKind::kIncomplete : p.dataVerdict;
    p.reasons = s.reasons;
    p.lagMs = s.lagMs;
    p.lagStdMs = s.lagStdMs;
    p.imuDelayMs = s.imuDelayMs;
    p.imuDelayStdMs = s.imuDelayStdMs;
    withRisk(p, v);
    return p;
  };
  if (!report) {
    for (const auto& s : r.points) v.points.push_back(fromStored(s));
    return v;
  }
  // The analysis' points, in its order; a point the record does not state has
  // no stored verdict, and its number (this analysis') is refused.
  for (const auto& a : report->points) {
    if (const StoredPointVerdict* s = r.point(a.index)) {
      v.points.push_back(fromStored(*s));
      continue;
    }
    ShownPoint p = withNumbersOf(a);
    p.reasons = {"the stored result has no delay for this test point"};
    v.points.push_back(std::move(p));
  }
  return v;
}

ShownVerdict judgedNow(const analysis::DelayReport& report, double limitMs, double k) {
  ShownVerdict v;
  v.limitMs = limitMs;
  v.coverageK = k;
  const analysis::ReportVerdict judged = analysis::judgeReport(report, limitMs, k);
  v.verdict = v.dataVerdict = kindOf(judged.verdict);
  v.reasons = judged.reasons;
  for (std::size_t i = 0; i < report.points.size() && i < judged.points.size(); ++i) {
    ShownPoint p = withNumbersOf(report.points[i]);
    p.verdict = p.dataVerdict = kindOf(judged.points[i].verdict);
    p.reasons = judged.points[i].reasons;
    withRisk(p, v);
    v.points.push_back(std::move(p));
  }
  return v;
}

}  // namespace

const char* shownVerdictName(ShownVerdictKind kind) {
  switch (kind) {
    case ShownVerdictKind::kPass: return "pass";
    case ShownVerdictKind::kFail: return "fail";
    case ShownVerdictKind::kInvalid: return "invalid";
    case ShownVerdictKind::kIncomplete: return "incomplete";
    case ShownVerdictKind::kNone: break;
  }
  return "";
}

const char* shownVerdictWord(ShownVerdictKind kind) {
  switch (kind) {
    case ShownVerdictKind::kPass: return "PASS";
    case ShownVerdictKind::kFail: return "FAIL";
    case ShownVerdictKind::kInvalid: return "INVALID";
    case ShownVerdictKind::kIncomplete: return "INCOMPLETE";
    case ShownVerdictKind::kNone: break;
  }
  return "NO VERDICT";
}

ShownVerdictKind shownVerdictKind(const std::string& name) {
  for (auto k : {ShownVerdictKind::kPass, ShownVerdictKind::kFail, ShownVerdictKind::kInvalid,
                 ShownVerdictKind::kIncomplete})
    if (name == shownVerdictName(k)) return k;
  return ShownVerdictKind::kNone;
}

std::string ShownPoint::refusal() const {
  if (vouched()) return {};
  std::string why;
  for (const auto& r : reasons) why += (why.empty() ? "" : "; ") + r;
  switch (verdict) {
    case ShownVerdictKind::kInvalid:
      return "INVALID: " + (why.empty() ? std::string("a validity check failed") : why);
    case ShownVerdictKind::kIncomplete:
      return std::string("INCOMPLETE: the run stopped before its plan ended (its data give ") +
             shownVerdictWord(dataVerdict) + ")";
    default:
      return "no verdict: " + (why.empty() ? std::string("the stored result states none for this test point") : why);
  }
}

const ShownPoint* ShownVerdict::point(int index) const {
  for (const auto& p : points)
    if (p.index == index) return &p;
  return nullptr;
}

bool ShownVerdict::allVouched() const {
  return !points.empty() && std::all_of(points.begin(), points.end(), [](const ShownPoint& p) { return p.vouched(); });
}

ShownVerdict judgeShown(const StoredResultRecord* record, const analysis::DelayReport* report, bool complete,
                        const std::string& incompleteReason, double limitMs, double coverageK) {
  if (record) return fromRecord(*record, report);
  ShownVerdict v;
  v.limitMs = limitMs;
  v.coverageK = coverageK;
  if (report) v = judgedNow(*report, limitMs, coverageK);
  if (!complete) markIncomplete(v, incompleteReason);
  return v;
}

std::string decisionRuleLine(const ShownVerdict& shown) {
  std::string s = analysis::decisionRuleStatement(shown.coverageK, shown.limitMs);
  if (!shown.ruleProvenance.empty()) s += " (k " + shown.ruleProvenance + ")";
  return s;
}

}  // namespace fog::session

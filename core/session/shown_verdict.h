#pragma once
// The verdict shown for a result, and which of its numbers may be used: the
// one rule every view, command and export formats (issue 39). Qt-free.
//
// The rule (docs/report.md, "The verdict shown"):
//  - A stored result is a record: its verdict, reasons and limit are shown as
//    stored, never re-judged. An incomplete run's record says INCOMPLETE with
//    what its data give (`dataVerdict`).
//  - A result not stored (a run without a session, a session without a usable
//    result) is judged once, here, with analysis::judgeReport and the run's
//    limit; when the run stopped early it is INCOMPLETE, and the data's own
//    verdict stands beside it.
//  - Every point of an INCOMPLETE result is INCOMPLETE (no point of a run
//    that stopped early passes), with its data's verdict beside it.
//  - A point's delay is *vouched for* only when the point shows PASS or FAIL:
//    an INVALID, INCOMPLETE or unstated point's number is refused. A refused
//    number is never printed bare and no arithmetic (B − A, a mean, a trend
//    line) uses it; `refusal` says why in one sentence.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/session/stored_result.h"

namespace fog::session {

// What is shown. kNone: a stored result that states no verdict (a very old
// row), or a point the stored result has no delay for.
enum class ShownVerdictKind { kPass, kFail, kInvalid, kIncomplete, kNone };

// "pass", "fail", "invalid", "incomplete", "" (the stored words).
const char* shownVerdictName(ShownVerdictKind kind);
// "PASS", "FAIL", "INVALID", "INCOMPLETE", "NO VERDICT" (the CLI's words).
const char* shownVerdictWord(ShownVerdictKind kind);
// The stored word as a kind; anything else (including "") is kNone.
ShownVerdictKind shownVerdictKind(const std::string& name);

struct ShownPoint {
  int index = 0;  // test point index (0-based)
  ShownVerdictKind verdict = ShownVerdictKind::kNone;
  // What the point's own data give: the same as `verdict` unless the result
  // is INCOMPLETE.
  ShownVerdictKind dataVerdict = ShownVerdictKind::kNone;
  std::vector<std::string> reasons;  // as stored or judged (English, core wording)
  // The record's numbers (a stored result), else this analysis' (ms; NaN
  // where a stored row states none).
  double lagMs = 0.0, lagStdMs = 0.0;
  double imuDelayMs = 0.0, imuDelayStdMs = 0.0;
  // The point's specific risk (vouched points only; NaN otherwise):
  // P(true delay >= limit | delay, sigma) and the guard band k sigma, ms.
  double falseAcceptProbability = std::numeric_limits<double>::quiet_NaN();
  double guardBandMs = std::numeric_limits<double>::quiet_NaN();
  // Only PASS and FAIL points' delays may be shown bare and used.
  bool vouched() const { return verdict == ShownVerdictKind::kPass || verdict == ShownVerdictKind::kFail; }
  // Why the delay is refused, one sentence ("" when vouched): "INVALID: the
  // gyro turns against the table ...", "INCOMPLETE: the run stopped early
  // (its data give PASS)", "no verdict: the stored result has no delay for
  // this test point".
  std::string refusal() const;
};

struct ShownVerdict {
  ShownVerdictKind verdict = ShownVerdictKind::kNone;
  ShownVerdictKind dataVerdict = ShownVerdictKind::kNone;  // an INCOMPLETE result's data; else = verdict
  bool stored = false;            // from a stored record (else judged now, not stored)
  double limitMs = analysis::kDefaultImuDelayLimitMs;
  // The decision rule's k (decision_rule.h): the record's (k = 2 for a row
  // stored before k was kept: `ruleProvenance` says so), else the run's.
  // Every view states the rule with this k, never today's default.
  double coverageK = analysis::kDefaultCoverageFactor;
  std::string ruleProvenance;  // "" or "not stored: the rule of that version, k = 2"
  std::vector<std::string> reasons;  // the result's, as stored or judged
  std::string incompleteReason;      // an INCOMPLETE result: why the run stopped
  // One per point of the analysis when there is one (its order), else one
  // per point the record states.
  std::vector<ShownPoint> points;

  const ShownPoint* point(int index) const;
  // True when every point's delay may be used (no refused point).
  bool allVouched() const;
};

// The rule above. `record`: the stored result shown, or null. `report`: this
// version's analysis (with the record's settings), or null when the data gave
// none. `complete`/`incompleteReason`: the session's run. `limitMs`: the
// limit a result not stored is judged with (a record's own limit wins);
// `coverageK` likewise (a record's own k wins).
ShownVerdict judgeShown(const StoredResultRecord* record, const analysis::DelayReport* report, bool complete,
                        const std::string& incompleteReason, double limitMs,
                        double coverageK = analysis::kDefaultCoverageFactor);

// The rule and its risk as a view states them: decisionRuleStatement with the
// shown k and limit, and "(k not stored: ...)" for a row stored before k was.
std::string decisionRuleLine(const ShownVerdict& shown);

}  // namespace fog::session

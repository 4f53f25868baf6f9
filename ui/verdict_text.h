#pragma once
// The shown verdict (core/session/shown_verdict.h) in the GUI's and the
// report's words: the verdict's word and colour, and a point's number with its
// mark. Formatting only: the rule is core's judgeShown, never re-judged here.

#include <QString>
#include <string>

#include "core/session/shown_verdict.h"

namespace fog::ui {

// "PASS", "FAIL", "INVALID", "INCOMPLETE", "NO VERDICT", translated.
QString verdictWord(session::ShownVerdictKind kind);
// The stored word ("pass", ..., "") as verdictWord.
QString verdictWord(const std::string& storedName);
// The colour the views write a verdict in (HTML #rrggbb): pass green,
// invalid amber, fail/incomplete/none red.
QString verdictColour(session::ShownVerdictKind kind);

// Why a point's delay is refused, translated ("" when vouched for).
QString refusalText(const session::ShownPoint& point);

// A point's number as it may be shown: "0.5155" when the point is vouched for,
// "refused (0.5155, INVALID)" otherwise (a refused number never bare;
// "refused (INVALID)" when it is not a finite number).
QString shownNumber(const session::ShownPoint& point, double value, int decimals);

}  // namespace fog::ui

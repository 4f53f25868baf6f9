#include "ui/verdict_text.h"

#include <QObject>
#include <QStringList>
#include <cmath>

#include "ui/core_text.h"
#include "ui/language/language.h"

namespace fog::ui {

QString verdictWord(session::ShownVerdictKind kind) {
  using K = session::ShownVerdictKind;
  switch (kind) {
    case K::kPass: return QObject::tr("PASS");
    case K::kFail: return QObject::tr("FAIL");
    case K::kInvalid: return QObject::tr("INVALID");
    case K::kIncomplete: return QObject::tr("INCOMPLETE");
    case K::kNone: break;
  }
  return QObject::tr("NO VERDICT");
}

QString verdictWord(const std::string& storedName) { return verdictWord(session::shownVerdictKind(storedName)); }

QString verdictColour(session::ShownVerdictKind kind) {
  using K = session::ShownVerdictKind;
  if (kind == K::kPass) return QStringLiteral("#146e28");
  if (kind == K::kInvalid) return QStringLiteral("#a05000");
  return QStringLiteral("#b00000");
}

QString refusalText(const session::ShownPoint& point) {
  using K = session::ShownVerdictKind;
  if (point.vouched()) return {};
  QStringList why;
  for (const auto& r : point.reasons) why << coreText(r);
  if (point.verdict == K::kInvalid)
    return QObject::tr("INVALID: %1").arg(why.isEmpty() ? QObject::tr("a validity check failed") : why.join("; "));
  if (point.verdict == K::kIncomplete)
    return QObject::tr("INCOMPLETE: the run stopped before its plan ended (its data give %1)").arg(verdictWord(point.dataVerdict));
  return QObject::tr("NO VERDICT: %1").arg(why.isEmpty() ? QObject::tr("the stored result states none for this test point")
                                                : why.join("; "));
}

QString shownNumber(const session::ShownPoint& point, double value, int decimals) {
  const QString number = localNumber(value, 'f', decimals);
  if (point.vouched()) return number;
  if (!std::isfinite(value)) return QObject::tr("refused (%1)").arg(verdictWord(point.verdict));
  return QObject::tr("refused (%1, %2)").arg(number, verdictWord(point.verdict));
}

}  // namespace fog::ui

#include "ui/session_compare.h"

#include <QObject>
#include <cmath>

#include "ui/language/language.h"

namespace fog::ui {

namespace {

bool sameTest(const analysis::TestPointResult& x, const analysis::TestPointResult& y) {
  return x.axis == y.axis &&
         std::abs(x.nominalFrequencyHz - y.nominalFrequencyHz) <= 1e-6 * std::max(1.0, x.nominalFrequencyHz) &&
         std::lround(x.tableFit.amplitudeDeg * 10.0) == std::lround(y.tableFit.amplitudeDeg * 10.0);
}

}  // namespace

QString comparisonLabel(const analysis::TestPointResult& p) {
  return QObject::tr("%1 axis, %2 Hz / %3°")
      .arg(QString(axisName(p.axis)).toUpper(), localNumber(p.nominalFrequencyHz, 'g', 6),
           localNumber(p.tableFit.amplitudeDeg, 'f', 2));
}

namespace {
session::ShownPoint shownOf(const session::ShownVerdict& v, const analysis::TestPointResult& p) {
  if (const auto* sp = v.point(p.index)) return *sp;
  session::ShownPoint none;  // kNone: refused
  none.index = p.index;
  return none;
}
}  // namespace

std::vector<PointComparison> compareReports(const analysis::DelayReport& a, const session::ShownVerdict& aVerdict,
                                            const analysis::DelayReport& b, const session::ShownVerdict& bVerdict) {
  std::vector<PointComparison> out;
  std::vector<bool> usedB(b.points.size(), false);
  const bool commonTable = a.constants.tableReadDelayMs == b.constants.tableReadDelayMs &&
                           a.constants.tableReadDelayStdMs == b.constants.tableReadDelayStdMs;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto& pa = a.points[i];
    PointComparison c;
    c.label = comparisonLabel(pa);
    c.a = i;
    c.aMs = pa.imuDelayMs;
    c.aStdMs = pa.imuDelayStdMs;
    c.aShown = shownOf(aVerdict, pa);
    c.commonTableConstant = commonTable;
    for (std::size_t j = 0; j < b.points.size(); ++j) {
      if (usedB[j] || !sameTest(pa, b.points[j])) continue;
      usedB[j] = true;
      const auto& pb = b.points[j];
      c.b = j;
      c.bMs = pb.imuDelayMs;
      c.bStdMs = pb.imuDelayStdMs;
      c.bShown = shownOf(bVerdict, pb);
      if (!c.comparable()) break;
      c.differenceMs = pb.imuDelayMs - pa.imuDelayMs;
      c.differenceStdMs = commonTable ? std::hypot(pa.lagStdMs, pb.lagStdMs)
                                      : std::hypot(pa.imuDelayStdMs, pb.imuDelayStdMs);
      c.significance = c.differenceStdMs > 0.0 ? std::abs(c.differenceMs) / c.differenceStdMs : 0.0;
      break;
    }
    out.push_back(c);
  }
  for (std::size_t j = 0; j < b.points.size(); ++j) {
    if (usedB[j]) continue;
    PointComparison c;
    c.label = comparisonLabel(b.points[j]);
    c.b = j;
    c.bMs = b.points[j].imuDelayMs;
    c.bStdMs = b.points[j].imuDelayStdMs;
    c.bShown = shownOf(bVerdict, b.points[j]);
    c.commonTableConstant = commonTable;
    out.push_back(c);
  }
  return out;
}

}  // namespace fog::ui

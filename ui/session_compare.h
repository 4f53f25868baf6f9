#pragma once
// What Compare computes: per test point, two results of the bench side by
// side and their difference with its combined uncertainty and significance;
// and, across several sessions of one IMU, the delay against the date.
//
// Test points are matched by what was tested (axis, nominal frequency,
// amplitude to 0.1°), in plan order when a plan repeats one. The difference
// is of the IMU delay (the calibration figure), B − A. Its σ combines both
// results' uncertainties; when both results used the same table read delay
// (value and σ), that constant's error is common to both and cancels, so only
// the lags' uncertainties combine; otherwise the IMU delays' do. A delay
// that is not vouched for (its shown verdict INVALID, INCOMPLETE or none) is
// never subtracted: the row says why instead.

#include <QString>
#include <optional>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/session/shown_verdict.h"

namespace fog::ui {

struct PointComparison {
  QString label;                  // "X axis, 1 Hz / 3.00°"
  std::optional<std::size_t> a, b;  // the point's position in each report (none: not tested there)
  double aMs = 0.0, aStdMs = 0.0;   // IMU delay ± 1σ
  double bMs = 0.0, bStdMs = 0.0;
  // Each side's shown point (its verdict; a refused delay says why).
  session::ShownPoint aShown, bShown;
  double differenceMs = 0.0;       // b − a; only when comparable()
  double differenceStdMs = 0.0;    // combined 1σ of the difference
  double significance = 0.0;       // |difference| / σ
  bool commonTableConstant = false;  // the table read delay's error cancels (both used the same)
  bool both() const { return a && b; }
  // Tested in both and both delays vouched for (PASS or FAIL): a refused
  // delay (INVALID, INCOMPLETE, no verdict) is never subtracted.
  bool comparable() const { return both() && aShown.vouched() && bShown.vouched(); }
  // The difference is significant at about 95 % (|d| > 2σ).
  bool significant() const { return comparable() && significance > 2.0; }
};

// Points matched as above; each side's verdicts from its shown verdict
// (session::judgeShown), a point a verdict does not state being refused.
std::vector<PointComparison> compareReports(const analysis::DelayReport& a, const session::ShownVerdict& aVerdict,
                                            const analysis::DelayReport& b, const session::ShownVerdict& bVerdict);

// A test point's label as Compare shows it.
QString comparisonLabel(const analysis::TestPointResult& p);

}  // namespace fog::ui

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
// the lags' uncertainties combine; otherwise the IMU delays' do.

#include <QString>
#include <optional>
#include <vector>

#include "core/analysis/delay_analysis.h"

namespace fog::ui {

struct PointComparison {
  QString label;                  // "X axis, 1 Hz / 3.00°"
  std::optional<std::size_t> a, b;  // the point's position in each report (none: not tested there)
  double aMs = 0.0, aStdMs = 0.0;   // IMU delay ± 1σ
  double bMs = 0.0, bStdMs = 0.0;
  double differenceMs = 0.0;       // b − a
  double differenceStdMs = 0.0;    // combined 1σ of the difference
  double significance = 0.0;       // |difference| / σ
  bool commonTableConstant = false;  // the table read delay's error cancelled
  bool both() const { return a && b; }
  // The difference is significant at about 95 % (|d| > 2σ).
  bool significant() const { return both() && significance > 2.0; }
};

std::vector<PointComparison> compareReports(const analysis::DelayReport& a, const analysis::DelayReport& b);

// A test point's label as Compare shows it.
QString comparisonLabel(const analysis::TestPointResult& p);

}  // namespace fog::ui

#pragma once
// What the bench plots for one analysed test point, computed with the
// analysis's own channels so that the data and the fitted curves agree
// exactly with the numbers in the report.
//
// Normalised as in the paper: (angle - offset) / amplitude, each channel by
// its own fit; the gyro angle is the cumulative sum of its increments on the
// swing axis with the fitted trend (bias + Earth rate) removed. Times are
// seconds on the session's time axis (the board counter).

#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/common/recording.h"
#include "core/common/status.h"

namespace fog::ui {

// A curve: x ascending, x.size() == y.size().
struct Trace {
  std::vector<double> x, y;
};

struct TestPointTraces {
  int index = 0;  // test point index, as in TestPointResult::index
  Trace tableNormalised, gyroNormalised;
  Trace tableResidualArcsec, gyroResidualArcsec;  // data minus fit
  analysis::SineFit tableFit, gyroFit;

  // The fitted sinusoids, normalised like the data, at session time tS.
  double tableFitNormalised(double tS) const;
  double gyroFitNormalised(double tS) const;
};

// The time (s) nearest `nearS` where the fit's periodic part,
// a·sin(ωτ) + b·cos(ωτ) = A·sin(ωτ + φ), rises through zero (ωτ + φ = 2πk);
// NaN when the fit has no frequency.
double risingZeroCrossingS(const analysis::SineFit& fit, double nearS);

// The gyro as the analysis saw it: in degrees, with the result's gyro sign.
Result<TestPointTraces> makeTestPointTraces(const TestPointData& data, const analysis::TestPointResult& result);

}  // namespace fog::ui

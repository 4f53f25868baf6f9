#pragma once
// Thinning of dense curves for display: a 300k-point curve replots in
// ~100 ms, its min/max per pixel column in ~2 ms and looks the same
// (docs/benchmarks.md).

#include <QPointF>
#include <QVector>
#include <span>

namespace fog::ui {

// The points of the curve (x ascending, x.size() == y.size()) that draw the
// same picture over [x0, x1] on `columns` pixel columns: in each column the
// first and last point and the minimum and maximum, in their original order,
// plus the nearest point outside the range on each side so that lines reach
// the edges. Returns every point in range when there are no more than four
// per column. Empty for an empty curve, columns < 1 or x1 <= x0.
QVector<QPointF> decimateMinMax(std::span<const double> x, std::span<const double> y, double x0, double x1,
                                int columns);

}  // namespace fog::ui

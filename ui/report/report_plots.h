#pragma once
// The report's Qwt plots, built for printing: fixed fonts in points, white
// canvas, legend below, data thinned to min/max per printed column
// (ui/curve_decimation) and fitted functions sampled finely. Internal to
// fog_report.

#include <QPen>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ui/plot_data/test_point_traces.h"

class QwtPlot;

namespace fog::report::detail {

struct PlotCurve {
  QString title;
  QPen pen;
  const ui::Trace* trace = nullptr;           // data, drawn scaled by yScale ...
  double yScale = 1.0;
  std::function<double(double)> function;      // ... or a function of x
  bool symbols = false;                         // data as dots, no line
};

struct PlotSpec {
  QString title, xTitle, yTitle;
  double x0 = 0.0, x1 = 1.0;  // shown x range
  std::optional<std::pair<double, double>> yRange;  // default: fitted to the curves
  double widthMm = 170.0;     // printed size, for the thinning resolution
  std::vector<PlotCurve> curves;
  std::optional<double> horizontalLine;  // e.g. the joint-fit lag
  QString horizontalLineTitle;
};

std::unique_ptr<QwtPlot> makePlot(const PlotSpec& spec);

// An empty plot styled like makePlot's (fonts, title, legend below, grid),
// for plots drawn by other code; restyleAxisTitles() applies the report's
// fonts to titles that code set.
std::unique_ptr<QwtPlot> makeFramePlot(const QString& title);
void restyleAxisTitles(QwtPlot* plot);

}  // namespace fog::report::detail

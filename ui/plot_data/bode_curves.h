#pragma once
// The curves of a Bode plot (docs/method.md "Frequency response"), the same
// on screen (BodeView, in Results and Compare) and in the calibration report:
// per series the measured points (gyro angle / table angle at each test
// frequency) with their ±1σ error bars, and a fitted model's curve over the
// points' span; magnitude in dB or phase in degrees against a log frequency
// axis.

#include <QColor>
#include <QString>
#include <vector>

#include "core/analysis/frequency_response.h"

class QwtPlot;

namespace fog::ui {

struct BodeSeries {
  QString name;  // the points' legend title ("X axis", "A", "B − A")
  QColor colour;
  std::vector<analysis::ResponsePoint> points;
  // Drawn over the points' span when set (not owned; outlives the drawing).
  const analysis::ResponseModelFit* model = nullptr;
  QString modelName;  // the model curve's legend title
};

enum class BodePart { kMagnitudeDb, kPhaseDeg };

// The words on the plot, in the caller's language.
struct BodeLabels {
  QString frequency;  // x axis title
  QString value;      // y axis title (magnitude or phase)
};

// Sets a log frequency axis and the axis titles, attaches the curves (removes
// the curves it attached before) and leaves the axes autoscaled.
void drawBodeCurves(QwtPlot* plot, BodePart part, const std::vector<BodeSeries>& series, const BodeLabels& labels);

// A point's value and 1σ in the plotted unit (dB or degrees).
double bodePointValue(const analysis::ResponsePoint& p, BodePart part);
double bodePointStd(const analysis::ResponsePoint& p, BodePart part);
// The model's value at f in the plotted unit.
double bodeModelValue(const analysis::ResponseModelFit& m, BodePart part, double frequencyHz);
// The points' value at f, interpolated linearly in log f between the two
// points around it; NaN outside the points' span.
double bodePointsAt(const std::vector<analysis::ResponsePoint>& points, BodePart part, double frequencyHz);

// A model's name and its parameters (± 1σ, with units) as the GUI and the
// report write them (translated in the context "fog::ui::BodeText").
QString responseModelTitle(analysis::ResponseModelKind kind);
QString responseParametersText(const analysis::ResponseModelFit& m);
// "0.2381 ± 0.0012 ms": the value to the σ's second significant digit.
QString valueWithStdText(double value, double stdDev, const QString& unit = QString());

}  // namespace fog::ui

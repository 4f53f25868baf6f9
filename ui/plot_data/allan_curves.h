#pragma once
// The curves of an Allan deviation plot, the same on screen (NoiseView) and
// in the calibration report: the measured overlapping Allan deviation
// (°/h) with its confidence band, each identified noise term as a dashed
// line and the model's sum, on log-log axes over the measured tau range.

#include <QString>
#include <array>

class QwtPlot;

namespace fog::noise {
struct GyroNoiseReport;
}

namespace fog::ui {

// The words on the plot, in the caller's language (the GUI and the report
// translate them in their own contexts).
struct AllanLabels {
  QString xTitle, yTitle;
  QString band;  // "confidence interval (%1 %)"
  QString measured, model;
  std::array<QString, 6> terms;  // by noise::NoiseTermKind
};

// Sets log scales and axis titles, attaches the curves and leaves the axes
// autoscaled. Removes curves it attached before.
void drawAllanCurves(QwtPlot* plot, const noise::GyroNoiseReport& report, const AllanLabels& labels);

}  // namespace fog::ui

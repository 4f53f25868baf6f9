#pragma once
// Saving a plot as a file: PNG (at the widget's size, 2x for print
// sharpness), SVG or PDF (vector, 160 x 100 mm), chosen by the suffix.

#include <QString>
#include <vector>

#include "core/common/status.h"

class QwtPlot;

namespace fog::ui {

// Errors: an unknown suffix (kInvalidArgument), a file that cannot be written (kIoError).
Status exportPlot(QwtPlot* plot, const QString& path);
// Several plots stacked top to bottom in one file (a Bode plot: magnitude
// over phase), each drawn as exportPlot draws one: PNG at 1600 x 640 px a
// plot (800 x 320 at 2x, whatever the window's size), SVG or PDF 160 mm
// wide and 80 mm a plot. Errors as exportPlot's; kInvalidArgument for no plots.
Status exportPlots(const std::vector<QwtPlot*>& plots, const QString& path);
// The file dialog filter for the formats above.
QString plotExportFilter();

}  // namespace fog::ui

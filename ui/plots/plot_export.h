#pragma once
// Saving a plot as a file: PNG (at the widget's size, 2x for print
// sharpness), SVG or PDF (vector, 160 x 100 mm), chosen by the suffix.

#include <QString>

#include "core/common/status.h"

class QwtPlot;

namespace fog::ui {

// Errors: an unknown suffix (kInvalidArgument), a file that cannot be written (kIoError).
Status exportPlot(QwtPlot* plot, const QString& path);
// The file dialog filter for the formats above.
QString plotExportFilter();

}  // namespace fog::ui

#pragma once
// A plot picker that reads out the value under the cursor and, while the
// left button is dragged, the time and value differences between the press
// point and the cursor ("Δt = 0.466 ms, Δ = 0.0012°"): how an operator
// measures the offset between two curves by hand.

#include <QString>
#include <qwt_plot_picker.h>

namespace fog::ui {

class DeltaPicker : public QwtPlotPicker {
  Q_OBJECT

 public:
  // unit: the value axis unit, appended to values ("°", "″").
  DeltaPicker(QWidget* canvas, QString unit);

  // The text shown for a cursor at `pos`; while a drag is under way, relative
  // to where it started. Public for tests.
  QString readout(const QPointF& pos) const;

 protected:
  QwtText trackerTextF(const QPointF& pos) const override;

 private:
  QString unit_;
};

// Time differences in the unit that reads best: "412 µs", "3.25 ms", "1.502 s".
QString formatDuration(double seconds);

}  // namespace fog::ui

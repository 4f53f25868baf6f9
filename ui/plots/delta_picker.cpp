#include "ui/plots/delta_picker.h"

#include "ui/language/language.h"

#include <QPen>
#include <cmath>
#include <qwt_picker_machine.h>
#include <qwt_plot.h>
#include <qwt_text.h>

namespace fog::ui {

QString formatDuration(double s) {
  const double a = std::abs(s);
  if (a < 1e-3) return QObject::tr("%1 µs").arg(localNumber(s * 1e6, 'f', 1));
  if (a < 1.0) return QObject::tr("%1 ms").arg(localNumber(s * 1e3, 'f', 4));
  return QObject::tr("%1 s").arg(localNumber(s, 'f', 4));
}

DeltaPicker::DeltaPicker(QWidget* canvas, QString unit)
    : QwtPlotPicker(QwtPlot::xBottom, QwtPlot::yLeft, QwtPicker::PolygonRubberBand, QwtPicker::AlwaysOn, canvas),
      unit_(std::move(unit)) {
  setStateMachine(new QwtPickerDragLineMachine());
  setRubberBandPen(QPen(QColor(80, 80, 80), 1, Qt::DashLine));
  setTrackerPen(QPen(Qt::black));
}

QString DeltaPicker::readout(const QPointF& pos) const {
  QString text = tr("t = %1 s, %2 %3").arg(localNumber(pos.x(), 'f', 4), localNumber(pos.y(), 'g', 6), unit_);
  const QPolygon band = selection();
  if (isActive() && band.size() >= 2) {
    const QPointF start = invTransform(band.front());
    text += tr("\nΔt = %1, Δ = %2 %3").arg(formatDuration(pos.x() - start.x()), localNumber(pos.y() - start.y(), 'g', 4), unit_);
  }
  return text;
}

QwtText DeltaPicker::trackerTextF(const QPointF& pos) const {
  QwtText t(readout(pos));
  t.setBackgroundBrush(QColor(255, 255, 255, 220));
  return t;
}

}  // namespace fog::ui

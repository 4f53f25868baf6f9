#include "ui/plot_data/allan_curves.h"

#include <QPen>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_scale_engine.h>
#include <qwt_symbol.h>

#include "core/noise/gyro_noise.h"

namespace fog::ui {

namespace {

constexpr double kDegPerSToDegPerH = 3600.0;
// Per NoiseTermKind; the measured curve is dark grey, the model's sum red.
const QColor kTermColours[] = {QColor(44, 160, 44), QColor(31, 119, 180), QColor(255, 127, 14),
                               QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194)};

}  // namespace

void drawAllanCurves(QwtPlot* plot, const noise::GyroNoiseReport& r, const AllanLabels& labels) {
  plot->detachItems(QwtPlotItem::Rtti_PlotCurve);
  plot->detachItems(QwtPlotItem::Rtti_PlotIntervalCurve);
  plot->setAxisScaleEngine(QwtPlot::xBottom, new QwtLogScaleEngine());
  plot->setAxisScaleEngine(QwtPlot::yLeft, new QwtLogScaleEngine());
  plot->setAxisTitle(QwtPlot::xBottom, labels.xTitle);
  plot->setAxisTitle(QwtPlot::yLeft, labels.yTitle);

  QVector<QPointF> points;
  QVector<QwtIntervalSample> band;
  double tauMin = 1e300, tauMax = 0.0;
  for (const auto& p : r.curve.points) {
    if (!(p.deviation > 0.0)) continue;
    points.push_back({p.tauS, p.deviation * kDegPerSToDegPerH});
    band.push_back(QwtIntervalSample(p.tauS, p.interval.low * kDegPerSToDegPerH, p.interval.high * kDegPerSToDegPerH));
    tauMin = std::min(tauMin, p.tauS);
    tauMax = std::max(tauMax, p.tauS);
  }
  auto* ci = new QwtPlotIntervalCurve(labels.band.arg(std::lround(100.0 * r.curve.confidence)));
  ci->setSamples(band);
  ci->setPen(QPen(Qt::NoPen));
  ci->setBrush(QColor(90, 90, 90, 45));
  ci->attach(plot);
  auto* adev = new QwtPlotCurve(labels.measured);
  adev->setSamples(points);
  adev->setPen(QPen(QColor(40, 40, 40), 1.5));
  adev->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(QColor(40, 40, 40)), QPen(Qt::NoPen), QSize(5, 5)));
  adev->attach(plot);
  if (!(tauMax > tauMin)) return;

  const int n = 80;
  auto tauAt = [&](int i) { return tauMin * std::pow(tauMax / tauMin, static_cast<double>(i) / (n - 1)); };
  for (const auto& term : r.model.terms) {
    QVector<QPointF> line;
    for (int i = 0; i < n; ++i) {
      const double tau = tauAt(i);
      const double var = term.value * term.value * noise::unitAllanVariance(term.kind, tau, term.correlationTimeS);
      if (var > 0.0) line.push_back({tau, std::sqrt(var) * kDegPerSToDegPerH});
    }
    auto* curve = new QwtPlotCurve(labels.terms[static_cast<std::size_t>(term.kind) % labels.terms.size()]);
    curve->setSamples(line);
    curve->setPen(QPen(kTermColours[static_cast<int>(term.kind) % 6], 1.2, Qt::DashLine));
    curve->attach(plot);
  }
  QVector<QPointF> total;
  for (int i = 0; i < n; ++i) {
    const double var = r.model.allanVariance(tauAt(i));
    if (var > 0.0) total.push_back({tauAt(i), std::sqrt(var) * kDegPerSToDegPerH});
  }
  auto* model = new QwtPlotCurve(labels.model);
  model->setSamples(total);
  model->setPen(QPen(QColor(214, 39, 40), 1.8));
  model->attach(plot);
}

}  // namespace fog::ui

#include "ui/plot_data/bode_curves.h"

#include <QCoreApplication>
#include <QPen>
#include <algorithm>
#include <cmath>
#include <limits>
#include <qwt_interval_symbol.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_scale_engine.h>
#include <qwt_symbol.h>

namespace fog::ui {

namespace {

constexpr double kDegPerRad = 57.29577951308232;
// The model is drawn a little beyond the points (a quarter of an octave on
// each side), where it is still an interpolation of what was measured.
constexpr double kModelMargin = 1.19;
constexpr int kModelSamples = 200;

}  // namespace

double bodePointValue(const analysis::ResponsePoint& p, BodePart part) {
  return part == BodePart::kMagnitudeDb ? p.magnitudeDb : p.phaseDeg;
}

double bodePointStd(const analysis::ResponsePoint& p, BodePart part) {
  return part == BodePart::kMagnitudeDb ? p.magnitudeDbStd : p.phaseStdDeg;
}

double bodeModelValue(const analysis::ResponseModelFit& m, BodePart part, double f) {
  return part == BodePart::kMagnitudeDb ? 20.0 * std::log10(m.magnitudeAt(f)) : m.phaseRadAt(f) * kDegPerRad;
}

double bodePointsAt(const std::vector<analysis::ResponsePoint>& points, BodePart part, double f) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto& a = points[i];
    const auto& b = points[i + 1];
    if (f < a.frequencyHz || f > b.frequencyHz) continue;
    const double span = std::log(b.frequencyHz / a.frequencyHz);
    const double w = span > 0.0 ? std::log(f / a.frequencyHz) / span : 0.0;
    return bodePointValue(a, part) + w * (bodePointValue(b, part) - bodePointValue(a, part));
  }
  if (points.size() == 1 && f == points.front().frequencyHz) return bodePointValue(points.front(), part);
  return std::numeric_limits<double>::quiet_NaN();
}

void drawBodeCurves(QwtPlot* plot, BodePart part, const std::vector<BodeSeries>& series, const BodeLabels& labels) {
  plot->detachItems(QwtPlotItem::Rtti_PlotCurve);
  plot->detachItems(QwtPlotItem::Rtti_PlotIntervalCurve);
  plot->setAxisScaleEngine(QwtPlot::xBottom, new QwtLogScaleEngine());
  plot->setAxisTitle(QwtPlot::xBottom, labels.frequency);
  plot->setAxisTitle(QwtPlot::yLeft, labels.value);
  for (const auto& s : series) {
    if (s.points.empty()) continue;
    QVector<QPointF> points;
    QVector<QwtIntervalSample> bars;
    for (const auto& p : s.points) {
      const double v = bodePointValue(p, part), sd = bodePointStd(p, part);
      points.push_back({p.frequencyHz, v});
      bars.push_back(QwtIntervalSample(p.frequencyHz, v - sd, v + sd));
    }
    auto* errors = new QwtPlotIntervalCurve(s.name);
    errors->setSamples(bars);
    errors->setStyle(QwtPlotIntervalCurve::NoCurve);
    auto* bar = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
    bar->setWidth(7);
    bar->setPen(QPen(s.colour, 1.2));
    errors->setSymbol(bar);
    errors->setItemAttribute(QwtPlotItem::Legend, false);
    errors->attach(plot);
    auto* dots = new QwtPlotCurve(s.name);
    dots->setSamples(points);
    dots->setStyle(QwtPlotCurve::NoCurve);
    dots->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(s.colour), QPen(s.colour.darker(130)), QSize(6, 6)));
    dots->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
    dots->attach(plot);
    if (!s.model) continue;
    const double f0 = s.points.front().frequencyHz / kModelMargin, f1 = s.points.back().frequencyHz * kModelMargin;
    QVector<QPointF> line;
    for (int i = 0; i < kModelSamples; ++i) {
      const double f = f0 * std::pow(f1 / f0, static_cast<double>(i) / (kModelSamples - 1));
      const double v = bodeModelValue(*s.model, part, f);
      if (std::isfinite(v)) line.push_back({f, v});
    }
    auto* model = new QwtPlotCurve(s.modelName);
    model->setSamples(line);
    model->setPen(QPen(s.colour, 1.5));
    model->setRenderHint(QwtPlotItem::RenderAntialiased, true);
    model->setLegendAttribute(QwtPlotCurve::LegendShowLine, true);
    model->attach(plot);
  }
  // The frequency axis spans the points and the model's margin, not whole
  // decades (the log engine's autoscale would add up to a decade each side).
  double f0 = 0.0, f1 = 0.0;
  for (const auto& s : series)
    if (!s.points.empty()) {
      f0 = f0 > 0.0 ? std::min(f0, s.points.front().frequencyHz) : s.points.front().frequencyHz;
      f1 = std::max(f1, s.points.back().frequencyHz);
    }
  if (f0 > 0.0 && f1 > f0)
    plot->setAxisScale(QwtPlot::xBottom, f0 / kModelMargin, f1 * kModelMargin);
  else
    plot->setAxisAutoScale(QwtPlot::xBottom);
  plot->setAxisAutoScale(QwtPlot::yLeft);
}

QString valueWithStdText(double value, double stdDev, const QString& unit) {
  int decimals = 4;
  if (stdDev > 0.0 && std::isfinite(stdDev))
    decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(stdDev))), 0, 8);
  QString text = QString::number(value, 'f', decimals) + QStringLiteral(" ± ") + QString::number(stdDev, 'f', decimals);
  return unit.isEmpty() ? text : text + QLatin1Char(' ') + unit;
}

QString responseModelTitle(analysis::ResponseModelKind kind) {
  // Marked for lupdate in the context "BodeText", which the translation
  // script qualifies as the GUI's others ("fog::ui::BodeText").
  const char* title = "";
  switch (kind) {
    case analysis::ResponseModelKind::kDelay: title = QT_TRANSLATE_NOOP("BodeText", "pure delay"); break;
    case analysis::ResponseModelKind::kFirstOrder: title = QT_TRANSLATE_NOOP("BodeText", "delay + first-order lag"); break;
    case analysis::ResponseModelKind::kSecondOrder:
      title = QT_TRANSLATE_NOOP("BodeText", "delay + second-order (resonant)");
      break;
  }
  return QCoreApplication::translate("fog::ui::BodeText", title);
}

QString responseParametersText(const analysis::ResponseModelFit& m) {
  QStringList parts;
  for (const auto& p : m.parameters) {
    QString symbol = QString::fromStdString(p.name), unit;
    for (const auto& s : analysis::responseParameterSymbols())
      if (p.name == s.key) symbol = QString::fromUtf8(s.symbol), unit = QString::fromUtf8(s.unit);
    parts << symbol + QStringLiteral(" = ") + valueWithStdText(p.value, p.stdDev, unit);
  }
  return parts.join(QStringLiteral("; "));
}

}  // namespace fog::ui

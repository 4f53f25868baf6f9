#include "ui/report/report_plots.h"

#include <QVector>
#include <algorithm>
#include <cmath>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_plot_grid.h>
#include <qwt_scale_widget.h>
#include <qwt_symbol.h>
#include <qwt_text.h>

#include "ui/plot_data/curve_decimation.h"
#include "ui/report/page_flow.h"

namespace fog::report::detail {

namespace {

#if QWT_VERSION >= 0x060200
constexpr int kXAxis = QwtAxis::XBottom;
constexpr int kYAxis = QwtAxis::YLeft;
#else
constexpr int kXAxis = QwtPlot::xBottom;
constexpr int kYAxis = QwtPlot::yLeft;
#endif

// Thinning resolution: 300 columns per inch of print is finer than any
// printer or screen preview resolves.
constexpr double kColumnsPerMm = 300.0 / 25.4;

QwtText styled(const QString& s, double pt, bool bold) {
  QwtText t(s);
  t.setFont(PageFlow::font(pt, bold));
  return t;
}

}  // namespace

std::unique_ptr<QwtPlot> makeFramePlot(const QString& title) {
  auto plot = std::make_unique<QwtPlot>();
  plot->setFont(PageFlow::font(7.5));
  plot->setTitle(styled(title, 8.5, true));
  plot->setCanvasBackground(Qt::white);
  plot->setAutoReplot(false);
  for (int axis : {kXAxis, kYAxis}) plot->setAxisFont(axis, PageFlow::font(7.5));
  auto* legend = new QwtLegend();
  legend->setFont(PageFlow::font(7.5));
  plot->insertLegend(legend, QwtPlot::BottomLegend);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(215, 215, 215), 0, Qt::DotLine));
  grid->attach(plot.get());
  return plot;
}

void restyleAxisTitles(QwtPlot* plot) {
  for (int axis : {kXAxis, kYAxis}) plot->setAxisTitle(axis, styled(plot->axisTitle(axis).text(), 8.0, false));
}

std::unique_ptr<QwtPlot> makePlot(const PlotSpec& spec) {
  auto plot = makeFramePlot(spec.title);
  plot->setAxisTitle(kXAxis, styled(spec.xTitle, 8.0, false));
  plot->setAxisTitle(kYAxis, styled(spec.yTitle, 8.0, false));
  plot->setAxisScale(kXAxis, spec.x0, spec.x1);
  if (spec.yRange) plot->setAxisScale(kYAxis, spec.yRange->first, spec.yRange->second);

  const int columns = std::max(100, static_cast<int>(std::lround(spec.widthMm * kColumnsPerMm)));
  for (const auto& c : spec.curves) {
    auto* item = new QwtPlotCurve(c.title);
    item->setPen(c.pen);
    item->setLegendAttribute(QwtPlotCurve::LegendShowLine, !c.symbols);
    item->setLegendIconSize(QSize(22, 8));
    item->setRenderHint(QwtPlotItem::RenderAntialiased, true);
    QVector<QPointF> points;
    // A dense trace (more samples than 2 per mm of print) is drawn as its
    // envelope: per 0.5 mm column a light band from the minimum to the
    // maximum and a line through the column means, so noise reads as a band
    // around its course instead of a solid block of 300k strokes.
    const int envelopeColumns = std::max(50, static_cast<int>(std::lround(spec.widthMm * 2.0)));
    if (c.trace && !c.symbols && static_cast<int>(c.trace->x.size()) > 4 * envelopeColumns) {
      QVector<QwtIntervalSample> band;
      const auto& x = c.trace->x;
      const auto& y = c.trace->y;
      const double w = (spec.x1 - spec.x0) / envelopeColumns;
      std::size_t k = 0;
      for (int col = 0; col < envelopeColumns && w > 0.0; ++col) {
        const double a = spec.x0 + col * w, b = a + w;
        double lo = 1e300, hi = -1e300, sum = 0.0;
        int n = 0;
        while (k < x.size() && x[k] < a) ++k;
        for (; k < x.size() && x[k] < b; ++k) {
          lo = std::min(lo, y[k]);
          hi = std::max(hi, y[k]);
          sum += y[k];
          ++n;
        }
        if (n == 0) continue;
        const double mid = a + 0.5 * w;
        band.push_back(QwtIntervalSample(mid, lo * c.yScale, hi * c.yScale));
        points.push_back(QPointF(mid, sum / n * c.yScale));
      }
      auto* envelope = new QwtPlotIntervalCurve(c.title);
      envelope->setItemAttribute(QwtPlotItem::Legend, false);  // the band is the curve's own
      QColor fill = c.pen.color();
      fill.setAlpha(70);
      envelope->setBrush(fill);
      envelope->setPen(QPen(Qt::NoPen));
      envelope->setStyle(QwtPlotIntervalCurve::Tube);
      envelope->setSamples(band);
      envelope->attach(plot.get());
    } else if (c.trace) {
      points = ui::decimateMinMax(c.trace->x, c.trace->y, spec.x0, spec.x1, columns);
      for (auto& p : points) p.setY(p.y() * c.yScale);
    } else if (c.function) {
      const int n = 2 * columns + 1;
      points.reserve(n);
      for (int i = 0; i < n; ++i) {
        const double x = spec.x0 + (spec.x1 - spec.x0) * i / (n - 1);
        points.push_back(QPointF(x, c.function(x)));
      }
    }
    if (c.symbols) {
      item->setStyle(QwtPlotCurve::NoCurve);
      item->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(c.pen.color()), QPen(c.pen.color()), QSize(4, 4)));
      item->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
    }
    item->setSamples(points);
    item->attach(plot.get());
  }
  if (spec.horizontalLine) {
    auto* item = new QwtPlotCurve(spec.horizontalLineTitle);
    item->setPen(QPen(QColor(165, 15, 21), 1.2, Qt::DashLine));
    item->setLegendAttribute(QwtPlotCurve::LegendShowLine, true);
    item->setLegendIconSize(QSize(22, 8));
    item->setSamples(QVector<QPointF>{{spec.x0, *spec.horizontalLine}, {spec.x1, *spec.horizontalLine}});
    item->attach(plot.get());
  }
  return plot;
}

}  // namespace fog::report::detail

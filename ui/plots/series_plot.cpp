#include "ui/plots/series_plot.h"

#include <QResizeEvent>
#include <algorithm>
#include <cmath>
#include <limits>
#include <qwt_legend.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_textlabel.h>
#include <qwt_scale_div.h>
#include <qwt_scale_widget.h>
#include <qwt_symbol.h>
#include <qwt_text.h>

#include "ui/plot_data/curve_decimation.h"
#include "ui/plots/plot_interaction.h"

namespace fog::ui {

namespace {

#if QWT_VERSION >= 0x060200
constexpr int kTimeAxis = QwtAxis::XBottom;
constexpr int kValueAxis = QwtAxis::YLeft;
#else
constexpr int kTimeAxis = QwtPlot::xBottom;
constexpr int kValueAxis = QwtPlot::yLeft;
#endif

// Replots are coalesced: a zoom or pan changes the scale several times.
constexpr int kThinningDelayMs = 15;

}  // namespace

SeriesPlot::SeriesPlot(const QString& title, const QString& yTitle, const QString& valueUnit, QWidget* parent)
    : QwtPlot(parent) {
  setTitle(title);
  setCanvasBackground(Qt::white);
  setAxisTitle(kTimeAxis, tr("time (s)"));
  setAxisTitle(kValueAxis, yTitle);
  useCompactTitles(this);
  insertLegend(new QwtLegend(), QwtPlot::BottomLegend);

  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
  grid->attach(this);

  PlotInteraction::Options options;
  options.cursors = true;
  options.yUnit = valueUnit;
  options.xOnlyZoom = true;
  options.tracker = true;
  interaction_ = new PlotInteraction(this, options);
  interaction_->setHomeFunction([this] { showAll(); });
  interaction_->setValuesAt([this](double t) {
    PlotInteraction::Values values;
    for (int i = 0; i < curveCount(); ++i) {
      const double v = valueAt(i, t);
      if (std::isfinite(v)) values.push_back({curves_[static_cast<std::size_t>(i)].item->title().text(), v});
    }
    return values;
  });

  thinTimer_.setSingleShot(true);
  thinTimer_.setInterval(kThinningDelayMs);
  connect(&thinTimer_, &QTimer::timeout, this, &SeriesPlot::thin);
  connect(axisWidget(kTimeAxis), &QwtScaleWidget::scaleDivChanged, this, &SeriesPlot::scheduleThinning);

  emptyLabel_ = new QwtPlotTextLabel();
  emptyLabel_->attach(this);
  emptyLabel_->setVisible(false);
  showAll();
}

void SeriesPlot::setEmptyText(const QString& text) {
  QwtText label(text);
  label.setRenderFlags(Qt::AlignCenter | Qt::TextWordWrap);
  label.setColor(QColor(90, 90, 90));
  label.setBackgroundBrush(QBrush(QColor(255, 255, 255, 230)));
  emptyLabel_->setText(label);
  updateEmptyLabel();
}

bool SeriesPlot::showsEmptyText() const { return emptyLabel_->isVisible(); }

void SeriesPlot::updateEmptyLabel() {
  emptyLabel_->setVisible(curves_.empty() && !emptyLabel_->text().isEmpty());
  replot();
}

SeriesPlot::~SeriesPlot() = default;

void SeriesPlot::clearCurves() {
  for (auto& c : curves_) {
    c.item->detach();
    delete c.item;
  }
  curves_.clear();
  interaction_->dataChanged();
  updateEmptyLabel();
}

void SeriesPlot::setTimeAxis(const QString& title, double secondsPerUnit) {
  QwtText text = axisTitle(kTimeAxis);
  text.setText(title);
  setAxisTitle(kTimeAxis, text);
  interaction_->setSecondsPerX(secondsPerUnit);
}

void SeriesPlot::addData(const QString& title, const QPen& pen, std::shared_ptr<const Trace> trace, bool samples) {
  auto* item = new QwtPlotCurve(title);
  item->setPen(pen);
  if (samples)
    item->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(pen.color()), QPen(pen.color()), QSize(5, 5)));
  item->setRenderHint(QwtPlotItem::RenderAntialiased, false);
  item->setPaintAttribute(QwtPlotCurve::ClipPolygons, true);
  item->attach(this);
  curves_.push_back({item, std::move(trace), {}});
  emptyLabel_->setVisible(false);
}

void SeriesPlot::addFunction(const QString& title, const QPen& pen, std::function<double(double)> function) {
  auto* item = new QwtPlotCurve(title);
  item->setPen(pen);
  item->setRenderHint(QwtPlotItem::RenderAntialiased, true);  // smooth and sparse: cheap
  item->attach(this);
  curves_.push_back({item, nullptr, std::move(function)});
  emptyLabel_->setVisible(false);
}

void SeriesPlot::showAll() {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& c : curves_) {
    if (!c.data || c.data->x.empty()) continue;
    x0 = std::min(x0, c.data->x.front());
    x1 = std::max(x1, c.data->x.back());
    const auto [lo, hi] = std::minmax_element(c.data->y.begin(), c.data->y.end());
    y0 = std::min(y0, *lo);
    y1 = std::max(y1, *hi);
  }
  if (!(x1 > x0)) {
    x0 = 0.0;
    x1 = 1.0;
  }
  if (!(y1 > y0)) {
    y0 = std::isfinite(y0) ? y0 - 1.0 : -1.0;
    y1 = std::isfinite(y1) ? y1 + 1.0 : 1.0;
  }
  const double margin = 0.05 * (y1 - y0);
  setAxisScale(kTimeAxis, x0, x1);
  setAxisScale(kValueAxis, y0 - margin, y1 + margin);
  replot();  // settles the scales that thin() reads
  thin();
}

double SeriesPlot::valueAt(int i, double t) const {
  if (i < 0 || i >= curveCount()) return std::numeric_limits<double>::quiet_NaN();
  const auto& c = curves_[static_cast<std::size_t>(i)];
  if (c.function) return c.function(t);
  if (!c.data || c.data->x.empty() || c.data->x.size() != c.data->y.size())
    return std::numeric_limits<double>::quiet_NaN();
  const auto& x = c.data->x;
  const auto& y = c.data->y;
  if (t < x.front() || t > x.back()) return std::numeric_limits<double>::quiet_NaN();
  const auto hi = static_cast<std::size_t>(std::lower_bound(x.begin(), x.end(), t) - x.begin());
  if (hi == 0) return y.front();
  const std::size_t lo = hi - 1;
  const double span = x[hi] - x[lo];
  return span > 0.0 ? y[lo] + (y[hi] - y[lo]) * (t - x[lo]) / span : y[hi];
}

std::size_t SeriesPlot::dataPoints(int i) const {
  if (i < 0 || i >= curveCount()) return 0;
  const auto& c = curves_[static_cast<std::size_t>(i)];
  return c.data ? c.data->x.size() : 0;
}

std::size_t SeriesPlot::shownPoints(int i) const {
  if (i < 0 || i >= curveCount()) return 0;
  return curves_[static_cast<std::size_t>(i)].item->dataSize();
}

void SeriesPlot::resizeEvent(QResizeEvent* event) {
  QwtPlot::resizeEvent(event);
  scheduleThinning();
}

void SeriesPlot::scheduleThinning() { thinTimer_.start(); }

void SeriesPlot::thin() {
  thinTimer_.stop();
  const QwtScaleDiv& div = axisScaleDiv(kTimeAxis);
  const double x0 = std::min(div.lowerBound(), div.upperBound());
  const double x1 = std::max(div.lowerBound(), div.upperBound());
  const int columns = std::max(canvas()->width(), 100);
  for (auto& c : curves_) {
    if (c.data) {
      c.item->setSamples(decimateMinMax(c.data->x, c.data->y, x0, x1, columns));
    } else if (c.function && x1 > x0) {
      const int n = 2 * columns + 1;
      QVector<QPointF> points;
      points.reserve(n);
      for (int i = 0; i < n; ++i) {
        const double x = x0 + (x1 - x0) * i / (n - 1);
        points.push_back(QPointF(x, c.function(x)));
      }
      c.item->setSamples(points);
    }
  }
  replot();
}

}  // namespace fog::ui

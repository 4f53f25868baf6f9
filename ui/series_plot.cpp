#include "ui/series_plot.h"

#include <QResizeEvent>
#include <algorithm>
#include <cmath>
#include <limits>
#include <qwt_legend.h>
#include <qwt_picker_machine.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_magnifier.h>
#include <qwt_plot_panner.h>
#include <qwt_plot_picker.h>
#include <qwt_plot_zoomer.h>
#include <qwt_scale_div.h>
#include <qwt_scale_widget.h>
#include <qwt_text.h>

#include "ui/curve_decimation.h"

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

SeriesPlot::SeriesPlot(const QString& title, const QString& yTitle, QWidget* parent) : QwtPlot(parent) {
  QwtText titleText(title);
  QFont titleFont = font();
  titleFont.setBold(true);
  titleText.setFont(titleFont);
  setTitle(titleText);
  setCanvasBackground(Qt::white);
  setAxisTitle(kTimeAxis, tr("time (s)"));
  setAxisTitle(kValueAxis, yTitle);
  insertLegend(new QwtLegend(), QwtPlot::BottomLegend);

  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
  grid->attach(this);

  zoomer_ = new QwtPlotZoomer(canvas());
  zoomer_->setTrackerMode(QwtPicker::AlwaysOff);
  zoomer_->setRubberBandPen(QPen(Qt::darkGray, 0, Qt::DashLine));
  // Right button: one zoom step back; Ctrl + right button: the full view.
  zoomer_->setMousePattern(QwtEventPattern::MouseSelect2, Qt::RightButton, Qt::ControlModifier);
  zoomer_->setMousePattern(QwtEventPattern::MouseSelect3, Qt::RightButton);

  panner_ = new QwtPlotPanner(canvas());
  panner_->setMouseButton(Qt::MiddleButton);
  magnifier_ = new QwtPlotMagnifier(canvas());
  magnifier_->setMouseButton(Qt::NoButton);  // wheel only; the right button belongs to the zoomer

  picker_ = new QwtPlotPicker(kTimeAxis, kValueAxis, QwtPicker::CrossRubberBand, QwtPicker::AlwaysOn, canvas());
  picker_->setStateMachine(new QwtPickerTrackerMachine());
  picker_->setRubberBandPen(QPen(QColor(150, 150, 150), 0, Qt::DotLine));
  picker_->setTrackerPen(QPen(Qt::black));

  thinTimer_.setSingleShot(true);
  thinTimer_.setInterval(kThinningDelayMs);
  connect(&thinTimer_, &QTimer::timeout, this, &SeriesPlot::thin);
  connect(axisWidget(kTimeAxis), &QwtScaleWidget::scaleDivChanged, this, &SeriesPlot::scheduleThinning);
  showAll();
}

SeriesPlot::~SeriesPlot() = default;

void SeriesPlot::clearCurves() {
  for (auto& c : curves_) {
    c.item->detach();
    delete c.item;
  }
  curves_.clear();
}

void SeriesPlot::addData(const QString& title, const QPen& pen, std::shared_ptr<const Trace> trace) {
  auto* item = new QwtPlotCurve(title);
  item->setPen(pen);
  item->setRenderHint(QwtPlotItem::RenderAntialiased, false);
  item->setPaintAttribute(QwtPlotCurve::ClipPolygons, true);
  item->attach(this);
  curves_.push_back({item, std::move(trace), {}});
}

void SeriesPlot::addFunction(const QString& title, const QPen& pen, std::function<double(double)> function) {
  auto* item = new QwtPlotCurve(title);
  item->setPen(pen);
  item->setRenderHint(QwtPlotItem::RenderAntialiased, true);  // smooth and sparse: cheap
  item->attach(this);
  curves_.push_back({item, nullptr, std::move(function)});
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
  replot();  // settles the scales that thin() and the zoom base read
  thin();
  zoomer_->setZoomBase(false);
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

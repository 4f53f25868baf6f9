#include "ui/live_view.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPen>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <cmath>
#include <vector>

#include "core/table/stream_recorder.h"
#include <algorithm>
#include <cmath>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_picker_machine.h>
#include <qwt_plot_picker.h>
#include <qwt_scale_div.h>
#include <qwt_scale_widget.h>
#include <vector>

#include "ui/core_text.h"
#include "ui/plot_data/curve_decimation.h"
#include "ui/plots/plot_interaction.h"
#include "ui/language/language.h"

namespace fog::ui {

namespace {

const QColor kTableColour(31, 119, 180);
const QColor kGyroColour(255, 127, 14);

// Plan time of the whole run as the simulator lays it out: rest, then per
// test point settle + record + rest.
double planTotalS(const TestPlan& plan) {
  double t = plan.restBetweenS;
  for (const auto& p : plan.points) t += p.settleS + p.durationS + plan.restBetweenS;
  return t;
}

QString clockText(double s) {
  const auto whole = static_cast<long long>(std::ceil(std::max(0.0, s)));
  return QObject::tr("%1:%2").arg(whole / 60).arg(whole % 60, 2, 10, QChar('0'));
}

}  // namespace

QwtPlot* LiveView::makePlot(const QString& title, const QString& yTitle, QwtPlotCurve** curve, const QColor& colour,
                            const QString& unit) {
  auto* plot = new QwtPlot();
  plot->setTitle(title);
  plot->setAxisTitle(QwtPlot::xBottom, tr("board time (s)"));
  plot->setAxisTitle(QwtPlot::yLeft, yTitle);
  plot->setCanvasBackground(Qt::white);
  useCompactTitles(plot);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
  grid->attach(plot);
  *curve = new QwtPlotCurve(title);
  (*curve)->setPen(QPen(colour, 1.2));
  (*curve)->setRenderHint(QwtPlotItem::RenderAntialiased, false);
  (*curve)->setPaintAttribute(QwtPlotCurve::ClipPolygons, true);
  (*curve)->attach(plot);

  // The bench's one interaction (ui/plots/plot_interaction.h): wheel zooms the
  // time axis, drag pans it (both stop the scrolling), click sets cursors A
  // and B, double-click follows live again. The value axis keeps the common
  // range.
  PlotInteraction::Options options;
  options.cursors = true;
  options.yUnit = unit;
  options.zoomY = false;
  options.xOnlyZoom = true;
  options.tracker = true;
  auto* interaction = new PlotInteraction(plot, options);
  interaction->setHomeFunction([this] { setFollowing(true); });
  const QwtPlotCurve* shown = *curve;
  interaction->setValuesAt([shown](double t) {
    PlotInteraction::Values values;
    const int n = static_cast<int>(shown->dataSize());
    if (n < 2 || t < shown->sample(0).x() || t > shown->sample(n - 1).x()) return values;
    int lo = 0, hi = n - 1;  // the samples are in time order
    while (hi - lo > 1) {
      const int m = (lo + hi) / 2;
      (shown->sample(m).x() < t ? lo : hi) = m;
    }
    const QPointF a = shown->sample(lo), b = shown->sample(hi);
    values.push_back({shown->title().text(),
                      b.x() > a.x() ? a.y() + (b.y() - a.y()) * (t - a.x()) / (b.x() - a.x()) : b.y()});
    return values;
  });
  connect(interaction, &PlotInteraction::viewChangedByUser, this, [this] { setFollowing(false); });
  // Both plots show the same stretch of time (refresh() sets both while
  // following; then the link rests).
  timeLink_->add(interaction);
  plot->setAxisScale(QwtPlot::yLeft, -1.0, 1.0);  // refresh() sets both plots' common range
  return plot;
}

LiveView::LiveView(QWidget* parent) : QWidget(parent) {
  timeLink_ = new TimeAxisLink(this);
  timeLink_->setPaused(following_);
  connect(timeLink_, &TimeAxisLink::rangeChanged, this, [this] { dirty_ = true; });
  auto* layout = new QVBoxLayout(this);
  auto* state = new QHBoxLayout();
  stateLabel_ = new QLabel(tr("No run yet: configure a plan and press Run."));
  stateLabel_->setObjectName("liveStateLabel");
  stateLabel_->setWordWrap(true);  // wraps on a narrow window instead of widening it
  state->addWidget(stateLabel_, 1);
  state->addWidget(new QLabel(tr("Window")));
  windowSpin_ = new QDoubleSpinBox();
  windowSpin_->setRange(0.5, 120.0);
  windowSpin_->setValue(10.0);
  windowSpin_->setSuffix(tr(" s"));
  windowSpin_->setToolTip(tr("How much of the stream the plots show while following"));
  state->addWidget(windowSpin_);
  followButton_ = new QPushButton(tr("Follow live"));
  followButton_->setObjectName("followButton");
  followButton_->setCheckable(true);
  state->addWidget(followButton_);
  layout->addLayout(state);

  // The table's status while the bench drives it (issue 17).
  tableBox_ = new QGroupBox(tr("Turntable"));
  tableBox_->setObjectName("liveTableStatus");
  auto* tableGrid = new QGridLayout(tableBox_);
  auto makeValue = [&](const char* name) {
    auto* l = new QLabel();
    l->setObjectName(name);
    return l;
  };
  tableDriverLabel_ = makeValue("tableDriverLabel");
  tableModeLabel_ = makeValue("tableModeLabel");
  tableCommandedLabel_ = makeValue("tableCommandedLabel");
  tableMeasuredLabel_ = makeValue("tableMeasuredLabel");
  tableFaultsLabel_ = makeValue("tableFaultsLabel");
  tableGrid->addWidget(new QLabel(tr("Driver")), 0, 0);
  tableGrid->addWidget(tableDriverLabel_, 0, 1);
  tableGrid->addWidget(new QLabel(tr("Mode")), 0, 2);
  tableGrid->addWidget(tableModeLabel_, 0, 3);
  tableGrid->addWidget(new QLabel(tr("Faults / interlocks")), 0, 4);
  tableGrid->addWidget(tableFaultsLabel_, 0, 5);
  tableGrid->addWidget(new QLabel(tr("Commanded")), 1, 0);
  tableGrid->addWidget(tableCommandedLabel_, 1, 1, 1, 2);
  tableGrid->addWidget(new QLabel(tr("Measured")), 1, 3);
  tableGrid->addWidget(tableMeasuredLabel_, 1, 4, 1, 2);
  // A driven table: the runner's last step, or what the operator must set.
  tableStepLabel_ = makeValue("tableStepLabel");
  tableStepLabel_->setWordWrap(true);
  tableStepTitle_ = new QLabel(tr("Step"));
  tableGrid->addWidget(tableStepTitle_, 2, 0);
  tableGrid->addWidget(tableStepLabel_, 2, 1, 1, 5);
  tableStepTitle_->setVisible(false);
  tableStepLabel_->setVisible(false);
  tableGrid->setColumnStretch(1, 1);
  tableGrid->setColumnStretch(5, 1);
  tableBox_->setVisible(false);
  layout->addWidget(tableBox_);

  tablePlot_ = makePlot(tr("Turntable angle"), tr("angle (°)"), &tableCurve_, kTableColour, "°");
  tablePlot_->setObjectName("liveTablePlot");
  tablePlot_->setMinimumSize(200, 150);  // below the plot's own hint: fits a laptop screen
  gyroPlot_ = makePlot(tr("Gyro angle (integrated, bias + Earth rate removed)"), tr("angle (°)"), &gyroCurve_,
                       kGyroColour, "°");
  gyroPlot_->setObjectName("liveGyroPlot");
  gyroPlot_->setMinimumSize(200, 150);
  layout->addWidget(tablePlot_, 1);
  layout->addWidget(gyroPlot_, 1);

  auto* progress = new QHBoxLayout();
  progress->addWidget(new QLabel(tr("Test point")));
  pointBar_ = new QProgressBar();
  pointBar_->setObjectName("pointProgress");
  pointBar_->setRange(0, 1000);
  pointBar_->setFormat("%p%");
  progress->addWidget(pointBar_, 1);
  progress->addWidget(new QLabel(tr("Plan")));
  planBar_ = new QProgressBar();
  planBar_->setObjectName("planProgress");
  planBar_->setRange(0, 1000);
  planBar_->setFormat("%p%");
  progress->addWidget(planBar_, 2);
  remainingLabel_ = new QLabel();
  remainingLabel_->setObjectName("remainingLabel");
  remainingLabel_->setMinimumWidth(160);
  progress->addWidget(remainingLabel_);
  layout->addLayout(progress);

  connect(followButton_, &QPushButton::toggled, this, [this](bool on) { setFollowing(on); });
  connect(windowSpin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this] {
    dirty_ = true;
    refresh();
  });
  setFollowing(true);
}

void LiveView::setFollowing(bool following) {
  following_ = following;
  timeLink_->setPaused(following);
  {
    const QSignalBlocker block(followButton_);
    followButton_->setChecked(following);
  }
  if (following) {
    dirty_ = true;
    refresh();
  }
}

void LiveView::startRun(const TestPlan& plan, double speed, double benchPulseEquivalentDeg) {
  traces_.setBenchPulseEquivalent(benchPulseEquivalentDeg);
  traces_.clear();
  plan_ = plan;
  speed_ = speed;
  wall_.start();
  tableCurve_->setSamples(QVector<QPointF>());
  gyroCurve_->setSamples(QVector<QPointF>());
  setFollowing(true);
  pointBar_->setValue(0);
  planBar_->setValue(0);
  stateLabel_->setText(tr("Waiting for the first frames …"));
  running_ = true;
  updateTableStatus();
  dirty_ = true;
  refresh();
}

void LiveView::addFrames(std::span<const protocol::DecodedFrame> frames) {
  if (frames.empty()) return;
  // While the operator inspects a zoomed stretch, the history must not scroll
  // out from under them: the window of kept data is generous.
  traces_.add(frames);
  dirty_ = true;
}

void LiveView::endRun() {
  running_ = false;
  updateProgress();
  remainingLabel_->setText(tr("run ended"));
}

void LiveView::setTableDriver(const QString& driver) {
  tableDriver_ = driver;
  tableBox_->setVisible(!driver.isEmpty());
  updateTableStatus();
}

QString LiveView::tableMode() const { return tableModeLabel_->text(); }

void LiveView::setTableSnapshot(const std::optional<TableSnapshot>& snapshot) {
  snapshot_ = snapshot;
  const bool driven = snapshot_.has_value();
  tableStepTitle_->setVisible(driven);
  tableStepLabel_->setVisible(driven);
  if (!driven) {
    tableFaultsLabel_->setStyleSheet(QString());
    tableModeLabel_->setStyleSheet(QString());
    return;
  }
  // Where the runner is places the plots (the board may send no markers).
  const int i = snapshot_->point;
  if (running_ && i >= 0 && i < static_cast<int>(plan_.points.size())) {
    const TestPoint& p = plan_.points[static_cast<std::size_t>(i)];
    if (i != traces_.testPoint() || p.axis != traces_.axis() || snapshot_->phase != traces_.phase()) {
      traces_.follow(i, p.axis, p.isStatic() ? 0.0 : p.frequencyHz, snapshot_->phase);
      dirty_ = true;
    }
  }
  updateTableStatus();
}

namespace {

QString axisModeText(table::AxisMode mode) {
  switch (mode) {
    case table::AxisMode::kRest: return LiveView::tr("at rest");
    case table::AxisMode::kPositioning: return LiveView::tr("positioning");
    case table::AxisMode::kSwinging: return LiveView::tr("swinging");
    case table::AxisMode::kStopping: return LiveView::tr("stopping");
    case table::AxisMode::kEmergencyStop: return LiveView::tr("emergency stop");
    case table::AxisMode::kUnknown: break;
  }
  return LiveView::tr("unknown");
}

}  // namespace

void LiveView::updateTableStatus() {
  if (tableDriver_.isEmpty()) return;
  tableDriverLabel_->setText(tableDriver_);
  const int i = traces_.testPoint();
  const bool known = i >= 0 && i < static_cast<int>(plan_.points.size());
  const auto phase = traces_.phase();
  const bool moving = running_ && known && !plan_.points[static_cast<std::size_t>(i)].isStatic() &&
                      (phase == protocol::TestPhase::kSettling || phase == protocol::TestPhase::kRecording);
  const QString axis = QString(axisName(traces_.axis())).toUpper();
  if (snapshot_) {
    showDrivenMode();
  } else if (!running_)
    tableModeLabel_->setText(tr("at rest (run over)"));
  else if (moving)
    tableModeLabel_->setText(tr("swinging %1").arg(axis));
  else if (phase == protocol::TestPhase::kDone)
    tableModeLabel_->setText(tr("at rest (plan done)"));
  else
    tableModeLabel_->setText(i < 0 ? tr("waiting") : tr("at rest"));
  if (known && running_) {
    const TestPoint& p = plan_.points[static_cast<std::size_t>(i)];
    const double centre = p.positionDeg[static_cast<std::size_t>(p.axis)];
    // An angle as the table is commanded: three decimals, and a centre a
    // rounding away from zero reads 0 (not "-1.56e-08").
    const QString centreText = localNumber(std::abs(centre) < 5e-4 ? 0.0 : centre, 'f', 3);
    tableCommandedLabel_->setText(
        p.isStatic() ? tr("%1 at rest at %2°").arg(axis, centreText)
                     : tr("%1 %2 Hz, %3° about %4°")
                           .arg(axis, localNumber(p.frequencyHz, 'g', 6), localNumber(p.amplitudeDeg, 'g', 6),
                                centreText));
  } else {
    tableCommandedLabel_->setText(tr("—"));
  }
  // Measured from the table-angle stream: the last max(2 periods, 1 s).
  measuredAmplitudeDeg_ = NAN;
  measuredFrequencyHz_ = NAN;
  if (moving) {
    const TestPoint& p = plan_.points[static_cast<std::size_t>(i)];
    const double spanS = std::max(2.0 / p.frequencyHz, 1.0);
    const auto& points = traces_.table();
    std::vector<TableSample> samples;
    const auto ax = static_cast<std::size_t>(traces_.axis());
    if (!points.empty() && points.back().timeS - points.front().timeS >= spanS)
      for (const auto& pt : points)
        if (pt.timeS >= points.back().timeS - spanS) {
          TableSample t;
          t.timeS = pt.timeS;
          t.angleDeg[ax] = pt.angleDeg;
          samples.push_back(t);
        }
    const auto fit = table::fitSwing(samples, traces_.axis(), p.frequencyHz);
    if (fit.ok) {
      measuredAmplitudeDeg_ = fit.amplitudeDeg;
      measuredFrequencyHz_ = fit.frequencyHz;
    }
  }
  tableMeasuredLabel_->setText(std::isnan(measuredAmplitudeDeg_)
                                   ? tr("—")
                                   : tr("%1 %2 Hz, %3°")
                                         .arg(axis, localNumber(measuredFrequencyHz_, 'f', 4),
                                              localNumber(measuredAmplitudeDeg_, 'f', 3)));
  if (!snapshot_) tableFaultsLabel_->setText(tr("none reported"));
}

void LiveView::showDrivenMode() {
  const TableSnapshot& s = *snapshot_;
  const auto& st = s.state;
  // Mode: what the controller reports, per moving axis; an operator-set
  // table by what the stream shows.
  QString mode;
  if (s.finished) {
    mode = s.atRest ? tr("at rest (run over)") : tr("NOT seen at rest: check the table");
  } else if (!s.connected) {
    mode = tr("connecting");
  } else if (!st.known) {
    switch (s.phase) {
      case protocol::TestPhase::kSettling: mode = tr("set by the operator; checking the swing"); break;
      case protocol::TestPhase::kRecording: mode = tr("set by the operator; swing verified"); break;
      case protocol::TestPhase::kDone: mode = tr("at rest (plan done)"); break;
      case protocol::TestPhase::kIdle: mode = tr("set by the operator"); break;
    }
  } else if (s.stateRead) {
    QStringList moving;
    for (int a = 0; a < kAxisCount; ++a) {
      const auto& ax = st.axes[static_cast<std::size_t>(a)];
      if (ax.mode != table::AxisMode::kRest)
        moving << tr("%1 %2 (%3°, %4 °/s)")
                      .arg(axisModeText(ax.mode), QString(axisName(static_cast<Axis>(a))).toUpper(),
                           localNumber(ax.positionDeg, 'f', 2), localNumber(ax.rateDegPerS, 'f', 1));
    }
    mode = moving.isEmpty() ? tr("at rest") : moving.join(QStringLiteral("; "));
  }
  tableModeLabel_->setText(mode);
  // Faults and interlocks, as the controller reports them.
  QStringList faults;
  if (st.interlockOpen) faults << tr("interlock open");
  if (st.emergencyStopped) faults << tr("emergency stop engaged");
  if (st.heartbeatLost) faults << tr("heartbeat lost (the controller stopped the table)");
  for (const auto& f : st.faults) faults << coreText(f);
  if (!s.failure.empty()) faults << tr("run stopped: %1").arg(coreText(s.failure));
  tableFaultsLabel_->setText(faults.isEmpty() ? (st.known ? tr("none reported") : tr("not readable (manual)"))
                                              : faults.join(QStringLiteral("; ")));
  tableFaultsLabel_->setStyleSheet(faults.isEmpty() && (s.atRest || !s.finished) ? QString()
                                                                                 : QStringLiteral("color:#b00000"));
  tableModeLabel_->setStyleSheet(s.finished && !s.atRest ? QStringLiteral("color:#b00000; font-weight:bold")
                                                         : QString());
  // The operator's instruction matters most while a manual table runs.
  if (!s.instruction.empty() && !st.known) {
    tableStepTitle_->setText(tr("Operator"));
    tableStepLabel_->setText(QStringLiteral("<b>%1</b>").arg(coreText(s.instruction).toHtmlEscaped()));
  } else {
    tableStepTitle_->setText(tr("Step"));
    tableStepLabel_->setText(coreText(s.step).toHtmlEscaped());
  }
}

std::size_t LiveView::shownTablePoints() const { return tableCurve_->dataSize(); }
std::size_t LiveView::shownGyroPoints() const { return gyroCurve_->dataSize(); }

double LiveView::planProgress() const {
  const double total = planTotalS(plan_);
  return total > 0.0 ? std::clamp(traces_.streamTimeS() / total, 0.0, 1.0) : 0.0;
}

double LiveView::pointProgress() const {
  const int i = traces_.testPoint();
  if (i < 0 || i >= static_cast<int>(plan_.points.size()) || traces_.recordingStartS() < 0.0) return 0.0;
  const double d = plan_.points[static_cast<std::size_t>(i)].durationS;
  return d > 0.0 ? std::clamp((traces_.streamTimeS() - traces_.recordingStartS()) / d, 0.0, 1.0) : 0.0;
}

QString LiveView::remainingText() const {
  const double total = planTotalS(plan_);
  if (plan_.points.empty() || total <= 0.0) return tr("plan unknown");
  const double wallS = static_cast<double>(wall_.elapsed()) / 1e3;
  // The stream's own pace once it is measurable; the requested speed before.
  const double rate = wallS > 2.0 && traces_.streamTimeS() > 0.0 ? traces_.streamTimeS() / wallS
                      : speed_ > 0.0                             ? speed_
                                                                 : 0.0;
  if (rate <= 0.0) return tr("as fast as possible");
  return tr("%1 left of %2").arg(clockText((total - traces_.streamTimeS()) / rate)).arg(clockText(total / rate));
}

void LiveView::updateProgress() {
  updateTableStatus();
  pointBar_->setValue(static_cast<int>(std::lround(1000.0 * pointProgress())));
  planBar_->setValue(static_cast<int>(std::lround(1000.0 * planProgress())));
  remainingLabel_->setText(remainingText());
  const int i = traces_.testPoint();
  QString phase;
  switch (traces_.phase()) {
    case protocol::TestPhase::kIdle: phase = tr("board idle"); break;
    case protocol::TestPhase::kSettling: phase = tr("settling"); break;
    case protocol::TestPhase::kRecording: phase = tr("recording"); break;
    case protocol::TestPhase::kDone: phase = tr("done"); break;
  }
  if (i < 0) {
    stateLabel_->setText(tr("t = %1 s · %2").arg(localNumber(traces_.streamTimeS(), 'f', 1), phase));
    return;
  }
  stateLabel_->setText(tr("Test point %1 of %2 · %3 axis, %4 Hz · %5 · t = %6 s · gyro trend %7 °/h")
                           .arg(i + 1)
                           .arg(plan_.points.empty() ? QStringLiteral("?") : QString::number(plan_.points.size()))
                           .arg(QString(axisName(traces_.axis())).toUpper())
                           .arg(localNumber(traces_.nominalFrequencyHz(), 'g', 6))
                           .arg(phase)
                           .arg(localNumber(traces_.streamTimeS(), 'f', 1))
                           .arg(std::isnan(traces_.gyroTrendDegPerS())
                                    ? tr("— (after two periods of recording)")
                                    : localNumber(traces_.gyroTrendDegPerS() * 3600.0, 'f', 2)));
}

void LiveView::refresh() {
  if (!dirty_) return;
  dirty_ = false;
  updateProgress();
  const double now = traces_.streamTimeS();
  // Until a whole window has arrived, the stream fills it from the left.
  double x0 = std::max(0.0, now - windowSpin_->value()), x1 = std::max(now, windowSpin_->value());
  if (!following_) {
    const auto div = tablePlot_->axisScaleDiv(QwtPlot::xBottom);
    x0 = div.lowerBound();
    x1 = div.upperBound();
  }
  const int columns = std::max(tablePlot_->canvas()->width(), 100);
  std::vector<double> x, y;
  double peak = 0.0;  // the largest |angle| either plot shows
  auto draw = [&](QwtPlotCurve* curve, const auto& points) {
    x.clear();
    y.clear();
    for (const auto& p : points) {
      x.push_back(p.timeS);
      y.push_back(p.angleDeg);
    }
    const auto shown = decimateMinMax(x, y, x0, x1, columns);
    for (const auto& p : shown) peak = std::max(peak, std::abs(p.y()));
    curve->setSamples(shown);
  };
  draw(tableCurve_, traces_.table());
  draw(gyroCurve_, traces_.gyroDetrended());
  // One symmetric value range for both plots, so that the gyro's swing reads
  // against the table's at a glance.
  const double range = peak > 0.0 ? 1.1 * peak : 1.0;
  for (auto* plot : {tablePlot_, gyroPlot_}) {
    if (following_) plot->setAxisScale(QwtPlot::xBottom, x0, std::max(x1, x0 + 1e-3));
    plot->setAxisScale(QwtPlot::yLeft, -range, range);
    plot->replot();
  }
}

}  // namespace fog::ui

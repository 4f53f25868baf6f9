#include "ui/plots/plot_interaction.h"

#include <QApplication>
#include <QEvent>
#include <QFontMetrics>
#include <QLabel>
#include <QMouseEvent>
#include <QPen>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_marker.h>
#include <qwt_plot_panner.h>
#include <qwt_plot_picker.h>
#include <qwt_picker_machine.h>
#include <qwt_scale_widget.h>
#include <qwt_scale_div.h>
#include <qwt_scale_map.h>
#include <qwt_text.h>
#include <qwt_text_label.h>

#include "ui/plots/delta_picker.h"
#include "ui/language/language.h"

namespace fog::ui {

namespace {

// Qwt's axis positions (QwtPlot::Axis in Qwt 6.1, QwtAxis::Position in 6.2+).
constexpr int kYLeft = 0, kYRight = 1, kXBottom = 2, kXTop = 3;
constexpr int kClickSlopPx = 4;
const QColor kCursorColour(150, 30, 150);

QString valueText(double v, const QString& unit) {
  return localNumber(v, 'g', 4) + (unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
}

// The mouse tracker: the plot interaction's text at the mouse's x.
class CurveTracker : public QwtPlotPicker {
 public:
  CurveTracker(QWidget* canvas, const PlotInteraction* owner)
      : QwtPlotPicker(QwtPlot::xBottom, QwtPlot::yLeft, QwtPicker::CrossRubberBand, QwtPicker::AlwaysOn, canvas),
        owner_(owner) {
    setStateMachine(new QwtPickerTrackerMachine());
    setRubberBandPen(QPen(QColor(150, 150, 150), 0, Qt::DotLine));
    setTrackerPen(QPen(Qt::black));
  }

 protected:
  QwtText trackerTextF(const QPointF& pos) const override {
    QwtText text(owner_->trackerText(pos.x()));
    text.setBackgroundBrush(QColor(255, 255, 255, 220));
    return text;
  }

 private:
  const PlotInteraction* owner_;
};

// Keeps the value axis' title whole on a short plot. A title longer than
// its axis is drawn clipped at both ends ("e − offset) / ampl" of
// "(angle − offset) / amplitude"), so on every resize the title's font
// shrinks, by half points down to 7 pt, until it fits; what still does not
// fit is cut at its start, keeping the unit at its end ("…amplitude",
// "…(arcsec)"). A title the program sets later is taken as the new whole one.
class AxisTitleFitter : public QObject {
 public:
  explicit AxisTitleFitter(QwtPlot* plot) : QObject(plot), plot_(plot) {
    plot->axisWidget(kYLeft)->installEventFilter(this);
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Resize) fit();
    return QObject::eventFilter(watched, event);
  }

 private:
  void fit() {
    QwtText title = plot_->axisTitle(kYLeft);
    if (title.text() != fitted_ || title.font() != fittedFont_) {
      whole_ = title.text();
      wholeFont_ = title.font();
    }
    const int room = plot_->axisWidget(kYLeft)->height() - 6;
    if (whole_.isEmpty() || room <= 0) return;
    QFont font = wholeFont_;
    while (QFontMetrics(font).horizontalAdvance(whole_) > room && font.pointSizeF() > 7.0)
      font.setPointSizeF(std::max(7.0, font.pointSizeF() - 0.5));
    const QString text = QFontMetrics(font).elidedText(whole_, Qt::ElideLeft, room);
    fitted_ = text;
    fittedFont_ = font;
    if (text == title.text() && font == title.font()) return;
    title.setText(text);
    title.setFont(font);
    plot_->setAxisTitle(kYLeft, title);
  }

  QwtPlot* plot_;
  QString whole_, fitted_;
  QFont wholeFont_, fittedFont_;
};

}  // namespace

void useCompactTitles(QwtPlot* plot) {
  QFont titleFont = plot->font();
  titleFont.setBold(true);
  QwtText title = plot->title();
  title.setFont(titleFont);
  plot->setTitle(title);
  plot->titleLabel()->setFont(titleFont);
  for (int axis : {kYLeft, kXBottom}) {
    QwtText text = plot->axisTitle(axis);
    text.setFont(plot->font());
    // One line: a wrapped axis title lost its second line, the unit
    // ("residual" without "(arcsec)"), on a short plot.
    text.setRenderFlags(text.renderFlags() & ~Qt::TextWordWrap);
    plot->setAxisTitle(axis, text);
  }
  // (A property, not findChild: the fitter has no meta-object of its own.)
  if (!plot->property("fogAxisTitleFitter").toBool()) {
    new AxisTitleFitter(plot);
    plot->setProperty("fogAxisTitleFitter", true);
  }
}

PlotInteraction::PlotInteraction(QwtPlot* plot, Options options)
    : QObject(plot), plot_(plot), canvas_(plot->canvas()), options_(std::move(options)) {
  QWidget* canvas = canvas_;
  panner_ = new QwtPlotPanner(canvas);
  panner_->setMouseButton(Qt::LeftButton);
  Qt::Orientations pan;
  if (options_.zoomX) pan |= Qt::Horizontal;
  if (options_.zoomY && !options_.xOnlyZoom) pan |= Qt::Vertical;
  panner_->setOrientations(pan);
  // Secondary axes (a colour bar) stay put.
  panner_->setAxisEnabled(kYRight, false);
  panner_->setAxisEnabled(kXTop, false);
  connect(panner_, &QwtPlotPanner::panned, this, &PlotInteraction::viewChangedByUser);
  if (options_.tracker) new CurveTracker(canvas, this);

  hint_ = new QLabel(canvas);
  hint_->setObjectName("plotHint");
  hint_->setAttribute(Qt::WA_TransparentForMouseEvents);
  QString text = options_.xOnlyZoom && options_.zoomY
                     ? tr("wheel: zoom time (Ctrl: both axes) · drag: pan · double-click: whole view")
                     : tr("wheel: zoom · drag: pan · double-click: whole view");
  if (options_.cursors) text += tr(" · click: cursors A/B · right-click: remove them");
  hint_->setText(text);
  QFont small = hint_->font();
  small.setPointSizeF(small.pointSizeF() * 0.8);
  hint_->setFont(small);
  hint_->setStyleSheet("QLabel { color: #707070; background: rgba(255,255,255,190); padding: 1px 3px; }");

  readout_ = new QLabel(canvas);
  readout_->setObjectName("plotCursorReadout");
  readout_->setAttribute(Qt::WA_TransparentForMouseEvents);
  readout_->setStyleSheet(
      "QLabel { color: #202020; background: rgba(255,255,255,225); border: 1px solid #b070b0; padding: 2px 4px; }");
  readout_->hide();

  for (int i = 0; i < 2 && options_.cursors; ++i) {
    auto* m = new QwtPlotMarker();
    m->setLineStyle(QwtPlotMarker::VLine);
    m->setLinePen(QPen(kCursorColour, 1, Qt::DashLine));
    QwtText label(i == 0 ? QStringLiteral("A") : QStringLiteral("B"));
    label.setColor(kCursorColour);
    QFont bold = label.font();
    bold.setBold(true);
    label.setFont(bold);
    m->setLabel(label);
    m->setLabelAlignment(Qt::AlignRight | Qt::AlignTop);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->setItemAttribute(QwtPlotItem::Legend, false);
    // Attached for good (the plot owns it), shown while placed.
    m->setVisible(false);
    m->attach(plot_);
    markers_[i] = m;
  }

  clickTimer_.setSingleShot(true);
  connect(&clickTimer_, &QTimer::timeout, this, [this] { placeCursor(pendingX_); });
  canvas->installEventFilter(this);
  placeOverlays();
}

void PlotInteraction::setHome() {
  homeFunction_ = nullptr;
  home_.clear();
  for (int axis = 0; axis < 4; ++axis) {
    if (!plot_->axisEnabled(axis)) continue;
    const QwtScaleDiv& div = plot_->axisScaleDiv(axis);
    home_.push_back({axis, {div.lowerBound(), div.upperBound()}});
  }
}

void PlotInteraction::setHomeFunction(std::function<void()> home) {
  home_.clear();
  homeFunction_ = std::move(home);
}

void PlotInteraction::setValuesAt(std::function<Values(double)> valuesAt) { valuesAt_ = std::move(valuesAt); }

void PlotInteraction::setSecondsPerX(double secondsPerX) {
  options_.secondsPerX = secondsPerX > 0.0 ? secondsPerX : 1.0;
  updateReadout();
}

void PlotInteraction::resetView() {
  if (homeFunction_) {
    homeFunction_();
    return;
  }
  if (home_.empty()) return;
  for (const auto& [axis, interval] : home_) plot_->setAxisScale(axis, interval.first, interval.second);
  plot_->replot();
}

void PlotInteraction::placeCursor(double x) {
  if (!options_.cursors || !std::isfinite(x)) return;
  const int i = nextCursor_;
  cursors_[i] = x;
  markers_[i]->setXValue(x);
  markers_[i]->setVisible(true);
  nextCursor_ = 1 - i;
  updateReadout();
  plot_->replot();
}

void PlotInteraction::clearCursors() {
  for (int i = 0; i < 2; ++i) {
    cursors_[i].reset();
    if (markers_[i]) markers_[i]->setVisible(false);
  }
  nextCursor_ = 0;
  updateReadout();
  plot_->replot();
}

int PlotInteraction::cursorCount() const { return (cursors_[0] ? 1 : 0) + (cursors_[1] ? 1 : 0); }

std::optional<double> PlotInteraction::cursor(int i) const {
  return i == 0 || i == 1 ? cursors_[i] : std::nullopt;
}

QString PlotInteraction::hint() const { return hint_->text(); }
QString PlotInteraction::readout() const { return readoutLines_.join("\n"); }
QString PlotInteraction::shownReadout() const { return readout_->isHidden() ? QString() : readout_->text(); }

void PlotInteraction::dataChanged() {
  for (int i = 0; i < 2; ++i) {
    cursors_[i].reset();
    if (markers_[i]) markers_[i]->setVisible(false);
  }
  nextCursor_ = 0;
  updateReadout();
}

QString PlotInteraction::xText(double x) const {
  if (!options_.timeAxis) return valueText(x, options_.xUnit);
  return options_.secondsPerX == 1e-3 ? tr("%1 ms").arg(localNumber(x, 'f', 4))
                                      : tr("%1 s").arg(localNumber(x * options_.secondsPerX, 'f', 4));
}

PlotInteraction::Values PlotInteraction::valuesAt(double x) const { return valuesAt_ ? valuesAt_(x) : Values{}; }

QStringList PlotInteraction::valueLines(double x) const {
  QStringList lines;
  for (const auto& [name, value] : valuesAt(x))
    lines << QString("%1: %2").arg(name.section(QStringLiteral(" ("), 0, 0), valueText(value, options_.yUnit));
  return lines;
}

QString PlotInteraction::trackerText(double x) const {
  QStringList lines;
  lines << QString("%1 = %2").arg(options_.timeAxis ? QStringLiteral("t") : options_.xName, xText(x));
  lines << valueLines(x);
  if (link_)
    for (PlotInteraction* other : link_->members())
      if (other != this) lines << other->valueLines(x);
  return lines.join("\n");
}

void PlotInteraction::updateReadout() {
  // First line: where A and B are and Δt; then a line per curve with its
  // value at A and B and the change (dropped when the canvas is too small
  // to leave the curves visible).
  const QString xName = options_.timeAxis ? QStringLiteral("t") : options_.xName;
  QStringList head;
  Values at[2];
  for (int i = 0; i < 2; ++i) {
    if (!cursors_[i]) continue;
    if (valuesAt_) at[i] = valuesAt_(*cursors_[i]);
    head << QString("%1: %2 = %3").arg(i == 0 ? "A" : "B", xName, xText(*cursors_[i]));
  }
  if (cursors_[0] && cursors_[1]) {
    const double dx = *cursors_[1] - *cursors_[0];
    head << (options_.timeAxis ? tr("B − A: Δt = %1").arg(formatDuration(dx * options_.secondsPerX))
                               : tr("B − A: Δ%1 = %2").arg(options_.xName, valueText(dx, options_.xUnit)));
  }
  QStringList lines;
  if (!head.isEmpty()) lines << head.join(QStringLiteral(" · "));
  // Per curve, by name ("gyro (integrated, trend removed)" reads as "gyro").
  QStringList names;
  for (const Values& v : at)
    for (const auto& [name, value] : v)
      if (!names.contains(name)) names << name;
  for (const QString& name : names) {
    double v[2];
    bool has[2] = {false, false};
    for (int i = 0; i < 2; ++i)
      for (const auto& [n, value] : at[i])
        if (n == name) {
          v[i] = value;
          has[i] = true;
        }
    QStringList parts;
    if (has[0]) parts << QString("A %1").arg(valueText(v[0], options_.yUnit));
    if (has[1]) parts << QString("B %1").arg(valueText(v[1], options_.yUnit));
    if (has[0] && has[1]) parts << QString("Δ %1").arg(valueText(v[1] - v[0], options_.yUnit));
    lines << QString("%1: %2").arg(name.section(QStringLiteral(" ("), 0, 0), parts.join(QStringLiteral(", ")));
  }
  readoutLines_ = lines;
  readout_->setVisible(!lines.isEmpty());
  placeOverlays();
}

void PlotInteraction::placeOverlays() {
  const QWidget* canvas = canvas_;
  hint_->adjustSize();
  hint_->move(canvas->width() - hint_->width() - 2, canvas->height() - hint_->height() - 2);
  // Only where it leaves the plot room.
  hint_->setVisible(hint_->width() + 8 < canvas->width() && 4 * hint_->height() < canvas->height());
  if (!readout_->isHidden()) {
    // As many curve lines as leave most of the canvas free.
    const int lineHeight = readout_->fontMetrics().lineSpacing();
    const int fit = std::max(1, canvas->height() / (2 * lineHeight) - 1);
    readout_->setText(readoutLines_.mid(0, std::min(fit, static_cast<int>(readoutLines_.size()))).join("\n"));
    readout_->setMaximumWidth(std::max(120, canvas->width() - 8));
    readout_->adjustSize();
    readout_->move(4, 4);
    readout_->raise();
  }
}

bool PlotInteraction::eventFilter(QObject* watched, QEvent* event) {
  if (watched != canvas_) return false;
  switch (event->type()) {
    case QEvent::Resize:
      placeOverlays();
      break;
    case QEvent::Wheel: {
      auto* we = static_cast<QWheelEvent*>(event);
      const int delta = we->angleDelta().y();
      if (delta == 0) return false;
      // Zoom about the cursor, in paint coordinates (so that log axes zoom
      // evenly): wheel forward zooms in.
      const double factor = std::pow(0.85, delta / 120.0);
#if QT_VERSION >= QT_VERSION_CHECK(5, 14, 0)
      const QPointF pos = we->position();
#else
      const QPointF pos = we->posF();
#endif
      const bool both = !options_.xOnlyZoom || (we->modifiers() & Qt::ControlModifier);
      for (int axis : {kXBottom, kYLeft}) {
        if ((axis == kXBottom && !options_.zoomX) || (axis == kYLeft && (!options_.zoomY || !both))) continue;
        if (!plot_->axisEnabled(axis)) continue;
        const QwtScaleMap map = plot_->canvasMap(axis);
        const double c = axis == kXBottom ? pos.x() : pos.y();
        const double lo = map.invTransform(c + (map.p1() - c) * factor);
        const double hi = map.invTransform(c + (map.p2() - c) * factor);
        if (std::isfinite(lo) && std::isfinite(hi) && lo != hi) plot_->setAxisScale(axis, lo, hi);
      }
      plot_->replot();
      emit viewChangedByUser();
      return true;
    }
    case QEvent::MouseButtonPress: {
      auto* me = static_cast<QMouseEvent*>(event);
      if (me->button() == Qt::LeftButton) {
        pressPos_ = me->pos();
        // A time plot pans along time; Ctrl+drag both ways. Set before the
        // panner (an earlier filter on the canvas) sees the press.
        if (options_.xOnlyZoom) {
          const bool both = (me->modifiers() & Qt::ControlModifier) && options_.zoomY;
          panner_->setMouseButton(Qt::LeftButton, me->modifiers() & Qt::ControlModifier);
          panner_->setOrientations(both ? Qt::Horizontal | Qt::Vertical : Qt::Horizontal);
        }
      }
      if (me->button() == Qt::RightButton && options_.cursors && cursorCount() > 0) {
        clearCursors();
        return true;
      }
      break;
    }
    case QEvent::MouseButtonRelease: {
      auto* me = static_cast<QMouseEvent*>(event);
      if (me->button() == Qt::LeftButton && options_.cursors &&
          (me->pos() - pressPos_).manhattanLength() <= kClickSlopPx) {
        // Placed once it is clear that this is no double-click.
        pendingX_ = plot_->invTransform(kXBottom, me->pos().x());
        clickTimer_.start(QApplication::doubleClickInterval());
      }
      break;
    }
    case QEvent::MouseButtonDblClick:
      if (static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton) {
        clickTimer_.stop();
        resetView();
        return true;
      }
      break;
    default:
      break;
  }
  return false;
}

TimeAxisLink::TimeAxisLink(QObject* parent) : QObject(parent) {}

void TimeAxisLink::add(PlotInteraction* member) {
  members_.push_back(member);
  member->link_ = this;
  QwtPlot* plot = member->plot();
  connect(plot->axisWidget(kXBottom), &QwtScaleWidget::scaleDivChanged, this, [this, member] { follow(member); });
}

std::vector<PlotInteraction*> TimeAxisLink::members() const {
  std::vector<PlotInteraction*> out;
  for (const auto& m : members_)
    if (m) out.push_back(m);
  return out;
}

void TimeAxisLink::follow(PlotInteraction* from) {
  if (paused_ || passing_) return;
  const QwtScaleDiv& div = from->plot()->axisScaleDiv(kXBottom);
  const double lower = div.lowerBound(), upper = div.upperBound();
  passing_ = true;
  for (PlotInteraction* other : members())
    if (other != from) {
      other->plot()->setAxisScale(kXBottom, lower, upper);
      other->plot()->replot();
    }
  passing_ = false;
  emit rangeChanged(lower, upper);
}

}  // namespace fog::ui

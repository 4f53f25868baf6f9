// The plots' one interaction scheme, driven with mouse events on the
// offscreen platform: clicks place cursors A and B whose readout gives Δt and
// every curve's value at both; the wheel zooms, a double-click brings back
// the whole view, a right-click removes the cursors; a plot whose time axis
// is in milliseconds reads Δt as a duration all the same.

#include <QLabel>
#include <QtTest>
#include <cmath>
#include <memory>
#include <qwt_plot_canvas.h>
#include <qwt_scale_div.h>
#include <qwt_scale_map.h>

#include "ui/plots/delta_picker.h"
#include "ui/language/language.h"
#include "ui/plots/plot_interaction.h"
#include "ui/plots/series_plot.h"

using fog::ui::PlotInteraction;
using fog::ui::SeriesPlot;
using fog::ui::Trace;

namespace {

// y = slope * (t - delay) sampled every `step` over [0, 2].
std::shared_ptr<const Trace> line(double slope, double delay, double step) {
  auto t = std::make_shared<Trace>();
  for (double x = 0.0; x <= 2.0 + 1e-12; x += step) {
    t->x.push_back(x);
    t->y.push_back(slope * (x - delay));
  }
  return t;
}

}  // namespace

class PlotInteractionTest : public QObject {
  Q_OBJECT

 private:
  static QWidget* canvas(SeriesPlot& p) { return p.canvas(); }
  static int pixelOf(SeriesPlot& p, double x) { return qRound(p.transform(QwtPlot::xBottom, x)); }
  static double pixelWidth(SeriesPlot& p) {
    const QwtScaleMap map = p.canvasMap(QwtPlot::xBottom);
    return std::abs(map.invTransform(1.0) - map.invTransform(0.0));
  }
  static void clickAt(SeriesPlot& p, int px) {
    const QPoint pos(px, canvas(p)->height() / 2);
    QTest::mouseClick(canvas(p), Qt::LeftButton, Qt::NoModifier, pos);
  }

 private slots:
  void clicksPlaceCursorsWhoseReadoutGivesDeltaTAndValues() {
    SeriesPlot plot("test", "angle (°)", "°");
    plot.resize(700, 400);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.addData("table", QPen(Qt::blue), line(2.0, 0.0, 0.001));
    plot.addData("gyro", QPen(Qt::red), line(2.0, 0.25, 0.002));
    plot.showAll();
    auto* in = plot.interaction();
    QVERIFY(in->hint().contains("wheel"));
    QCOMPARE(in->cursorCount(), 0);
    QVERIFY(in->readout().isEmpty());

    // A at t = 0.5, B at t = 1.25, by mouse.
    clickAt(plot, pixelOf(plot, 0.5));
    QTRY_COMPARE(in->cursorCount(), 1);
    clickAt(plot, pixelOf(plot, 1.25));
    QTRY_COMPARE(in->cursorCount(), 2);
    const double a = *in->cursor(0), b = *in->cursor(1);
    const double px = pixelWidth(plot);
    QVERIFY2(std::abs(a - 0.5) <= px && std::abs(b - 1.25) <= px, qPrintable(QString("A %1 B %2").arg(a).arg(b)));

    // The readout: both positions, Δt, each curve's value at A and B from
    // the data (y = 2 t and y = 2 (t - 0.25)) and its change.
    const QString text = in->readout();
    QVERIFY2(text.contains(QString("Δt = %1").arg(fog::ui::formatDuration(b - a))), qPrintable(text));
    auto number = [](double v) { return fog::ui::localNumber(v, 'g', 4); };
    const QString table = QString("table: A %1 °, B %2 °, Δ %3 °").arg(number(2.0 * a), number(2.0 * b), number(2.0 * (b - a)));
    const QString gyro = QString("gyro: A %1 °, B %2 °").arg(number(2.0 * (a - 0.25)), number(2.0 * (b - 0.25)));
    QVERIFY2(text.contains(table), qPrintable(text + "\nexpected " + table));
    QVERIFY2(text.contains(gyro), qPrintable(text + "\nexpected " + gyro));
    // Shown on the canvas.
    auto* label = plot.findChild<QLabel*>("plotCursorReadout");
    QVERIFY(label && label->isVisible());
    QCOMPARE(label->text(), text);  // the canvas has room for every line
    QCOMPARE(in->shownReadout(), text);

    // A third click moves A.
    clickAt(plot, pixelOf(plot, 1.75));
    QTRY_VERIFY(std::abs(*in->cursor(0) - 1.75) <= px);
    QCOMPARE(in->cursorCount(), 2);

    // Right-click removes them.
    QTest::mouseClick(canvas(plot), Qt::RightButton, Qt::NoModifier, QPoint(100, 100));
    QCOMPARE(in->cursorCount(), 0);
    QVERIFY(in->readout().isEmpty());
    QVERIFY(!label->isVisible());
  }

  void wheelZoomsAndDoubleClickShowsTheWhole() {
    SeriesPlot plot("test", "angle (°)");
    plot.resize(700, 400);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.addData("table", QPen(Qt::blue), line(1.0, 0.0, 0.001));
    plot.showAll();
    const QwtScaleDiv whole = plot.axisScaleDiv(QwtPlot::xBottom);
    const QPoint centre = canvas(plot)->rect().center();
    QWheelEvent wheel(QPointF(centre), QPointF(canvas(plot)->mapToGlobal(centre)), QPoint(), QPoint(0, 240),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(canvas(plot), &wheel);
    const QwtScaleDiv zoomed = plot.axisScaleDiv(QwtPlot::xBottom);
    QVERIFY2(zoomed.range() < 0.8 * whole.range(), qPrintable(QString("%1 -> %2").arg(whole.range()).arg(zoomed.range())));
    // About the mouse: the centre stays where it was.
    const double mid = 0.5 * (whole.lowerBound() + whole.upperBound());
    QVERIFY(zoomed.lowerBound() < mid && zoomed.upperBound() > mid);

    QTest::mouseDClick(canvas(plot), Qt::LeftButton, Qt::NoModifier, centre);
    const QwtScaleDiv back = plot.axisScaleDiv(QwtPlot::xBottom);
    QCOMPARE(back.lowerBound(), whole.lowerBound());
    QCOMPARE(back.upperBound(), whole.upperBound());
    // A double-click is no cursor.
    QTest::qWait(QApplication::doubleClickInterval() + 100);
    QCOMPARE(plot.interaction()->cursorCount(), 0);
  }

  // The zero-crossing overlay's axis is in ms: Δt is still a duration.
  void aMillisecondAxisReadsDeltaTAsADuration() {
    SeriesPlot plot("test", "angle (°)", "°");
    plot.setTimeAxis("time (ms)", 1e-3);
    plot.resize(700, 400);
    plot.show();
    plot.addData("table", QPen(Qt::blue), line(1.0, 0.0, 0.001));
    plot.showAll();
    auto* in = plot.interaction();
    in->placeCursor(0.2);
    in->placeCursor(0.6658);
    const QString text = in->readout();
    QVERIFY2(text.contains(QString("Δt = %1").arg(fog::ui::formatDuration((0.6658 - 0.2) * 1e-3))), qPrintable(text));
    QVERIFY2(text.contains(QString("t = %1 ms").arg(fog::ui::localNumber(0.6658, 'f', 4))), qPrintable(text));
  }

  // Two time plots of one view: a range set on either is taken by the other.
  void linkedTimeAxesFollowEachOther() {
    SeriesPlot a("a", "angle (°)", "°"), b("b", "residual (arcsec)", "″");
    for (SeriesPlot* p : {&a, &b}) {
      p->resize(600, 300);
      p->show();
      p->addData("table", QPen(Qt::blue), line(1.0, 0.0, 0.001));
      p->showAll();
    }
    fog::ui::TimeAxisLink link;
    link.add(a.interaction());
    link.add(b.interaction());
    QCOMPARE(a.interaction()->timeAxisLink(), &link);
    a.setAxisScale(QwtPlot::xBottom, 0.5, 0.75);
    a.replot();
    QCOMPARE(b.axisScaleDiv(QwtPlot::xBottom).lowerBound(), 0.5);
    QCOMPARE(b.axisScaleDiv(QwtPlot::xBottom).upperBound(), 0.75);
    // And back the other way, by the wheel on b.
    const QPoint centre = canvas(b)->rect().center();
    QWheelEvent wheel(QPointF(centre), QPointF(canvas(b)->mapToGlobal(centre)), QPoint(), QPoint(0, 240),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(canvas(b), &wheel);
    const QwtScaleDiv zoomed = b.axisScaleDiv(QwtPlot::xBottom);
    QVERIFY(zoomed.range() < 0.2);
    QCOMPARE(a.axisScaleDiv(QwtPlot::xBottom).lowerBound(), zoomed.lowerBound());
    QCOMPARE(a.axisScaleDiv(QwtPlot::xBottom).upperBound(), zoomed.upperBound());
    // A paused link passes nothing on.
    link.setPaused(true);
    a.setAxisScale(QwtPlot::xBottom, 1.0, 2.0);
    a.replot();
    QCOMPARE(b.axisScaleDiv(QwtPlot::xBottom).lowerBound(), zoomed.lowerBound());
  }

  // On a time plot the wheel zooms time only; with Ctrl both axes.
  void theWheelZoomsTimeOnlyUnlessCtrlIsHeld() {
    SeriesPlot plot("test", "angle (°)");
    plot.resize(700, 400);
    plot.show();
    plot.addData("table", QPen(Qt::blue), line(1.0, 0.0, 0.001));
    plot.showAll();
    const QwtScaleDiv x0 = plot.axisScaleDiv(QwtPlot::xBottom), y0 = plot.axisScaleDiv(QwtPlot::yLeft);
    const QPoint centre = canvas(plot)->rect().center();
    auto wheel = [&](Qt::KeyboardModifiers modifiers) {
      QWheelEvent e(QPointF(centre), QPointF(canvas(plot)->mapToGlobal(centre)), QPoint(), QPoint(0, 240),
                    Qt::NoButton, modifiers, Qt::NoScrollPhase, false);
      QApplication::sendEvent(canvas(plot), &e);
    };
    wheel(Qt::NoModifier);
    QVERIFY(plot.axisScaleDiv(QwtPlot::xBottom).range() < 0.8 * x0.range());
    QCOMPARE(plot.axisScaleDiv(QwtPlot::yLeft).lowerBound(), y0.lowerBound());
    QCOMPARE(plot.axisScaleDiv(QwtPlot::yLeft).upperBound(), y0.upperBound());
    wheel(Qt::ControlModifier);
    QVERIFY(plot.axisScaleDiv(QwtPlot::yLeft).range() < 0.8 * y0.range());
  }

  // The tracker names every curve with its value at the mouse's time, those
  // of a linked plot too.
  void theTrackerListsEveryCurveAtTheTime() {
    SeriesPlot a("a", "angle (°)", "°"), b("b", "residual (arcsec)", "″");
    a.addData("table", QPen(Qt::blue), line(2.0, 0.0, 0.001));
    a.addData("gyro (integrated)", QPen(Qt::red), line(2.0, 0.25, 0.002));
    a.addFunction("fit", QPen(Qt::black), [](double t) { return 3.0 * t; });
    b.addData("residual", QPen(Qt::green), line(-1.0, 0.0, 0.001));
    auto number = [](double v) { return fog::ui::localNumber(v, 'g', 4); };
    QString text = a.interaction()->trackerText(1.5);
    QVERIFY2(text.contains(QString("t = %1 s").arg(fog::ui::localNumber(1.5, 'f', 4))), qPrintable(text));
    QVERIFY2(text.contains(QString("table: %1 °").arg(number(3.0))), qPrintable(text));
    QVERIFY2(text.contains(QString("gyro: %1 °").arg(number(2.5))), qPrintable(text));
    QVERIFY2(text.contains(QString("fit: %1 °").arg(number(4.5))), qPrintable(text));
    QVERIFY2(!text.contains("residual"), qPrintable(text));
    fog::ui::TimeAxisLink link;
    link.add(a.interaction());
    link.add(b.interaction());
    text = a.interaction()->trackerText(1.5);
    QVERIFY2(text.contains(QString("residual: %1 ″").arg(number(-1.5))), qPrintable(text));
    QVERIFY2(text.contains(QString("gyro: %1 °").arg(number(2.5))), qPrintable(text));
    // Outside a curve's data it is left out, not invented.
    text = a.interaction()->trackerText(5.0);
    QVERIFY2(!text.contains("table:") && text.contains("fit:"), qPrintable(text));
  }
};

QTEST_MAIN(PlotInteractionTest)
#include "plot_interaction_test.moc"

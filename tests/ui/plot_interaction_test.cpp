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
};

QTEST_MAIN(PlotInteractionTest)
#include "plot_interaction_test.moc"

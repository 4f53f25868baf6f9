// The bench window as a user drives it: pick a preset, press Run, read the
// result; press Stop mid-run; and the curve thinning behind the plots.

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QtTest>
#include <cmath>
#include <vector>

#include "ui/curve_decimation.h"
#include "ui/main_window.h"
#include "ui/series_plot.h"

using fog::ui::MainWindow;

class BenchUiTest : public QObject {
  Q_OBJECT

 private:
  static void choosePreset(MainWindow& window, const QString& name) {
    auto* combo = window.findChild<QComboBox*>("presetCombo");
    QVERIFY(combo);
    const int i = combo->findData(name);
    QVERIFY(i >= 0);
    combo->setCurrentIndex(i);
  }
  static void clickButton(MainWindow& window, const char* name) {
    auto* button = window.findChild<QPushButton*>(name);
    QVERIFY(button);
    QVERIFY(button->isEnabled());
    QTest::mouseClick(button, Qt::LeftButton);
  }

 private slots:
  // Quick preset, 1 Hz / 3 deg for 20 s with the paper's delays: the bench
  // must show the paper's 0.4658 ms lag, its report and both plots.
  void quickRunShowsThePaperLag() {
    MainWindow window;
    window.resize(1200, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy ended(&window, &MainWindow::runEnded);
    choosePreset(window, "quick");
    clickButton(window, "runButton");
    QVERIFY(window.isRunning());

    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 120000);
    QCOMPARE(ended.size(), 1);
    QCOMPARE(ended.front().front().toBool(), true);
    const auto* report = window.lastReport();
    QVERIFY(report);
    QCOMPARE(report->points.size(), std::size_t(1));
    QVERIFY2(std::abs(report->points.front().lagMs - 0.4658) < 0.01,
             qPrintable(QString("lag %1 ms").arg(report->points.front().lagMs)));
    QVERIFY(window.reportText().contains("simulator truth: lag 0.4658"));
    QVERIFY(window.findChild<QLabel*>("lagLabel")->text().contains("lag 0.46"));
    QVERIFY(window.findChild<QLabel*>("framesLabel")->text().contains("checksum failures: 0"));

    // Angles: table, gyro, and the two fits; residuals: gyro and table.
    auto* angles = window.anglePlot();
    auto* residuals = window.residualPlot();
    QCOMPARE(angles->curveCount(), 4);
    QCOMPARE(residuals->curveCount(), 2);
    QVERIFY(angles->dataPoints(0) > 15000);  // 20 s of 1 ms table samples
    QVERIFY(angles->dataPoints(1) > 7000);   // 20 s of 2 ms IMU frames
    for (int i = 0; i < angles->curveCount(); ++i) {
      QVERIFY(angles->shownPoints(i) > 100);
      QVERIFY(angles->shownPoints(i) <= std::size_t(4 * angles->canvas()->width() + 2) ||
              angles->shownPoints(i) == angles->dataPoints(i));
    }
    QVERIFY(angles->shownPoints(0) < angles->dataPoints(0));  // thinned, not all 20k points
    for (int i = 0; i < residuals->curveCount(); ++i) QVERIFY(residuals->shownPoints(i) > 100);
    QVERIFY(!window.findChild<QPushButton*>("stopButton")->isEnabled());
  }

  // Stop during the paper plan ends the run without a result, and the next
  // run works. Stop follows Run at once: the whole plan takes well under a
  // second on a fast machine, so waiting for progress first would race.
  void stopCancelsARunAndLeavesTheWindowUsable() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy ended(&window, &MainWindow::runEnded);
    choosePreset(window, "paper");
    clickButton(window, "runButton");
    QVERIFY(window.isRunning());
    QVERIFY(!window.findChild<QPushButton*>("runButton")->isEnabled());
    clickButton(window, "stopButton");

    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QCOMPARE(ended.front().front().toBool(), false);
    QVERIFY(!window.isRunning());
    QVERIFY(window.lastReport() == nullptr);
    QCOMPARE(window.anglePlot()->curveCount(), 0);
    QVERIFY(window.findChild<QPushButton*>("runButton")->isEnabled());
    QVERIFY(!window.findChild<QPushButton*>("stopButton")->isEnabled());

    choosePreset(window, "quick");
    clickButton(window, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(ended.size() == 2, 120000);
    QCOMPARE(ended.back().front().toBool(), true);
    QVERIFY(window.lastReport());
  }

  // Closing the window mid-run cancels the worker: no crash, no hang.
  void destroyingTheWindowMidRunCancelsTheWorker() {
    auto window = std::make_unique<MainWindow>();
    window->show();
    choosePreset(*window, "paper");
    clickButton(*window, "runButton");
    QVERIFY(window->isRunning());
    QElapsedTimer clock;
    clock.start();
    window.reset();
    QVERIFY(clock.elapsed() < 5000);
  }

  // Thinning keeps each column's extremes, bounds the point count, and keeps
  // sparse data whole.
  void decimationKeepsExtremesAndBoundsThePointCount() {
    std::vector<double> x(100000), y(100000);
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = static_cast<double>(i) * 1e-3;
      y[i] = std::sin(x[i]) + (i == 54321 ? 5.0 : 0.0);  // one spike
    }
    const auto thinned = fog::ui::decimateMinMax(x, y, 0.0, 100.0, 500);
    QVERIFY(thinned.size() <= 4 * 500 + 2);
    QVERIFY(thinned.size() >= 2 * 500);
    double top = -10.0;
    for (const auto& p : thinned) top = std::max(top, p.y());
    QCOMPARE(top, y[54321]);
    for (int i = 1; i < thinned.size(); ++i) QVERIFY(thinned[i].x() >= thinned[i - 1].x());

    const auto zoomed = fog::ui::decimateMinMax(x, y, 10.0, 10.5, 500);  // 501 points in range
    QVERIFY(zoomed.size() == 503);  // all of them plus one neighbour each side
    QCOMPARE(zoomed.front().x(), x[9999]);
    QVERIFY(fog::ui::decimateMinMax(x, y, 1.0, 1.0, 500).isEmpty());
    QVERIFY(fog::ui::decimateMinMax({}, {}, 0.0, 1.0, 500).isEmpty());
  }
};

QTEST_MAIN(BenchUiTest)
#include "bench_ui_test.moc"

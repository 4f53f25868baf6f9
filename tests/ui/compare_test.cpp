// Compare as a comparison: test points matched by what was tested, the
// difference B − A with its combined σ and significance (numbers worked out
// by hand below), the table and the plots driven by one selector.

#include <QComboBox>
#include <QFile>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTableWidget>
#include <QtTest>
#include <cmath>
#include <memory>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_symbol.h>
#include <qwt_text.h>

#include "ui/compare_view.h"
#include "ui/session_compare.h"

using fog::Axis;
using fog::analysis::DelayReport;
using fog::analysis::TestPointResult;

namespace {

TestPointResult point(int index, Axis axis, double hz, double ampDeg, double lagMs, double lagStdMs,
                      double tableMs, double tableStdMs) {
  TestPointResult p;
  p.index = index;
  p.axis = axis;
  p.nominalFrequencyHz = hz;
  p.tableFit.amplitudeDeg = ampDeg;
  p.lagMs = lagMs;
  p.lagStdMs = lagStdMs;
  p.imuDelayMs = lagMs + tableMs;
  p.imuDelayStdMs = std::hypot(lagStdMs, tableStdMs);
  return p;
}

DelayReport report(double tableMs, double tableStdMs, const std::vector<TestPointResult>& points) {
  DelayReport r;
  r.constants.tableReadDelayMs = tableMs;
  r.constants.tableReadDelayStdMs = tableStdMs;
  r.points = points;
  return r;
}

// A: X 0.1 Hz / 10° lag 0.4680 ± 0.0018, X 1 Hz / 3° lag 0.4660 ± 0.0002.
DelayReport reportA() {
  return report(0.05, 0.01, {point(0, Axis::kX, 0.1, 10.00003, 0.4680, 0.0018, 0.05, 0.01),
                             point(1, Axis::kX, 1.0, 3.00001, 0.4660, 0.0002, 0.05, 0.01)});
}
// B, in another order, with a point A did not test; table read delay `tableMs`.
DelayReport reportB(double tableMs) {
  return report(tableMs, 0.01, {point(0, Axis::kX, 1.0, 2.99998, 0.4700, 0.0003, tableMs, 0.01),
                                point(1, Axis::kY, 1.0, 3.0, 0.4650, 0.0003, tableMs, 0.01),
                                point(2, Axis::kX, 0.1, 9.99990, 0.4710, 0.0024, tableMs, 0.01)});
}

// A result not stored, judged against 0.8 ms as a run's would be.
fog::session::ShownVerdict judged(const DelayReport& r) { return fog::session::judgeShown(nullptr, &r, true, {}, 0.8); }

// B with its 0.1 Hz point refused: a validity check failed.
DelayReport reportBRefused() {
  DelayReport b = reportB(0.05);
  b.points[2].checks.push_back({"axis_sign", false, "the gyro turns against the table"});
  return b;
}

}  // namespace

class CompareTest : public QObject {
  Q_OBJECT

 private slots:
  void differencesWithTheirCombinedSigma() {
    const auto rows = fog::ui::compareReports(reportA(), judged(reportA()), reportB(0.05), judged(reportB(0.05)));
    QCOMPARE(rows.size(), std::size_t(3));
    // 0.1 Hz: d = 0.5210 − 0.5180 = 0.0030; same table constant, so
    // σ = √(0.0018² + 0.0024²) = 0.0030; |d|/σ = 1.0: consistent.
    QVERIFY(rows[0].both());
    QCOMPARE(*rows[0].a, std::size_t(0));
    QCOMPARE(*rows[0].b, std::size_t(2));
    QVERIFY(rows[0].commonTableConstant);
    QVERIFY(std::abs(rows[0].differenceMs - 0.0030) < 1e-12);
    QVERIFY(std::abs(rows[0].differenceStdMs - 0.0030) < 1e-12);
    QVERIFY(std::abs(rows[0].significance - 1.0) < 1e-9);
    QVERIFY(!rows[0].significant());
    // 1 Hz: d = 0.0040, σ = √(0.0002² + 0.0003²) = 0.00036056, 11.09σ: differs.
    QCOMPARE(*rows[1].b, std::size_t(0));
    QVERIFY(std::abs(rows[1].differenceMs - 0.0040) < 1e-12);
    QVERIFY(std::abs(rows[1].differenceStdMs - 0.00036056) < 1e-8);
    QVERIFY(std::abs(rows[1].significance - 11.094) < 1e-3);
    QVERIFY(rows[1].significant());
    // Y 1 Hz only in B.
    QVERIFY(!rows[2].a && rows[2].b && *rows[2].b == 1);
    QVERIFY(!rows[2].significant());
  }

  void otherTableConstantsCombineTheImuDelays() {
    // B's table read delay 0.06 ms: d = (0.4710 + 0.06) − (0.4680 + 0.05) =
    // 0.0130; σ = √(0.0018² + 0.01² + 0.0024² + 0.01²) = 0.014457.
    const auto rows = fog::ui::compareReports(reportA(), judged(reportA()), reportB(0.06), judged(reportB(0.06)));
    QVERIFY(!rows[0].commonTableConstant);
    QVERIFY(std::abs(rows[0].differenceMs - 0.0130) < 1e-12);
    QVERIFY(std::abs(rows[0].differenceStdMs - 0.014457) < 1e-6);
  }

  void theViewShowsTheDifferenceAndLinksItsSelectors() {
    fog::ui::CompareView view({"/x/a.fbs", "/x/b.fbs", "/x/c.fbs"});
    view.resize(1000, 700);
    view.show();
    auto outcome = [](DelayReport r, const char* when) {
      auto o = std::make_shared<fog::ui::RunOutcome>();
      o->info.imuModel = "FOG-3";
      o->info.imuSerial = "SN7";
      o->info.createdUtc = when;
      o->report = std::move(r);
      return std::shared_ptr<const fog::ui::RunOutcome>(o);
    };
    view.setOutcome(1, outcome(reportB(0.05), "2026-11-23T10:00:00Z"));
    QVERIFY(!view.allLoaded());
    view.setOutcome(0, outcome(reportA(), "2026-11-22T10:00:00Z"));
    view.setOutcome(2, outcome(reportA(), "2026-11-24T10:00:00Z"));
    QVERIFY(view.allLoaded());
    QCOMPARE(view.chosenA(), 0);
    QCOMPARE(view.chosenB(), 1);
    auto* table = view.differenceTable();
    QCOMPARE(table->rowCount(), 3);
    QCOMPARE(table->item(1, 3)->text(), QString("+0.0040"));
    QCOMPARE(table->item(1, 4)->text(), QString("0.0004"));
    QCOMPARE(table->item(1, 5)->text(), QString("11.1"));
    QVERIFY(table->item(1, 6)->text().contains("differs"));
    QVERIFY(table->item(0, 6)->text().contains("consistent"));
    QVERIFY(table->item(2, 6)->text().contains("only in B"));
    QVERIFY2(view.summary().contains("1 differ"), qPrintable(view.summary()));
    // One selector: a row of the table chooses the test point everywhere.
    table->setCurrentCell(1, 0);
    QCOMPARE(view.pointCombo()->currentIndex(), 1);
    view.pointCombo()->setCurrentIndex(0);
    QCOMPARE(table->currentRow(), 0);
    // The third session against the first: no differences.
    view.choose(0, 2);
    QCOMPARE(table->item(0, 3)->text(), QString("+0.0000"));
    // The trend: every session on the date axis, one series per test point kind.
    int curves = 0;
    for (const auto* item : view.trendPlot()->itemList(QwtPlotItem::Rtti_PlotCurve)) {
      ++curves;
      QVERIFY(static_cast<const QwtPlotCurve*>(item)->dataSize() >= 1);
    }
    QCOMPARE(curves, 3);  // X 0.1 Hz, X 1 Hz, Y 1 Hz
    QVERIFY(view.trendPlot()->title().text().contains("FOG-3 SN7"));
  }

  // A refused delay (INVALID) is never subtracted: no B − A, no
  // "consistent", the row and the CSV say why; the trend marks it apart.
  void aRefusedDelayIsNotCompared() {
    const DelayReport b = reportBRefused();
    const auto rows = fog::ui::compareReports(reportA(), judged(reportA()), b, judged(b));
    QVERIFY(rows[0].both());
    QVERIFY(!rows[0].comparable());
    QVERIFY(!rows[0].significant());
    QCOMPARE(rows[0].differenceMs, 0.0);
    QVERIFY(rows[1].comparable());

    fog::ui::CompareView view({"/x/a.fbs", "/x/b.fbs"});
    view.resize(1000, 700);
    auto outcome = [](DelayReport r, const char* when) {
      auto o = std::make_shared<fog::ui::RunOutcome>();
      o->info.createdUtc = when;
      o->report = std::move(r);
      return std::shared_ptr<const fog::ui::RunOutcome>(o);
    };
    view.setOutcome(0, outcome(reportA(), "2026-11-22T10:00:00Z"));
    view.setOutcome(1, outcome(b, "2026-11-23T10:00:00Z"));
    auto* table = view.differenceTable();
    QVERIFY(table->item(0, 3) == nullptr || table->item(0, 3)->text().isEmpty());
    QVERIFY2(table->item(0, 6)->text().contains("not compared: B's delay is refused (INVALID"),
             qPrintable(table->item(0, 6)->text()));
    QVERIFY(!table->item(0, 6)->text().contains("consistent"));
    QVERIFY2(table->item(0, 2)->text().startsWith("refused ("), qPrintable(table->item(0, 2)->text()));
    QVERIFY2(view.summary().contains("1 test point(s) in both are not compared"), qPrintable(view.summary()));
    // The trend: the refused delay is a cross in a series of its own, not joined.
    int refusedCurves = 0;
    for (const auto* item : view.trendPlot()->itemList(QwtPlotItem::Rtti_PlotCurve)) {
      const auto* curve = static_cast<const QwtPlotCurve*>(item);
      if (!curve->title().text().contains("refused")) continue;
      ++refusedCurves;
      QCOMPARE(curve->style(), QwtPlotCurve::NoCurve);
      QCOMPARE(curve->symbol()->style(), QwtSymbol::XCross);
      QCOMPARE(curve->dataSize(), std::size_t(1));
    }
    QCOMPARE(refusedCurves, 1);
    // The CSV: verdict columns, no difference, the reason.
    QTemporaryDir dir;
    const QString path = dir.filePath("c.csv");
    QVERIFY(view.exportTo(path).isEmpty());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    QStringList rowsText;
    for (const QString& l : lines)
      if (!l.startsWith('#')) rowsText << l;
    QVERIFY(rowsText.front().contains("a_verdict") && rowsText.front().contains("b_verdict"));
    QVERIFY2(rowsText[1].contains(",pass,") && rowsText[1].contains(",invalid,,,,") &&
                 rowsText[1].contains("not compared: B's delay is refused"),
             qPrintable(rowsText[1]));
  }

  // Two sessions with no test point in common: nothing is said of table
  // read delays (both 0.05 ms here).
  void noPointInCommonSaysNothingOfTheConstants() {
    fog::ui::CompareView view({"/x/a.fbs", "/x/b.fbs"});
    auto outcome = [](DelayReport r) {
      auto o = std::make_shared<fog::ui::RunOutcome>();
      o->report = std::move(r);
      return std::shared_ptr<const fog::ui::RunOutcome>(o);
    };
    view.setOutcome(0, outcome(report(0.05, 0.01, {point(0, Axis::kZ, 2.0, 1.0, 0.47, 0.001, 0.05, 0.01)})));
    view.setOutcome(1, outcome(reportB(0.05)));
    QVERIFY2(view.summary().contains("0 test point(s) compared"), qPrintable(view.summary()));
    QVERIFY2(!view.summary().contains("table read delays differ"), qPrintable(view.summary()));
  }

  // The comparison's rows as CSV, read back: A's and B's IMU delays and
  // B − A with its σ are the comparison's numbers, one row per test point.
  void theComparisonExportsAsCsv() {
    fog::ui::CompareView view({"/x/a.fbs", "/x/b.fbs"});
    QVERIFY(!view.exportButton()->isEnabled());
    auto outcome = [](DelayReport r) {
      auto o = std::make_shared<fog::ui::RunOutcome>();
      o->report = std::move(r);
      return std::shared_ptr<const fog::ui::RunOutcome>(o);
    };
    view.setOutcome(0, outcome(reportA()));
    view.setOutcome(1, outcome(reportB(0.05)));
    QVERIFY(view.exportButton()->isEnabled());
    QTemporaryDir dir;
    const QString path = dir.filePath("c.csv");
    QVERIFY(view.exportTo(path).isEmpty());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    QVERIFY(text.contains("# A: /x/a.fbs") && text.contains("# B: /x/b.fbs"));
    QStringList rows;
    for (const QString& line : text.split('\n', Qt::SkipEmptyParts))
      if (!line.startsWith('#')) rows << line;
    QCOMPARE(rows.size(), 1 + 3);
    const QStringList header = rows.front().split(',');
    const auto& c = view.comparisons();
    for (int i = 0; i < 3; ++i) {
      const QStringList f = rows[i + 1].split(',');
      QCOMPARE(f.size(), header.size());
      const auto& r = c[static_cast<std::size_t>(i)];
      QCOMPARE(f[header.indexOf("b_imu_delay_ms")].toDouble(), r.bMs);
      if (r.both()) {
        QCOMPARE(f[header.indexOf("a_imu_delay_ms")].toDouble(), r.aMs);
        QCOMPARE(f[header.indexOf("difference_ms")].toDouble(), r.differenceMs);
        QCOMPARE(f[header.indexOf("difference_std_ms")].toDouble(), r.differenceStdMs);
      } else {
        QVERIFY(f[header.indexOf("a_imu_delay_ms")].isEmpty());
        QVERIFY(f[header.indexOf("difference_ms")].isEmpty());
      }
    }
    // The 1 Hz row: 0.4700 + 0.05 against 0.4660 + 0.05.
    QVERIFY(std::abs(rows[2].split(',')[header.indexOf("difference_ms")].toDouble() - 0.0040) < 1e-12);
  }
};

QTEST_MAIN(CompareTest)
#include "compare_test.moc"

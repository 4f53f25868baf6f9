// Units (ui/units_view.h): the catalog of a folder of sessions recorded by
// fogbench-cli, indexed in the background; the units it lists, a unit's
// history, a refused result never plotted as a value, a lot's statistics,
// and a result opened in Results through the window's own path.

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_text.h>

#include "core/catalog/catalog.h"
#include "ui/language/language.h"
#include "ui/main_window.h"
#include "ui/units_view.h"
#include "ui/verdict_text.h"

using fog::ui::UnitsView;

namespace {

// Curves of a plot, by title: PASS and FAIL are values, "refused …" marks.
struct Plotted {
  int values = 0, refused = 0, joined = 0;
  std::vector<double> ys;
};
Plotted plotted(QwtPlot* plot) {
  Plotted out;
  for (QwtPlotItem* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
    auto* curve = static_cast<QwtPlotCurve*>(item);
    if (curve->style() != QwtPlotCurve::NoCurve) ++out.joined;
    const int n = static_cast<int>(curve->dataSize());
    if (curve->title().text().startsWith("refused")) {
      out.refused += n;
      continue;
    }
    out.values += n;
    for (int i = 0; i < n; ++i) out.ys.push_back(curve->sample(static_cast<size_t>(i)).y());
  }
  return out;
}

int rowOf(QTableWidget* t, const QString& text, int column = 0) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, column) && t->item(r, column)->text() == text) return r;
  return -1;
}

}  // namespace

class UnitsViewTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString invalidSession_;

  bool cli(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(FOG_CLI), args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
      qWarning() << "fogbench-cli" << args << "failed:" << p.readAllStandardError();
      return false;
    }
    return true;
  }
  // fogbench-cli's stdout, or "" when it failed.
  QByteArray cliOutput(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(FOG_CLI), args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
      qWarning() << "fogbench-cli" << args << "failed:" << p.readAllStandardError();
      return {};
    }
    return p.readAllStandardOutput();
  }

  std::vector<fog::catalog::CatalogResult> catalogResults(const std::string& serial) {
    auto db = fog::catalog::CatalogDb::open(dir_.filePath("fogbench-catalog.sqlite").toStdString());
    if (!db) return {};
    auto cat = fog::catalog::Catalog::open(std::move(*db));
    if (!cat) return {};
    auto r = (*cat)->results(serial, "", false);
    return r ? *r : std::vector<fog::catalog::CatalogResult>{};
  }

  // A view over the folder's catalog, read (indexed by the CLI when a test
  // runs alone, before the indexing test made it).
  std::unique_ptr<UnitsView> view() {
    if (!QFileInfo::exists(dir_.filePath("fogbench-catalog.sqlite")) && !cli({"catalog", "index", dir_.path()}))
      return nullptr;
    auto v = std::make_unique<UnitsView>();
    QSignalSpy loaded(v.get(), &UnitsView::loaded);
    v->setSessionFolder(dir_.path());
    if (!loaded.wait(20000) || !loaded.front().front().toBool()) return nullptr;
    return v;
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    // Two sessions of U-100 (lot L-7), one of U-200 (lot L-8) re-analysed
    // with the x gyro's sign reversed: its shown (second) result is INVALID.
    const struct {
      const char* file;
      const char* serial;
      const char* lot;
      int seed;
    } sessions[] = {{"a1.fbs", "U-100", "L-7", 1}, {"a2.fbs", "U-100", "L-7", 2}, {"b1.fbs", "U-200", "L-8", 3}};
    for (const auto& s : sessions)
      QVERIFY(cli({"run", "--preset", "quick", "--speed", "0", "--seed", QString::number(s.seed), "--out",
                   dir_.filePath(s.file), "--imu-serial", s.serial, "--lot", s.lot}));
    invalidSession_ = dir_.filePath("b1.fbs");
    QVERIFY(cli({"analyze", invalidSession_, "--gyro-sign", "x=-1"}));
  }

  // No catalog yet: said, with what to do; indexing makes it in the
  // background while the event loop keeps turning.
  void indexingRunsInTheBackground() {
    UnitsView v;
    QSignalSpy loaded(&v, &UnitsView::loaded);
    v.setSessionFolder(dir_.path());
    QVERIFY(loaded.wait(20000));
    QCOMPARE(loaded.front().front().toBool(), false);
    QVERIFY2(v.stateText().contains("Index folder"), qPrintable(v.stateText()));
    QVERIFY(!QFileInfo::exists(dir_.filePath("fogbench-catalog.sqlite")));  // a read never makes a catalog

    int ticks = 0;
    QTimer timer;
    connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start(1);
    QSignalSpy indexed(&v, &UnitsView::indexed);
    QSignalSpy status(&v, &UnitsView::statusMessage);
    loaded.clear();
    v.indexFolder(dir_.path());
    // Returned at once: the work is on the thread pool.
    QCOMPARE(indexed.count(), 0);
    QVERIFY(v.isIndexing());
    QVERIFY(indexed.wait(60000));
    QVERIFY(indexed.front().front().toBool());
    QVERIFY2(ticks > 0, "the event loop stood still while indexing");
    QVERIFY(loaded.wait(20000));
    QVERIFY(loaded.front().front().toBool());
    QVERIFY(!v.isIndexing());
    QVERIFY(!status.isEmpty());
    const QString last = status.back().front().toString();
    QVERIFY2(last.contains("3 session files") && last.contains("0 refused"), qPrintable(last));
  }

  void theUnitsTableListsTheUnits() {
    auto v = view();
    QVERIFY(v);
    QTableWidget* t = v->unitTable();
    QCOMPARE(t->rowCount(), 2);
    const int a = rowOf(t, "U-100"), b = rowOf(t, "U-200");
    QVERIFY(a >= 0 && b >= 0);
    QCOMPARE(t->item(a, 4)->text(), QString("2"));  // sessions
    QCOMPARE(t->item(b, 4)->text(), QString("1"));
    QCOMPARE(t->item(b, 5)->text(), QString("2"));  // results: the superseded one too
    // The latest verdict as stored, in the GUI's verdict colour.
    QCOMPARE(t->item(b, 7)->text(), fog::ui::verdictWord(std::string("invalid")));
    QCOMPARE(t->item(b, 7)->foreground().color(),
             QColor(fog::ui::verdictColour(fog::session::ShownVerdictKind::kInvalid)));
    QCOMPARE(t->item(a, 7)->text(), fog::ui::verdictWord(std::string("pass")));
  }

  // U-200's shown result is INVALID: "refused" in the history, a mark on the
  // plots, never among the plotted values; U-100's vouched points are all
  // there, at the catalog's values, and no curve joins points.
  void aRefusedResultIsNeverPlottedAsAValue() {
    auto v = view();
    QVERIFY(v);
    QVERIFY(v->selectUnit("U-200"));
    QTableWidget* h = v->historyTable();
    QCOMPARE(h->rowCount(), 2);
    int shown = -1;
    for (int r = 0; r < h->rowCount(); ++r)
      if (h->item(r, 1)->text().endsWith("shown")) shown = r;
    QVERIFY(shown >= 0);
    QCOMPARE(h->item(shown, 5)->text(), fog::ui::verdictWord(std::string("invalid")));
    QVERIFY2(h->item(shown, 6)->text().contains("refused ("), qPrintable(h->item(shown, 6)->text()));
    QVERIFY2(!h->item(shown, 6)->text().contains(" ms"), qPrintable(h->item(shown, 6)->text()));  // no number
    const int superseded = 1 - shown;
    QVERIFY(h->item(superseded, 1)->text().endsWith("superseded"));
    for (QwtPlot* plot : {v->datePlot(), v->temperaturePlot()}) {
      const Plotted p = plotted(plot);
      QCOMPARE(p.values, 0);  // the superseded PASS is not the session's result
      QVERIFY(p.refused >= 1);
      QCOMPARE(p.joined, 0);
    }

    QVERIFY(v->selectUnit("U-100"));
    QCOMPARE(h->rowCount(), 2);
    std::vector<double> expected;
    for (const auto& r : catalogResults("U-100"))
      for (const auto& pt : r.points)
        if (r.shown && pt.vouched()) expected.push_back(pt.imuDelayMs);
    QVERIFY(!expected.empty());
    const Plotted p = plotted(v->datePlot());
    QCOMPARE(p.values, static_cast<int>(expected.size()));
    QCOMPARE(p.refused, 0);
    QCOMPARE(p.joined, 0);
    auto ys = p.ys;
    std::sort(ys.begin(), ys.end());
    std::sort(expected.begin(), expected.end());
    for (std::size_t i = 0; i < ys.size(); ++i) QCOMPARE(ys[i], expected[i]);
  }

  // Lots as the sessions recorded them (a session stores its lot, schema
  // 6): the filter and the lot's statistics, the Cpk shown the catalog's
  // (`fogbench-cli catalog lot` over the same catalog).
  void aLotShowsItsStatistics() {
    auto v = view();
    QVERIFY(v);
    QCOMPARE(v->lotCombo()->count(), 3);  // all lots, L-7, L-8
    QVERIFY(v->selectLot("L-7"));
    QCOMPARE(v->unitTable()->rowCount(), 1);
    QCOMPARE(v->unitTable()->item(0, 0)->text(), QString("U-100"));
    const QString summary = v->lotSummary()->text();
    QVERIFY2(summary.contains("Lot L-7") && summary.contains("1 units, 2 sessions"), qPrintable(summary));
    QVERIFY2(summary.contains("Pass rate: 100.0 % (1 of 1)"), qPrintable(summary));
    const QJsonDocument lot = QJsonDocument::fromJson(
        cliOutput({"catalog", "lot", "L-7", "--db", dir_.filePath("fogbench-catalog.sqlite"), "--json"}));
    QVERIFY(lot.isObject());
    const QJsonArray delay = lot.object().value("imu_delay").toArray();
    QCOMPARE(delay.size(), 1);  // one axis
    const QJsonObject x = delay.at(0).toObject();
    QCOMPARE(x.value("n").toInt(), 2);  // U-100's two sessions
    QVERIFY2(x.value("cpk").isDouble(), "the catalog states no Cpk for L-7");
    const QString cpk = fog::ui::localNumber(x.value("cpk").toDouble(), 'f', 2);
    const QString line = QString("IMU delay %1: 2 points, mean %2 ms, s %3 ms, Cpk %4")
                             .arg(x.value("axis").toString(), fog::ui::localNumber(x.value("mean_ms").toDouble(), 'f', 4),
                                  fog::ui::localNumber(x.value("std_ms").toDouble(), 'f', 4), cpk);
    QVERIFY2(summary.contains(line + "<br>"), qPrintable(line + " not in " + summary));
    QVERIFY(v->lotSummary()->toolTip().contains("one-sided"));
    QVERIFY(v->selectLot("L-8"));
    const QString other = v->lotSummary()->text();
    QVERIFY2(other.contains("Pass rate: 0.0 % (0 of 1)") && other.contains("no vouched test point"), qPrintable(other));
    QVERIFY(v->selectLot(""));
    QCOMPARE(v->unitTable()->rowCount(), 2);
  }

  // Double-click on a result asks for its session; in the window, the
  // "Open in Results" button opens it there (Sessions' own path).
  void aResultOpensInResults() {
    auto v = view();
    QVERIFY(v);
    QVERIFY(v->selectUnit("U-200"));
    QSignalSpy asked(v.get(), &UnitsView::openSessionRequested);
    QTableWidget* h = v->historyTable();
    v->resize(1200, 800);
    v->show();
    QVERIFY(QTest::qWaitForWindowExposed(v.get()));
    const QRect cell = h->visualItemRect(h->item(0, 0));
    QVERIFY2(h->viewport()->rect().contains(cell.center()),
             qPrintable(QString("cell %1,%2 outside the %3x%4 viewport").arg(cell.center().x()).arg(cell.center().y())
                            .arg(h->viewport()->width()).arg(h->viewport()->height())));
    QTest::mouseClick(h->viewport(), Qt::LeftButton, {}, cell.center());
    QTest::mouseDClick(h->viewport(), Qt::LeftButton, {}, cell.center());
    QCOMPARE(asked.count(), 1);
    QCOMPARE(asked.front().front().toString(), invalidSession_);

    fog::ui::MainWindow w;
    w.setRemembering(false);
    QSignalSpy loaded(w.unitsView(), &UnitsView::loaded);
    w.setSessionFolder(dir_.path());
    QTRY_VERIFY_WITH_TIMEOUT(!loaded.isEmpty() && loaded.back().front().toBool(), 20000);
    w.showView(fog::ui::MainWindow::kUnits);
    QVERIFY(w.unitsView()->selectUnit("U-200"));
    w.unitsView()->historyTable()->selectRow(0);
    auto* open = w.unitsView()->findChild<QPushButton*>("openResultButton");
    QVERIFY(open && open->isEnabled());
    QSignalSpy opened(&w, &fog::ui::MainWindow::sessionOpened);
    open->click();
    QVERIFY(opened.wait(30000));
    QVERIFY(opened.front().front().toBool());
    QCOMPARE(w.shownSessionPath(), invalidSession_);
    QCOMPARE(w.currentView(), fog::ui::MainWindow::kResults);
  }
};

QTEST_MAIN(UnitsViewTest)
#include "units_view_test.moc"

// The desktop bench as an operator drives it, on the offscreen platform:
// edit a plan (and be told what is wrong), run on the simulator and watch it
// live, read the result, stop a run and keep what was recorded, open a saved
// session from the browser, re-analyse and export.

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QHeaderView>
#include <QLayout>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabBar>
#include <QToolButton>
#include <QCryptographicHash>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QGroupBox>
#include <QLabel>
#include <QJsonObject>
#include <QJsonDocument>
#include <QJsonArray>
#include <QProcess>
#include <QTcpSocket>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <functional>
#include <optional>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_barchart.h>
#include <qwt_scale_div.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_map.h>
#include <qwt_scale_widget.h>
#include <qwt_text.h>
#include <vector>

#include "core/common/version.h"
#include "core/acquisition/acquisition.h"
#include "core/acquisition/simulator_source.h"
#include "core/analysis/uncertainty_bound.h"
#include "core/protocol/recording_builder.h"
#include "core/diagnosis/effects.h"
#include "core/io/csv_export.h"
#include "core/session/session_file.h"
#include "ui/bench_presets.h"
#include "ui/bench_settings_dialog.h"
#include "ui/commanded_motion.h"
#include "ui/compare_view.h"
#include "ui/configure_view.h"
#include "ui/core_text.h"
#include "ui/import_dialog.h"
#include "ui/plot_data/curve_decimation.h"
#include "ui/diagnosis_view.h"
#include "ui/language/language.h"
#include "ui/plots/delta_picker.h"
#include "core/io/csv_import.h"
#include "ui/live_view.h"
#include "ui/data_export.h"
#include "ui/main_window.h"
#include "ui/messages.h"
#include "ui/noise_view.h"
#include "ui/plan_editor.h"
#include "ui/plots/plot_interaction.h"
#include "ui/plots/plot_export.h"
#include "ui/result_view.h"
#include "ui/plots/series_plot.h"
#include "ui/session_browser.h"
#include "ui/table_panel.h"
#include "ui/window_host.h"

using fog::ui::MainWindow;
using fog::ui::PlanEditor;

class BenchUiTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir sessions_;
  // This process's remembered choices (QSettings). Test mode alone is not
  // private: it puts every test process's settings in one file,
  // ~/.qttest/config/<organisation>/<program>.conf, whatever XDG_CONFIG_HOME
  // says, so UI tests running at once (ctest -j2 runs fog_ui_tests beside
  // the other UI tests; other checkouts run theirs) overwrote each other's
  // remembered session folder between a test's two windows.
  QTemporaryDir settings_;

  static QPushButton* button(QWidget& w, const char* name) {
    auto* b = w.findChild<QPushButton*>(name);
    if (!b) qFatal("no button %s", name);
    return b;
  }
  static void click(QWidget& w, const char* name) {
    auto* b = button(w, name);
    QVERIFY2(b->isEnabled(), name);
    QTest::mouseClick(b, Qt::LeftButton);
  }
  static void setValue(PlanEditor* editor, int row, PlanEditor::Column column, double value) {
    auto* spin = qobject_cast<QDoubleSpinBox*>(editor->cellEditor(row, column));
    QVERIFY(spin);
    spin->setValue(value);
  }
  static void settle() {
    for (int i = 0; i < 3; ++i) {
      QCoreApplication::sendPostedEvents();
      QCoreApplication::processEvents();
    }
  }
  static QString describe(const QWidget* w) {
    return QString("%1 '%2'").arg(w->metaObject()->className(), w->objectName());
  }
  // The deepest widgets whose minimum size exceeds `limit` (why a window
  // cannot shrink), for the failure message.
  static QStringList tooLarge(const QWidget* w, QSize limit) {
    QStringList out;
    for (const QWidget* c : w->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
      if (c->isHidden() || c->isWindow()) continue;
      out << tooLarge(c, limit);
    }
    const QSize m = w->minimumSizeHint().expandedTo(w->minimumSize());
    if (out.isEmpty() && (m.width() > limit.width() || m.height() > limit.height()))
      out << QString("%1 %2x%3").arg(describe(w)).arg(m.width()).arg(m.height());
    return out;
  }
  static QSize minimumOf(const QWidget* w) {
    QSize m = w->minimumSizeHint().expandedTo(w->minimumSize());
    if (w->layout()) m = m.expandedTo(w->layout()->minimumSize());
    return m;
  }
  // The push and tool buttons of the shown view that cannot be brought into
  // view whole: each is scrolled to (ensureWidgetVisible in its scroll area)
  // and must then lie inside the window and the scroll area's viewport at
  // its full minimum size.
  static QStringList unreachableButtons(QWidget* window) {
    QStringList bad;
    for (QAbstractButton* b : window->findChildren<QAbstractButton*>()) {
      if (!b->isVisible() || !(qobject_cast<QPushButton*>(b) || qobject_cast<QToolButton*>(b))) continue;
      if (qobject_cast<QTabBar*>(b->parentWidget())) continue;  // the tab bar's own scroll arrows
      if (b->window() != window) continue;
      QScrollArea* area = nullptr;
      for (QWidget* p = b->parentWidget(); p && !area; p = p->parentWidget()) area = qobject_cast<QScrollArea*>(p);
      if (area) area->ensureWidgetVisible(b, 0, 0);
      settle();
      const QRect r(b->mapTo(window, QPoint(0, 0)), b->size());
      // Whole: inside the window and the viewport, as wide as it asks, tall
      // enough for its text (a style may fit it a few pixels under its
      // height hint in a form row).
      bool ok = window->rect().contains(r) && b->width() >= b->minimumSizeHint().width() &&
                b->height() >= b->fontMetrics().height() + 4;
      const QRect viewport =
          area ? QRect(area->viewport()->mapTo(window, QPoint(0, 0)), area->viewport()->size()) : window->rect();
      ok = ok && viewport.contains(r);
      if (!ok)
        bad << QString("%1 (%2) at %3,%4 %5x%6, needs %7x%8, viewport %9,%10 %11x%12")
                   .arg(describe(b), b->text()).arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height())
                   .arg(b->minimumSizeHint().width()).arg(b->minimumSizeHint().height())
                   .arg(viewport.x()).arg(viewport.y()).arg(viewport.width()).arg(viewport.height());
    }
    return bad;
  }
  // The board emulator (10 s of 1 Hz / 3° on X at 5x) on a new
  // pseudo-terminal, with `extra` arguments (faults); returns the terminal
  // the emulator names on its first line, empty when it did not start.
  static QString startBoard(QProcess& board, const QStringList& extra) {
    board.setProgram(FOG_BOARD_EMU);
    board.setArguments(QStringList({"--axis", "x", "--freq-hz", "1", "--amp-deg", "3", "--duration-s", "10", "--seed",
                                    "3", "--speed", "5"}) +
                       extra);
    board.start();
    if (!board.waitForStarted(10000)) return {};
    QString pty;
    QElapsedTimer waited;
    waited.start();
    while (pty.isEmpty() && waited.elapsed() < 10000) {
      board.waitForReadyRead(100);
      while (board.canReadLine()) {
        const QString line = QString::fromUtf8(board.readLine()).trimmed();
        if (line.startsWith("pty: ")) pty = line.mid(5);
      }
    }
    return pty;
  }
  // fogbench-table-emu (localhost TCP, its board on a pseudo-terminal) at
  // `speed`, with `extra` arguments; fills the table's address and the
  // board's terminal from its first lines (empty when it did not start).
  static void startTableEmu(QProcess& emu, const QStringList& extra, QString* table, QString* board) {
    emu.setProgram(FOG_TABLE_EMU);
    emu.setArguments(QStringList({"--seed", "3", "--exit-after-s", "120"}) + extra);
    emu.setProcessChannelMode(QProcess::SeparateChannels);
    emu.start();
    if (!emu.waitForStarted(10000)) return;
    QElapsedTimer waited;
    waited.start();
    while ((table->isEmpty() || board->isEmpty()) && waited.elapsed() < 10000) {
      emu.waitForReadyRead(100);
      while (emu.canReadLine()) {
        const QString line = QString::fromUtf8(emu.readLine()).trimmed();
        if (line.startsWith("table: ")) *table = line.mid(7);
        if (line.startsWith("board: ")) *board = line.mid(7);
      }
    }
  }
  static QByteArray sha256(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
  }
  std::unique_ptr<MainWindow> window() {
    QSettings().remove("state");  // each test starts from the defaults
    QSettings().remove("diagnosis");
    QSettings().remove("layout");
    auto w = std::make_unique<MainWindow>();
    w->setSessionFolder(sessions_.path());
    w->resize(1400, 900);
    w->show();
    return w;
  }

 private slots:
  void initTestCase() {
    // Settings (bench constants, folder) go to a test location, never the user's.
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("fogbench-tests");
    QVERIFY(sessions_.isValid());
    QVERIFY(settings_.isValid());
    for (auto format : {QSettings::NativeFormat, QSettings::IniFormat})
      QSettings::setPath(format, QSettings::UserScope, settings_.path());
    // No other process can write where this one remembers.
    const QString file = QSettings().fileName();
    QVERIFY2(file.startsWith(settings_.path() + "/"), qPrintable(file));
  }

  // One test point with several problems lists every one of them, in the
  // row (wrapped, the whole text in its tooltip), at each field it is about
  // and in the plan's summary; the GUI's check agrees with the core's.
  void planCheckListsEveryProblemOfAPoint() {
    auto w = window();
    auto* editor = w->planEditor();
    QVERIFY(editor->loadPreset("paper-fast"));
    setValue(editor, 0, PlanEditor::kFrequency, 30.0);  // beyond 20 Hz
    setValue(editor, 0, PlanEditor::kAmplitude, 50.0);  // beyond 45°
    auto* check = editor->table()->item(0, PlanEditor::kCheck);
    for (const QString& expected : {QString("frequency 30 Hz is beyond the table limit of 20 Hz"),
                                    QString("amplitude 50° is beyond the table limit of 45°"),
                                    QString("peak rate 9424.78 °/s exceeds the table limit of 400 °/s")}) {
      QVERIFY2(check->toolTip().contains(expected), qPrintable(check->toolTip()));
      QVERIFY2(editor->problem().contains("test point 1: " + expected), qPrintable(editor->problem()));
    }
    QCOMPARE(editor->problem().count("test point 1:"), 4);  // frequency, amplitude, rate, acceleration
    QCOMPARE(check->text(), QString("4 problems"));  // each in the tooltip and the list below the table
    QVERIFY(editor->cellEditor(0, PlanEditor::kAmplitude)->toolTip().contains("amplitude 50°"));
    QVERIFY(!editor->cellEditor(0, PlanEditor::kAmplitude)->toolTip().contains("frequency 30 Hz"));
    QVERIFY(editor->cellEditor(0, PlanEditor::kFrequency)->toolTip().contains("frequency 30 Hz"));
    QVERIFY(editor->cellEditor(0, PlanEditor::kDuration)->toolTip().isEmpty());
    QVERIFY(!editor->problem().contains("deg"));

    // The core's problems over a grid of points, each at a column and in
    // the GUI's words: the first is validate()'s message.
    const fog::TurntableLimits limits;
    int bad = 0;
    for (double f : {-1.0, 0.0, 0.5, 5.0, 25.0})
      for (double a : {0.0, 2.0, 30.0, 60.0})
        for (double d : {0.5, 10.0, 1e5})
          for (double settle : {-1.0, 2.0})
            for (bool still : {false, true}) {
              fog::TestPoint p = still ? fog::TestPoint::staticSegment(fog::Axis::kY, d, settle) : fog::TestPoint{};
              if (!still) {
                p.frequencyHz = f;
                p.amplitudeDeg = a;
                p.durationS = d;
                p.settleS = settle;
              }
              const auto problems = PlanEditor::pointProblems(p, limits);
              const fog::Status core = p.validate(limits);
              QVERIFY2(problems.empty() == core.isOk(),
                       qPrintable(QString("f %1 a %2 d %3 settle %4 static %5: core '%6'")
                                      .arg(f).arg(a).arg(d).arg(settle).arg(still)
                                      .arg(QString::fromStdString(core.message()))));
              QCOMPARE(problems.size(), p.problems(limits).size());
              if (!problems.empty()) QCOMPARE(problems.front().text, fog::ui::coreText(core.message()));
              for (const auto& problem : problems) QVERIFY(!problem.text.contains("deg"));
              bad += core.isOk() ? 0 : 1;
            }
    QVERIFY(bad > 20);
  }

  // A value beyond the table's limits is explained next to the field, and Run
  // is refused until it is fixed; periods and duration follow each other.
  void planEditorExplainsABadValueBeforeARunCanStart() {
    auto w = window();
    auto* editor = w->planEditor();
    QVERIFY(editor->loadPreset("paper-fast"));
    QVERIFY(editor->isValid());
    QVERIFY(button(*w, "runButton")->isEnabled());
    // The preset box names the preset the plan is, and "custom plan" once it
    // is edited: never a preset the table does not hold.
    auto* presets = editor->findChild<QComboBox*>("planPresetCombo");
    QCOMPARE(presets->currentData().toString(), QString("paper-fast"));
    // Choosing a preset applies it at once (no second button).
    const int quick = presets->findData("quick");
    presets->setCurrentIndex(quick);
    emit presets->activated(quick);
    QCOMPARE(editor->plan().points.size(), fog::ui::findBenchPreset("quick")->plan.points.size());
    QCOMPARE(QString::fromStdString(fog::testPlanToJson(editor->plan())),
             QString::fromStdString(fog::testPlanToJson(fog::ui::findBenchPreset("quick")->plan)));
    QVERIFY(editor->loadPreset("paper-fast"));

    setValue(editor, 0, PlanEditor::kFrequency, 30.0);  // the table stops at 20 Hz
    QCOMPARE(presets->currentData().toString(), QString());
    QCOMPARE(presets->currentText(), QString("custom plan"));
    QVERIFY(!editor->isValid());
    const QString check = editor->table()->item(0, PlanEditor::kCheck)->toolTip();
    QVERIFY2(check.contains("frequency 30 Hz is beyond the table limit of 20 Hz"), qPrintable(check));
    QVERIFY(editor->cellEditor(0, PlanEditor::kFrequency)->toolTip().contains("beyond the table limit"));
    QVERIFY(!button(*w, "runButton")->isEnabled());
    QVERIFY(button(*w, "runButton")->toolTip().contains("test point 1: frequency 30 Hz"));
    QVERIFY(w->findChild<QLabel*>("configureMessage")->text().contains("Cannot run"));

    // Every problem is told, not only the first, in the GUI's units.
    click(*w, "addPointButton");
    setValue(editor, 1, PlanEditor::kFrequency, 1.0);
    setValue(editor, 1, PlanEditor::kAmplitude, 50.0);
    QVERIFY2(editor->problem().contains("test point 1: frequency 30 Hz") &&
                 editor->problem().contains("test point 2: amplitude 50° is beyond the table limit of 45°"),
             qPrintable(editor->problem()));
    QVERIFY(!editor->problem().contains(" deg"));
    QVERIFY(button(*w, "runButton")->toolTip().contains("test point 2: amplitude 50°"));
    // The check column's word is whole in its cell on a laptop's window
    // (the desk tests check the table's columns and rows at 1024 x 700).
    w->resize(1024, 700);
    settle();
    {
      auto* table = editor->table();
      auto* item = table->item(1, PlanEditor::kCheck);
      QCOMPARE(editor->problem().count("test point 2:"), 1);
      QCOMPARE(item->text(), QString("1 problem"));
      const QRect cell = table->visualItemRect(item);
      const int needed = table->fontMetrics().horizontalAdvance(item->text());
      QVERIFY2(needed <= cell.width(), qPrintable(QString("'%1' needs %2 px, has %3").arg(item->text()).arg(needed)
                                                     .arg(cell.width())));
    }
    editor->table()->selectRow(1);
    click(*w, "removePointButton");

    setValue(editor, 0, PlanEditor::kFrequency, 2.0);
    setValue(editor, 0, PlanEditor::kAmplitude, 3.0);
    QVERIFY(editor->isValid());
    QVERIFY(button(*w, "runButton")->isEnabled());
    // 2 Hz: 20 periods are 10 s; 0.5 s is under two periods and refused.
    setValue(editor, 0, PlanEditor::kPeriods, 20.0);
    QCOMPARE(qobject_cast<QDoubleSpinBox*>(editor->cellEditor(0, PlanEditor::kDuration))->value(), 10.0);
    setValue(editor, 0, PlanEditor::kDuration, 0.5);
    QVERIFY(editor->problem().contains("under two swing periods"));
    QVERIFY(!button(*w, "runButton")->isEnabled());

    // Several test points; removing them all is explained too.
    setValue(editor, 0, PlanEditor::kDuration, 10.0);
    click(*w, "addPointButton");
    QCOMPARE(editor->plan().points.size(), std::size_t(2));
    QVERIFY(editor->isValid());
    editor->table()->selectRow(0);
    click(*w, "removePointButton");
    editor->table()->selectRow(0);
    click(*w, "removePointButton");
    QVERIFY(editor->problem().contains("no test points"));
  }

  // Configure shows what the table is asked to do, per point, against its
  // limits: 1 Hz / 10 deg peaks at 62.83 deg/s and 394.8 deg/s^2; a point
  // beyond a limit is flagged in the cell that is over.
  void configureShowsTheCommandedMotionAgainstTheLimits() {
    auto w = window();
    auto* editor = w->planEditor();
    QVERIFY(editor->loadPreset("quick"));
    setValue(editor, 0, PlanEditor::kFrequency, 1.0);
    setValue(editor, 0, PlanEditor::kAmplitude, 10.0);
    auto* motion = w->findChild<fog::ui::CommandedMotionTable*>();
    QVERIFY(motion);
    auto* table = motion->table();
    QCOMPARE(table->rowCount(), static_cast<int>(editor->plan().points.size()));
    using M = fog::ui::CommandedMotionTable;
    const auto text = [&](int row, int column) { return table->item(row, column)->text(); };
    QCOMPARE(text(0, M::kFrequency), QString("1"));
    QCOMPARE(text(0, M::kAngle), QString("±10.00"));
    QCOMPARE(text(0, M::kRate), QString("62.83 / 400"));
    QCOMPARE(text(0, M::kAccel), QString("394.8 / 3000"));
    QCOMPARE(motion->flaggedCells(), 0);
    QVERIFY(table->item(0, M::kRate)->toolTip().isEmpty());
    QVERIFY(w->findChild<QLabel*>("commandedMotionLimits")->text().contains("the simulator's turntable"));
    // 10 Hz / 10 deg: 628 deg/s and 39478 deg/s^2, both beyond the table.
    setValue(editor, 0, PlanEditor::kFrequency, 10.0);
    QCOMPARE(text(0, M::kRate), QString("628.32 / 400"));
    QCOMPARE(text(0, M::kAccel), QString("39478.4 / 3000"));
    QCOMPARE(motion->flaggedCells(), 2);
    QVERIFY2(table->item(0, M::kRate)->toolTip().contains("peak rate beyond the table's 400 °/s on X"),
             qPrintable(table->item(0, M::kRate)->toolTip()));
    QVERIFY(!table->item(0, M::kAngle)->toolTip().contains("beyond"));
    // A controller's own limits replace the simulator's.
    fog::table::TableLimits tight;
    tight.axes[0].maxAmplitudeDeg = 5.0;
    tight.maxPositionDeg = 180.0;
    motion->setLimits(tight, "remote tcp:127.0.0.1:5025");
    QVERIFY(table->item(0, M::kAngle)->toolTip().contains("amplitude 10° is beyond the table's 5° on X"));
    QCOMPARE(motion->flaggedCells(), 3);
  }

  // Live shows the table's status while the simulator drives its table:
  // the mode, the commanded swing and the one measured from the table-angle
  // stream (within the bench's swing-check tolerances: 2 % amplitude, 0.5 %
  // frequency), no faults; Stop ends the run and the status says at rest.
  void liveShowsTheTableStatusAndStopBringsItToRest() {
    auto w = window();
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    QVERIFY(w->planEditor()->loadPreset("paper-fast"));
    const fog::TestPoint first = w->planEditor()->plan().points.at(0);
    w->useSimulator(5.0, 3);
    click(*w, "runButton");
    auto* live = w->liveView();
    QVERIFY(live->tableStatusBox()->isVisibleTo(w.get()));
    QTRY_VERIFY_WITH_TIMEOUT(std::isfinite(live->measuredAmplitudeDeg()) &&
                                 live->traces().phase() == fog::protocol::TestPhase::kRecording,
                             30000);
    const QString axis = QString(fog::axisName(first.axis)).toUpper();
    QCOMPARE(live->tableMode(), QString("swinging %1").arg(axis));
    const QString commanded = w->findChild<QLabel*>("tableCommandedLabel")->text();
    QVERIFY2(commanded.startsWith(QString("%1 %2 Hz, %3°").arg(axis).arg(first.frequencyHz).arg(first.amplitudeDeg)),
             qPrintable(commanded));
    QVERIFY2(std::abs(live->measuredAmplitudeDeg() - first.amplitudeDeg) <= 0.02 * first.amplitudeDeg,
             qPrintable(QString::number(live->measuredAmplitudeDeg())));
    QVERIFY2(std::abs(live->measuredFrequencyHz() - first.frequencyHz) <= 0.005 * first.frequencyHz,
             qPrintable(QString::number(live->measuredFrequencyHz())));
    QVERIFY(w->findChild<QLabel*>("tableMeasuredLabel")->text().startsWith(axis + " "));
    QCOMPARE(w->findChild<QLabel*>("tableFaultsLabel")->text(), QString("none reported"));
    click(*w, "stopButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QCOMPARE(live->tableMode(), QString("at rest (run over)"));
    QVERIFY(std::isnan(live->measuredAmplitudeDeg()));
    // A replay drives no table: the status is hidden.
    live->setTableDriver(QString());
    QVERIFY(!live->tableStatusBox()->isVisibleTo(w.get()));
  }

  // The quick plan on the simulator at 20x: frames appear live, then the
  // result with the paper's lag, its tables and plots, and a session file.
  void quickRunShowsItLiveThenTheResult() {
    auto w = window();
    // Before any result, Results says what to do instead of showing bare axes.
    QVERIFY2(w->resultView()->findChild<QLabel*>("lagLabel")->text().contains("run a test plan"),
             qPrintable(w->resultView()->findChild<QLabel*>("lagLabel")->text()));
    QVERIFY(w->resultView()->anglePlot()->showsEmptyText());
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    QVERIFY(w->planEditor()->loadPreset("quick"));
    w->useSimulator(20.0, 1);
    click(*w, "runButton");
    QVERIFY(w->isRunning());
    QCOMPARE(w->currentView(), MainWindow::kLive);
    // Live: frames and a drawn curve while the run is under way.
    QTRY_VERIFY_WITH_TIMEOUT(w->liveView()->traces().framesSeen() > 5000, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(w->liveView()->shownTablePoints() > 100, 5000);
    QVERIFY(w->isRunning());
    // The gyro's value axis is the table's, symmetric about zero.
    const auto tableRange = w->liveView()->tablePlot()->axisScaleDiv(QwtPlot::yLeft);
    const auto gyroRange = w->liveView()->gyroPlot()->axisScaleDiv(QwtPlot::yLeft);
    QVERIFY(tableRange.upperBound() >= 3.0);  // the 3° swing fits
    QCOMPARE(tableRange.lowerBound(), -tableRange.upperBound());
    QCOMPARE(gyroRange.lowerBound(), tableRange.lowerBound());
    QCOMPARE(gyroRange.upperBound(), tableRange.upperBound());
    QVERIFY(w->liveView()->planProgress() > 0.0);

    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 60000);
    QCOMPARE(ended.front().front().toBool(), true);
    QCOMPARE(w->currentView(), MainWindow::kResults);
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome && outcome->report);
    QVERIFY(outcome->complete);
    const double lag = outcome->report->points.front().lagMs;
    QVERIFY2(std::abs(lag - 0.4658) < 0.01, qPrintable(QString("lag %1 ms").arg(lag)));
    QVERIFY(w->resultView()->reportText().contains("simulator truth: lag 0.4658"));
    QVERIFY(w->findChild<QLabel*>("lagLabel")->text().contains("lag 0.46"));
    {
      // The verdict in the GUI's words: the IMU delay + 2σ against the limit.
      const QString verdict = w->findChild<QLabel*>("verdictLabel")->text();
      QVERIFY2(verdict.contains("<b>PASS</b>") && verdict.contains(" ms limit (margin ") &&
                   verdict.contains("IMU delay 0.5"),
               qPrintable(verdict));
    }
    QVERIFY(w->findChild<QLabel*>("framesLabel")->text().contains("checksum failures: 0"));
    // The live view saw every frame the run decoded.
    const auto& h = outcome->recording.health;
    QCOMPARE(w->liveView()->traces().framesSeen(), h.tableFrames + h.imuFrames + h.statusFrames);

    // Fit table (3- and 4-parameter fits of both channels, joint fit) and the
    // breakdown, IMU delay = lag + 0.05 ms.
    QCOMPARE(w->resultView()->fitTable()->rowCount(), 5);
    QCOMPARE(w->resultView()->delayTable()->rowCount(), 5);
    QVERIFY(w->resultView()->delayTable()->item(2, 0)->text().contains("IMU delay"));
    const double imu = w->resultView()->delayTable()->item(2, 1)->text().toDouble();
    QVERIFY(std::abs(imu - (lag + 0.05)) < 1e-4);
    auto* angles = w->resultView()->anglePlot();
    QCOMPARE(angles->curveCount(), 4);
    QVERIFY(!angles->showsEmptyText());
    QVERIFY(angles->dataPoints(0) > 15000);
    QVERIFY(angles->shownPoints(0) < angles->dataPoints(0));  // thinned
    QVERIFY(!w->resultView()->frequencyPlot()->itemList().isEmpty());

    // The zero-crossing overlay: the table fit crosses zero at 0 ms, the gyro
    // fit where the fitted lag is marked, and so do the data; cursors set at
    // the two data crossings by mouse read the lag as Δt.
    auto* zc = w->resultView()->zeroCrossingPlot();
    QCOMPARE(zc->curveCount(), 4);  // table, gyro, table fit, gyro fit
    QCOMPARE(w->resultView()->zeroCrossingLagMs(), lag);
    auto risingZero = [zc](int curve) {
      const auto div = zc->axisScaleDiv(QwtPlot::xBottom);
      double lo = div.lowerBound(), hi = div.upperBound();
      const int steps = 400;
      for (int k = 0; k < steps; ++k) {
        const double a = lo + (hi - lo) * k / steps, b = lo + (hi - lo) * (k + 1) / steps;
        if (zc->valueAt(curve, a) < 0.0 && zc->valueAt(curve, b) >= 0.0) {
          lo = a;
          hi = b;
          for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (lo + hi);
            (zc->valueAt(curve, m) < 0.0 ? lo : hi) = m;
          }
          return 0.5 * (lo + hi);
        }
      }
      return std::nan("");
    };
    const double tableFitZero = risingZero(2), gyroFitZero = risingZero(3);
    const double tableZero = risingZero(0), gyroZero = risingZero(1);
    const QString crossings = QString("table fit %1, gyro fit %2, table %3, gyro %4 ms; lag %5 ms")
                                  .arg(tableFitZero).arg(gyroFitZero).arg(tableZero).arg(gyroZero).arg(lag);
    QVERIFY2(std::abs(tableFitZero) < 1e-6, qPrintable(crossings));
    QVERIFY2(std::abs(gyroFitZero - lag) < 0.01, qPrintable(crossings));
    QVERIFY2(std::abs(gyroZero - tableZero - lag) < 0.05, qPrintable(crossings));
    auto* zcIn = zc->interaction();
    const QPoint row(0, zc->canvas()->height() / 2);
    int placed = 0;
    for (double x : {tableZero, gyroZero}) {
      QTest::mouseClick(zc->canvas(), Qt::LeftButton, Qt::NoModifier,
                        row + QPoint(qRound(zc->transform(QwtPlot::xBottom, x)), 0));
      ++placed;
      QTRY_COMPARE(zcIn->cursorCount(), placed);
      QTest::qWait(QApplication::doubleClickInterval());  // two clicks, not a double-click
    }
    const double measuredMs = *zcIn->cursor(1) - *zcIn->cursor(0);
    const auto map = zc->canvasMap(QwtPlot::xBottom);
    const double pixelMs = std::abs(map.invTransform(1.0) - map.invTransform(0.0));
    QVERIFY2(std::abs(measuredMs - (gyroZero - tableZero)) <= 2.0 * pixelMs,
             qPrintable(QString("measured %1 ms, pixel %2 ms; %3").arg(measuredMs).arg(pixelMs).arg(crossings)));
    QVERIFY2(zcIn->readout().contains(QString("Δt = %1").arg(fog::ui::formatDuration(measuredMs * 1e-3))),
             qPrintable(zcIn->readout()));
    qInfo("%s; measured by cursor %.4f ms", qPrintable(crossings), measuredMs);

    // Recorded: the session is in the folder and listed with its lag.
    QVERIFY(QFile::exists(QString::fromStdString(outcome->sessionPath)));
    w->showView(MainWindow::kSessions);
    auto* table = w->sessionBrowser()->table();
    QVERIFY(table->rowCount() >= 1);
    QVERIFY(w->sessionBrowser()->selectedPaths().contains(QString::fromStdString(outcome->sessionPath)));
    QVERIFY(!button(*w, "stopButton")->isEnabled());

    // The calibration report of what is shown.
    QTemporaryDir dir;
    const QString pdf = dir.filePath("report.pdf");
    const auto written = w->resultView()->writeReportPdf(pdf);
    QVERIFY2(written.isOk(), written.message().c_str());
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.read(8).startsWith("%PDF-1."));
  }

  // Stop mid-run: the run ends incomplete, everything received is kept,
  // stored, analysed as far as it goes, and the window is ready again.
  void stopKeepsEverythingRecordedSoFar() {
    auto w = window();
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    QVERIFY(w->planEditor()->loadPreset("paper-fast"));  // 60 s at real time
    w->useSimulator(1.0, 2);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(w->liveView()->traces().framesSeen() > 3000, 20000);  // ~2 s of stream
    click(*w, "stopButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QVERIFY(!w->isRunning());
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome);
    QVERIFY(!outcome->complete);
    QVERIFY(QString::fromStdString(outcome->incompleteReason).contains("stopped by the operator"));
    QVERIFY(w->lastMessage().contains("Run incomplete"));
    auto reader = fog::session::SessionReader::open(outcome->sessionPath);
    QVERIFY2(reader.isOk(), reader.status().message().c_str());
    QVERIFY(!(*reader)->complete());
    // Every frame the live view saw is stored; the smallest frame (TABLE) is
    // 25 bytes. The mean (26) is no bound: the mix of frames at the moment of
    // the stop varies.
    QVERIFY((*reader)->rawByteCount() >= 3000u * 25u);
    QVERIFY(button(*w, "runButton")->isEnabled());
  }

  // A stored result is a record (docs/sessions.md, "Stored results"): a
  // result stored INVALID by `fogbench-cli analyze --gyro-sign x=-1` (here
  // stored exactly as analyze stores it) is INVALID in Results, Sessions,
  // Compare and the PDF, never a re-judged PASS; a run stopped early is
  // INCOMPLETE in each. The GUI's gyro signs and limit are stored with a
  // re-analysis.
  // A point whose stated σ is 6x below its Cramér–Rao bound: the Results
  // view marks its failed check beside the σ/CRLB it shows, the verdict is
  // not PASS and the text report pane says it too.
  void aSigmaBelowTheBoundIsMarkedInResults() {
    fog::TestPlan plan;
    plan.points = {fog::TestPoint{fog::Axis::kX, 2.0, 2.0, 10.0, 0.3}};
    auto run = fog::model::simulate(fog::model::SimConfig{}, plan);
    QVERIFY(run.isOk());
    auto recording = fog::protocol::decodeRecording(run->bytes);
    QVERIFY(recording.isOk());
    auto report = fog::analysis::analyzeRecording(*recording, {});
    QVERIFY2(report.isOk(), report.status().message().c_str());
    auto& p = report->points.front();
    p.crlbMs = 6.0 * p.lagStdMs;
    p.stdOverCrlb = p.lagStdMs / p.crlbMs;
    for (auto& c : p.checks)
      if (c.id == "uncertainty_below_bound") c = fog::analysis::uncertaintyBelowBoundCheck(p);
    QVERIFY(fog::analysis::sigmaBelowBound(p));

    auto outcome = std::make_shared<fog::ui::RunOutcome>();
    outcome->info.plan = plan;
    outcome->recording = std::move(*recording);
    outcome->report = std::move(*report);
    fog::ui::completeOutcome(*outcome, "simulator");
    fog::ui::ResultView view;
    view.resize(1200, 800);
    view.showOutcome(outcome);
    QVERIFY2(view.delayTable()->item(0, 2)->text().endsWith(" ⚠"), qPrintable(view.delayTable()->item(0, 2)->text()));
    const QString note = view.delayTable()->item(0, 4)->text();
    QVERIFY2(note.contains("σ/CRLB 0.17") && note.contains("σ below the bound") &&
                 note.contains("uncertainty_below_bound"),
             qPrintable(note));
    const QString verdict = view.verdictHtml(outcome->report->points.front());
    QVERIFY2(!verdict.contains("PASS") && verdict.contains("INVALID"), qPrintable(verdict));
    QVERIFY2(view.reportText().contains("BELOW THE BOUND"), qPrintable(view.reportText()));
  }

  void storedResultsShowTheirStoredVerdict() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    fog::TestPlan plan;
    plan.points = {fog::TestPoint{fog::Axis::kX, 2.0, 2.0, 10.0, 0.3}};
    auto record = [&](const QString& path, std::function<std::optional<std::string>()> shouldEnd) {
      auto source = fog::acquisition::SimulatorSource::create(fog::model::SimConfig{}, plan, 0.0);
      QVERIFY(source.isOk());
      fog::acquisition::AcquisitionOptions options;
      options.sessionPath = path.toStdString();
      options.info.plan = plan;
      options.shouldEnd = std::move(shouldEnd);
      QVERIFY(fog::acquisition::acquire(**source, options, nullptr).isOk());
    };
    const QString reversed = dir.filePath("reversed.fbs");
    record(reversed, {});
    {
      // What `fogbench-cli analyze reversed.fbs --gyro-sign x=-1` stores.
      auto reader = fog::session::SessionReader::open(reversed.toStdString());
      QVERIFY(reader.isOk());
      auto recording = (*reader)->recording();
      QVERIFY(recording.isOk());
      auto constants = (*reader)->info().bench;
      constants.gyroSign = {-1, 1, 1};
      auto report = fog::analysis::analyzeRecording(*recording, constants);
      QVERIFY(report.isOk());
      reader->reset();
      fog::analysis::ReportContext context;
      QVERIFY(fog::session::addResult(reversed.toStdString(),
                                      fog::session::analysisSettingsJson(constants, 0.8, "fogbench-cli analyze"),
                                      fog::analysis::formatReportJson(*report, context))
                  .isOk());
    }
    // Stopped after about 3 s of its 10.3 s, as the operator's Stop does.
    const QString stopped = dir.filePath("stopped.fbs");
    int loops = 0;
    record(stopped, [&]() -> std::optional<std::string> {
      if (++loops < 12) return std::nullopt;  // 0.25 s of stream per read at full speed
      return std::string("stopped by the operator after 3.0 s");
    });

    auto w = window();
    // The GUI's own limit, k and signs are not the record's: they change nothing shown.
    w->setAnalysisChoices(fog::ui::AnalysisChoices{{1, 1, 1}, 5.0, 3.0});
    // Configure states the signs the next analysis uses, and the IMU frame.
    const QString configured = w->configureView()->findChild<QLabel*>("constantsLabel")->text();
    QVERIFY2(configured.contains("gyro signs X +1, Y +1, Z +1") && configured.contains("IMU frame "),
             qPrintable(configured));
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(reversed);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    auto* results = w->resultView();
    const QString verdict = w->findChild<QLabel*>("verdictLabel")->text();
    QVERIFY2(verdict.contains("INVALID") && !verdict.contains("PASS") && verdict.contains("stored verdict") &&
                 verdict.contains("limit 0.800 ms") && verdict.contains("turns against the table"),
             qPrintable(verdict));
    // The decision rule under it: the record's k (2), not the GUI's 3; an
    // INVALID point states no risk.
    const QString rule = w->findChild<QLabel*>("decisionRuleLabel")->text();
    QVERIFY2(rule.contains("Decision rule: PASS when IMU delay + k·σ &lt; limit (k = 2,") &&
                 rule.contains("1 − Φ(k) = 2.28 %") && rule.contains("no risk stated, its delay is refused") &&
                 !rule.contains("k = 3"),
             qPrintable(rule));
    QVERIFY2(results->resultDescription().startsWith("result 2 of 2: INVALID") &&
                 results->resultDescription().contains("gyro signs X -1, Y +1, Z +1, IMU frame "),
             qPrintable(results->resultDescription()));
    // The headline never shows the refused delay bare; the title names it all.
    const QString headline = w->findChild<QLabel*>("lagLabel")->text();
    QVERIFY2(headline.contains("delay refused (INVALID)") && !headline.contains("<b>lag"), qPrintable(headline));
    QVERIFY2(w->windowTitle().startsWith("reversed.fbs, result 2 of 2: INVALID"), qPrintable(w->windowTitle()));
    // Re-analysed with exactly the stored settings (the gyro sign -1) for the
    // plots: it agrees with the record, so no note.
    QVERIFY(w->lastOutcome()->differences.empty());
    QCOMPARE(w->lastOutcome()->report->points.front().gyroSign, -1);
    QVERIFY(results->reportText().contains("Stored verdict: INVALID"));
    QStringList drawn;
    auto input = results->reportInput();
    QVERIFY(input.isOk());
    QVERIFY(fog::report::renderCalibrationPages(*input, 30, &drawn).isOk());
    // The audit trail lists both stored results with their own stored
    // verdicts (the older PASS among them): records, not the verdict shown.
    const QStringList trail = drawn.filter(QRegularExpression("^#[0-9]+ "));
    QCOMPARE(trail.size(), 2);
    QVERIFY2(trail[0].endsWith("PASS") && trail[1].endsWith("INVALID"), qPrintable(trail.join("\n")));
    QStringList shownText = drawn;
    for (const auto& line : trail) shownText.removeAll(line);
    QVERIFY2(drawn.contains("INVALID") && !shownText.join("\n").contains("PASS"), qPrintable(drawn.join("\n").left(3000)));
    const QString pdf = dir.filePath("reversed.pdf");
    QVERIFY(results->writeReportPdf(pdf).isOk());

    // The older result (PASS as stored) stays PASS when chosen: a record each.
    QSignalSpy chosen(w.get(), &MainWindow::resultShown);
    emit results->resultCombo()->activated(0);
    QTRY_VERIFY_WITH_TIMEOUT(!chosen.isEmpty(), 30000);
    QVERIFY(w->findChild<QLabel*>("verdictLabel")->text().contains("PASS"));
    QVERIFY(results->resultDescription().startsWith("result 1 of 2: PASS"));

    // The stopped run.
    opened.clear();
    w->openSession(stopped);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    const QString stoppedVerdict = w->findChild<QLabel*>("verdictLabel")->text();
    QVERIFY2(stoppedVerdict.contains("INCOMPLETE") && stoppedVerdict.contains("stopped by the operator") &&
                 !stoppedVerdict.contains("<b>PASS</b>"),
             qPrintable(stoppedVerdict));
    drawn.clear();
    input = results->reportInput();
    QVERIFY(input.isOk());
    QVERIFY(fog::report::renderCalibrationPages(*input, 30, &drawn).isOk());
    QVERIFY2(drawn.contains("INCOMPLETE") && !drawn.contains("PASS"), qPrintable(drawn.join("\n").left(3000)));

    // Sessions: the verdict column.
    w->showView(MainWindow::kSessions);
    auto* browser = w->sessionBrowser();
    browser->setFolder(dir.path());
    settle();
    auto* table = browser->table();
    QCOMPARE(table->horizontalHeaderItem(6)->text(), QString("Verdict"));
    QMap<QString, QString> shown;
    for (int r = 0; r < table->rowCount(); ++r) shown[table->item(r, 0)->text()] = table->item(r, 6)->text();
    QCOMPARE(shown.value("reversed.fbs"), QString("INVALID (2 of 2)"));
    QCOMPARE(shown.value("stopped.fbs"), QString("INCOMPLETE (1 of 1)"));
    // Their delays: refused, with the mark, never bare.
    for (int r = 0; r < table->rowCount(); ++r)
      for (int column : {7, 8})
        QVERIFY2(table->item(r, column)->text().startsWith("refused ("), qPrintable(table->item(r, column)->text()));

    // Compare: each session's stored verdict.
    browser->table()->clearSelection();
    browser->table()->setSelectionMode(QAbstractItemView::MultiSelection);
    QVERIFY(browser->selectPath(reversed));
    QVERIFY(browser->selectPath(stopped));
    click(*w, "compareButton");
    auto* compareView = w->findChild<QWidget*>("compareWindow")->findChild<fog::ui::CompareView*>();
    QVERIFY(compareView);
    QTRY_VERIFY_WITH_TIMEOUT(compareView->allLoaded(), 30000);
    auto* sessions = compareView->findChild<QTableWidget*>("compareSessionTable");
    QVERIFY(sessions);
    QStringList rows;
    for (int r = 0; r < sessions->rowCount(); ++r) rows << sessions->item(r, 5)->text();
    QVERIFY2(rows.size() == 2 && rows[0].startsWith("INVALID (stored, limit 0.800 ms)") &&
                 rows[1].startsWith("INCOMPLETE (stored"),
             qPrintable(rows.join("\n")));
    QVERIFY2(compareView->differenceTable()->item(0, 1)->text().startsWith("refused (") &&
                 compareView->differenceTable()->item(0, 1)->text().endsWith("INVALID)"),
             qPrintable(compareView->differenceTable()->item(0, 1)->text()));
    // Neither delay is vouched for: no B − A, no "consistent".
    QVERIFY2(compareView->differenceTable()->item(0, 6)->text().startsWith("not compared"),
             qPrintable(compareView->differenceTable()->item(0, 6)->text()));
    // Results still shows the stopped session, and the status bar and title say so.
    QVERIFY2(w->windowTitle().startsWith("stopped.fbs"), qPrintable(w->windowTitle()));
    QVERIFY2(w->statusBar()->currentMessage().startsWith("stopped.fbs"), qPrintable(w->statusBar()->currentMessage()));
    w->findChild<QWidget*>("compareWindow")->close();

    // A record this version's analysis does not reproduce (its IMU delay
    // changed by 0.01 ms, its verdict FAIL): the stored FAIL is shown, and a
    // note says the analysis differs and offers re-analysis.
    {
      auto reader = fog::session::SessionReader::open(reversed.toStdString());
      QVERIFY(reader.isOk());
      auto recording = (*reader)->recording();
      QVERIFY(recording.isOk());
      const auto constants = (*reader)->info().bench;
      auto report = fog::analysis::analyzeRecording(*recording, constants);
      QVERIFY(report.isOk());
      reader->reset();
      QJsonObject doc = QJsonDocument::fromJson(QByteArray::fromStdString(fog::analysis::formatReportJson(
                                                    *report, fog::analysis::ReportContext{})))
                            .object();
      QJsonArray points = doc["test_points"].toArray();
      QJsonObject point = points[0].toObject();
      point["imu_delay_ms"] = point["imu_delay_ms"].toDouble() + 0.01;
      point["verdict"] = "fail";
      points[0] = point;
      doc["test_points"] = points;
      doc["verdict"] = "fail";
      QVERIFY(fog::session::addResult(reversed.toStdString(),
                                      fog::session::analysisSettingsJson(constants, 0.8, "an older fogbench"),
                                      QJsonDocument(doc).toJson().toStdString())
                  .isOk());
    }
    opened.clear();
    w->openSession(reversed);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QCOMPARE(w->lastOutcome()->differences.size(), std::size_t{2});
    const QString differing = w->findChild<QLabel*>("verdictLabel")->text();
    QVERIFY2(differing.contains("<b>FAIL</b>") && differing.contains("differs from the stored result") &&
                 differing.contains("Re-analyse") && differing.contains("pass by this version's analysis"),
             qPrintable(differing));

    // The bench-constants dialog sets what the CLI sets: gyro signs, limit, k.
    {
      fog::ui::BenchSettingsDialog dialog(w->benchConstants(), fog::ui::AnalysisChoices{{1, 1, -1}, 0.6, 3.0});
      auto* k = dialog.findChild<QDoubleSpinBox*>("coverageKSpin");
      auto* risk = dialog.findChild<QLabel*>("coverageKRisk");
      QVERIFY(k && risk);
      QCOMPARE(k->value(), 3.0);
      QVERIFY2(risk->text().contains("0.135 %"), qPrintable(risk->text()));
      k->setValue(2.5);
      QCOMPARE(dialog.analysisChoices().coverageK, 2.5);
      QVERIFY2(risk->text().contains("0.621 %"), qPrintable(risk->text()));
      auto* z = dialog.findChild<QComboBox*>("gyroSignZCombo");
      auto* limit = dialog.findChild<QDoubleSpinBox*>("limitSpin");
      QVERIFY(z && limit && dialog.findChild<QComboBox*>("gyroSignXCombo"));
      QCOMPARE(z->currentData().toInt(), -1);
      QCOMPARE(limit->value(), 0.6);
      z->setCurrentIndex(0);
      limit->setValue(0.5);
      QCOMPARE(dialog.analysisChoices().gyroSign[2], 1);
      QCOMPARE(dialog.analysisChoices().imuDelayLimitMs, 0.5);
      // ... and the IMU's frame, as --imu-frame: a heading only where the
      // convention has a forward axis, "not stated" at its minimum.
      auto* frame = dialog.findChild<QComboBox*>("imuFrameCombo");
      auto* forward = dialog.findChild<QDoubleSpinBox*>("forwardHeadingSpin");
      QVERIFY(frame && forward);
      QVERIFY(!dialog.settings().imuFrame.stated());
      frame->setCurrentIndex(frame->findData(int(fog::ImuFrame::Convention::kEastNorthUp)));
      QVERIFY(!forward->isEnabled());
      QCOMPARE(fog::imuFrameToText(dialog.settings().imuFrame), std::string("ENU"));
      frame->setCurrentIndex(frame->findData(int(fog::ImuFrame::Convention::kRightForwardUp)));
      QVERIFY(forward->isEnabled());
      QCOMPARE(fog::imuFrameToText(dialog.settings().imuFrame), std::string("RFU"));
      forward->setValue(30.0);
      QCOMPARE(fog::imuFrameToText(dialog.settings().imuFrame), std::string("RFU:30"));
      // Every heading it offers reads back: -360 is the lowest, one step
      // below it reads "not stated".
      forward->setValue(-360.0);
      QCOMPARE(fog::imuFrameToText(dialog.settings().imuFrame), std::string("RFU:-360"));
      forward->setValue(-1000.0);
      QCOMPARE(forward->text(), forward->specialValueText());
      QVERIFY(!dialog.settings().imuFrame.forwardHeadingDeg.has_value());
      forward->setValue(30.0);
      // Kept in the settings and read back.
      fog::ui::saveBenchConstants(dialog.settings());
      QCOMPARE(fog::imuFrameToText(fog::ui::loadBenchConstants().imuFrame), std::string("RFU:30"));
      fog::ui::saveBenchConstants(w->benchConstants());
    }

    // A re-analysis stores the GUI's gyro signs, limit and k with its result.
    w->setAnalysisChoices(fog::ui::AnalysisChoices{{-1, 1, 1}, 0.5, 3.0});
    opened.clear();
    QSignalSpy reanalysed(w.get(), &MainWindow::reanalysed);
    w->reanalyseSession(reversed);
    QTRY_VERIFY_WITH_TIMEOUT(!reanalysed.isEmpty(), 30000);
    if (auto* box = w->findChild<QMessageBox*>("infoDialog")) box->close();
    auto reader = fog::session::SessionReader::open(reversed.toStdString());
    QVERIFY(reader.isOk());
    const auto stored = *(*reader)->results();
    QCOMPARE(stored.size(), std::size_t{4});
    const auto newest = fog::session::readStoredResult(stored.back(), {});
    QCOMPARE(newest.constants.gyroSign[0], -1);
    QVERIFY(newest.gyroSignStated);
    QCOMPARE(newest.imuDelayLimitMs, 0.5);
    QVERIFY(newest.coverageKStated);
    QCOMPARE(newest.coverageK, 3.0);
    QCOMPARE(newest.verdict, std::string("invalid"));
    QVERIFY(newest.analysedBy == "fogbench GUI");
  }

  // A saved session opens read-only in the browser; re-analysis adds a
  // result and leaves the recorded data alone; two sessions compare side by side.
  void openASavedSessionFromTheBrowser() {
    auto w = window();
    auto* browser = w->sessionBrowser();
    browser->refresh();
    QString complete;
    for (int r = 0; r < browser->table()->rowCount(); ++r)
      if (browser->table()->item(r, 5)->text() == "complete") complete = browser->table()->item(r, 0)->data(Qt::UserRole).toString();
    QVERIFY2(!complete.isEmpty(), "the quick run's session should be listed as complete");
    const QByteArray before = sha256(complete);
    const auto resultsBefore = (*fog::session::SessionReader::open(complete.toStdString()))->results()->size();

    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    QVERIFY(browser->selectPath(complete));
    click(*w, "openSessionButton");
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QCOMPARE(opened.front().front().toBool(), true);
    QCOMPARE(w->currentView(), MainWindow::kResults);
    QVERIFY(w->lastOutcome() && w->lastOutcome()->report);
    QVERIFY(std::abs(w->lastOutcome()->report->points.front().lagMs - 0.4658) < 0.01);
    QVERIFY(w->lastMessage().contains("read-only review"));
    QCOMPARE(sha256(complete), before);  // review never writes

    // Re-analysis with other constants: one more result, same raw data.
    fog::BenchConstants other = w->benchConstants();
    other.boardDelayMs = 0.3;
    w->setBenchConstants(other);
    QVERIFY(browser->selectPath(complete));
    click(*w, "reanalyseButton");
    QTRY_VERIFY_WITH_TIMEOUT(w->lastMessage().contains("re-analysed"), 30000);
    // The confirmation is shown whole, not only in the status bar.
    auto* confirmation = w->findChild<QMessageBox*>("infoDialog");
    QVERIFY(confirmation && confirmation->isVisible());
    QVERIFY(confirmation->text().contains(QFileInfo(complete).fileName()));
    QVERIFY(confirmation->informativeText().contains(QDir::toNativeSeparators(complete)));
    confirmation->close();
    auto reader = fog::session::SessionReader::open(complete.toStdString());
    QVERIFY(reader.isOk());
    QCOMPARE((*reader)->results()->size(), resultsBefore + 1);
    const qint64 newestId = (*reader)->results()->back().id;
    reader->reset();

    // The new result is shown, chosen, and is what the report draws.
    auto* results = w->resultView();
    QCOMPARE(w->currentView(), MainWindow::kResults);
    QVERIFY(w->lastOutcome() && w->lastOutcome()->report);
    QCOMPARE(w->lastOutcome()->shownResultId, newestId);
    QCOMPARE(results->resultCombo()->count(), static_cast<int>(resultsBefore + 1));
    QCOMPARE(results->resultCombo()->currentIndex(), static_cast<int>(resultsBefore));
    QCOMPARE(results->resultCombo()->currentData().toLongLong(), newestId);
    QVERIFY(results->resultCombo()->isEnabled());
    // A copy: choosing another result below replaces the outcome this point lived in.
    const auto reanalysedPoint = w->lastOutcome()->report->points.front();
    QCOMPARE(results->delayTable()->item(3, 1)->text().toDouble(), 0.3);
    QVERIFY(std::abs(reanalysedPoint.gyroDelayMs - (reanalysedPoint.imuDelayMs - 0.3)) < 1e-9);
    const QString newest = QString("result %1 of %1").arg(resultsBefore + 1);
    QVERIFY2(results->resultDescription().startsWith(newest) && results->resultDescription().contains("board 0.3000 ms"),
             qPrintable(results->resultDescription()));
    QVERIFY(results->reportText().contains(newest));
    auto reportOf = [&] {
      QStringList drawn;
      auto input = results->reportInput();
      if (!input.isOk() || !fog::report::renderCalibrationPages(*input, 30, &drawn).isOk()) return QString();
      return drawn.join("\n");
    };
    QString drawn = reportOf();
    QVERIFY2(drawn.contains(newest) && drawn.contains("board 0.3000 ms"), qPrintable(drawn.left(2000)));
    // The constants table (page 2) is the chosen result's too.
    QVERIFY(drawn.count("0.3000 ms") >= 2);

    // The older result, chosen: its constants and numbers, in the view and the report.
    QSignalSpy chosen(w.get(), &MainWindow::resultShown);
    emit results->resultCombo()->activated(0);
    QTRY_VERIFY_WITH_TIMEOUT(!chosen.isEmpty(), 30000);
    QCOMPARE(chosen.front().front().toBool(), true);
    QCOMPARE(results->resultCombo()->currentIndex(), 0);
    QCOMPARE(w->lastOutcome()->shownResultNumber(), 1);
    QCOMPARE(results->delayTable()->item(3, 1)->text().toDouble(), 0.28);
    const auto& olderPoint = w->lastOutcome()->report->points.front();
    QVERIFY(std::abs(olderPoint.gyroDelayMs - (olderPoint.imuDelayMs - 0.28)) < 1e-9);
    QVERIFY(std::abs(olderPoint.gyroDelayMs - reanalysedPoint.gyroDelayMs - 0.02) < 1e-9);
    drawn = reportOf();
    QVERIFY2(drawn.contains(QString("result 1 of %1").arg(resultsBefore + 1)) && drawn.contains("board 0.2800 ms"),
             qPrintable(drawn.left(2000)));
    QVERIFY(!drawn.contains("board 0.3000 ms"));

    // Opening the session again shows its newest result.
    opened.clear();
    w->openSession(complete);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QCOMPARE(w->lastOutcome()->shownResultId, newestId);
    QCOMPARE(results->delayTable()->item(3, 1)->text().toDouble(), 0.3);

    // Compare: the complete session and a copy of it (the same data, so
    // every difference is 0 and consistent).
    const QString copy = QFileInfo(complete).absolutePath() + "/copy-of-" + QFileInfo(complete).fileName();
    QFile::remove(copy);
    QVERIFY(QFile::copy(complete, copy));
    browser->refresh();
    browser->table()->clearSelection();
    browser->table()->setSelectionMode(QAbstractItemView::MultiSelection);
    // A and B in the order chosen, whichever row comes first.
    QVERIFY(browser->selectPath(copy));
    QVERIFY(browser->selectPath(complete));
    QCOMPARE(browser->selectedPaths(), QStringList({copy, complete}));
    browser->table()->clearSelection();
    QVERIFY(browser->selectPath(complete));
    QVERIFY(browser->selectPath(copy));
    QCOMPARE(browser->selectedPaths(), QStringList({complete, copy}));
    click(*w, "compareButton");
    QWidget* compare = w->findChild<QWidget*>("compareWindow");
    QVERIFY(compare);
    auto* compareView = compare->findChild<fog::ui::CompareView*>();
    QVERIFY(compareView);
    QTRY_VERIFY_WITH_TIMEOUT(compareView->allLoaded(), 30000);
    // Per test point both results and their difference; the overlays drawn.
    QVERIFY(!compareView->comparisons().empty());
    QVERIFY(compareView->differenceTable()->rowCount() >= 1);
    QVERIFY(compareView->zeroCrossingPlot()->curveCount() >= 3);
    for (const auto& c : compareView->comparisons()) {
      QVERIFY(c.both());
      QCOMPARE(c.differenceMs, 0.0);
      QVERIFY(c.differenceStdMs > 0.0 && !c.significant());
    }
    // The Compare window fits a laptop too.
    settle();
    const QSize m = minimumOf(compare);
    QVERIFY2(m.width() <= 1024 && m.height() <= 700,
             qPrintable(QString("compare minimum %1x%2; too large: %3")
                            .arg(m.width()).arg(m.height()).arg(tooLarge(compare, QSize(1024, 700)).join("; "))));
    compare->close();
    QFile::remove(copy);
  }

  // Data from another bench (here: a CSV export of the quick run) is imported
  // into the folder as a session and reviewed like a recorded one.
  void importedCsvBecomesASession() {
    auto w = window();
    QString complete;
    auto* browser = w->sessionBrowser();
    for (int r = 0; r < browser->table()->rowCount(); ++r)
      if (browser->table()->item(r, 5)->text() == "complete")
        complete = browser->table()->item(r, 0)->data(Qt::UserRole).toString();
    QVERIFY(!complete.isEmpty());
    auto reader = fog::session::SessionReader::open(complete.toStdString());
    QVERIFY(reader.isOk());
    QTemporaryDir csv;
    QVERIFY(fog::io::exportCsv(csv.filePath("run").toStdString(), (*reader)->info(), *(*reader)->recording(), nullptr)
                .isOk());
    QSignalSpy imported(w.get(), &MainWindow::importEnded);
    w->importCsv(csv.filePath("run"));
    QTRY_VERIFY_WITH_TIMEOUT(!imported.isEmpty(), 30000);
    const QString path = imported.front().front().toString();
    QVERIFY2(!path.isEmpty(), qPrintable(w->lastMessage()));
    QVERIFY(w->sessionBrowser()->selectedPaths().contains(path));
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(path);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QVERIFY(w->lastOutcome() && w->lastOutcome()->report);
    QVERIFY(std::abs(w->lastOutcome()->report->points.front().lagMs - 0.4658) < 0.01);
    QVERIFY(QString::fromStdString(w->lastOutcome()->info.source).startsWith("import "));

    // A folder that is not in the layout is refused with the reason.
    QTemporaryDir empty;
    w->importCsv(empty.path());
    QTRY_VERIFY_WITH_TIMEOUT(imported.size() == 2, 30000);
    QVERIFY(imported.back().front().toString().isEmpty());
    QVERIFY2(w->lastMessage().contains("Cannot import") && w->lastMessage().contains("metadata.json"),
             qPrintable(w->lastMessage()));
  }

  // The window's layout is remembered when it closes: the next start shows
  // the same view, size and splitters; nothing remembered: restoreLayout
  // says so and the caller sizes the window.
  void theLayoutIsRememberedBetweenStarts() {
    QList<int> sizes;
    {
      auto w = window();
      QVERIFY(!w->restoreLayout());
      w->showView(MainWindow::kConfigure);
      w->resize(1100, 720);
      settle();
      auto* split = w->findChild<QSplitter*>("configureSplitter");
      sizes = split->sizes();
      QVERIFY2(sizes.size() == 2 && sizes[0] > 40, qPrintable(QString("sizes %1").arg(sizes.size() ? sizes[0] : -1)));
      sizes = {sizes[0] - 30, sizes[1] + 30};
      split->setSizes(sizes);
      sizes = split->sizes();
      w->showView(MainWindow::kSessions);
      w->close();
    }
    auto again = std::make_unique<MainWindow>();
    QVERIFY(again->restoreLayout());
    again->show();
    QCOMPARE(again->currentView(), MainWindow::kSessions);
    QCOMPARE(again->size(), QSize(1100, 720));
    // The divider of a view not shown yet is restored when the view appears.
    again->showView(MainWindow::kConfigure);
    QTRY_COMPARE(again->findChild<QSplitter*>("configureSplitter")->sizes(), sizes);
    again->showView(MainWindow::kSessions);
    again->setRemembering(false);  // a window that remembers nothing leaves the layout alone
    again->showView(MainWindow::kNoise);
    again->close();
    auto third = std::make_unique<MainWindow>();
    QVERIFY(third->restoreLayout());
    QCOMPARE(third->currentView(), MainWindow::kSessions);
    QSettings().remove("layout");
  }

  // A session's stored gyro signs (here x = -1: an axis mounted the other
  // way round, e.g. from an import's bench.gyro_sign) are what the GUI's
  // re-analysis uses, as the CLI does: with the data not reversed, the axis
  // turns against the table and the result is INVALID, never a PASS made
  // with the GUI's +1.
  void reanalysisKeepsTheSessionsStoredGyroSigns() {
    QTemporaryDir dir;
    fog::TestPlan plan;
    plan.points = {fog::TestPoint{fog::Axis::kX, 2.0, 2.0, 10.0, 0.3}};
    auto source = fog::acquisition::SimulatorSource::create(fog::model::SimConfig{}, plan, 0.0);
    QVERIFY(source.isOk());
    fog::acquisition::AcquisitionOptions options;
    options.sessionPath = dir.filePath("signed.fbs").toStdString();
    options.info.plan = plan;
    options.info.bench.gyroSign = {-1, 1, 1};
    options.constants = options.info.bench;
    QVERIFY(fog::acquisition::acquire(**source, options, nullptr).isOk());
    auto w = window();
    w->setAnalysisChoices(fog::ui::AnalysisChoices{{1, 1, 1}, 0.8});
    QSignalSpy reanalysed(w.get(), &MainWindow::reanalysed);
    w->reanalyseSession(dir.filePath("signed.fbs"));
    QTRY_VERIFY_WITH_TIMEOUT(!reanalysed.isEmpty(), 30000);
    const auto* shown = w->lastOutcome()->shownResult();
    QVERIFY(shown);
    QCOMPARE(shown->analysedBy, std::string("fogbench GUI"));
    QCOMPARE(shown->constants.gyroSign[0], -1);
    QCOMPARE(QString::fromStdString(shown->verdict), QString("invalid"));
  }

  // The import dialog sets what the CLI's --segment and --rate-convention
  // set; what the import applied is stored with the session, shown with its
  // result and stored again with every re-analysis.
  void importOptionsAreChosenAppliedAndStored() {
    {
      fog::ui::ImportDialog dialog("/data/run7");
      QVERIFY(dialog.options().segmentation.empty() && dialog.options().gyroRateConvention.empty());
      auto* segmentation = dialog.findChild<QComboBox*>("importSegmentation");
      auto* windows = dialog.findChild<QLineEdit*>("importWindows");
      auto* rates = dialog.findChild<QComboBox*>("importRateConvention");
      QVERIFY(segmentation && windows && rates);
      QVERIFY(!windows->isEnabled());
      segmentation->setCurrentIndex(1);
      QCOMPARE(QString::fromStdString(dialog.options().segmentation), QString("auto"));
      segmentation->setCurrentIndex(2);
      QVERIFY(windows->isEnabled());
      windows->setText("12-5");
      QVERIFY2(!dialog.problem().isEmpty(), "a window that ends before it starts is refused");
      auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
      QVERIFY(!ok->isEnabled());
      windows->setText("2-8");
      QVERIFY(dialog.problem().isEmpty() && ok->isEnabled());
      QCOMPARE(QString::fromStdString(dialog.options().segmentation), QString("2-8"));
      rates->setCurrentIndex(2);
      QCOMPARE(QString::fromStdString(dialog.options().gyroRateConvention), QString("sample_at_stamp"));
    }
    // A one-point recording cut at a window given.
    QTemporaryDir dir;
    fog::TestPlan plan;
    plan.points = {fog::TestPoint{fog::Axis::kX, 2.0, 2.0, 12.0, 0.3}};
    auto run = fog::model::simulate(fog::model::SimConfig{}, plan);
    QVERIFY(run.isOk());
    auto recording = fog::protocol::decodeRecording(run->bytes);
    QVERIFY(recording.isOk());
    fog::SessionInfo info;
    info.plan = plan;
    QVERIFY(fog::io::exportCsv(dir.filePath("run").toStdString(), info, *recording, nullptr).isOk());
    const double start = recording->testPoints.front().table.front().timeS;
    fog::io::ImportOptions options;
    options.segmentation = QString("%1-%2").arg(start + 2.0, 0, 'f', 3).arg(start + 10.0, 0, 'f', 3).toStdString();
    auto w = window();
    QSignalSpy imported(w.get(), &MainWindow::importEnded);
    w->importCsv(dir.filePath("run"), options);
    QTRY_VERIFY_WITH_TIMEOUT(!imported.isEmpty(), 30000);
    const QString path = imported.front().front().toString();
    QVERIFY2(!path.isEmpty(), qPrintable(w->lastMessage()));
    {
      auto reader = fog::session::SessionReader::open(path.toStdString());
      QVERIFY(reader.isOk());
      QVERIFY2(QString::fromStdString((*reader)->info().imported.segmentation).startsWith("given: "),
               (*reader)->info().imported.segmentation.c_str());
    }
    QSignalSpy reanalysed(w.get(), &MainWindow::reanalysed);
    w->reanalyseSession(path);
    QTRY_VERIFY_WITH_TIMEOUT(!reanalysed.isEmpty(), 30000);
    QVERIFY(reanalysed.front().front().toBool());
    const auto* shown = w->lastOutcome()->shownResult();
    QVERIFY(shown);
    QVERIFY(shown->imported.segmentation.rfind("given: ", 0) == 0);
    QVERIFY2(w->resultView()->resultDescription().contains("cut at the swing windows given: "),
             qPrintable(w->resultView()->resultDescription()));
  }

  // A session recorded with a 300 ppm scale-factor error the bench is not
  // told about: Diagnose names it, and the view draws the gap map, the curves,
  // the spectrum and one shrink bar per candidate effect.
  void diagnosisNamesAWithheldEffect() {
    QTemporaryDir dir;
    const QString path = dir.filePath("withheld.fbs");
    fog::TestPlan plan = fog::TestPlan::paperFast();
    plan.points.front().durationS = 30.0;
    std::vector<std::unique_ptr<fog::model::Effect>> effects;
    effects.push_back(fog::diagnosis::makeEffect(fog::diagnosis::EffectId::kScaleFactorError, {300.0}));
    auto source = fog::acquisition::SimulatorSource::create(fog::model::SimConfig{}, plan, 0.0, std::move(effects));
    QVERIFY(source.isOk());
    fog::acquisition::AcquisitionOptions options;
    options.sessionPath = path.toStdString();
    options.info.plan = plan;
    QVERIFY(fog::acquisition::acquire(**source, options, nullptr).isOk());

    auto w = window();
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(path);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QSignalSpy diagnosed(w.get(), &MainWindow::diagnosisEnded);
    auto* view = w->diagnosisView();
    // Progress as the bar shows it, with the stage beside it.
    std::vector<int> values;
    QStringList stages;
    connect(view->progressBar(), &QProgressBar::valueChanged, view, [&](int v) {
      values.push_back(v);
      stages << view->stageShown();
    });
    // The IMU's bias instability, stated (the simulator's own: 0.5 deg/h
    // over 300 s), goes to the diagnosis and is remembered.
    QVERIFY(!view->noiseStatedBox()->isChecked() && !view->instabilitySpin()->isEnabled());
    view->noiseStatedBox()->setChecked(true);
    QVERIFY(view->instabilitySpin()->isEnabled());
    view->instabilitySpin()->setValue(0.5);
    view->correlationSpin()->setValue(300.0);
    {
      fog::ui::DiagnosisView again;
      QVERIFY(again.noiseStatedBox()->isChecked());
      QCOMPARE(again.instabilitySpin()->value(), 0.5);
      QCOMPARE(again.correlationSpin()->value(), 300.0);
    }
    click(*w, "diagnoseButton");
    // Running: the bar, Cancel, and no plots (no empty default axes).
    QCOMPARE(view->state(), fog::ui::DiagnosisView::State::kRunning);
    QVERIFY(view->progressBar()->isVisible() && view->cancelButton()->isVisible());
    QVERIFY(!view->plotsShown());
    QVERIFY(!view->curvePlot()->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(!diagnosed.isEmpty(), 60000);
    QCOMPARE(diagnosed.front().front().toBool(), true);
    QCOMPARE(w->currentView(), MainWindow::kDiagnosis);
    QVERIFY2(values.size() >= 3, qPrintable(QString("%1 progress steps").arg(values.size())));
    QVERIFY(std::is_sorted(values.begin(), values.end()));
    QCOMPARE(values.back(), 1000);
    QVERIFY2(stages.contains(fog::ui::DiagnosisView::stageText("replays")), qPrintable(stages.join(" | ")));
    // Done: the plots, no bar.
    QCOMPARE(view->state(), fog::ui::DiagnosisView::State::kShown);
    QVERIFY(view->plotsShown() && view->curvePlot()->isVisible());
    QVERIFY(!view->progressBar()->isVisible());
    const auto* d = w->diagnosisView()->diagnosis();
    QVERIFY(d);
    QCOMPARE(QString::fromStdString(d->verdict), QString("scale_factor_error"));
    QVERIFY(d->calibration.biasInstabilityStated);
    QCOMPARE(d->calibration.config.fog.biasInstabilityDegPerH, 0.5);
    QCOMPARE(d->calibration.config.fog.biasCorrelationS, 300.0);
    // In words; the identifier only in the tooltip (and the JSON).
    QVERIFY2(w->diagnosisView()->verdictText().contains("verdict: scale-factor error") &&
                 !w->diagnosisView()->verdictText().contains("scale_factor_error"),
             qPrintable(w->diagnosisView()->verdictText()));
    QVERIFY(w->diagnosisView()->findChild<QLabel*>("diagnosisVerdict")->toolTip().contains("scale_factor_error"));
    QVERIFY(w->diagnosisView()->gapMapRows() > 10);
    QVERIFY(w->diagnosisView()->gapMapColumns() >= 1);
    {
      // Labels readable (at least 9 pt) and "P1 S1" explained on the axis.
      auto* gap = w->diagnosisView()->findChild<QwtPlot*>("gapMapPlot");
      QVERIFY(gap);
      for (int axis : {QwtPlot::yLeft, QwtPlot::xBottom})
        QVERIFY2(gap->axisWidget(axis)->font().pointSizeF() >= 9.0,
                 qPrintable(QString::number(gap->axisWidget(axis)->font().pointSizeF())));
      QVERIFY2(gap->axisTitle(QwtPlot::xBottom).text().contains("P test point, S segment"),
               qPrintable(gap->axisTitle(QwtPlot::xBottom).text()));
    }
    int bars = 0;
    for (auto* item : w->diagnosisView()->shrinkPlot()->itemList(QwtPlotItem::Rtti_PlotBarChart))
      bars += static_cast<int>(static_cast<QwtPlotBarChart*>(item)->dataSize());
    // The best-ranked six, readable; all are ranked in the text.
    QCOMPARE(bars, std::min(6, static_cast<int>(d->effects.size())));
    // Bars across with the names down the left, the best ranked on top.
    const QwtScaleDiv& names = w->diagnosisView()->shrinkPlot()->axisScaleDiv(QwtPlot::yLeft);
    QVERIFY(names.lowerBound() > names.upperBound());
    QCOMPARE(w->diagnosisView()->shrinkPlot()->axisScaleDraw(QwtPlot::yLeft)->label(0.0).text(),
             QString::fromStdString(fog::diagnosis::effectTitle(d->effects.front().name)));
    QVERIFY(!w->diagnosisView()->shrinkPlot()->axisScaleDraw(QwtPlot::yLeft)->label(0.0).text().contains('_'));
    QCOMPARE(w->diagnosisView()->curvePlot()->itemList(QwtPlotItem::Rtti_PlotCurve).size(), 2);
    {
      // At 1024x700 (and narrower) a reason of several lines keeps every plot
      // its room (the view scrolls): the wrapped verdict's lines were not
      // counted, so the rows of plots were squeezed over each other; and the
      // gap map's segment names do not run together on its narrow canvas.
      auto longer = std::make_shared<fog::diagnosis::Diagnosis>(*d);
      for (int i = 0; i < 8; ++i) longer->verdictReason += "; " + d->verdictReason + ", a clause long enough to wrap";
      // Three times the segments (the paper's plan has 8): 12 names on a
      // canvas of ~170 px.
      const auto cells = longer->gapMap;
      for (int copy = 1; copy <= 2; ++copy)
        for (auto cell : cells) {
          cell.key.point += copy * static_cast<int>(d->points.size());
          longer->gapMap.push_back(cell);
        }
      const int columns = view->gapMapColumns();
      view->showDiagnosis(longer, "long.fbs");
      QCOMPARE(view->gapMapColumns(), 3 * columns);
      for (const QSize size : {QSize(1366, 768), QSize(1024, 700)}) {
        w->resize(size);
        QTest::qWait(100);
        const QString at = QString("%1x%2: ").arg(size.width()).arg(size.height());
        auto* verdict = view->findChild<QLabel*>("diagnosisVerdict");
        QVERIFY2(verdict->heightForWidth(verdict->width()) > 4 * verdict->fontMetrics().height(),
                 qPrintable(at + "the reason does not wrap: the check below would not be exercised"));
        const int firstRowBottom = view->curvePlot()->mapTo(view, QPoint(0, view->curvePlot()->height())).y();
        const int secondRowTop = view->spectrumPlot()->mapTo(view, QPoint(0, 0)).y();
        QVERIFY2(firstRowBottom <= secondRowTop, qPrintable(at + QString("%1 > %2").arg(firstRowBottom).arg(secondRowTop)));
        auto* gap = view->gapMapPlot();
        const QwtScaleMap map = gap->canvasMap(QwtPlot::xBottom);
        const QList<double> ticks = gap->axisScaleDiv(QwtPlot::xBottom).ticks(QwtScaleDiv::MajorTick);
        const QFontMetrics metrics(gap->axisWidget(QwtPlot::xBottom)->font());
        auto halfWidth = [&](double tick) {
          return 0.5 * metrics.horizontalAdvance(gap->axisScaleDraw(QwtPlot::xBottom)->label(tick).text());
        };
        QVERIFY(!ticks.isEmpty());
        for (int i = 1; i < ticks.size(); ++i)
          QVERIFY2(map.transform(ticks[i]) - map.transform(ticks[i - 1]) > halfWidth(ticks[i]) + halfWidth(ticks[i - 1]),
                   qPrintable(at + QString("segment names at %1 and %2 overlap").arg(ticks[i - 1]).arg(ticks[i])));
      }
    }
  }

  // Cancel ends a running diagnosis: no result, the view says so and shows
  // no plots, and the bench is ready (a new diagnosis runs to the end).
  void diagnosisCancels() {
    // A minute at 1 Hz: a diagnosis of a few seconds, long enough to be
    // cancelled well before its end.
    QTemporaryDir dir;
    const QString path = dir.filePath("minute.fbs");
    const fog::TestPlan plan = fog::TestPlan::paperFast();
    auto source = fog::acquisition::SimulatorSource::create(fog::model::SimConfig{}, plan, 0.0);
    QVERIFY(source.isOk());
    fog::acquisition::AcquisitionOptions options;
    options.sessionPath = path.toStdString();
    options.info.plan = plan;
    QVERIFY(fog::acquisition::acquire(**source, options, nullptr).isOk());

    auto w = window();
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(path);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QSignalSpy diagnosed(w.get(), &MainWindow::diagnosisEnded);
    auto* view = w->diagnosisView();
    click(*w, "diagnoseButton");
    QVERIFY(w->isDiagnosing());
    QTRY_VERIFY_WITH_TIMEOUT(view->progressBar()->value() > 0, 30000);
    QVERIFY(diagnosed.isEmpty());
    QCOMPARE(view->state(), fog::ui::DiagnosisView::State::kRunning);
    QVERIFY(!view->stageShown().isEmpty());
    QVERIFY(!view->plotsShown());
    QTest::mouseClick(view->cancelButton(), Qt::LeftButton);
    QVERIFY(!view->cancelButton()->isEnabled());  // pressed once; the diagnosis stops soon
    QTRY_VERIFY_WITH_TIMEOUT(!diagnosed.isEmpty(), 30000);
    QCOMPARE(diagnosed.front().front().toBool(), false);
    QCOMPARE(view->state(), fog::ui::DiagnosisView::State::kCancelled);
    QVERIFY(view->diagnosis() == nullptr);
    QVERIFY2(view->verdictText().contains("Diagnosis cancelled"), qPrintable(view->verdictText()));
    QVERIFY(!view->plotsShown() && !view->progressBar()->isVisible());
    QVERIFY(!w->isDiagnosing());
    QVERIFY(w->lastMessage().contains("cancelled"));
    // A cancel is not an error: no error box.
    auto* box = w->findChild<QMessageBox*>("errorDialog");
    QVERIFY(!box || !box->isVisible());
    // Ready again: Run is available and a new diagnosis runs to its result.
    QVERIFY(button(*w, "runButton")->isEnabled());
    click(*w, "diagnoseButton");
    QTRY_VERIFY_WITH_TIMEOUT(diagnosed.size() == 2, 60000);
    QCOMPARE(diagnosed.back().front().toBool(), true);
    QCOMPARE(view->state(), fog::ui::DiagnosisView::State::kShown);
    QVERIFY(view->diagnosis() && view->plotsShown());
    qInfo("the whole diagnosis took %.1f s", view->diagnosis()->elapsedS);
  }

  // A plan with a static segment (edited as such in the plan editor) gives
  // the gyro's Allan deviation and noise terms in the Noise view.
  void staticSegmentGivesTheNoiseView() {
    auto w = window();
    auto* editor = w->planEditor();
    QVERIFY(editor->loadPreset("quick"));
    auto* kind = qobject_cast<QComboBox*>(editor->cellEditor(0, PlanEditor::kKind));
    QVERIFY(kind);
    kind->setCurrentIndex(1);  // static
    QVERIFY(editor->plan().points.front().isStatic());
    QVERIFY(!editor->cellEditor(0, PlanEditor::kFrequency)->isEnabled());
    QVERIFY2(editor->isValid(), qPrintable(editor->problem()));
    setValue(editor, 0, PlanEditor::kDuration, 120.0);

    QSignalSpy analysed(w.get(), &MainWindow::noiseAnalysed);
    w->useSimulator(0.0, 5);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!analysed.isEmpty(), 60000);
    QCOMPARE(analysed.front().front().toBool(), true);
    auto* view = w->noiseView();
    QCOMPARE(view->reports().size(), std::size_t(1));
    QVERIFY(view->termTable()->rowCount() >= 1);
    QVERIFY(view->allanPlot()->itemList(QwtPlotItem::Rtti_PlotCurve).size() >= 3);  // measured, a term, the sum
    QVERIFY(view->summaryText().contains("Earth-corrected bias"));
    QVERIFY(view->plotShown());
    for (int r = 0; r < view->termTable()->rowCount(); ++r)  // units as the GUI writes them
      QVERIFY2(!view->termTable()->item(r, 3)->text().contains("deg"), qPrintable(view->termTable()->item(r, 3)->text()));

    // A swing-only result says how to get a noise analysis.
    QVERIFY(editor->loadPreset("quick"));
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(analysed.size() == 2, 60000);
    QCOMPARE(analysed.back().front().toBool(), false);
    QVERIFY(view->summaryText().contains("no static segment"));
    QVERIFY(!view->plotShown());  // no empty 0 .. 1000 plot that looks like a result
  }

  // Issue 17 in the window: a serial board with the turntable driven
  // through fogbench-table-emu's remote protocol over TCP. Live shows what
  // the controller reports (mode, commanded against measured swing, faults)
  // for the remote table, placed from the runner (the emulator's board sends
  // no test-point markers of its own); Stop brings the table to rest (the
  // controller is sent STOP and seen at rest) before the run ends, and the
  // session keeps the data and the table log.
  void aRemoteTableIsDrivenFromTheWindowAndStopBringsItToRest() {
    QProcess emu;
    QString table, board;
    startTableEmu(emu, {"--speed", "5"}, &table, &board);
    QVERIFY2(!table.isEmpty() && !board.isEmpty(), emu.readAllStandardError().constData());
    QTemporaryDir folder;  // an incomplete session of its own
    auto w = window();
    w->setSessionFolder(folder.path());
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    fog::TestPlan plan;
    plan.restBetweenS = 0.5;
    fog::TestPoint point;
    point.axis = fog::Axis::kY;
    point.frequencyHz = 2.0;
    point.amplitudeDeg = 1.5;
    point.durationS = 60.0;
    point.settleS = 1.0;
    plan.points = {point};
    w->planEditor()->setPlan(plan);
    w->useSerialBoard(board, fog::ui::ConfigureView::TableDriver::kRemote, table);
    w->configureView()->setPace(5.0);
    QVERIFY2(button(*w, "runButton")->isEnabled(), qPrintable(button(*w, "runButton")->toolTip()));
    click(*w, "runButton");
    auto* live = w->liveView();
    QVERIFY(live->tableStatusBox()->isVisibleTo(w.get()));
    QVERIFY(w->findChild<QLabel*>("tableDriverLabel")->text().contains(table));
    QTRY_VERIFY_WITH_TIMEOUT(std::isfinite(live->measuredAmplitudeDeg()) &&
                                 live->traces().phase() == fog::protocol::TestPhase::kRecording,
                             30000);
    QVERIFY2(live->tableMode().startsWith("swinging Y"), qPrintable(live->tableMode()));
    QCOMPARE(live->traces().axis(), fog::Axis::kY);
    QVERIFY2(std::abs(live->measuredAmplitudeDeg() - 1.5) <= 0.02 * 1.5, qPrintable(QString::number(live->measuredAmplitudeDeg())));
    QVERIFY2(std::abs(live->measuredFrequencyHz() - 2.0) <= 0.005 * 2.0, qPrintable(QString::number(live->measuredFrequencyHz())));
    QVERIFY(w->findChild<QLabel*>("tableCommandedLabel")->text().startsWith("Y 2 Hz, 1.5°"));
    QCOMPARE(w->findChild<QLabel*>("tableFaultsLabel")->text(), QString("none reported"));
    QTRY_VERIFY_WITH_TIMEOUT(live->pointProgress() >= 0.1, 30000);  // a few periods recorded
    click(*w, "stopButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QCOMPARE(live->tableMode(), QString("at rest (run over)"));
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome);
    QVERIFY(!outcome->complete);
    QVERIFY2(outcome->incompleteReason.find("stopped by the operator") != std::string::npos, outcome->incompleteReason.c_str());
    QVERIFY(QString::fromStdString(outcome->info.source).contains("table remote " + table));
    auto reader = fog::session::SessionReader::open(outcome->sessionPath);
    QVERIFY(reader);
    auto log = (*reader)->tableLog();
    QVERIFY(log);
    bool stopSent = false, atRest = false;
    for (const auto& e : *log) {
      stopSent = stopSent || (e.kind == "command" && e.text == "STOP");
      atRest = atRest || (e.kind == "step" && e.text == "table at rest");
    }
    QVERIFY(stopSent);
    QVERIFY(atRest);
    // What was recorded before Stop is kept and analysed: the delay within
    // its uncertainty of the truth.
    QVERIFY(outcome->report);
    const auto& measured = outcome->report->points.front();
    QVERIFY2(std::abs(measured.lagMs - 0.4658) <= std::max(5.0 * measured.lagStdMs, 0.002),
             qPrintable(QString("lag %1 ± %2 ms").arg(measured.lagMs).arg(measured.lagStdMs)));
    emu.waitForFinished(20000);
  }

  // The tool bar's emergency stop during a run that drives a remote table,
  // the table panel not connected: it is enabled, goes through the run's own
  // controller connection (SYST:ESTOP, not the decelerating STOP), and the
  // run ends with what it recorded.
  void theEmergencyStopDuringARemoteTableRunGoesThroughTheRunsConnection() {
    QProcess emu;
    QString table, board;
    startTableEmu(emu, {"--speed", "5"}, &table, &board);
    QVERIFY2(!table.isEmpty() && !board.isEmpty(), emu.readAllStandardError().constData());
    QTemporaryDir folder;
    auto w = window();
    w->setSessionFolder(folder.path());
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    fog::TestPlan plan;
    fog::TestPoint point;
    point.axis = fog::Axis::kX;
    point.frequencyHz = 2.0;
    point.amplitudeDeg = 1.5;
    point.durationS = 60.0;
    point.settleS = 1.0;
    plan.points = {point};
    w->planEditor()->setPlan(plan);
    w->useSerialBoard(board, fog::ui::ConfigureView::TableDriver::kRemote, table);
    w->configureView()->setPace(5.0);
    QVERIFY(!w->tablePanel()->connected());
    QVERIFY(!w->emergencyStopAction()->isEnabled());  // no table connection yet
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(w->liveView()->traces().phase() == fog::protocol::TestPhase::kRecording, 30000);
    QVERIFY2(w->emergencyStopAction()->isEnabled(), qPrintable(w->emergencyStopAction()->toolTip()));
    w->emergencyStopAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QVERIFY(!w->emergencyStopAction()->isEnabled());  // the run's connection is closed
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome);
    QVERIFY(!outcome->complete);
    auto reader = fog::session::SessionReader::open(outcome->sessionPath);
    QVERIFY(reader);
    auto log = (*reader)->tableLog();
    QVERIFY(log);
    bool asked = false, estopSent = false, stopSent = false, ended_ = false;
    for (const auto& e : *log) {
      asked = asked || (e.kind == "step" && e.text == "emergency stop asked by the operator");
      estopSent = estopSent || (e.kind == "command" && e.text == "SYST:ESTOP");
      stopSent = stopSent || (e.kind == "command" && e.text == "STOP");
      ended_ = ended_ || (e.kind == "step" && e.text.find("emergency stop by the operator") != std::string::npos);
    }
    QVERIFY(asked);
    QVERIFY(estopSent);
    QVERIFY(!stopSent);
    QVERIFY(ended_);
    emu.kill();
    emu.waitForFinished(20000);
  }

  // A plan beyond the limits the controller reports is refused before
  // anything moves: no swing, no session file, the reason shown.
  void aPlanBeyondTheRemoteTablesLimitsIsRefusedBeforeAnyMotion() {
    QProcess emu;
    QString table, board;
    startTableEmu(emu, {"--speed", "5", "--max-amplitude-deg", "2"}, &table, &board);
    QVERIFY2(!table.isEmpty() && !board.isEmpty(), emu.readAllStandardError().constData());
    QTemporaryDir folder;
    auto w = window();
    w->setSessionFolder(folder.path());
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    QVERIFY(w->planEditor()->loadPreset("quick"));  // 1 Hz / 3 deg on X
    w->useSerialBoard(board, fog::ui::ConfigureView::TableDriver::kRemote, table);
    w->configureView()->setPace(5.0);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QCOMPARE(ended.front().front().toBool(), false);
    QVERIFY2(w->lastMessage().contains("amplitude is beyond the table's 2 deg on X; the plan was refused before any motion"),
             qPrintable(w->lastMessage()));
    QVERIFY(QDir(folder.path()).entryList({"*.fbs"}).isEmpty());
    emu.terminate();
    emu.waitForFinished(10000);
    QVERIFY(!emu.readAllStandardOutput().contains("swing:"));
  }

  // The manual driver in the window, with a scripted operator: Live shows
  // what to set on the controller; the operator sets it (here through the
  // emulated controller's protocol, as on its front panel); the bench
  // records once the table-angle stream shows the planned swing; Stop tells
  // the operator to bring the table to rest.
  void aManualTableIsSetByTheOperatorAsLiveSaysAndStopTellsThemToStopIt() {
    QProcess emu;
    QString table, board;
    startTableEmu(emu, {"--speed", "5"}, &table, &board);
    QVERIFY2(table.startsWith("tcp:") && !board.isEmpty(), emu.readAllStandardError().constData());
    QTemporaryDir folder;
    auto w = window();
    w->setSessionFolder(folder.path());
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    fog::TestPlan plan;
    fog::TestPoint point;
    point.axis = fog::Axis::kX;
    point.frequencyHz = 1.0;
    point.amplitudeDeg = 3.0;
    point.durationS = 60.0;
    point.settleS = 1.0;
    plan.points = {point};
    w->planEditor()->setPlan(plan);
    w->useSerialBoard(board, fog::ui::ConfigureView::TableDriver::kManual);
    w->configureView()->setPace(5.0);
    click(*w, "runButton");
    auto* step = w->findChild<QLabel*>("tableStepLabel");
    // The core says "3 deg"; the window shows the symbol, as everywhere else.
    QTRY_VERIFY_WITH_TIMEOUT(step->text().contains("swing sinusoidally at 1 Hz, amplitude 3° about 0°"), 20000);
    // Not recorded before the table swings.
    QVERIFY(w->liveView()->traces().phase() != fog::protocol::TestPhase::kRecording);
    const QStringList hostPort = table.mid(4).split(':');
    QTcpSocket panel;
    panel.connectToHost(hostPort.at(0), hostPort.at(1).toUShort());
    QVERIFY(panel.waitForConnected(5000));
    panel.write("AXIS:X:SWING 1,3,0\nAXIS:X:START\n");
    QVERIFY(panel.waitForBytesWritten(5000));
    auto* live = w->liveView();
    QTRY_VERIFY_WITH_TIMEOUT(std::isfinite(live->measuredAmplitudeDeg()) &&
                                 live->traces().phase() == fog::protocol::TestPhase::kRecording,
                             30000);
    QVERIFY2(std::abs(live->measuredAmplitudeDeg() - 3.0) <= 0.02 * 3.0, qPrintable(QString::number(live->measuredAmplitudeDeg())));
    QVERIFY2(live->tableMode().contains("swing verified"), qPrintable(live->tableMode()));
    // A few periods recorded, then Stop.
    QTRY_VERIFY_WITH_TIMEOUT(live->pointProgress() >= 0.1, 30000);
    click(*w, "stopButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QVERIFY2(step->text().contains("stop every axis and let the table come to rest"), qPrintable(step->text()));
    panel.write("STOP\n");
    QVERIFY(panel.waitForBytesWritten(5000));
    panel.disconnectFromHost();
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome && outcome->report);
    // The delay of what was recorded, within its uncertainty of the truth.
    const auto& measured = outcome->report->points.front();
    QVERIFY2(std::abs(measured.lagMs - 0.4658) <= std::max(5.0 * measured.lagStdMs, 0.002),
             qPrintable(QString("lag %1 ± %2 ms").arg(measured.lagMs).arg(measured.lagStdMs)));
    emu.terminate();
    emu.waitForFinished(10000);
  }

  // A sampling board on a serial port: the board emulator on a real
  // pseudo-terminal, recorded by the window like a live board.
  void serialBoardIsRecordedFromThePort() {
    QProcess board;
    const QString pty = startBoard(board, {});
    QVERIFY2(!pty.isEmpty(), board.readAllStandardError().constData());
    auto w = window();
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    w->setSourceKind(MainWindow::SourceKind::kSerial);
    w->findChild<QComboBox*>("portCombo")->setCurrentText(pty);
    QVERIFY2(button(*w, "runButton")->isEnabled(), qPrintable(button(*w, "runButton")->toolTip()));
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 60000);
    board.waitForFinished(20000);
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome);
    QVERIFY2(outcome->complete, outcome->incompleteReason.c_str());  // the board's "done" ends the run
    QVERIFY(QString::fromStdString(outcome->info.source).startsWith("serial " + pty));
    QVERIFY(outcome->report);
    QVERIFY(std::abs(outcome->report->points.front().lagMs - 0.4658) < 0.01);
  }

  // Issue 18: the window fits a laptop. Its minimum size is at most
  // 1024 x 700; at 1024 x 700 every button of every view can be scrolled
  // into view whole, the status bar is on screen; at 1366 x 768 no view
  // needs a scroll bar at all. Run with a result shown (the quick run's
  // session) so that the views hold what they hold in use.
  void windowFitsALaptopScreen() {
    auto w = window();
    QString session;
    for (int r = 0; r < w->sessionBrowser()->table()->rowCount(); ++r)
      if (w->sessionBrowser()->table()->item(r, 5)->text() == "complete")
        session = w->sessionBrowser()->table()->item(r, 0)->data(Qt::UserRole).toString();
    QVERIFY(!session.isEmpty());
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(session);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    settle();
    for (int view = MainWindow::kConfigure; view <= MainWindow::kNoise; ++view) {
      w->showView(static_cast<MainWindow::View>(view));
      settle();
      const QSize m = minimumOf(w.get());
      QVERIFY2(m.width() <= 1024 && m.height() <= 700,
               qPrintable(QString("view %1: minimum %2x%3; too large: %4")
                              .arg(view).arg(m.width()).arg(m.height())
                              .arg(tooLarge(w.get(), QSize(1024, 700)).join("; "))));
    }

    w->resize(1024, 700);
    settle();
    QCOMPARE(w->size(), QSize(1024, 700));
    for (int view = MainWindow::kConfigure; view <= MainWindow::kNoise; ++view) {
      w->showView(static_cast<MainWindow::View>(view));
      settle();
      const QStringList bad = unreachableButtons(w.get());
      QVERIFY2(bad.isEmpty(), qPrintable(QString("view %1 at 1024x700: %2").arg(view).arg(bad.join("; "))));
      const QRect status(w->statusBar()->mapTo(w.get(), QPoint(0, 0)), w->statusBar()->size());
      QVERIFY(w->statusBar()->isVisible() && w->rect().contains(status));
    }

    w->resize(1366, 768);
    settle();
    for (int view = MainWindow::kConfigure; view <= MainWindow::kNoise; ++view) {
      w->showView(static_cast<MainWindow::View>(view));
      settle();
      auto* tabs = w->findChild<QTabWidget*>("viewTabs");
      auto* area = qobject_cast<QScrollArea*>(tabs->currentWidget());
      QVERIFY(area);
      const QSize need = minimumOf(area->widget());
      QVERIFY2(area->horizontalScrollBar()->maximum() == 0 && area->verticalScrollBar()->maximum() == 0,
               qPrintable(QString("view %1 at 1366x768 scrolls: needs %2x%3 in %4x%5; too large: %6")
                              .arg(view).arg(need.width()).arg(need.height())
                              .arg(area->viewport()->width()).arg(area->viewport()->height())
                              .arg(tooLarge(area->widget(), area->viewport()->size()).join("; "))));
    }
  }

  // Errors are shown whole in a message box that does not block (so the
  // test, like an unattended bench, goes on) and whose text can be copied:
  // a file that is not a session, a folder that is not a CSV export.
  void errorsAreShownWholeAndCopyable() {
    auto w = window();
    QTemporaryDir dir;
    const QString path = dir.filePath("broken.fbs");
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray("this is not a session file, it was cut off by a full disk ").repeated(20));
    }
    const auto expected = fog::session::SessionReader::open(path.toStdString());
    QVERIFY(!expected.isOk());
    const QString reason = fog::ui::displayUnits(QString::fromStdString(expected.status().message()));
    QVERIFY(reason.size() > 20);
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(path);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QCOMPARE(opened.front().front().toBool(), false);
    auto* box = w->findChild<QMessageBox*>("errorDialog");
    QVERIFY(box);
    QVERIFY(box->isVisible());
    QVERIFY(!box->isModal());
    QVERIFY2(box->text().contains("broken.fbs"), qPrintable(box->text()));
    QVERIFY2(box->informativeText().contains(reason), qPrintable(box->informativeText()));
    QVERIFY(box->informativeText().contains(QDir::toNativeSeparators(path)));
    QVERIFY(box->textInteractionFlags() & Qt::TextSelectableByMouse);

    // Replaying it: the run is refused with the same reason.
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    w->useReplay(path, 0.0);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QCOMPARE(ended.front().front().toBool(), false);
    QVERIFY(!w->isRunning());
    QCOMPARE(box->text(), QString("Run failed"));
    QVERIFY2(box->informativeText().contains(reason), qPrintable(box->informativeText()));

    // The next error replaces the text of the open box: the core's whole
    // reason for refusing a folder that is not in the CSV layout.
    QTemporaryDir empty;
    const auto csv = fog::io::importCsvDirectory(empty.path().toStdString());
    QVERIFY(!csv.isOk());
    QSignalSpy imported(w.get(), &MainWindow::importEnded);
    w->importCsv(empty.path());
    QTRY_VERIFY_WITH_TIMEOUT(!imported.isEmpty(), 30000);
    QCOMPARE(w->findChildren<QMessageBox*>("errorDialog").size(), 1);
    QVERIFY2(box->informativeText() == fog::ui::displayUnits(QString::fromStdString(csv.status().message())),
             qPrintable(box->informativeText()));
    box->close();
  }

  // A damaged session file is listed as unreadable with its reason (not
  // counted among other files); the long reason is elided in the State
  // column, whole in the tooltip, and lag and IMU delay stay in view.
  // A many-point session (a frequency response has 20) is summarised in the
  // delay columns, count and range, with every point in the tooltip, so the
  // IMU-delay column stays on screen.
  void aManyPointSessionIsSummarisedInSessions() {
    QTemporaryDir dir;
    fog::TestPlan plan;
    for (double hz : {1.0, 1.5, 2.0, 3.0, 4.0}) plan.points.push_back(fog::TestPoint{fog::Axis::kX, hz, 2.0, 3.0, 0.3});
    auto source = fog::acquisition::SimulatorSource::create(fog::model::SimConfig{}, plan, 0.0);
    QVERIFY(source.isOk());
    fog::acquisition::AcquisitionOptions options;
    options.sessionPath = dir.filePath("many.fbs").toStdString();
    options.info.plan = plan;
    options.constants = options.info.bench;
    QVERIFY(fog::acquisition::acquire(**source, options, nullptr).isOk());
    auto w = window();
    w->resize(1024, 700);
    w->showView(MainWindow::kSessions);
    w->sessionBrowser()->setFolder(dir.path());
    settle();
    auto* table = w->sessionBrowser()->table();
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(table->item(0, 4)->text(), QString("X, 5 points"));
    for (int column : {7, 8}) {
      const auto* item = table->item(0, column);
      QVERIFY2(QRegularExpression("^0\\.[0-9]{4}–0\\.[0-9]{4}$").match(item->text()).hasMatch(), qPrintable(item->text()));
      QCOMPARE(item->toolTip().split('\n').size(), 5);
    }
    auto* header = table->horizontalHeader();
    QVERIFY2(header->sectionViewportPosition(8) + header->sectionSize(8) <= table->viewport()->width(),
             qPrintable(QString("the IMU delay column ends at %1 of %2")
                            .arg(header->sectionViewportPosition(8) + header->sectionSize(8))
                            .arg(table->viewport()->width())));
    w->sessionBrowser()->setFolder(sessions_.path());
  }

  // A first start: the sessions folder is made by the first recording, so a
  // folder not made yet is an invitation to run, not an error.
  void aSessionsFolderNotMadeYetInvitesARun() {
    QTemporaryDir parent;
    const QString notYet = QDir(parent.path()).filePath("fogbench-sessions");
    auto w = window();
    w->showView(MainWindow::kSessions);
    w->sessionBrowser()->setFolder(notYet);
    settle();
    const QString summary = w->findChild<QLabel*>("sessionSummary")->text();
    QVERIFY2(summary.startsWith("No sessions yet") && summary.contains("Run a test plan"), qPrintable(summary));
    QVERIFY2(!summary.contains("not a folder"), qPrintable(summary));
    QCOMPARE(w->sessionBrowser()->table()->rowCount(), 0);
    QVERIFY(!QFileInfo::exists(notYet));  // looking makes nothing
    w->sessionBrowser()->setFolder(sessions_.path());
  }

  void sessionsBrowserListsDamagedFilesWithoutLosingTheDelays() {
    QString good;
    {
      auto w = window();
      for (int r = 0; r < w->sessionBrowser()->table()->rowCount(); ++r)
        if (w->sessionBrowser()->table()->item(r, 5)->text() == "complete")
          good = w->sessionBrowser()->table()->item(r, 0)->data(Qt::UserRole).toString();
    }
    QVERIFY(!good.isEmpty());
    QTemporaryDir dir;
    QVERIFY(QFile::copy(good, dir.filePath("a-good.fbs")));
    {
      QFile f(dir.filePath("b-broken.fbs"));
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray(4096, 'x'));
    }
    // A session whose SQLite header was overwritten: a long reason.
    QVERIFY(QFile::copy(good, dir.filePath("c-header.fbs")));
    {
      QFile f(dir.filePath("c-header.fbs"));
      QVERIFY(f.open(QIODevice::ReadWrite));
      f.write(QByteArray(16, '\0'));
    }
    {
      QFile f(dir.filePath("notes.txt"));
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("not a session\n");
    }
    auto w = window();
    w->resize(1024, 700);
    w->showView(MainWindow::kSessions);
    auto* browser = w->sessionBrowser();
    browser->setFolder(dir.path());
    settle();
    auto* table = browser->table();
    QCOMPARE(table->rowCount(), 3);
    const QString summary = w->findChild<QLabel*>("sessionSummary")->text();
    QVERIFY2(summary.contains("1 session") && summary.contains("2 unreadable") && summary.contains("1 other file"),
             qPrintable(summary));
    for (int row : {1, 2}) {
      auto* state = table->item(row, 5);
      QVERIFY2(state->text().startsWith("unreadable: "), qPrintable(state->text()));
      QCOMPARE(state->toolTip(), state->text());
    }
    auto* longest = table->item(2, 5);
    QVERIFY(longest->text().contains("header"));
    // The reason does not fit: the column elides it instead of widening.
    QVERIFY(table->fontMetrics().horizontalAdvance(longest->text()) > table->columnWidth(5));
    auto* header = table->horizontalHeader();
    for (int column : {6, 7, 8})
      QVERIFY2(header->sectionViewportPosition(column) + header->sectionSize(column) <= table->viewport()->width(),
               qPrintable(QString("column %1 ends at %2 of %3").arg(column)
                              .arg(header->sectionViewportPosition(column) + header->sectionSize(column))
                              .arg(table->viewport()->width())));
    QVERIFY(!table->item(0, 6)->text().isEmpty() && table->item(0, 6)->text() != "-");
  }

  // File / Run / View / Tools / Help with the usual shortcuts; Run and Stop
  // work from the keyboard; closing during a run asks first (without
  // blocking) and "Stop the run and close" keeps what was recorded.
  void menusShortcutsAndClosingDuringARun() {
    auto w = window();
    QStringList menus;
    for (QAction* a : w->menuBar()->actions()) menus << a->text().remove('&');
    QCOMPARE(menus, QStringList({"File", "Run", "View", "Tools", "Help"}));
    const std::vector<std::pair<const char*, QKeySequence>> shortcuts = {
        {"runAction", QKeySequence(QStringLiteral("F5"))},
        {"stopAction", QKeySequence(QStringLiteral("Shift+F5"))},
        {"diagnoseAction", QKeySequence(QStringLiteral("Ctrl+D"))},
        {"reanalyseAction", QKeySequence(QStringLiteral("Ctrl+Shift+R"))},
        {"openSessionAction", QKeySequence(QKeySequence::Open)},
        {"loadPlanAction", QKeySequence(QStringLiteral("Ctrl+L"))},
        {"savePlanAction", QKeySequence(QKeySequence::Save)},
        {"quitAction", QKeySequence(QStringLiteral("Ctrl+Q"))},
        {"viewAction2", QKeySequence(QStringLiteral("Ctrl+3"))}};
    for (const auto& [name, keys] : shortcuts) {
      auto* action = w->findChild<QAction*>(name);
      QVERIFY2(action, name);
      QCOMPARE(action->shortcut(), keys);
    }
    // The second keys of Run and Stop, as before F5 came.
    QVERIFY(w->findChild<QAction*>("runAction")->shortcuts().contains(QKeySequence(QStringLiteral("Ctrl+R"))));
    QVERIFY(w->findChild<QAction*>("stopAction")->shortcuts().contains(QKeySequence(QStringLiteral("Ctrl+."))));
    QCOMPARE(QKeySequence(QKeySequence::Save).toString(), QString("Ctrl+S"));
    QCOMPARE(QKeySequence(QKeySequence::Open).toString(), QString("Ctrl+O"));

    // A shortcut typed on the keyboard reaches its action.
    w->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(w.get()));
    QTest::keyClick(w.get(), Qt::Key_3, Qt::ControlModifier);
    QCOMPARE(w->currentView(), MainWindow::kResults);
    QTest::keyClick(w.get(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(w->currentView(), MainWindow::kConfigure);
    QVERIFY(w->planEditor()->loadPreset("paper-fast"));  // 60 s at real time
    w->useSimulator(1.0, 4);
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    auto* run = w->findChild<QAction*>("runAction");
    auto* stop = w->findChild<QAction*>("stopAction");
    QVERIFY(run->isEnabled() && !stop->isEnabled());
    run->trigger();
    QVERIFY(w->isRunning());
    QVERIFY(!run->isEnabled() && stop->isEnabled());

    // Closing asks; "Keep running" keeps running.
    QVERIFY(!w->close());
    auto* ask = w->findChild<QMessageBox*>("closeConfirmDialog");
    QVERIFY(ask && ask->isVisible() && !ask->isModal());
    QTest::mouseClick(ask->findChild<QPushButton*>("keepRunningButton"), Qt::LeftButton);
    settle();
    QVERIFY(w->isRunning() && w->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(w->liveView()->traces().framesSeen() > 1500, 20000);
    w->findChild<QAction*>("quitAction")->trigger();
    ask = w->findChild<QMessageBox*>("closeConfirmDialog");
    QVERIFY(ask && ask->isVisible());
    QTest::mouseClick(ask->findChild<QPushButton*>("stopAndCloseButton"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(!w->isVisible(), 5000);
    QVERIFY(!w->isRunning());
    QVERIFY(w->lastOutcome() && !w->lastOutcome()->complete);
    QVERIFY(QString::fromStdString(w->lastOutcome()->incompleteReason).contains("stopped by the operator"));
    // Stopped on request: not reported as an error.
    auto* error = w->findChild<QMessageBox*>("errorDialog");
    QVERIFY(!error || !error->isVisible());
    const QString recorded = QFileInfo(QString::fromStdString(w->lastOutcome()->sessionPath)).absoluteFilePath();
    QVERIFY(w->recentSessions().contains(recorded));
    // File > Open recent lists it (newest first) and opens it.
    auto* recent = w->findChild<QMenu*>("recentMenu");
    QVERIFY(recent);
    emit recent->aboutToShow();
    QVERIFY(!recent->actions().isEmpty());
    QAction* first = recent->actions().front();
    QCOMPARE(first->text(), QFileInfo(recorded).fileName());
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    first->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 30000);
    QCOMPARE(opened.front().front().toBool(), true);
    QCOMPARE(QString::fromStdString(w->lastOutcome()->sessionPath), recorded);
  }

  // Plans save and load in the CLI's JSON plan format; a bad file is
  // refused with the core's reason and leaves the plan alone.
  void planFilesRoundTrip() {
    auto w = window();
    auto* editor = w->planEditor();
    QVERIFY(editor->loadPreset("paper"));
    setValue(editor, 1, PlanEditor::kAmplitude, 4.5);
    QTemporaryDir dir;
    const QString path = dir.filePath("plan.json");
    const auto saved = w->savePlanFile(path);
    QVERIFY2(saved.isOk(), saved.message().c_str());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto parsed = fog::testPlanFromJson(file.readAll().toStdString());
    QVERIFY(parsed.isOk());
    QCOMPARE(parsed->points.size(), std::size_t(2));
    QCOMPARE(parsed->points[1].amplitudeDeg, 4.5);

    QVERIFY(editor->loadPreset("quick"));
    QCOMPARE(editor->plan().points.size(), std::size_t(1));
    const auto loaded = w->loadPlanFile(path);
    QVERIFY2(loaded.isOk(), loaded.message().c_str());
    const fog::TestPlan plan = editor->plan();
    QCOMPARE(plan.points.size(), std::size_t(2));
    QCOMPARE(plan.points[0].frequencyHz, 0.1);
    QCOMPARE(plan.points[0].durationS, 294.0);
    QCOMPARE(plan.points[1].amplitudeDeg, 4.5);
    QCOMPARE(plan.restBetweenS, parsed->restBetweenS);

    // The table position has no column: a plan file's survives an edit.
    const QString positioned = dir.filePath("positioned.json");
    QFile pf(positioned);
    QVERIFY(pf.open(QIODevice::WriteOnly));
    pf.write(R"({"rest_between_s":2,"points":[{"axis":"y","frequency_hz":1,"amplitude_deg":3,"duration_s":20,)"
             R"("start_phase_deg":30,"position_deg":[30,0,45]}]})");
    pf.close();
    QVERIFY(w->loadPlanFile(positioned).isOk());
    setValue(editor, 0, PlanEditor::kAmplitude, 2.5);
    const fog::TestPlan edited = editor->plan();
    QCOMPARE(edited.points[0].amplitudeDeg, 2.5);
    QCOMPARE(edited.points[0].positionDeg[0], 30.0);
    QCOMPARE(edited.points[0].positionDeg[2], 45.0);
    QCOMPARE(edited.points[0].startPhaseDeg, 30.0);

    const QString bad = dir.filePath("typo.json");
    QFile typo(bad);
    QVERIFY(typo.open(QIODevice::WriteOnly));
    typo.write(R"({"points":[{"axis":"x","frequncy_hz":1,"amplitude_deg":3,"duration_s":20}]})");
    typo.close();
    const auto refused = w->loadPlanFile(bad);
    QVERIFY(!refused.isOk());
    QVERIFY2(QString::fromStdString(refused.message()).contains("frequncy_hz"), refused.message().c_str());
    QCOMPARE(editor->plan().points.size(), std::size_t(1));  // the positioned plan stays
    QCOMPARE(editor->plan().points[0].amplitudeDeg, 2.5);
    QVERIFY(!w->loadPlanFile(dir.filePath("missing.json")).isOk());
  }

  // The plan, pace, operator, IMU model and serial are remembered across
  // starts; a one-off folder (as --session-folder sets it) is not.
  void choicesAreRememberedAcrossStarts() {
    QSettings().remove("state");
    QTemporaryDir oneOff;
    {
      MainWindow first;
      first.setSessionFolder(sessions_.path());
      QVERIFY(first.planEditor()->loadPreset("paper-fast"));
      setValue(first.planEditor(), 0, PlanEditor::kDuration, 42.0);
      auto* pace = first.findChild<QComboBox*>("speedCombo");
      pace->setCurrentIndex(pace->findData(20.0));
      first.findChild<QLineEdit*>("operatorEdit")->setText("Ann Lee");
      first.findChild<QLineEdit*>("imuModelEdit")->setText("FOG-9");
      first.findChild<QLineEdit*>("imuSerialEdit")->setText("SN-77");
      first.findChild<QLineEdit*>("lotEdit")->setText("L-2026-11");
      first.findChild<QLineEdit*>("benchIdEdit")->setText("bench-3");
      first.setRemembering(false);
      first.setSessionFolder(oneOff.path());
      first.setRemembering(true);
      // Enter on the one-off folder, or leaving its field, does not choose it.
      first.show();
      auto* folderEdit = first.configureView()->findChild<QLineEdit*>("sessionFolderEdit");
      QVERIFY(folderEdit);
      folderEdit->setFocus();
      QTest::keyClick(folderEdit, Qt::Key_Return);
      first.configureView()->findChild<QLineEdit*>("operatorEdit")->setFocus();
      QCOMPARE(QSettings().value("sessions/folder").toString(), sessions_.path());
    }
    MainWindow second;
    const fog::TestPlan plan = second.planEditor()->plan();
    QCOMPARE(plan.points.size(), std::size_t(1));
    QCOMPARE(plan.points[0].frequencyHz, 1.0);
    QCOMPARE(plan.points[0].durationS, 42.0);
    QCOMPARE(second.findChild<QComboBox*>("speedCombo")->currentData().toDouble(), 20.0);
    QCOMPARE(second.findChild<QLineEdit*>("operatorEdit")->text(), QString("Ann Lee"));
    QCOMPARE(second.findChild<QLineEdit*>("imuModelEdit")->text(), QString("FOG-9"));
    QCOMPARE(second.findChild<QLineEdit*>("imuSerialEdit")->text(), QString("SN-77"));
    QCOMPARE(second.findChild<QLineEdit*>("lotEdit")->text(), QString("L-2026-11"));
    QCOMPARE(second.findChild<QLineEdit*>("benchIdEdit")->text(), QString("bench-3"));
    QCOMPARE(second.sessionFolder(), sessions_.path());
  }

  // The lot and the bench id of the Configure view reach the session a GUI
  // run records; its stored result carries its audit entry (the run's).
  void aGuiRunStoresTheLotTheBenchAndItsAudit() {
    auto w = window();
    w->findChild<QLineEdit*>("operatorEdit")->setText("Zhao Min");
    w->findChild<QLineEdit*>("lotEdit")->setText("L-7");
    w->findChild<QLineEdit*>("benchIdEdit")->setText("bench-2");
    QVERIFY(w->planEditor()->loadPreset("quick"));
    w->useSimulator(0.0, 6);
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 60000);
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome && !outcome->sessionPath.empty());
    auto reader = fog::session::SessionReader::open(outcome->sessionPath);
    QVERIFY2(reader.isOk(), reader.status().message().c_str());
    QCOMPARE((*reader)->info().lot, std::string("L-7"));
    QCOMPARE((*reader)->info().benchId, std::string("bench-2"));
    auto rows = (*reader)->results();
    QVERIFY(rows.isOk() && rows->size() == 1);
    const auto record = fog::session::readStoredResult(rows->front(), (*reader)->info().bench);
    QVERIFY(record.audit.has_value());
    QCOMPARE(record.audit->who, std::string("Zhao Min"));
    QCOMPARE(record.audit->whoSource, std::string("operator"));
    QCOMPARE(record.audit->tool, std::string("acquisition"));
    QCOMPARE(record.audit->command, std::string("fogbench GUI Configure: Run"));
    auto sha = (*reader)->rawSha256();
    QVERIFY(sha.isOk() && sha->size() == 64);
    QCOMPARE(record.audit->inputSha256, *sha);
  }

  // The source, the serial port and who drives the table (with the remote
  // controller's address) are remembered: a bench is set up once.
  void theSourceAndTheTableAreRememberedAcrossStarts() {
    using fog::ui::ConfigureView;
    QSettings().remove("state");
    {
      MainWindow first;
      first.configureView()->setSourceKind(ConfigureView::SourceKind::kSerial);
      first.configureView()->setSerialPort("/dev/pts/77");
      first.configureView()->setTableDriver(ConfigureView::TableDriver::kRemote, "tcp:192.0.2.7:5025");
    }
    {
      MainWindow second;
      QCOMPARE(second.configureView()->sourceKind(), ConfigureView::SourceKind::kSerial);
      QCOMPARE(second.configureView()->serialPort(), QString("/dev/pts/77"));
      QCOMPARE(second.configureView()->tableDriver(), ConfigureView::TableDriver::kRemote);
      QCOMPARE(second.configureView()->tableAddress(), QString("tcp:192.0.2.7:5025"));
      second.configureView()->setTableDriver(ConfigureView::TableDriver::kNone);
      second.configureView()->setSourceKind(ConfigureView::SourceKind::kSimulator);
    }
    MainWindow third;
    QCOMPARE(third.configureView()->sourceKind(), ConfigureView::SourceKind::kSimulator);
    QCOMPARE(third.configureView()->tableDriver(), ConfigureView::TableDriver::kNone);
  }

  // A folder the operator types (and confirms with Enter) is remembered.
  void aTypedFolderIsRemembered() {
    QTemporaryDir typed;
    auto w = window();
    auto* folderEdit = w->configureView()->findChild<QLineEdit*>("sessionFolderEdit");
    QVERIFY(folderEdit);
    folderEdit->setFocus();
    folderEdit->selectAll();
    QTest::keyClicks(folderEdit, typed.path());
    QTest::keyClick(folderEdit, Qt::Key_Return);
    QCOMPARE(QSettings().value("sessions/folder").toString(), typed.path());
    QCOMPARE(w->sessionFolder(), typed.path());
    w->setSessionFolder(sessions_.path());
  }

  // The real program: --help answers without a display, and a one-off
  // --session-folder leaves the remembered folder alone.
  void commandLineHelpAndOneOffFolder() {
    QTemporaryDir home;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* v : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"}) env.remove(v);
    env.insert("XDG_CONFIG_HOME", home.filePath("config"));
    QProcess help;
    help.setProcessEnvironment(env);
    help.start(FOG_GUI, {"--help"});
    QVERIFY(help.waitForFinished(30000));
    QCOMPARE(help.exitStatus(), QProcess::NormalExit);
    QCOMPARE(help.exitCode(), 0);
    QVERIFY(QString::fromUtf8(help.readAllStandardOutput()).contains("--session-folder"));

    QVERIFY(QDir().mkpath(home.filePath("config/fogbench")));
    const QString conf = home.filePath("config/fogbench/fogbench.conf");
    QVERIFY(QDir().mkpath(home.filePath("saved")));
    {
      QSettings settings(conf, QSettings::IniFormat);
      settings.setValue("sessions/folder", home.filePath("saved"));
    }
    env.insert("QT_QPA_PLATFORM", "offscreen");
    QProcess gui;
    gui.setProcessEnvironment(env);
    gui.start(FOG_GUI, {"--session-folder", home.filePath("once"), "--view", "configure", "--screenshot",
                        home.filePath("configure.png")});
    QVERIFY(gui.waitForFinished(60000));
    QVERIFY2(gui.exitCode() == 0, gui.readAllStandardError().constData());
    QVERIFY(QFileInfo(home.filePath("configure.png")).size() > 1000);
    QSettings settings(conf, QSettings::IniFormat);
    QCOMPARE(settings.value("sessions/folder").toString(), home.filePath("saved"));
  }

  // Exports default to the session's folder, named with the IMU serial and
  // the recording date; the status bar says where; the folder can be opened.
  void exportsGoNextToTheSession() {
    auto w = window();
    w->findChild<QLineEdit*>("imuSerialEdit")->setText("SN 77/b");
    QVERIFY(w->planEditor()->loadPreset("quick"));
    w->useSimulator(0.0, 6);
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 60000);
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome && !outcome->sessionPath.empty());
    const QString folder = QFileInfo(QString::fromStdString(outcome->sessionPath)).absolutePath();
    const QString date =
        QDateTime::fromString(QString::fromStdString(outcome->info.createdUtc), Qt::ISODate).toUTC().toString("yyyyMMdd");
    QVERIFY(!date.isEmpty());

    const QString pdf = w->resultView()->defaultExportPath("calibration-report", "pdf");
    QCOMPARE(QFileInfo(pdf).absolutePath(), folder);
    QVERIFY2(QFileInfo(pdf).fileName().startsWith("calibration-report-SN_77_b-" + date), qPrintable(pdf));
    QVERIFY(pdf.endsWith(".pdf"));
    QVERIFY(!w->findChild<QAction*>("openExportFolderAction")->isEnabled() || w->lastExport().isEmpty());
    const auto written = w->resultView()->exportReportTo(pdf);
    QVERIFY2(written.isOk(), written.message().c_str());
    QVERIFY(QFile::exists(pdf));
    QCOMPARE(w->lastExport(), pdf);
    QVERIFY2(w->lastMessage().contains(QDir::toNativeSeparators(pdf)), qPrintable(w->lastMessage()));
    QVERIFY(w->findChild<QAction*>("openExportFolderAction")->isEnabled());

    auto* plot = w->resultView()->anglePlot();
    const QString png = w->resultView()->defaultExportPath(plot->objectName(), "png");
    QVERIFY2(QFileInfo(png).fileName().startsWith("anglePlot-SN_77_b-" + date), qPrintable(png));
    QVERIFY(w->resultView()->exportPlotTo(plot, png).isOk());
    QVERIFY(QFileInfo(png).size() > 500);
    QCOMPARE(w->lastExport(), png);
    QVERIFY(!w->resultView()->exportPlotTo(plot, "/nonexistent-dir/p.png").isOk());
    QCOMPARE(w->lastExport(), png);
  }

  // CSV out of Results, read back: the delay rows are the stored result's
  // numbers; the session data is the CLI's export (its fits.csv holds the
  // shown lag); the HDF5 file is written and never over the session; a
  // folder that holds anything is refused and its file left as it was; a
  // path that cannot be written says so and writes nothing.
  void csvExportsReadBackAsTheStoredResult() {
    auto w = window();
    QVERIFY(w->planEditor()->loadPreset("paper"));
    w->useSimulator(0.0, 3);
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 120000);
    const QString session = QString::fromStdString(w->lastOutcome()->sessionPath);
    QSignalSpy opened(w.get(), &MainWindow::sessionOpened);
    w->openSession(session);
    QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 60000);
    const auto* outcome = w->resultView()->outcome();
    QVERIFY(outcome && outcome->report && outcome->shownResult());
    const auto& report = *outcome->report;
    QCOMPARE(report.points.size(), std::size_t(2));

    QTemporaryDir out;
    const QString csv = out.filePath("delays.csv");
    QVERIFY2(w->resultView()->exportDelayRowsTo(csv).isEmpty(), qPrintable(w->lastMessage()));
    QCOMPARE(w->lastExport(), csv);
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QStringList rows;
    for (const QString& line : QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts))
      if (!line.startsWith('#')) rows << line;
    QCOMPARE(rows.front(), QString("test_point,axis,frequency_hz,quantity,value_ms,std_ms,verdict,vouched,reason"));
    QCOMPARE(rows.size(), 1 + 5 * 2);
    int imuRows = 0;
    for (const QString& row : rows.mid(1)) {
      const QStringList f = row.split(',');
      QCOMPARE(f.size(), 9);
      // Every row carries its point's shown (stored) verdict.
      QCOMPARE(f[6], QString("pass"));
      QCOMPARE(f[7], QString("true"));
      QVERIFY2(f[8].startsWith("IMU delay "), qPrintable(row));
      const int index = f[0].toInt() - 1;
      QVERIFY(index >= 0 && index < 2);
      const auto& p = report.points[static_cast<std::size_t>(index)];
      QCOMPARE(f[1], QString(fog::axisLabel(p.axis)));
      if (f[3] == "imu_delay") {
        ++imuRows;
        // Exactly this analysis's number, and the stored record's to its rounding.
        QCOMPARE(f[4].toDouble(), p.imuDelayMs);
        QCOMPARE(f[5].toDouble(), p.imuDelayStdMs);
        const auto* stored = outcome->shownResult()->point(p.index);
        QVERIFY(stored);
        QVERIFY2(std::abs(f[4].toDouble() - stored->imuDelayMs) < 1e-6, qPrintable(row));
        QVERIFY2(std::abs(f[5].toDouble() - stored->imuDelayStdMs) < 1e-6, qPrintable(row));
      }
      if (f[3] == "measured_lag") QCOMPARE(f[4].toDouble(), p.lagMs);
      if (f[3] == "gyro_delay") QCOMPARE(f[4].toDouble(), p.gyroDelayMs);
      if (f[3] == "table_read_delay") QCOMPARE(f[4].toDouble(), report.constants.tableReadDelayMs);
    }
    QCOMPARE(imuRows, 2);

    // The session's data as fogbench-cli export writes it.
    const QString data = out.filePath("data");
    const auto written = w->resultView()->exportDataTo(data);
    QVERIFY2(written.isOk(), written.message().c_str());
    QCOMPARE(w->lastExport(), data);
    for (const char* name : {"metadata.json", "table.csv", "gyro.csv", "fits.csv", "report.json", "residuals_1.csv"})
      QVERIFY2(QFile::exists(QDir(data).filePath(name)), name);
    QFile fits(QDir(data).filePath("fits.csv"));
    QVERIFY(fits.open(QIODevice::ReadOnly));
    QStringList header;
    int joints = 0;
    for (const QString& line : QString::fromUtf8(fits.readAll()).split('\n', Qt::SkipEmptyParts)) {
      if (line.startsWith('#')) continue;
      if (header.isEmpty()) {
        header = line.split(',');
        continue;
      }
      const QStringList f = line.split(',');
      if (f.value(2) != "joint") continue;
      const auto& p = report.points[static_cast<std::size_t>(f[0].toInt() - 1)];
      QCOMPARE(f[header.indexOf("lag_ms")].toDouble(), p.joint.lagS * 1e3);
      ++joints;
    }
    QCOMPARE(joints, 2);

    // The same data and the shown result in one HDF5 file (Export menu,
    // "Session data and result (HDF5 file)"; its values are compared with the
    // CSV export's by tests/hdf5). A session is never the file replaced.
    const QString h5 = out.filePath("data.h5");
    const auto h5Written = fog::ui::exportSessionHdf5(*outcome, h5);
    QVERIFY2(h5Written.isOk(), h5Written.message().c_str());
    QFile h5File(h5);
    QVERIFY(h5File.open(QIODevice::ReadOnly));
    QVERIFY(h5File.read(8) == QByteArray("\x89HDF\r\n\x1a\n", 8));  // the HDF5 signature
    h5File.close();
    const QByteArray sessionBytes = [&] {
      QFile f(session);
      return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }();
    QVERIFY(!fog::ui::exportSessionHdf5(*outcome, session).isOk());
    QFile sessionAfter(session);
    QVERIFY(sessionAfter.open(QIODevice::ReadOnly));
    QCOMPARE(sessionAfter.readAll(), sessionBytes);

    // Never over a file the operator did not name: a folder holding one is
    // refused, the file untouched.
    const QString busy = out.filePath("busy");
    QVERIFY(QDir().mkpath(busy));
    QFile keep(QDir(busy).filePath("notes.txt"));
    QVERIFY(keep.open(QIODevice::WriteOnly));
    keep.write("mine");
    keep.close();
    QVERIFY(!w->resultView()->exportDataTo(busy).isOk());
    QVERIFY(keep.open(QIODevice::ReadOnly));
    QCOMPARE(keep.readAll(), QByteArray("mine"));
    keep.close();
    QCOMPARE(QDir(busy).entryList(QDir::Files).size(), 1);

    // A path that cannot be written (its folder is a file): a reason naming
    // it, nothing written, the last export unchanged.
    const QString blocked = QDir(busy).filePath("notes.txt/delays.csv");
    const QString why = w->resultView()->exportDelayRowsTo(blocked);
    QVERIFY2(why.contains(QDir::toNativeSeparators(blocked)), qPrintable(why));
    QCOMPARE(w->lastExport(), data);
    QVERIFY(keep.open(QIODevice::ReadOnly));
    QCOMPARE(keep.readAll(), QByteArray("mine"));
  }

  // A board whose port vanishes mid-run: the run ends incomplete by itself,
  // and the reason is shown whole in the error box (not only in the status
  // bar, where the frame counters cut it).
  void aRunThatEndsEarlyIsExplainedWhole() {
    QProcess board;
    const QString pty = startBoard(board, {"--disconnect-at-s", "3"});
    QVERIFY2(!pty.isEmpty(), board.readAllStandardError().constData());
    auto w = window();
    QSignalSpy ended(w.get(), &MainWindow::runEnded);
    w->setSourceKind(MainWindow::SourceKind::kSerial);
    w->findChild<QComboBox*>("portCombo")->setCurrentText(pty);
    click(*w, "runButton");
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 60000);
    board.waitForFinished(20000);
    const auto* outcome = w->lastOutcome();
    QVERIFY(outcome);
    QVERIFY(!outcome->complete);
    const QString reason = QString::fromStdString(outcome->incompleteReason);
    QVERIFY(!reason.isEmpty());
    auto* box = w->findChild<QMessageBox*>("errorDialog");
    QVERIFY(box && box->isVisible());
    QCOMPARE(box->windowTitle(), QString("Run incomplete"));
    QVERIFY2(box->informativeText().contains(fog::ui::displayUnits(reason)), qPrintable(box->informativeText()));
    QVERIFY(box->textInteractionFlags() & Qt::TextSelectableByMouse);
  }

  // Plots export as PNG, SVG and PDF; a bad name is explained.
  void plotsExport() {
    QTemporaryDir dir;
    auto w = window();
    auto* plot = w->liveView()->tablePlot();
    for (const char* name : {"p.png", "p.svg", "p.pdf"}) {
      const QString path = dir.filePath(name);
      const auto s = fog::ui::exportPlot(plot, path);
      QVERIFY2(s.isOk(), s.message().c_str());
      QVERIFY(QFileInfo(path).size() > 500);
    }
    QVERIFY(!fog::ui::exportPlot(plot, dir.filePath("p.txt")).isOk());
    QVERIFY(!fog::ui::exportPlot(plot, "/nonexistent-dir/p.pdf").isOk());
  }

  // Closing the window mid-run stops the worker: no crash, no hang.
  void destroyingTheWindowMidRunStopsTheWorker() {
    auto w = window();
    w->planEditor()->loadPreset("paper");
    w->useSimulator(1.0, 3);
    click(*w, "runButton");
    QVERIFY(w->isRunning());
    QElapsedTimer clock;
    clock.start();
    w.reset();
    QVERIFY(clock.elapsed() < 5000);
  }

  // One version everywhere: the About box says the CMake project version.
  void aboutBoxShowsTheVersion() {
    auto w = window();
    QVERIFY(w->findChild<QAction*>("aboutAction"));
    QVERIFY(w->aboutText().contains(QString("fogbench %1").arg(FOG_VERSION)));
    QVERIFY(w->windowTitle().contains(FOG_VERSION));
  }

  // The core's ASCII units read as the GUI writes them everywhere else.
  void unitsReadAsTheGuiWritesThem() {
    using fog::ui::displayUnits;
    QCOMPARE(displayUnits("amplitude 50 deg is beyond the table limit of 45 deg"),
             QString("amplitude 50° is beyond the table limit of 45°"));
    QCOMPARE(displayUnits("peak acceleration 3947.8 deg/s^2 exceeds the table limit of 3000 deg/s^2; lower it"),
             QString("peak acceleration 3947.8 °/s² exceeds the table limit of 3000 °/s²; lower it"));
    QCOMPARE(displayUnits("peak rate 628 deg/s"), QString("peak rate 628 °/s"));
    QCOMPARE(displayUnits("deg/sqrt(h)"), QString("°/√h"));
    QCOMPARE(displayUnits("deg/h/sqrt(h)"), QString("°/h/√h"));
    QCOMPARE(displayUnits("a degree of freedom, 3 degrees"), QString("a degree of freedom, 3 degrees"));
  }

  void durationsReadWell() {
    QCOMPARE(fog::ui::formatDuration(0.0004658), QString("465.8 µs"));
    QCOMPARE(fog::ui::formatDuration(0.0123), QString("12.3000 ms"));
    QCOMPARE(fog::ui::formatDuration(-1.5), QString("-1.5000 s"));
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

  // The language changes while the program runs: the window is made again in
  // it, with the plan it had; and back.
  void languageChangesWithoutRestart() {
    fog::ui::WindowHost host(*qApp);
    host.window()->show();
    fog::TestPlan plan;
    plan.points = {fog::TestPoint{}};
    plan.points[0].frequencyHz = 0.7;
    plan.points[0].amplitudeDeg = 4.0;
    plan.points[0].durationS = 30.0;
    host.window()->planEditor()->setPlan(plan);
    // A one-off folder and seed (as the command line gives them) are kept too.
    QTemporaryDir folder;
    host.window()->setRemembering(false);
    host.window()->setSessionFolder(folder.path());
    host.window()->configureView()->setSeed(17);
    host.window()->setRemembering(true);
    QSignalSpy replaced(&host, &fog::ui::WindowHost::windowReplaced);
    auto* chinese = host.window()->findChild<QAction*>("language_zh_CN");
    QVERIFY(chinese);
    chinese->trigger();
    QTRY_COMPARE(replaced.count(), 1);
    QCOMPARE(replaced.at(0).at(1).toString(), QString("zh_CN"));
    auto* tabs = host.window()->findChild<QTabWidget*>("viewTabs");
    QCOMPARE(tabs->tabText(0), QString::fromUtf8("配置"));
    QCOMPARE(button(*host.window(), "runButton")->text(), QString::fromUtf8("运行"));
    QVERIFY(host.window()->isVisible());
    QCOMPARE(host.window()->planEditor()->plan().points.size(), std::size_t{1});
    QCOMPARE(host.window()->planEditor()->plan().points[0].frequencyHz, 0.7);
    QCOMPARE(host.window()->sessionFolder(), folder.path());
    QCOMPARE(host.window()->configureView()->seed(), 17);
    host.window()->findChild<QAction*>("language_en")->trigger();
    QTRY_COMPARE(replaced.count(), 2);
    QCOMPARE(host.window()->findChild<QTabWidget*>("viewTabs")->tabText(0), QString("Configure"));
  }

  // Runs last: it installs the Chinese translation into the application.
  void chineseGuiWhenChosen() {
    QCOMPARE(fog::ui::installTranslations(*qApp, "zh_CN"), QString("zh_CN"));
    auto w = window();
    auto* tabs = w->findChild<QTabWidget*>("viewTabs");
    QVERIFY(tabs);
    QCOMPARE(tabs->tabText(0), QString::fromUtf8("配置"));
    QCOMPARE(tabs->tabText(1), QString::fromUtf8("实时"));
    QCOMPARE(button(*w, "runButton")->text(), QString::fromUtf8("运行"));
    // Numbers follow the locale; the files the bench writes do not (CSV/JSON
    // use std::to_chars, see docs/formats.md).
    QCOMPARE(QLocale().name(), QString("zh_CN"));
  }
};

QTEST_MAIN(BenchUiTest)
#include "bench_ui_test.moc"

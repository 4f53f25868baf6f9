// The table's axis panel and the emergency stop, against the emulated
// controller (core/table/emulator_link.h: the remote driver and the
// emulator's own code in this process): positions and states, jog, home and
// go-to checked against the table's limits before anything is sent, Stop,
// the controller's refusals in words, the emergency stop, an unreachable
// table, and everything disabled with the reason when no table is connected.
// The panel's link runs on a thread of its own, so what it shows arrives
// after the call that asked for it (QTRY_*).

#include <QAction>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QtTest>
#include <cmath>
#include <memory>

#include "core/table/emulator_link.h"
#include "ui/main_window.h"
#include "ui/table_panel.h"

using fog::Axis;
using fog::ui::TablePanel;
namespace table = fog::table;

namespace {

// speed 20: moves of a few degrees end within a fraction of a second; 1: a
// 40-degree move takes some 2 s (time to stop it or to refuse a second one).
std::unique_ptr<table::TableController> emulated(double speed = 20.0) {
  table::EmulatorLinkOptions options;
  options.speed = speed;
  auto c = table::connectEmulatedTable(options);
  return c ? std::move(*c) : nullptr;
}

// Runs the GUI's event loop for `ms`.
void spin(int ms) {
  QElapsedTimer t;
  t.start();
  while (t.elapsed() < ms) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

// A controller whose every call fails as a lost link does.
class LostController : public table::TableController {
 public:
  std::string description() const override { return "lost"; }
  fog::Result<std::string> identify() override { return fog::ioError("table link lost"); }
  fog::Result<table::TableLimits> limits() override { return fog::ioError("table link lost"); }
  fog::Result<table::TableState> state() override { return fog::ioError("table link lost"); }
  fog::Status configureSwing(Axis, const table::SwingSpec&) override { return fog::ioError("table link lost"); }
  fog::Status moveTo(Axis, double) override {
    ++moves;
    return fog::ioError("table link lost");
  }
  fog::Status startSwing(Axis) override { return fog::ioError("table link lost"); }
  fog::Status stop(Axis) override { return fog::ioError("table link lost"); }
  fog::Status stopAll() override { return fog::ioError("table link lost"); }
  fog::Status emergencyStop() override { return fog::ioError("table link lost"); }
  fog::Status keepAlive() override { return fog::ioError("table link lost"); }
  std::atomic<int> moves{0};  // counted on the panel's link thread
};

double degrees(const QString& text) {
  QString t = text;
  t.remove(QChar(0x00B0));
  bool ok = false;
  const double v = QLocale().toDouble(t, &ok);
  return ok ? v : std::nan("");
}

}  // namespace

// The panel connected to the controller and showing its state.
bool ready(const TablePanel& panel) {
  return panel.link() == TablePanel::Link::kConnected && panel.stateText(Axis::kX) == "idle";
}

class TablePanelTest : public QObject {
  Q_OBJECT

 private slots:
  void withoutATableEverythingIsDisabledAndSaysWhy() {
    TablePanel panel;
    QVERIFY(!panel.connected());
    QVERIFY(!panel.emergencyStopAvailable());
    QVERIFY(panel.disabledReason().contains("No table is connected"));
    for (int a = 0; a < fog::kAxisCount; ++a) {
      const auto axis = static_cast<Axis>(a);
      for (QPushButton* b : {panel.jogButton(axis, -1), panel.jogButton(axis, 1), panel.homeButton(axis)}) {
        QVERIFY(!b->isEnabled());
        QCOMPARE(b->toolTip(), panel.disabledReason());
      }
    }
    QVERIFY(!panel.goButton()->isEnabled());
    QVERIFY(!panel.stopButton()->isEnabled());
    QVERIFY(!panel.emergencyStopButton()->isEnabled());
    QVERIFY(!panel.emergencyStop().isEmpty());
    QVERIFY(!panel.stop().isEmpty());
  }

  void jogHomeAndGoToMoveTheTable() {
    TablePanel panel;
    auto controller = emulated();
    QVERIFY(controller);
    panel.setController(std::move(controller));
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 5000);
    QVERIFY(panel.connected());
    QVERIFY(panel.jogButton(Axis::kY, 1)->isEnabled());
    QCOMPARE(degrees(panel.positionText(Axis::kY)), 0.0);

    panel.stepSpin()->setValue(2.5);
    QVERIFY(panel.jog(Axis::kY, +1).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kY) == "idle" && degrees(panel.positionText(Axis::kY)) > 2.0,
                             10000);
    QCOMPARE(degrees(panel.positionText(Axis::kY)), 2.5);
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 0.0);  // the others stay
    QVERIFY(panel.jog(Axis::kY, -1).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kY) == "idle" && degrees(panel.positionText(Axis::kY)) < 0.5,
                             10000);
    QCOMPARE(degrees(panel.positionText(Axis::kY)), 0.0);

    QVERIFY(panel.goTo(Axis::kZ, -7.25).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kZ) == "idle" && degrees(panel.positionText(Axis::kZ)) < -7.0,
                             10000);
    QCOMPARE(degrees(panel.positionText(Axis::kZ)), -7.25);
    QVERIFY(panel.home(Axis::kZ).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kZ) == "idle" && degrees(panel.positionText(Axis::kZ)) > -0.5,
                             10000);
    QCOMPARE(degrees(panel.positionText(Axis::kZ)), 0.0);
  }

  // Beyond the table's range: refused with the limit, nothing sent.
  void aMoveBeyondTheLimitsIsRefusedBeforeAnyMotion() {
    TablePanel panel;
    panel.setController(emulated());
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 5000);
    const QString why = panel.goTo(Axis::kX, 200.0);
    QVERIFY2(why.contains("beyond") && why.contains("180") && why.contains("not moved"), qPrintable(why));
    QCOMPARE(panel.message(), why);
    spin(3 * fog::ui::TableLink::kPollMs);
    QCOMPARE(panel.stateText(Axis::kX), QString("idle"));
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 0.0);
    // A jog that would leave the range, too.
    QVERIFY(panel.goTo(Axis::kX, 179.5).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kX) == "idle" && degrees(panel.positionText(Axis::kX)) > 179.0,
                             20000);
    panel.stepSpin()->setValue(1.0);
    QVERIFY(panel.jog(Axis::kX, +1).contains("beyond"));
    spin(3 * fog::ui::TableLink::kPollMs);
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 179.5);
  }

  // The emergency stop reaches the controller; then nothing moves until it
  // is reset there.
  void theEmergencyStopStopsTheTableAndBlocksMotion() {
    TablePanel panel;
    panel.setController(emulated(1.0));
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 5000);
    QVERIFY(panel.goTo(Axis::kY, 40.0).isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(Axis::kY), QString("moving"), 5000);
    QVERIFY(panel.emergencyStop().isEmpty());
    for (int a = 0; a < fog::kAxisCount; ++a)
      QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(static_cast<Axis>(a)), QString("emergency stop"), 5000);
    QVERIFY2(panel.message().startsWith("Emergency stop sent"), qPrintable(panel.message()));
    const QString why = panel.jog(Axis::kX, +1);
    QVERIFY2(why.contains("emergency stop"), qPrintable(why));
  }

  // Stop: the move ends short of its target, decelerated (the axis reads
  // "idle", not "emergency stop"), and the table moves again at once (not latched).
  void stopEndsAMoveAndIsNotLatched() {
    TablePanel panel;
    panel.setController(emulated(1.0));
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 5000);
    QVERIFY(panel.stopButton()->isEnabled());
    QVERIFY(panel.goTo(Axis::kY, 40.0).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kY) == "moving" && degrees(panel.positionText(Axis::kY)) > 2.0,
                             5000);
    panel.stopButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(Axis::kY), QString("idle"), 5000);
    const double stoppedAt = degrees(panel.positionText(Axis::kY));
    QVERIFY2(stoppedAt > 0.0 && stoppedAt < 35.0, qPrintable(panel.positionText(Axis::kY)));
    QVERIFY2(panel.message().contains("decelerates to rest"), qPrintable(panel.message()));
    QVERIFY(panel.goTo(Axis::kY, 0.0).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kY) == "idle" && degrees(panel.positionText(Axis::kY)) < 0.01,
                             10000);
  }

  // Home while the axis moves: the controller refuses (-221 settings
  // conflict); the panel says so in words and what to do, and the words go
  // once the move has ended.
  void aRefusalIsShownInWordsAndClearedWhenTheStateChanges() {
    TablePanel panel;
    panel.setController(emulated(1.0));
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 5000);
    QVERIFY(panel.goTo(Axis::kX, 10.0).isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(Axis::kX), QString("moving"), 5000);
    QVERIFY(panel.home(Axis::kX).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.message().contains("refuses"), 5000);
    const QString words = panel.message();
    QVERIFY2(words.contains("the table is moving") && words.contains("press Stop") && !words.contains("-221"),
             qPrintable(words));
    QCOMPARE(panel.stateText(Axis::kX), QString("moving"));  // still moving: the words stay
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kX) == "idle", 10000);
    QTRY_VERIFY_WITH_TIMEOUT(panel.message().isEmpty(), 2000);
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 10.0);
  }

  void aLostTableReadsUnreachableAndMovesNothing() {
    TablePanel panel;
    auto lost = std::make_unique<LostController>();
    auto* raw = lost.get();
    panel.setController(std::move(lost));
    for (int a = 0; a < fog::kAxisCount; ++a)
      QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(static_cast<Axis>(a)), QString("unreachable"), 5000);
    QVERIFY(!panel.jogButton(Axis::kX, 1)->isEnabled());
    QVERIFY(panel.goTo(Axis::kX, 1.0).contains("does not answer"));
    spin(2 * fog::ui::TableLink::kPollMs);
    QCOMPARE(raw->moves.load(), 0);
  }

  // The main window's tool bar: the emergency stop is there, disabled with
  // the reason until a table is connected, and stops it when triggered.
  void theToolBarEmergencyStopFollowsTheConnection() {
    fog::ui::MainWindow w;
    QAction* estop = w.emergencyStopAction();
    QVERIFY(estop);
    QVERIFY(!estop->isEnabled());
    QVERIFY2(estop->toolTip().contains("No table is connected"), qPrintable(estop->toolTip()));
    w.tablePanel()->setController(emulated());
    QVERIFY(estop->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(ready(*w.tablePanel()), 5000);
    estop->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(w.tablePanel()->stateText(Axis::kX), QString("emergency stop"), 5000);
    w.tablePanel()->setController(nullptr);
    QVERIFY(!estop->isEnabled());
  }
};

QTEST_MAIN(TablePanelTest)
#include "table_panel_test.moc"

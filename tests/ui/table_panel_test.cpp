// The table's axis panel and the emergency stop, against the emulated
// controller (core/table/emulator_link.h: the remote driver and the
// emulator's own code in this process): positions and states, jog, home and
// go-to checked against the table's limits before anything is sent, the
// emergency stop, an unreachable table, and everything disabled with the
// reason when no table is connected.

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

std::unique_ptr<table::TableController> emulated() {
  table::EmulatorLinkOptions options;
  options.speed = 20.0;  // moves of a few degrees end within a fraction of a second
  auto c = table::connectEmulatedTable(options);
  return c ? std::move(*c) : nullptr;
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
  int moves = 0;
};

double degrees(const QString& text) {
  QString t = text;
  t.remove(QChar(0x00B0));
  bool ok = false;
  const double v = QLocale().toDouble(t, &ok);
  return ok ? v : std::nan("");
}

}  // namespace

class TablePanelTest : public QObject {
  Q_OBJECT

 private slots:
  void withoutATableEverythingIsDisabledAndSaysWhy() {
    TablePanel panel;
    QVERIFY(!panel.connected());
    QVERIFY(panel.disabledReason().contains("No table is connected"));
    for (int a = 0; a < fog::kAxisCount; ++a) {
      const auto axis = static_cast<Axis>(a);
      for (QPushButton* b : {panel.jogButton(axis, -1), panel.jogButton(axis, 1), panel.homeButton(axis)}) {
        QVERIFY(!b->isEnabled());
        QCOMPARE(b->toolTip(), panel.disabledReason());
      }
    }
    QVERIFY(!panel.goButton()->isEnabled());
    QVERIFY(!panel.emergencyStop().isEmpty());
  }

  void jogHomeAndGoToMoveTheTable() {
    TablePanel panel;
    auto controller = emulated();
    QVERIFY(controller);
    panel.setController(std::move(controller));
    QVERIFY(panel.connected());
    QVERIFY(panel.jogButton(Axis::kY, 1)->isEnabled());
    QCOMPARE(panel.stateText(Axis::kY), QString("idle"));
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
    const QString why = panel.goTo(Axis::kX, 200.0);
    QVERIFY2(why.contains("beyond") && why.contains("180") && why.contains("not moved"), qPrintable(why));
    QCOMPARE(panel.message(), why);
    panel.poll();
    QCOMPARE(panel.stateText(Axis::kX), QString("idle"));
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 0.0);
    // A jog that would leave the range, too.
    QVERIFY(panel.goTo(Axis::kX, 179.5).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(panel.stateText(Axis::kX) == "idle" && degrees(panel.positionText(Axis::kX)) > 179.0,
                             20000);
    panel.stepSpin()->setValue(1.0);
    QVERIFY(panel.jog(Axis::kX, +1).contains("beyond"));
    panel.poll();
    QCOMPARE(degrees(panel.positionText(Axis::kX)), 179.5);
  }

  // The emergency stop reaches the controller; then nothing moves until it
  // is reset there.
  void theEmergencyStopStopsTheTableAndBlocksMotion() {
    TablePanel panel;
    panel.setController(emulated());
    QVERIFY(panel.goTo(Axis::kY, 40.0).isEmpty());
    QVERIFY(panel.emergencyStop().isEmpty());
    for (int a = 0; a < fog::kAxisCount; ++a) QCOMPARE(panel.stateText(static_cast<Axis>(a)), QString("emergency stop"));
    const QString why = panel.jog(Axis::kX, +1);
    QVERIFY2(why.contains("emergency stop"), qPrintable(why));
  }

  void aLostTableReadsUnreachableAndMovesNothing() {
    TablePanel panel;
    auto lost = std::make_unique<LostController>();
    auto* raw = lost.get();
    panel.setController(std::move(lost));
    for (int a = 0; a < fog::kAxisCount; ++a) QCOMPARE(panel.stateText(static_cast<Axis>(a)), QString("unreachable"));
    QVERIFY(!panel.jogButton(Axis::kX, 1)->isEnabled());
    QVERIFY(panel.goTo(Axis::kX, 1.0).contains("does not answer"));
    QCOMPARE(raw->moves, 0);
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
    estop->trigger();
    QCOMPARE(w.tablePanel()->stateText(Axis::kX), QString("emergency stop"));
    w.tablePanel()->setController(nullptr);
    QVERIFY(!estop->isEnabled());
  }
};

QTEST_MAIN(TablePanelTest)
#include "table_panel_test.moc"

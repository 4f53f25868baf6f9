// The table's axis panel and the emergency stop, against the emulated
// controller (core/table/emulator_link.h: the remote driver and the
// emulator's own code in this process): positions and states, jog, home and
// go-to checked against the table's limits before anything is sent, Stop,
// the controller's refusals in words, the emergency stop, an unreachable
// table, and everything disabled with the reason when no table is connected.
// The panel's link runs on a thread of its own, so what it shows arrives
// after the call that asked for it (QTRY_*).
//
// The desk tests of issue 41 ("a safety path never waits"): a controller
// that hangs — fogbench-table-emu stopped with SIGSTOP mid-session, a fake
// controller that stops answering mid-session, one that accepts the
// connection and never answers — does not freeze the window (a 20-ms timer
// on the GUI thread records no gap over 200 ms), and an emergency stop
// clicked meanwhile reaches the controller within 50 ms.

#include <QAction>
#include <QDoubleSpinBox>
#include <QProcess>
#include <QPushButton>
#include <QtTest>
#include <csignal>
#include <cmath>
#include <memory>
#include <thread>

#include "core/table/emulator_link.h"
#include "tests/core/table/fake_tcp_controller.h"
#include "ui/commanded_motion.h"
#include "ui/configure_view.h"
#include "ui/main_window.h"
#include "ui/plan_editor.h"
#include "ui/table_panel.h"

using fog::Axis;
using fog::ui::TablePanel;
namespace table = fog::table;

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// speed 20: moves of a few degrees end within a fraction of a second; 1: a
// 40-degree move takes some 2 s (time to stop it or to refuse a second one).
std::unique_ptr<table::TableController> emulated(double speed = 20.0) {
  table::EmulatorLinkOptions options;
  options.speed = speed;
  auto c = table::connectEmulatedTable(options);
  return c ? std::move(*c) : nullptr;
}

// The GUI thread's heartbeat: a 20-ms timer whose largest gap between two
// ticks is how long the window was frozen.
class GuiTicks {
 public:
  GuiTicks() {
    timer_.setInterval(20);
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      const auto now = Clock::now();
      maxGapMs_ = std::max(maxGapMs_, msBetween(last_, now));
      last_ = now;
    });
    last_ = Clock::now();
    timer_.start();
  }
  double maxGapMs() const { return maxGapMs_; }

 private:
  QTimer timer_;
  Clock::time_point last_;
  double maxGapMs_ = 0.0;
};

// Runs the GUI's event loop for `ms`.
void spin(int ms) {
  QElapsedTimer t;
  t.start();
  while (t.elapsed() < ms) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

// The operator's click, `afterMs` from now, as a window system delivers it:
// queued to the GUI thread from outside it (here, another thread), whatever
// the GUI thread is doing. Returns when the click was queued.
class LaterClick {
 public:
  LaterClick(QPushButton* button, int afterMs)
      : thread_([this, button, afterMs] {
          std::this_thread::sleep_for(std::chrono::milliseconds(afterMs));
          at_ = Clock::now();
          QMetaObject::invokeMethod(button, "click", Qt::QueuedConnection);
        }) {}
  ~LaterClick() { join(); }
  Clock::time_point at() {
    join();
    return at_;
  }

 private:
  void join() {
    if (thread_.joinable()) thread_.join();
  }
  Clock::time_point at_;
  std::thread thread_;
};

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

  // Configure checks the plan against the table that will swing it: with the
  // serial board and a remote controller, the connected controller's limits
  // (here a Y axis limited to 2 Hz), named as its; back to the simulator's
  // turntable, saying so, when the panel disconnects.
  void configureNamesTheConnectedTablesLimits() {
    fog::ui::MainWindow w;
    auto* configure = w.configureView();
    configure->setSourceKind(fog::ui::ConfigureView::SourceKind::kSerial);
    configure->setTableDriver(fog::ui::ConfigureView::TableDriver::kRemote, "tcp:127.0.0.1:5025");
    const QString before = configure->commandedMotion()->limitsText();
    QVERIFY2(before.contains("simulator") && before.contains("no controller connected"), qPrintable(before));
    fog::TestPlan plan;
    fog::TestPoint point;
    point.axis = Axis::kY;
    point.frequencyHz = 5.0;
    point.amplitudeDeg = 1.0;
    point.durationS = 10.0;
    plan.points = {point};
    configure->planEditor()->setPlan(plan);
    QVERIFY2(configure->planEditor()->isValid(), qPrintable(configure->planEditor()->problem()));
    QCOMPARE(configure->commandedMotion()->flaggedCells(), 0);

    table::EmulatorLinkOptions options;
    options.speed = 20.0;
    options.table.limits.axes[1].maxFrequencyHz = 2.0;
    auto controller = table::connectEmulatedTable(options);
    QVERIFY(controller);
    w.tablePanel()->setController(std::move(*controller));
    QTRY_VERIFY_WITH_TIMEOUT(configure->commandedMotion()->limitsText().contains("connected controller"), 5000);
    const QString connected = configure->commandedMotion()->limitsText();
    QVERIFY2(connected.contains("table-emu") && connected.contains("Y: amplitude") && connected.contains("2 Hz"),
             qPrintable(connected));
    QCOMPARE(configure->commandedMotion()->flaggedCells(), 1);  // 5 Hz beyond Y's 2 Hz
    QVERIFY(!configure->planEditor()->isValid());
    QVERIFY2(configure->planEditor()->problem().contains("2 Hz"), qPrintable(configure->planEditor()->problem()));

    // The simulator swings its own turntable, whatever the panel holds.
    configure->setSourceKind(fog::ui::ConfigureView::SourceKind::kSimulator);
    QCOMPARE(configure->commandedMotion()->limitsText().contains("connected controller"), false);
    QVERIFY(configure->planEditor()->isValid());
    configure->setSourceKind(fog::ui::ConfigureView::SourceKind::kSerial);
    QVERIFY(!configure->planEditor()->isValid());

    w.tablePanel()->setController(nullptr);
    QVERIFY(configure->commandedMotion()->limitsText().contains("no controller connected"));
    QVERIFY(configure->planEditor()->isValid());
  }

  // fogbench-table-emu stopped (SIGSTOP) mid-session: the window keeps
  // running, and an emergency stop clicked meanwhile is written to the
  // emulator's socket within 50 ms (on the emergency line's own connection;
  // a stopped process cannot read it, the kernel holds it); once the
  // emulator runs again it takes it ("estop: engaged") and the panel,
  // reconnected, shows every axis in emergency stop.
  void aStoppedEmulatorNeitherFreezesTheWindowNorDelaysTheEmergencyStop() {
    QProcess emu;
    const QString address = startEmulator(emu);
    QVERIFY2(!address.isEmpty(), emu.readAllStandardError().constData());
    TablePanel panel;
    panel.show();
    panel.setAddressSource([&] { return address; });
    panel.connectButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 10000);
    QVERIFY(panel.goTo(Axis::kY, 30.0).isEmpty());  // 1.5 s at 20 deg/s: stopped mid-move
    QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(Axis::kY), QString("moving"), 5000);

    GuiTicks ticks;
    QCOMPARE(::kill(static_cast<pid_t>(emu.processId()), SIGSTOP), 0);
    LaterClick click(panel.emergencyStopButton(), 500);
    spin(3500);  // past the link's 2-s reply timeout and a reconnect attempt
    const auto clickedAt = click.at();
    const double gap = ticks.maxGapMs();
    const auto line = panel.lastEmergencyLine();
    const QString status = panel.statusText();
    const QString yState = panel.stateText(Axis::kY);
    ::kill(static_cast<pid_t>(emu.processId()), SIGCONT);
    qInfo("emulator stopped 3.5 s: GUI max gap %.1f ms; emergency stop written %.1f ms after the click",
          gap, line ? msBetween(clickedAt, line->sentAt) : -1.0);
    QVERIFY2(gap < 200.0, qPrintable(QString("the GUI thread stalled %1 ms").arg(gap)));
    QVERIFY(line.has_value());
    QVERIFY2(line->sent, line->why.c_str());
    QVERIFY2(msBetween(clickedAt, line->sentAt) < 50.0,
             qPrintable(QString("written %1 ms after the click").arg(msBetween(clickedAt, line->sentAt))));
    QVERIFY2(status.contains("reconnecting") || status.contains("no answer"), qPrintable(status));
    QVERIFY2(yState == "unreachable" || yState == "no answer", qPrintable(yState));

    // Running again: the emulator takes the emergency stop it was sent.
    QString out;
    QTRY_VERIFY_WITH_TIMEOUT((out += QString::fromUtf8(emu.readAllStandardOutput())).contains("estop: engaged"),
                             10000);
    for (int a = 0; a < fog::kAxisCount; ++a)
      QTRY_COMPARE_WITH_TIMEOUT(panel.stateText(static_cast<Axis>(a)), QString("emergency stop"), 15000);
    emu.terminate();
    QVERIFY(emu.waitForFinished(10000));
  }

  // A controller that stops answering mid-session (a fake that keeps
  // reading, and records when each line arrives): no freeze, and the
  // emergency stop clicked meanwhile arrives within 50 ms on a connection of
  // its own; the panel says the controller has not confirmed it.
  void aControllerThatHangsMidSessionNeitherFreezesTheWindowNorDelaysTheEmergencyStop() {
    fogtest::FakeTableController fake;
    QVERIFY(fake.listening());
    TablePanel panel;
    connectToFake(panel, fake);
    if (QTest::currentTestFailed()) return;

    GuiTicks ticks;
    fake.hang();
    LaterClick click(panel.emergencyStopButton(), 500);
    spin(3500);
    const auto clickedAt = click.at();
    const double gap = ticks.maxGapMs();
    const auto arrived = fake.firstLine("SYST:ESTOP", clickedAt);
    const double latency = arrived.text.empty() ? -1.0 : msBetween(clickedAt, arrived.at);
    qInfo("controller hung 3.5 s: GUI max gap %.1f ms; emergency stop arrived %.1f ms after the click", gap, latency);
    QVERIFY2(gap < 200.0, qPrintable(QString("the GUI thread stalled %1 ms").arg(gap)));
    QVERIFY2(!arrived.text.empty(), "the emergency stop never arrived");
    QVERIFY2(arrived.connection == 2, "it came on the panel's hung connection, not on the line's own");
    QVERIFY(panel.lastEmergencyLine().has_value() && panel.lastEmergencyLine()->armedLink);
    QVERIFY2(latency < 50.0, qPrintable(QString("arrived %1 ms after the click").arg(latency)));
    QTRY_VERIFY_WITH_TIMEOUT(panel.message().contains("has not confirmed"), 5000);
    QVERIFY2(panel.statusText().contains("reconnecting"), qPrintable(panel.statusText()));
    QVERIFY(!panel.jogButton(Axis::kX, 1)->isEnabled());
  }

  // The ordinary Stop, clicked while the controller hangs mid-move (a
  // fake that stops answering while the panel's link waits for a reply):
  // no freeze, and "STOP" arrives within 50 ms on the line's connection of
  // its own, not queued behind the hung call; the panel says it was sent.
  void aStopClickedWhileTheControllerHangsGoesOutAtOnce() {
    fogtest::FakeTableController fake;
    QVERIFY(fake.listening());
    TablePanel panel;
    connectToFake(panel, fake);
    if (QTest::currentTestFailed()) return;

    GuiTicks ticks;
    fake.hang();
    QVERIFY(panel.stopButton()->isEnabled());
    LaterClick click(panel.stopButton(), 300);  // the link's poll is hung by then (every 250 ms)
    spin(1500);
    const auto clickedAt = click.at();
    const double gap = ticks.maxGapMs();
    const auto arrived = fake.firstLine("STOP", clickedAt);
    const double latency = arrived.text.empty() ? -1.0 : msBetween(clickedAt, arrived.at);
    qInfo("controller hung: GUI max gap %.1f ms; Stop arrived %.1f ms after the click", gap, latency);
    QVERIFY2(gap < 200.0, qPrintable(QString("the GUI thread stalled %1 ms").arg(gap)));
    QVERIFY2(!arrived.text.empty(), "the stop never arrived");
    QVERIFY2(arrived.connection == 2, "it came on the panel's hung connection, not on the line's own");
    QVERIFY2(latency < 50.0, qPrintable(QString("arrived %1 ms after the click").arg(latency)));
    QVERIFY(panel.lastStopLine().has_value() && panel.lastStopLine()->sent && panel.lastStopLine()->armedLink);
    QVERIFY2(panel.message().contains("on a connection of its own"), qPrintable(panel.message()));
    QVERIFY(!panel.lastEmergencyLine().has_value());  // a stop, not an emergency stop
    QVERIFY(fake.firstLine("SYST:ESTOP").text.empty());
  }

  // A controller that accepts the connection and never answers: Connect
  // returns at once, the panel says it is connecting and for how long, the
  // emergency stop is offered and arrives within 50 ms; after the reply
  // timeout the panel says it cannot connect.
  void aControllerThatNeverAnswersNeitherFreezesTheWindowNorDelaysTheEmergencyStop() {
    fogtest::FakeTableController fake(/*hangFromStart=*/true);
    QVERIFY(fake.listening());
    TablePanel panel;
    panel.show();
    panel.setAddressSource([&] { return QString::fromStdString(fake.address()); });
    GuiTicks ticks;
    QElapsedTimer clickTook;
    clickTook.start();
    panel.connectButton()->click();
    QVERIFY2(clickTook.elapsed() < 50, qPrintable(QString("Connect took %1 ms").arg(clickTook.elapsed())));
    QCOMPARE(panel.link(), TablePanel::Link::kConnecting);
    QVERIFY(panel.emergencyStopButton()->isEnabled());
    QVERIFY(!panel.goButton()->isEnabled());
    LaterClick click(panel.emergencyStopButton(), 500);
    spin(1600);  // (not QTRY: its qWait sleeps 10 ms at a time, which would delay the click)
    QVERIFY2(panel.statusText().contains("no answer for 1 s"), qPrintable(panel.statusText()));
    QTRY_VERIFY_WITH_TIMEOUT(panel.message().contains("Cannot connect"), 5000);
    const auto clickedAt = click.at();
    const double gap = ticks.maxGapMs();
    const auto arrived = fake.firstLine("SYST:ESTOP", clickedAt);
    const double latency = arrived.text.empty() ? -1.0 : msBetween(clickedAt, arrived.at);
    const auto line = panel.lastEmergencyLine();
    qInfo("controller silent from the start: GUI max gap %.1f ms; emergency stop arrived %.1f ms after the click "
          "(connect and write on the line's thread: %.1f ms)", gap, latency, line ? line->sentAfterMs : -1.0);
    QVERIFY2(gap < 200.0, qPrintable(QString("the GUI thread stalled %1 ms").arg(gap)));
    QVERIFY2(!arrived.text.empty(), "the emergency stop never arrived");
    QVERIFY2(latency < 50.0, qPrintable(QString("arrived %1 ms after the click").arg(latency)));
    QVERIFY2(panel.message().contains("no reply"), qPrintable(panel.message()));
    QCOMPARE(panel.link(), TablePanel::Link::kNone);
    QVERIFY(!panel.emergencyStopButton()->isEnabled());
  }

 private:
  // Shows the panel, connects it to the fake controller and waits until the
  // panel's link and the emergency line's own connection (armed once the
  // controller answered) are both up.
  static void connectToFake(TablePanel& panel, fogtest::FakeTableController& fake) {
    panel.show();
    panel.setAddressSource([&fake] { return QString::fromStdString(fake.address()); });
    panel.connectButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(ready(panel), 10000);
    QTRY_COMPARE_WITH_TIMEOUT(fake.connections(), 2, 5000);
  }

  // fogbench-table-emu on a free TCP port, no board; it stays up while the
  // panel reconnects (--linger-s). Its address, or empty.
  static QString startEmulator(QProcess& emu) {
    emu.setProgram(FOG_TABLE_EMU);
    emu.setArguments({"--board", "none", "--linger-s", "60", "--exit-after-s", "120"});
    emu.start();
    if (!emu.waitForStarted(10000)) return {};
    QElapsedTimer waited;
    waited.start();
    while (waited.elapsed() < 10000) {
      emu.waitForReadyRead(100);
      while (emu.canReadLine()) {
        const QString line = QString::fromUtf8(emu.readLine()).trimmed();
        if (line.startsWith("table: ")) return line.mid(7);
      }
    }
    return {};
  }
};

QTEST_MAIN(TablePanelTest)
#include "table_panel_test.moc"

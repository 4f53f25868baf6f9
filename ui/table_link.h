#pragma once
// The table panel's connection to the turntable controller, on a thread of
// its own (issue 41; docs/table-control.md, "The table panel off the GUI
// thread"). The bench's rule: a safety path never waits — so the GUI thread
// never waits for the controller. Every call below returns at once; the
// work (connect, the poll every kPollMs, moves, stops) is done in order on
// the link's thread, and what comes of it reaches the GUI thread as queued
// signals. A controller that accepts the connection and never answers, or
// hangs in the middle of a session, holds up only the link's thread.
//
// Order: calls are served in the order made, except that
//  - emergencyStop() goes before anything still queued (the link's thread
//    sends it at the start of whatever it does next), and
//  - stopAll() and emergencyStop() drop the moves queued before them (a
//    stop means "not that move either").
// Neither can overtake a call the controller is hanging in: the emergency
// stop's path that does not wait is core/table/emergency_line.h, which the
// panel fires beside this one.
//
// A remote link that fails (no reply within the reply timeout, the
// connection lost, a reply out of step) is dropped and reopened
// kReconnectMs after it failed, and again kReconnectMs after each attempt
// that fails, until retire(); each attempt is announced by opening(again =
// true). Reconnecting is the only way back in step with a controller that
// resumes after hanging. A controller handed over by adopt() (tests, an
// in-process emulator) is kept and polled however it fails.
//
// Lifetime: retire() lets the controller go (its heartbeat timeout set to 0
// when the link still works), ends the thread and deletes this object once
// the thread has ended, never waiting on the GUI thread; no signal arrives
// after retire(). Destroying the object instead cancels the call under way
// (a read gives up within kSliceMs; a TCP connect under way within the
// reply timeout) and waits for the thread.

#include <QObject>
#include <QString>
#include <QThread>
#include <atomic>
#include <memory>
#include <string>

#include "core/table/remote_table.h"
#include "core/table/table_controller.h"

namespace fog::ui {

struct TableLinkOptions {
  table::RemoteOptions remote;  // reply timeout (also the connect timeout), heartbeat
  int baud = 115200;            // a controller on a serial line
};

// A command the panel queued on the link.
struct TableCommand {
  enum Kind { kMove, kStop, kEmergencyStop } kind = kMove;
  Axis axis = Axis::kX;
  double positionDeg = 0.0;  // kMove
};

// How it ended.
struct TableCommandResult {
  enum Outcome {
    kDone,        // sent and confirmed by the controller
    kRefused,     // the controller refused it: scpiCode, reply
    kLinkFailed,  // not sent or not confirmed: the link is down (message says why)
    kDropped,     // a stop came first: never sent
  } outcome = kDone;
  std::string message;  // the core's message ("the table controller refused 'AXIS:X:POS 0': -221,\"…\"")
  int scpiCode = 0;     // kRefused: the controller's error number (-221, 202, …)
  std::string reply;    // kRefused: its reply as given ("-221,\"Settings conflict; …\"")
};

class TableLinkWorker;

class TableLink : public QObject {
  Q_OBJECT

 public:
  static constexpr int kPollMs = 250;
  static constexpr int kReconnectMs = 1000;
  static constexpr int kSliceMs = 50;

  explicit TableLink(QObject* parent = nullptr);
  ~TableLink() override;

  // Opens a remote controller (tcp:HOST:PORT or a serial device): opening(),
  // then opened() — and a state read at once and every kPollMs — or lost().
  // An address that cannot be opened at the first attempt is not retried.
  void open(const QString& address, const TableLinkOptions& options = {});
  // A controller made elsewhere: opened() at once, then polled.
  void adopt(std::unique_ptr<table::TableController> controller);
  void pollNow();
  void moveTo(Axis axis, double positionDeg);
  void stopAll();
  void emergencyStop();
  void retire();

 signals:
  void opening(const QString& address, bool again);
  void opened(const QString& description, const fog::table::TableLimits& limits);
  // The link failed or could not be opened; `reconnecting`: the link's
  // thread keeps trying.
  void lost(const QString& why, bool reconnecting);
  void stateRead(const fog::table::TableState& state);
  // An adopted controller's state read failed (it is kept and polled again).
  void readFailed(const QString& why);
  void commandDone(const fog::ui::TableCommand& command, const fog::ui::TableCommandResult& result);

 private:
  // Shared with the link's thread: what the GUI thread sets without waiting.
  struct Flags {
    std::atomic<bool> cancel{false};     // give up the call under way (destruction)
    std::atomic<bool> emergency{false};  // an emergency stop is to go before anything else
    std::atomic<unsigned> stopEpoch{0};  // moves queued before the latest stop are dropped
  };
  std::shared_ptr<Flags> flags_ = std::make_shared<Flags>();
  QThread thread_;
  TableLinkWorker* worker_ = nullptr;  // lives on thread_; deleted once it has ended
  bool retired_ = false;

  friend class TableLinkWorker;
};

}  // namespace fog::ui

Q_DECLARE_METATYPE(fog::table::TableState)
Q_DECLARE_METATYPE(fog::table::TableLimits)
Q_DECLARE_METATYPE(fog::ui::TableCommand)
Q_DECLARE_METATYPE(fog::ui::TableCommandResult)

#pragma once
// The desktop bench drives the turntable (docs/table-control.md): the same
// parts as fogbench-cli run --table (the plan runner on a controller — the
// remote protocol or an operator told what to set —, the stream-side swing
// check that cuts the test points from the table angle, the host-to-board
// commands, the session's table log), put together for AcquisitionRunner's
// worker and read by the GUI thread for the Live view's table status.
//
//   worker thread:  connect()        controller, limits, the plan checked: nothing moves yet
//                   configure(opts)  the acquisition ends when the runner does; points cut from the stream
//                   start(src, stop) the runner's thread drives the table; `stop` (the Stop button,
//                                    closing the window) ends it and brings the table to rest
//   any thread:     requestEmergencyStop()  the runner sends the emergency stop at its next step
//                   observe(batch)   every decoded batch (the swing check reads the table angle)
//                   finish(why)      after the acquisition: the runner ends (the recording is
//                                    over), the table is brought to rest, the thread joined
//   GUI thread:     snapshot()       mode, axes, faults, interlock, point, phase, operator instruction
//
// Thread-safety: snapshot() and the log are mutex-guarded; the controller is
// used by the runner's thread only (its state, as the runner polls it, is
// copied into the snapshot). Destroying a TableDrive whose runner still runs
// ends it as finish() does.

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/acquisition/acquisition.h"
#include "core/acquisition/board_commander.h"
#include "core/common/status.h"
#include "core/common/test_plan.h"
#include "core/protocol/frame.h"
#include "core/session/session_file.h"
#include "core/table/plan_runner.h"
#include "core/table/stream_recorder.h"
#include "core/table/table_controller.h"

namespace fog::ui {

struct TableDriveSettings {
  bool manual = false;       // the operator sets the controller by hand
  std::string address;       // remote: tcp:HOST:PORT or a serial device
  int baud = 115200;         // remote on a serial line
  double heartbeatS = 2.0;   // the controller's heartbeat timeout
  double replyTimeoutS = 2.0;
  double operatorTimeoutS = 600.0;  // manual: time to set a point
  double speed = 1.0;        // plan seconds per wall second (> 1 only for emulators)
  bool boardCommands = true; // tell the board where the plan stands
  std::optional<double> pulseEquivalentDeg;  // sent to the board when given
};

// What the Live view shows of the table.
struct TableSnapshot {
  bool connected = false;
  std::string description;    // "remote tcp:127.0.0.1:5025 (fogbench,table-emu,0,0.1.0)"
  bool stateRead = false;     // the controller answered a state query
  table::TableState state;    // as last polled (state.known false: an operator-set table)
  int point = -1;             // the plan's point the runner is at, -1 before the first
  protocol::TestPhase phase = protocol::TestPhase::kIdle;  // idle, settling (swing checked), recording, done
  std::string step;           // the runner's last step line
  std::string instruction;    // manual: the last instruction to the operator
  bool finished = false;      // the runner has returned
  bool atRest = false;        // ... and saw (or made) the table at rest
  std::string failure;        // why the runner stopped early, empty when it did not
};

class TableDrive {
 public:
  TableDrive(TableDriveSettings settings, TestPlan plan);
  ~TableDrive();
  TableDrive(const TableDrive&) = delete;
  TableDrive& operator=(const TableDrive&) = delete;

  const TableDriveSettings& settings() const { return settings_; }
  // "remote tcp:…" or "manual": known before connect().
  std::string driverName() const;

  // Worker thread. Connects, reads the limits and checks the whole plan
  // against them: an error (unreachable, not a table controller, a point
  // beyond the limits: "…; the plan was refused before any motion") means
  // nothing moved and nothing must be recorded.
  Status connect();
  std::string description() const;  // the controller's, after connect()
  void configure(acquisition::AcquisitionOptions& options);
  void start(acquisition::ByteSource* source, const std::atomic<bool>* stop);
  void observe(const acquisition::AcquisitionBatch& batch);
  void finish(const std::string& why);
  // Log lines not yet handed to the session (configure() drains them while
  // the acquisition runs; the worker appends the rest after finish()).
  std::vector<session::TableLogEntry> drainLog();

  // Any thread.
  TableSnapshot snapshot() const;
  // The tool bar's emergency stop while this run holds the controller: the
  // runner's thread sends it at its next step (PlanRunner::setEmergencyFlag;
  // within a poll interval, or after the controller call under way) and the
  // run ends. False when no runner is driving the table (before start(), or
  // after the plan ended).
  bool requestEmergencyStop();

 private:
  class Observed;   // the controller, its state copied into the snapshot
  class Marking;    // the recorder, with phases for the snapshot and the board
  void log(const std::string& kind, const std::string& text);
  void setSnapshot(const std::function<void(TableSnapshot&)>& change);

  TableDriveSettings settings_;
  TestPlan plan_;
  std::unique_ptr<table::TableController> controller_;
  std::unique_ptr<Observed> observed_;
  table::StreamPointRecorder recorder_;
  std::unique_ptr<acquisition::BoardCommander> board_;
  std::unique_ptr<Marking> marking_;
  std::unique_ptr<table::RunnerClock> clock_;
  std::thread runner_;
  std::atomic<bool> runnerStarted_{false};
  std::atomic<bool> runnerDone_{false};
  std::atomic<bool> emergency_{false};
  table::RunnerResult result_;  // written by the runner's thread before runnerDone_

  mutable std::mutex mutex_;  // guards snapshot_ and log_
  TableSnapshot snapshot_;
  std::vector<session::TableLogEntry> log_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace fog::ui

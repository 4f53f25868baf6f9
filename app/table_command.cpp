// fogbench-cli run --table remote:ADDR|manual --source serial --port DEV:
// the bench drives the turntable through the plan (docs/table-control.md)
// while it records the sampling board, and cuts the board's stream into the
// plan's test points from the table angle it carries.
//
// Threads: the acquisition (the board's serial port, the session, decoding)
// runs in the main thread, as for `run --source serial`; the plan runner
// drives the table from a second thread. They meet in a StreamPointRecorder
// (thread-safe) and in the table log (a mutex). Whatever ends the run — the
// plan done, the runner failing, the board's link lost, Ctrl+C — the runner
// brings the table to rest before the command returns.

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>

#include "core/acquisition/acquisition.h"
#include "core/analysis/report_writer.h"
#include "core/acquisition/board_commander.h"
#include "app/catalog_command.h"
#include "app/cli_common.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "app/serial_command.h"
#include "core/session/session_file.h"
#include "app/session_commands.h"
#include "app/sim_options.h"
#include "core/table/manual_table.h"
#include "core/table/plan_runner.h"
#include "core/table/remote_table.h"
#include "core/table/stream_recorder.h"

namespace fog::app {

namespace {

std::atomic<bool> gStop{false};
extern "C" void onTableInterrupt(int) { gStop = true; }

// The table log: lines for the session (drained by the acquisition while it
// runs; the rest appended after it) and, for people, the steps on stderr.
class TableLog {
 public:
  void add(const std::string& kind, const std::string& text) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::lock_guard lock(mutex_);
    pending_.push_back({t, kind, text});
    if (kind == "step" || kind == "event" || kind == "status" || kind == "operator" || kind == "board")
      std::cerr << "fogbench-cli: table " << kind << ": " << forTerminal(text) << "\n";
  }
  std::vector<session::TableLogEntry> drain() {
    std::lock_guard lock(mutex_);
    std::vector<session::TableLogEntry> out;
    out.swap(pending_);
    return out;
  }

 private:
  std::mutex mutex_;
  std::vector<session::TableLogEntry> pending_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The stream recorder, with the board told where the plan stands (test-point
// markers, docs/protocol.md "Host to board"): settling while the swing is
// checked, recording once it is verified, idle when the point is over. The
// bench still cuts the points from the table angle; the markers make the raw
// stream describe itself for a board that echoes them.
class MarkingRecorder : public table::PointRecorder {
 public:
  MarkingRecorder(table::StreamPointRecorder& inner, acquisition::BoardCommander& board) : inner_(inner), board_(board) {}
  Status begin(int index, const TestPoint& point) override {
    index_ = index;
    point_ = point;
    windowsAtBegin_ = inner_.windows().size();
    marked_ = false;
    board_.markPoint(index, point, protocol::TestPhase::kSettling);
    return inner_.begin(index, point);
  }
  table::RecorderProgress poll() override {
    auto progress = inner_.poll();
    if (!marked_ && inner_.windows().size() > windowsAtBegin_) {
      marked_ = true;
      board_.markPoint(index_, point_, protocol::TestPhase::kRecording);
    }
    return progress;
  }
  void end(int index) override {
    inner_.end(index);
    board_.markPoint(index, point_, protocol::TestPhase::kIdle);
  }
  Status health() override { return inner_.health(); }
  bool streamShowsRest(Axis axis) override { return inner_.streamShowsRest(axis); }

 private:
  table::StreamPointRecorder& inner_;
  acquisition::BoardCommander& board_;
  int index_ = -1;
  TestPoint point_;
  std::size_t windowsAtBegin_ = 0;
  bool marked_ = false;
};

}  // namespace

int runTableCommand(CliArguments& args, const std::string& tableSpec) {
  const bool json = args.flag("json");
  const bool manual = tableSpec == "manual";
  if (!manual && tableSpec.rfind("remote:", 0) != 0)
    return fail(invalidArgument("--table must be sim, manual or remote:ADDRESS (tcp:HOST:PORT or a serial device)"), 2);
  if (args.text("source").value_or("") != "serial")
    return fail(invalidArgument("--table " + tableSpec +
                                " records a real sampling board: give --source serial --port DEV (the board's port)"),
                2);
  auto settings = readSerialSettings(args);
  if (!settings) return fail(settings.status(), 2);
  auto warnS = args.number("stall-warning-s", 2.0);
  auto limitS = args.number("stall-timeout-s", 10.0);
  auto speed = args.number("speed", 1.0);
  auto heartbeatS = args.number("table-heartbeat-s", 2.0);
  auto replyS = args.number("table-reply-timeout-s", 2.0);
  auto tableBaud = args.number("table-baud", 115200.0);
  auto operatorS = args.number("operator-timeout-s", 600.0);
  for (auto* r : {&warnS, &limitS, &speed, &heartbeatS, &replyS, &tableBaud, &operatorS})
    if (!*r) return fail(r->status(), 2);
  if (!(*warnS > 0.0) || !(*limitS > 0.0)) return fail(invalidArgument("--stall-warning-s and --stall-timeout-s must be > 0"), 2);
  if (!(*speed > 0.0) || *speed > 1000.0)
    return fail(invalidArgument("--speed must be in (0, 1000] (plan seconds per wall second; > 1 only for emulators)"), 2);
  if (!(*heartbeatS >= 0.2 && *heartbeatS <= 60.0)) return fail(invalidArgument("--table-heartbeat-s must be 0.2 .. 60"), 2);
  if (!(*replyS > 0.0 && *replyS <= 60.0)) return fail(invalidArgument("--table-reply-timeout-s must be in (0, 60]"), 2);
  const bool pulseGiven = args.has("pulse-equivalent-deg");
  auto constants = readConstants(args);
  if (!constants) return fail(constants.status(), 2);
  auto plan = readPlan(args);
  if (!plan) return fail(plan.status(), 2);
  auto sessionOut = readSessionOutput(args);
  if (!sessionOut) return fail(sessionOut.status(), 2);
  auto catalogDb = readCatalogDb(args);
  if (!catalogDb) return fail(catalogDb.status(), 2);
  const bool boardCommands = !args.flag("no-board-commands");
  (void)args.text("table");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("unexpected argument '" + args.positionals()[0] + "'"), 2);

  // The table first: nothing is recorded for a table that cannot run the plan.
  TableLog log;
  std::unique_ptr<table::TableController> controller;
  if (manual) {
    controller = std::make_unique<table::ManualTable>([&log](const std::string& text) { log.add("operator", text); });
  } else {
    const std::string address = tableSpec.substr(7);
    auto link = table::openTransport(address, static_cast<int>(*tableBaud));
    if (!link) return fail(link.status(), 2);
    table::RemoteOptions ro;
    ro.replyTimeout = std::chrono::milliseconds(std::llround(*replyS * 1e3));
    ro.heartbeatTimeoutS = *heartbeatS;
    auto remote = table::RemoteTable::connect(std::move(*link), ro,
                                              [&log](const std::string& k, const std::string& t) { log.add(k, t); });
    if (!remote) return fail(remote.status(), 2);
    controller = std::move(*remote);
  }
  {
    auto limits = controller->limits();
    if (!limits) return fail(limits.status(), 2);
    if (auto s = table::checkPlanAgainstLimits(*plan, *limits); !s.isOk()) {
      log.add("step", "plan refused: " + s.message());
      return fail(s, 2);
    }
  }

  auto source = serial::SerialSource::open(*settings);
  if (!source) return fail(source.status(), 2);

  acquisition::AcquisitionOptions options;
  options.constants = *constants;
  options.reportContext.source = (*source)->description() + "; table " + controller->description();
  options.stallWarning = std::chrono::milliseconds(std::llround(*warnS * 1e3));
  options.stallLimit = std::chrono::milliseconds(std::llround(*limitS * 1e3));
  if (*sessionOut) {
    options.sessionPath = (*sessionOut)->path;
    options.info = (*sessionOut)->info;
    options.info.source = options.reportContext.source;
    options.auditCommand = auditCommandLine();
    options.info.softwareVersion = FOG_VERSION;
    options.info.createdUtc = session::utcNow();
    options.info.plan = *plan;
    storeConstants(*constants, options.info.bench);
  }

  table::StreamPointRecorder recorder;
  // The host-to-board direction (docs/protocol.md): optional, never waited for.
  acquisition::BoardCommander board(boardCommands ? source->get() : nullptr,
                       [&log](const std::string& what) { log.add("board", what); });
  MarkingRecorder markingRecorder(recorder, board);
  std::atomic<bool> runnerDone{false};
  table::RunnerResult runnerResult;
  table::RunnerOptions runnerOptions;
  runnerOptions.pollIntervalS = 0.1 * *speed;
  runnerOptions.heartbeatIntervalS = std::min(0.5, *heartbeatS / 4.0) * *speed;
  if (manual) runnerOptions.recordMarginS = *operatorS;
  auto clock = table::steadyClock(*speed);
  recorder.setHostClock(clock.get());
  options.shouldEnd = [&]() -> std::optional<std::string> {
    if (!runnerDone) return std::nullopt;
    if (runnerResult.status.isOk()) return std::string();
    return "table: " + runnerResult.status.message();
  };
  options.drainTableLog = [&] { return log.drain(); };
  options.segment = [&](const Recording& whole) { return table::segmentByWindows(whole, recorder.windows()); };
  auto observer = [&](acquisition::AcquisitionBatch&& b) { recorder.addFrames(b.frames); };

  std::cerr << "fogbench-cli: recording " << (*source)->description() << " while the table ("
            << controller->description() << ") runs the plan: " << plan->points.size()
            << " test points (Ctrl+C stops the table and keeps what arrived)\n";
  if (pulseGiven) board.setPulseEquivalent(constants->pulseEquivalentDeg);
  board.startStreaming();
  gStop = false;
  std::signal(SIGINT, onTableInterrupt);
  std::signal(SIGTERM, onTableInterrupt);
  std::thread runner([&] {
    table::PlanRunner r(*controller, *clock, markingRecorder, runnerOptions,
                        [&log](const std::string& line) { log.add("step", line); });
    runnerResult = r.run(*plan, &gStop);
    if (runnerResult.status.isOk()) board.markDone();
    runnerDone = true;
  });
  auto run = acquisition::acquire(**source, options, &gStop, observer);
  // The board's recording has ended: a runner still going stops the table.
  if (!runnerDone)
    recorder.failLink(run ? (run->incompleteReason.empty() ? std::string("the recording ended") : run->incompleteReason)
                          : run.status().message());
  runner.join();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  board.stopStreaming();
  (*source)->flushToDevice(std::chrono::milliseconds(200));
  if (!run) return fail(run.status(), 2);
  if (!options.sessionPath.empty())
    if (auto s = session::appendTableLog(options.sessionPath, log.drain()); !s.isOk())
      std::cerr << "fogbench-cli: " << s.message() << "\n";
  if (!runnerResult.tableAtRest)
    std::cerr << "fogbench-cli: WARNING: the table was not seen at rest at the end; check it\n";
  if (!run->complete) printIncompleteRun(*run);
  if (!run->recordingStatus.isOk()) return fail(run->recordingStatus, 1);
  if (!run->report) return fail(run->report.status(), exitCodeFor(run->report.status()));
  const auto context = acquisition::reportContextOf(*run, options);
  std::cout << reportOutput(*run->report, context, json);
  // The stored result (and the table log) reach the catalog (docs/catalog.md).
  if (!run->sessionPath.empty()) updateCatalogAfterAnalysis(*catalogDb, run->sessionPath, json);
  return 0;
}

}  // namespace fog::app

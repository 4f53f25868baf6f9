#include "app/serial_command.h"

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "core/acquisition/acquisition.h"
#include "core/analysis/report_writer.h"
#include "core/acquisition/board_commander.h"
#include "app/catalog_command.h"
#include "app/cli_common.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/serial/serial_source.h"
#include "core/session/session_file.h"
#include "app/session_commands.h"
#include "app/sim_options.h"

namespace fog::app {

namespace {

std::atomic<bool> gStop{false};
extern "C" void onInterrupt(int) { gStop = true; }

}  // namespace

Result<serial::SerialSettings> readSerialSettings(CliArguments& args) {
  serial::SerialSettings s;
  s.port = args.text("port").value_or("");
  auto baud = args.number("baud", s.baudRate);
  auto dataBits = args.number("data-bits", s.dataBits);
  auto stopBits = args.number("stop-bits", s.stopBits);
  for (const auto* r : {&baud, &dataBits, &stopBits})
    if (!*r) return r->status();
  if (*baud != std::floor(*baud) || *dataBits != std::floor(*dataBits) || *stopBits != std::floor(*stopBits))
    return invalidArgument("--baud, --data-bits and --stop-bits must be whole numbers");
  s.baudRate = static_cast<int>(*baud);
  s.dataBits = static_cast<int>(*dataBits);
  s.stopBits = static_cast<int>(*stopBits);
  if (auto p = args.text("parity")) {
    FOG_ASSIGN_OR_RETURN(auto parity, serial::parseParity(*p));
    s.parity = parity;
  }
  FOG_RETURN_IF_ERROR(s.validate());
  return s;
}

namespace {

std::string fixed1(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

}  // namespace

int runSerialCommand(CliArguments& args) {
  const bool json = args.flag("json");
  auto settings = readSerialSettings(args);
  if (!settings) return fail(settings.status(), 2);
  auto warnS = args.number("stall-warning-s", 2.0);
  auto limitS = args.number("stall-timeout-s", 10.0);
  if (!warnS) return fail(warnS.status(), 2);
  if (!limitS) return fail(limitS.status(), 2);
  if (!(*warnS > 0.0) || !(*limitS > 0.0))
    return fail(invalidArgument("--stall-warning-s and --stall-timeout-s must be > 0"), 2);
  const bool pulseGiven = args.has("pulse-equivalent-deg");
  auto constants = readConstants(args);
  if (!constants) return fail(constants.status(), 2);
  // The board runs its own plan; the operator's plan (if any) is what the
  // session records as intended.
  const bool withPlan = planGiven(args);
  TestPlan plan;
  if (withPlan) {
    auto given = readPlan(args);
    if (!given) return fail(given.status(), 2);
    plan = *given;
  }
  auto sessionOut = readSessionOutput(args);
  if (!sessionOut) return fail(sessionOut.status(), 2);
  auto catalogDb = readCatalogDb(args);
  if (!catalogDb) return fail(catalogDb.status(), 2);
  const bool boardCommands = args.flag("no-board-commands") == false;
  (void)args.text("source");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("unexpected argument '" + args.positionals()[0] + "'"), 2);

  auto source = serial::SerialSource::open(*settings);
  if (!source) return fail(source.status(), 2);
  const std::string port = settings->port;

  acquisition::AcquisitionOptions options;
  options.constants = *constants;
  options.reportContext.source = (*source)->description();
  options.stallWarning = std::chrono::milliseconds(std::llround(*warnS * 1e3));
  options.stallLimit = std::chrono::milliseconds(std::llround(*limitS * 1e3));
  options.endWhenBoardDone = true;
  if (*sessionOut) {
    options.sessionPath = (*sessionOut)->path;
    options.info = (*sessionOut)->info;
    options.info.source = (*source)->description();
    options.auditCommand = auditCommandLine();
    options.info.softwareVersion = FOG_VERSION;
    options.info.createdUtc = session::utcNow();
    options.info.plan = plan;
    storeConstants(*constants, options.info.bench);
  }

  std::cerr << "fogbench-cli: recording from " << (*source)->description()
            << " until the board's plan is done (Ctrl+C stops and keeps what arrived)\n";
  // What the operator is told while it runs: a quiet line, and a line full
  // of bytes that never make a frame (usually the wrong baud rate).
  double nextSilenceReportS = *warnS;
  bool toldNoFrames = false;
  constexpr std::uint64_t kBytesWithoutFrame = 4096;
  auto observer = [&](acquisition::AcquisitionBatch&& b) {
    if (b.silentForS >= nextSilenceReportS) {
      std::cerr << "fogbench-cli: timeout: no data from " << port << " for " << fixed1(b.silentForS)
                << " s (the run ends after " << fixed1(*limitS) << " s without data)\n";
      nextSilenceReportS = std::floor(b.silentForS) + 1.0;
    } else if (b.silentForS == 0.0) {
      nextSilenceReportS = *warnS;
    }
    const auto& h = b.health;
    if (!toldNoFrames && b.bytesReceived >= kBytesWithoutFrame && h.tableFrames + h.imuFrames + h.statusFrames == 0) {
      toldNoFrames = true;
      std::cerr << "fogbench-cli: " << b.bytesReceived << " bytes from " << port
                << " but no valid sampling-board frames; is the baud rate (" << settings->baudRate
                << ") or the parity right?\n";
    }
  };
  // The host-to-board direction (docs/protocol.md): the pulse equivalent the
  // operator gave, and the stream started; it is stopped at the end. The
  // board runs its own plan, so no test-point markers. Never waited for.
  acquisition::BoardCommander board(boardCommands ? source->get() : nullptr, [](const std::string& what) {
    std::cerr << "fogbench-cli: board command: " << what << "\n";
  });
  if (pulseGiven) board.setPulseEquivalent(constants->pulseEquivalentDeg);
  board.startStreaming();
  gStop = false;
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  auto run = acquisition::acquire(**source, options, &gStop, observer);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  board.stopStreaming();
  (*source)->flushToDevice(std::chrono::milliseconds(200));
  if (!run) return fail(run.status(), 2);
  if (!run->complete) printIncompleteRun(*run);
  if (!run->recordingStatus.isOk()) return fail(run->recordingStatus, 1);
  if (!run->report) return fail(run->report.status(), exitCodeFor(run->report.status()));
  const auto context = acquisition::reportContextOf(*run, options);
  std::cout << reportOutput(*run->report, context, json);
  // The stored result reaches the catalog (docs/catalog.md).
  if (!run->sessionPath.empty()) updateCatalogAfterAnalysis(*catalogDb, run->sessionPath, json);
  return 0;
}

int portsCommand(CliArguments& args) {
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("ports takes no arguments"), 2);
  const auto ports = serial::availablePorts();
  if (ports.empty()) {
    std::cout << "no serial ports found (a USB adapter may need its driver, or permission: group dialout)\n";
    return 0;
  }
  std::cout << ports.size() << " serial port" << (ports.size() == 1 ? "" : "s") << ":\n";
  for (const auto& p : ports) {
    std::cout << "  " << p.systemLocation;
    if (!p.description.empty()) std::cout << "  " << p.description;
    if (!p.manufacturer.empty()) std::cout << "  " << p.manufacturer;
    if (!p.serialNumber.empty()) std::cout << "  serial " << p.serialNumber;
    std::cout << "\n";
  }
  return 0;
}

}  // namespace fog::app

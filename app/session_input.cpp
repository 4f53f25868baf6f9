#include "app/session_input.h"

#include <iostream>

#include "app/cli_common.h"
#include "core/common/text.h"

namespace fog::app {

Result<session::OpenedSession> openInput(const std::string& path, const session::OpenOptions& options) {
  auto opened = session::openSessionOrStream(path, options);
  if (opened && (!opened->damage.empty() || !opened->rawDamage.empty()))
    std::cerr << "fogbench-cli: note: " << forTerminal(opened->damageNote()) << "\n" << std::flush;
  return opened;
}

std::optional<session::OpenedSession> openFileArgument(CliArguments& args, const std::string& needs, int& exitCode,
                                                       const session::OpenOptions& options) {
  Status bad;
  if (args.positionals().size() != 1) bad = invalidArgument(needs);
  // --pulse-equivalent-deg decodes a stream that states none (and is read
  // again with the other constants).
  session::OpenOptions withPulse = options;
  if (bad.isOk() && args.has("pulse-equivalent-deg")) {
    auto pulse = args.number("pulse-equivalent-deg", 0.0);
    if (!pulse) bad = pulse.status();
    else withPulse.pulseEquivalentDeg = *pulse;
  }
  auto opened = bad.isOk() ? openInput(args.positionals()[0], withPulse) : Result<session::OpenedSession>(bad);
  if (opened) return std::move(*opened);
  (void)args.checkAllUsed();
  exitCode = fail(opened.status(), exitCodeFor(opened.status()));
  return std::nullopt;
}

Result<CommandSettings> shownResultSettings(CliArguments& args, const session::OpenedSession& opened,
                                            bool withLimit) {
  CommandSettings out;
  const session::StoredResultRecord* shown = session::newestUsable(opened.results);
  bool given = false;
  for (const char* option : {"read-delay-ms", "read-delay-std-ms", "board-delay-ms", "board-delay-std-ms",
                             "pulse-equivalent-deg", "gyro-sign", "imu-frame", "gain-tolerance"})
    given = given || args.has(option);
  BenchConstants base = opened.info.bench;
  if (shown && !given) {
    base = shown->constants;
    base.imuFrame = opened.info.bench.imuFrame;  // the frame is the session's statement (checked by diagnose)
  }
  FOG_ASSIGN_OR_RETURN(out.constants, readConstants(args, base));
  out.imuDelayLimitMs = shown ? shown->imuDelayLimitMs : analysis::kDefaultImuDelayLimitMs;
  out.coverageK = shown ? shown->coverageK : analysis::kDefaultCoverageFactor;
  if (withLimit && args.has("limit-ms")) {
    FOG_ASSIGN_OR_RETURN(out.imuDelayLimitMs, readDelayLimit(args));
  }
  if (withLimit && args.has("coverage-k")) {
    FOG_ASSIGN_OR_RETURN(out.coverageK, readCoverageK(args));
  }
  if (!shown) return out;
  if (!given && !(withLimit && (args.has("limit-ms") || args.has("coverage-k")))) out.shownResult = shown;
  const std::string which = session::describeResult(opened.results, *shown);
  out.note = given ? "analysed with the constants given on the command line over the session's own, not those of "
                     "the result shown (" + which + ")"
                   : "analysed with the constants of the result shown (" + which + ")";
  return out;
}

}  // namespace fog::app

#include "app/session_input.h"

#include <iostream>

#include "app/cli_common.h"
#include "core/common/text.h"

namespace fog::app {

Result<session::OpenedSession> openInput(const std::string& path, const session::OpenOptions& options) {
  auto opened = session::openSessionOrStream(path, options);
  if (opened && !opened->damage.empty())
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

}  // namespace fog::app

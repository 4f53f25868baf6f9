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
  auto opened = bad.isOk() ? openInput(args.positionals()[0], options) : Result<session::OpenedSession>(bad);
  if (opened) return std::move(*opened);
  (void)args.checkAllUsed();
  exitCode = fail(opened.status(), exitCodeFor(opened.status()));
  return std::nullopt;
}

}  // namespace fog::app

#pragma once
// The CLI's way into a FILE argument: session::openSessionOrStream, and the
// damage note printed first (docs/sessions.md). Every command that reads a
// session or a raw stream goes through here.

#include <optional>
#include <string>

#include "app/cli_arguments.h"
#include "core/session/session_api.h"

namespace fog::app {

// Opens `path` (session::openSessionOrStream). A damaged session read from
// the raw stream it holds says so before anything else is printed, on
// stderr ("fogbench-cli: note: S.fbs is a damaged session (...); analysed
// from the raw board stream it holds ..."), so that --json output stays one
// JSON document.
Result<session::OpenedSession> openInput(const std::string& path, const session::OpenOptions& options = {});

// A command's one FILE argument, opened with openInput. Without exactly one
// (`needs` says what: "analyze needs exactly one FILE"), or when it cannot
// be opened, the one-line error is printed, `exitCode` is set (2, or 1 when
// the data hold too little: exitCodeFor) and nothing is returned. The other
// arguments are marked seen first, so that the file's error is the one shown.
std::optional<session::OpenedSession> openFileArgument(CliArguments& args, const std::string& needs, int& exitCode,
                                                       const session::OpenOptions& options = {});

// The constants and limit a command (export, response, diagnose, noise)
// analyses `opened` with, so that it shows the numbers of the result the
// report shows: the shown stored result's (the newest usable one), unless the
// command line gives a constant (--read-delay-ms, --gyro-sign, ...; then
// those, over the session's own) or, when `withLimit`, a limit (--limit-ms;
// without it the limit is the shown result's or the default). `note` says which,
// in one line for stderr; "" for a raw stream or a session with no usable
// stored result and nothing given.
struct CommandSettings {
  BenchConstants constants;
  double imuDelayLimitMs = 0.0;
  double coverageK = analysis::kDefaultCoverageFactor;  // --coverage-k with the limit, else the shown result's
  std::string note;
  // The shown stored result whose settings these are exactly (null when the
  // command line gave others, or none is stored): its verdict is the one
  // shown with the numbers.
  const session::StoredResultRecord* shownResult = nullptr;
};
Result<CommandSettings> shownResultSettings(CliArguments& args, const session::OpenedSession& opened,
                                            bool withLimit = false);

}  // namespace fog::app

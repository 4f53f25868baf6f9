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

}  // namespace fog::app

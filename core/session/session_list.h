#pragma once
// A folder of session files at a glance: for the CLI's `sessions DIR` and the
// GUI's session browser. Qt-free.

#include <cstddef>
#include <string>
#include <vector>

#include "core/common/session_info.h"
#include "core/common/status.h"
#include "core/session/shown_verdict.h"

namespace fog::session {

struct SessionSummary {
  std::string path;
  std::string fileName;
  std::string error;  // non-empty: the file looks like a session (or is named *.fbs) but cannot be read; says why
  SessionInfo info;
  bool complete = false;
  std::string incompleteReason;
  // Non-empty: the raw board stream, the session's source of truth, fails
  // its checks (SessionReader::checkRawStream's words).
  std::string rawDamage;
  std::size_t results = 0;
  // Stored results that fail their checksum or do not parse: never shown,
  // always counted, so a listing says a result is damaged instead of "-".
  std::size_t damagedResults = 0;
  // The result shown: the latest usable one (1-based; 0: none), and its
  // verdict with its points' numbers and their verdicts, as stored
  // (judgeShown: a refused point's delay is never listed bare).
  std::size_t shownResult = 0;
  ShownVerdict shown;
};

struct SessionListing {
  std::vector<SessionSummary> sessions;  // by file name
  int skippedFiles = 0;                   // other files that are not sessions (SQLite side files not counted)
};

// Errors: `dir` is not a folder or cannot be listed (kIoError).
Result<SessionListing> listSessions(const std::string& dir);

// "x,z": the axes a plan swings, "-" for none.
std::string axesOf(const TestPlan& plan);

}  // namespace fog::session

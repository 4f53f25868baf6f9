#pragma once
// The one way into a recording for the CLI and the GUI (issue 28, "one
// result, one verdict, everywhere"): open a session file or a raw board
// stream, analyse it again and store the result, and choose the result a view
// or a report shows. fogbench-cli (analyze, diagnose, noise, report, export,
// replay) and the desktop bench (open, review, re-analyse, replay, the PDF)
// call only these, so a session reads, judges and reports the same in both
// (the test source.views_and_commands_judge_no_verdict_and_reach_results_through_the_session_api
// fails on a view or command that reads or stores a result row itself).
// Qt-free; docs/sessions.md ("Reading a session: the session API").
//
// Contracts:
//  - A file is a session when session::isSqliteFile() says so (any SQLite
//    database, or a session whose header is damaged); everything else is a
//    raw sampling-board stream. A session that cannot be opened (damaged
//    header or first page, foreign database, newer schema, ...) is refused
//    with the SessionReader's message: it is never decoded as a raw stream
//    (issues 15 and 29: that once printed PASS with a wrong delay).
//  - A session whose decoded samples are damaged but whose raw stream is
//    intact (every chunk passes its checksum) is read from that raw stream,
//    the session's source of truth (session_file.h); `damage` then says what
//    was damaged and damageNote() is the line a caller prints first.
//  - Stored results are records (stored_result.h): the verdict shown is the
//    stored one; a new setting is a new analysis stored as a new result.
//  - Errors are Status values naming the file; nothing throws.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"
#include "core/session/session_file.h"
#include "core/session/shown_verdict.h"
#include "core/session/stored_result.h"

namespace fog::session {

struct OpenOptions {
  // Keep the raw stream's bytes (the report hashes them, a replay plays
  // them). A raw stream file is read whole to be decoded, but its bytes are
  // kept only then; a session's are read only then.
  bool rawBytes = false;
  // Decode the recording (stored samples, else the raw stream). Off for a
  // caller that only wants the bytes, the identity or the results (replay).
  bool decode = true;
  // Refuse a file that is not a session with SessionReader::open's message
  // (export and replay need a session's identity and results).
  bool sessionOnly = false;
  // Degrees per gyro pulse for decoding (RecordingBuilder::finish): given
  // (> 0) it wins over the session's bench constant, as the CLI's
  // --pulse-equivalent-deg; the fallback serves only a session and stream
  // that state none (the GUI's bench constants). A stream's own statement
  // always wins.
  double pulseEquivalentDeg = 0.0;
  double fallbackPulseEquivalentDeg = 0.0;

  // The combinations the callers use, named by what they are for.
  static OpenOptions session();        // a session (no raw stream), decoded: export, the GUI's review
  static OpenOptions sessionStream();  // a session's raw bytes, not decoded: replay, the report's hash
  static OpenOptions withRawBytes();   // a session or a stream, decoded, with its bytes: the report
  static OpenOptions sessionRecords(); // a session's identity and results, nothing decoded: after a run
};

struct OpenedSession {
  std::string path;
  bool isSession = false;  // false: a raw sampling-board stream file
  // A raw stream has no identity: defaults, with pulseEquivalentDeg 0 (only
  // the stream's STATUS frames or the command line can state it).
  SessionInfo info;
  Recording recording;                 // with OpenOptions::decode
  std::vector<std::uint8_t> rawBytes;  // with OpenOptions::rawBytes
  std::uint64_t rawByteCount = 0;      // the raw stream's length, read or not
  // The stored rows as stored (export writes them out) and as records, oldest
  // first; a constant a row does not state is the session's own. Empty for a
  // raw stream.
  std::vector<StoredResult> stored;
  std::vector<StoredResultRecord> results;
  bool complete = true;  // a raw stream: unknown, taken as complete
  std::string incompleteReason;
  bool beingRecorded = false;  // a recorder holds the file: nothing is stored into it
  // Non-empty: the session is damaged and `recording` was decoded from the
  // raw board stream it holds; what was damaged (the reader's words).
  std::string damage;
  // Non-empty: the recording was read from the stored decoded samples, but
  // the raw board stream they came from is damaged (SessionReader::
  // checkRawStream's words): nothing vouches for the samples.
  std::string rawDamage;

  // The report's source line: "session S.fbs (simulator, seed 1)", with
  // " [incomplete: why]" and " [damaged: ...]" when so; "raw stream S.bin".
  // `what` names a session ("session", "replay of session").
  std::string sourceLine(const std::string& what = "session") const;
  // The line to print before anything else when `damage` or `rawDamage` is
  // set, else "": "S.fbs is a damaged session (...); analysed from the raw
  // board stream it holds ...", "S.fbs is a damaged session: its raw board
  // stream ... is damaged (...)".
  std::string damageNote() const;
};

// Opens `path` as a session or a raw stream (see the contracts above).
Result<OpenedSession> openSessionOrStream(const std::string& path, const OpenOptions& options = {});

// The settings of an analysis, stored with its result (analysisSettingsJson).
struct AnalysisSettings {
  BenchConstants constants;
  double imuDelayLimitMs = analysis::kDefaultImuDelayLimitMs;
  double coverageK = analysis::kDefaultCoverageFactor;  // the decision rule's k (decision_rule.h)
  std::string producedBy;  // "fogbench-cli analyze", "fogbench GUI Results": the audit's tool too
  // The audit entry's who and command (AnalysisAudit): the operator named to
  // the analysing command ("" = the login name) and its argument line or the
  // GUI view's name. analyseAndStore adds the raw stream's SHA-256.
  std::string operatorName;
  std::string command;
  // The audit's tool when it says more than `producedBy` ("fogbench GUI
  // Results" where analysed_by stays "fogbench GUI"); "" = producedBy.
  std::string tool;
};

struct NewResult {
  Result<analysis::DelayReport> report = Status(StatusCode::kInsufficientData, "not analysed");
  analysis::ReportContext context;  // source, limit, incompleteness: what the report was formatted with
  bool stored = false;
  // A store that failed (a locked or read-only file, a full disk): the
  // report is still here, to be shown with the error.
  Status storeStatus;
  // Why a result that could have been stored was not ("" when it was, when
  // storing was not asked for, or when the data gave no report).
  std::string notStored;
  // The session's results after storing, oldest first (the new one last);
  // `session.results` when nothing was stored.
  std::vector<StoredResultRecord> results;
};

// Analyses the session's recording with `settings` and, when `store` and the
// analysis gave a report, appends it to the session file (addResult) with
// its settings. A session being recorded is not written to (`notStored` says
// why); a raw stream has no session to store into (nor is it asked to). A
// session that stopped early stays incomplete whatever the analysis gives.
// Never fails as a whole: a report that could not be made is in `report`, a
// store that failed in `storeStatus`.
NewResult analyseAndStore(const OpenedSession& session, const AnalysisSettings& settings, bool store = true);

// The result a view or a report of the session shows, and this version's
// analysis with its settings (for plots and fits; the verdict shown is the
// record's).
struct ShownResult {
  std::optional<StoredResultRecord> record;  // unset: none usable is stored
  int number = 0;                            // 1-based among session.results; 0: none
  BenchConstants constants;        // the record's, else the fallback
  Result<analysis::DelayReport> report = Status(StatusCode::kInsufficientData, "not analysed");
  // source; the record's limit (else the fallback); incompleteReason when no
  // record states the verdict.
  analysis::ReportContext context;
  std::vector<std::string> differences;  // differencesFromRecord; empty without a record
  // "result 2 of 3, stored T by X (fogbench V)"; "" when none is shown.
  std::string description;
  // The verdict shown and each point's numbers with theirs (judgeShown: the
  // record's, else `report` judged with the limit; INCOMPLETE for a run that
  // stopped early). Every view and command formats this, never re-judges.
  ShownVerdict verdict;
};

// The stored result `resultId` when it is usable, else the newest usable one,
// else none (then `fallback` constants, `fallbackLimitMs` and
// `fallbackCoverageK` judge; a record's own k and limit win).
ShownResult showResult(const OpenedSession& session, std::int64_t resultId, const BenchConstants& fallback,
                       double fallbackLimitMs, double fallbackCoverageK = analysis::kDefaultCoverageFactor);

// "result 2 of 3, stored T by X (fogbench V)": `record` among `results`
// (ShownResult::description; the CLI's report names it when it refuses
// settings that would re-judge it).
std::string describeResult(const std::vector<StoredResultRecord>& results, const StoredResultRecord& record);

}  // namespace fog::session

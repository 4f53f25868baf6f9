#pragma once
// The session file (.fbs): one SQLite database per recorded session holding
// its metadata, the raw sampling-board byte stream, the decoded samples and
// every analysis result with the settings that produced it. docs/sessions.md
// describes the tables, columns and units.
//
// Contracts:
//  - The raw byte stream is the source of truth: it is stored exactly as
//    received, in order, and never changed once committed. Decoded samples
//    and results can always be rebuilt from it.
//  - Crash safety: while recording, the file is in WAL mode and raw bytes are
//    committed (synchronous=FULL) at least every kCommitInterval plus the gap
//    between two appendRaw()/flush() calls; after a crash or kill -9 the file
//    opens and holds everything the writer was given except, at most, the
//    bytes of that last interval. finish() switches the file back to a single
//    self-contained file (rollback journal), so a finished session can be
//    copied, mailed or opened from read-only media.
//  - Review is read-only: SessionReader opens with SQLITE_OPEN_READONLY and
//    cannot change the file. addResult() is the only post-recording write and
//    only appends a row to the results table.
//  - A file that is missing, empty, truncated, corrupt, not SQLite, a foreign
//    SQLite database, or a session of a newer schema gives an error Status
//    that names the file and says what to do; never a crash or an exception.
//  - Schema: PRAGMA application_id == kApplicationId marks a fogbench session;
//    PRAGMA user_version == schema version. Files of an older schema are read
//    (and migrated before addResult() writes to them); a newer schema is
//    refused with "update fogbench".
// Core code: no Qt. Errors are fog::Status values; nothing throws.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

struct sqlite3;

namespace fog::session {

inline constexpr int kSchemaVersion = 6;
// 'F' 'O' 'G' 'B' at offset 68 of the SQLite header.
inline constexpr std::int32_t kApplicationId = 0x464F4742;
inline constexpr const char* kFileExtension = ".fbs";
// Raw bytes are committed once the oldest uncommitted byte is this old. Kept
// below the promised 250 ms so that a caller appending every <= 50 ms (a serial
// read timeout, the simulator's pacing) still commits at least every 250 ms.
inline constexpr std::chrono::milliseconds kCommitInterval{200};
inline constexpr std::chrono::milliseconds kPromisedMaxLoss{250};

struct StoredResult {
  std::int64_t id = 0;         // increasing: a later result has a larger id
  std::string createdUtc;      // ISO 8601, when the result was stored
  std::string settingsJson;    // the settings that produced it (bench constants, software version, ...)
  std::string reportJson;      // the report (analysis::formatReportJson)
  // False: the row fails its checksum (schema 2); the texts above are then
  // not to be trusted. Results of schema 1 files have no checksum.
  bool intact = true;
};

// One line of a table-driven run's log (schema 3, docs/table-control.md):
// a command sent to the table controller, its reply, a status change, a
// step of the plan runner, an event.
struct TableLogEntry {
  double elapsedS = 0.0;  // wall seconds since the run started
  std::string kind;       // "command", "reply", "status", "step", "event"
  std::string text;
};

// Recording side. Not thread-safe; one writer per file, one file per session.
// Destroying a writer without finish() commits what is buffered and leaves
// the session marked as interrupted ("recording" state), like a crash would.
class SessionWriter {
 public:
  // Creates a new session file and stores `info` (createdUtc is filled with
  // the current time when empty). Refuses to overwrite an existing file.
  static Result<std::unique_ptr<SessionWriter>> create(const std::string& path, const SessionInfo& info);
  ~SessionWriter();
  SessionWriter(const SessionWriter&) = delete;
  SessionWriter& operator=(const SessionWriter&) = delete;

  // Buffers raw bytes; commits them when the oldest buffered byte is
  // kCommitInterval old (checked on every call, including size 0 calls, which
  // a recording loop may make while the line is quiet).
  Status appendRaw(const std::uint8_t* data, std::size_t size);
  // Decoded samples per test point, with the recording's health counters,
  // counter frequency/width and pulse equivalent. Replaces any decoded data
  // stored before (the raw stream is untouched). Commits.
  Status storeRecording(const Recording& decoded);
  // Appends lines to the table log (one transaction; commits buffered raw
  // bytes first, so the log never runs ahead of the stream it describes).
  Status appendTableLog(const std::vector<TableLogEntry>& entries);
  // Commits everything buffered.
  Status flush();
  // Flushes, marks the session complete or incomplete with a reason ("port
  // vanished at 12.3 s"), and makes the file self-contained. The writer
  // accepts nothing after finish().
  Status finish(bool complete, const std::string& reason);
  // After a write failed (a full disk): tries once to mark the session
  // incomplete with `reason` and closes it. What was committed stays; what was
  // still buffered is dropped. If even that write fails, the session reads as
  // interrupted.
  Status finishAfterFailure(const std::string& reason);

  // Raw bytes appended so far / safely committed to the file so far.
  std::uint64_t appendedBytes() const { return appended_; }
  std::uint64_t committedBytes() const { return committed_; }
  // Number of commits of raw data so far.
  std::uint64_t commits() const { return commits_; }
  const std::string& path() const { return path_; }

 private:
  SessionWriter() = default;
  Status commitPending();
  Status fail(const std::string& what);

  sqlite3* db_ = nullptr;
  std::string path_;
  std::vector<std::uint8_t> pending_;
  std::chrono::steady_clock::time_point oldestPending_{};
  std::uint64_t appended_ = 0;
  std::uint64_t committed_ = 0;
  std::uint64_t commits_ = 0;
  std::int64_t nextChunk_ = 0;
  int lockFd_ = -1;  // the file's descriptor holding the recording lock (flock) until finished
  bool finished_ = false;
  Status broken_;  // first write error; the writer refuses further writes after one
};

// Review side: read-only.
class SessionReader {
 public:
  static Result<std::unique_ptr<SessionReader>> open(const std::string& path);
  ~SessionReader();
  SessionReader(const SessionReader&) = delete;
  SessionReader& operator=(const SessionReader&) = delete;

  const SessionInfo& info() const { return info_; }
  int schemaVersion() const { return schemaVersion_; }
  bool complete() const { return state_ == "complete"; }
  // A recorder (this or another program) was recording into the file when it
  // was opened: the session is live, not interrupted.
  bool beingRecorded() const { return live_ && state_ == "recording"; }
  // Empty when complete; the writer's reason, or "recording was interrupted"
  // when the recording program stopped without finishing (crash, kill, power).
  std::string incompleteReason() const;
  // True: the connection cannot write (sqlite3_db_readonly); always true.
  bool isReadOnly() const;
  const std::string& path() const { return path_; }

  // The whole raw stream, in order.
  Result<std::vector<std::uint8_t>> rawBytes() const;
  // Checks every raw chunk (order, offsets, checksums) as rawBytes() does,
  // keeping none of them (memory: one chunk). kCorruptData names the first
  // damaged chunk.
  Status checkRawStream() const;
  // The SHA-256 (lower-case hex) of the whole raw stream, checked as
  // checkRawStream() does (memory: one chunk): what a stored result's audit
  // states as the data it analysed (docs/sessions.md). The raw stream never
  // changes once committed, so every analysis of a finished session states
  // the same hash.
  Result<std::string> rawSha256() const;
  std::uint64_t rawByteCount() const;
  // Whether decoded samples were stored (false after a crash).
  bool hasStoredRecording() const;
  // The stored decoded samples; if none were stored, decodes rawBytes().
  // Increments are in degrees: a stream that does not state its pulse
  // equivalent takes pulseEquivalentDeg when > 0, else the session's bench
  // constant, else fails as protocol::RecordingBuilder::finish does.
  Result<Recording> recording(double pulseEquivalentDeg = 0.0) const;
  // Every stored analysis result, oldest first.
  Result<std::vector<StoredResult>> results() const;
  // The table log, in order; empty for a session without one (the simulator,
  // a board alone, schema 1 and 2 files).
  Result<std::vector<TableLogEntry>> tableLog() const;

 private:
  SessionReader() = default;
  Status readError(const std::string& what) const;
  // Every raw chunk in order, checked (order, offsets, checksums); `each`
  // (when set) is given each chunk's bytes.
  Status walkRawStream(const std::function<void(const std::uint8_t*, std::size_t)>& each) const;

  sqlite3* db_ = nullptr;
  std::string path_;
  SessionInfo info_;
  int schemaVersion_ = 0;
  std::string state_;
  std::string reason_;
  bool live_ = false;  // a recorder had the file locked when it was opened
};

// Appends an analysis result (opens the file read-write briefly). Never
// touches the raw stream or the decoded samples. Refuses (an error saying "not
// stored") while the session is being recorded, and when the file stays
// locked by another writer for more than a few seconds.
Status addResult(const std::string& path, const std::string& settingsJson, const std::string& reportJson);

// Appends table-log lines to a finished session (what the plan runner said
// after the recording ended: the table brought to rest). Same rules as
// addResult: never while the session is being recorded; migrates an older
// file first.
Status appendTableLog(const std::string& path, const std::vector<TableLogEntry>& entries);

// Cheap test for listing folders: an SQLite header whose application_id is
// fogbench's, or a session whose SQLite header is damaged (its schema text is
// still there). Says nothing about the schema version or the file's health
// (a truncated or newer session still "looks like" one; open() says why not).
bool looksLikeSession(const std::string& path);
// Any SQLite database (the header magic), or a session whose header is
// damaged: what a caller that accepts both raw streams and sessions hands to
// SessionReader for a clear verdict, never to the raw-stream decoder.
bool isSqliteFile(const std::string& path);
// A SessionWriter (in any process) is recording into the file right now: it
// holds an exclusive flock() on it from create() until finish(). False for a
// finished or an interrupted (crashed, killed) session.
bool isBeingRecorded(const std::string& path);

// Current UTC time as ISO 8601 with seconds, "2026-11-22T02:45:00Z".
std::string utcNow();

}  // namespace fog::session

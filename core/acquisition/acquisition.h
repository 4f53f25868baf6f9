#pragma once
// One acquisition run: bytes from a ByteSource are recorded into a session
// file as they arrive (crash-safe, docs/sessions.md), decoded by the same
// decoder every source uses, handed to an observer in batches for live
// display, and at the end stored as decoded samples and analysed.
//
//   std::atomic<bool> stop{false};
//   AcquisitionOptions o; o.sessionPath = "run1.fbs"; o.info = ...; o.constants = ...;
//   auto r = acquire(source, o, &stop, [&](AcquisitionBatch&& b) { queue.push(std::move(b)); });
//
// Contracts:
//  - Runs in the calling thread until the source ends, `stop` becomes true,
//    or the source fails. The observer is called from that thread, about
//    every batchInterval while data flows (and at least every stallWarning
//    while it does not); it must not block for long (hand the batch to
//    another thread). The engine never waits on its observer's consumer.
//  - Nothing received is ever lost: every byte goes to the session before it
//    is decoded. A stop or a source failure ends the run as incomplete, with
//    the reason in the session ("stopped by the operator after 12.3 s",
//    "serial port vanished: ..."), and everything received so far is stored
//    and analysed like a complete run.
//  - The returned Result is an error only when nothing could be recorded
//    (the session file could not be created, or writing to it failed:
//    then the run stops at once, because recording without storing is what
//    the bench must never do). Data problems are not errors: the analysis
//    status says why no delay was reported.
//  - Without a sessionPath nothing is written (the command line's quick runs).
//  - With a stallLimit, a source silent for that long ends the run as
//    incomplete ("no data for 10 s"); with endWhenBoardDone the board's
//    "done" STATUS after a recording phase ends it as complete.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/acquisition/byte_source.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"
#include "core/protocol/decoder.h"
#include "core/session/session_file.h"
#include "core/session/stored_result.h"  // analysisSettingsJson

namespace fog::acquisition {

struct AcquisitionOptions {
  std::string sessionPath;  // empty: do not record
  SessionInfo info;         // stored in the session (plan, bench constants, who, source)
  // What the analysis uses; its pulse equivalent converts a stream that
  // does not state its own (protocol::RecordingBuilder::finish).
  BenchConstants constants;
  analysis::ReportContext reportContext;  // source line and truth for the stored report
  // The stored result's audit command (AnalysisAudit::command): the CLI's
  // argument line or the GUI view's name. Its who is the info's operator
  // (else the login name), its tool "acquisition".
  std::string auditCommand;
  std::chrono::milliseconds readTimeout{20};
  std::chrono::milliseconds batchInterval{33};  // ~30 batches per second
  std::chrono::milliseconds stallWarning{1000}; // "no data for 1.0 s" from here on
  // No byte for this long ends the run as incomplete ("no data for 10 s");
  // zero: wait for ever (the simulator and replay never stall).
  std::chrono::milliseconds stallLimit{0};
  // A live board keeps sending after its plan: end the run as complete at
  // the first STATUS frame saying phase "done" after a recording phase.
  bool endWhenBoardDone = false;
  // A table-driven run (docs/table-control.md) decides itself when the run
  // is over: called every loop; nullopt = go on, "" = end as complete, any
  // other text = end as incomplete with that reason.
  std::function<std::optional<std::string>()> shouldEnd;
  // Called every loop; lines returned go into the session's table log
  // (after the raw bytes received so far).
  std::function<std::vector<session::TableLogEntry>()> drainTableLog;
  // Applied to the decoded recording before it is analysed and stored: the
  // table-driven run cuts the stream into its test points here. With it, the
  // recording handed over is the whole stream as one test point (the STATUS
  // frames' test-point markers are not followed).
  std::function<Recording(const Recording&)> segment;
  // The memory budget (test_plan.h): once this many table and IMU frames
  // have arrived the run ends as incomplete ("the run reached its memory
  // budget ..."), keeping and analysing what it recorded.
  std::uint64_t maxSamples = kMaxRunSamples;
};

struct AcquisitionBatch {
  std::vector<protocol::DecodedFrame> frames;  // new since the previous batch, stream order
  StreamHealth health;                         // decoder counters so far
  std::uint64_t bytesReceived = 0;
  std::uint64_t bytesCommitted = 0;            // safely in the session file
  double silentForS = 0.0;                     // > 0: no byte has arrived for this long
};

struct AcquisitionResult {
  bool complete = false;         // the source ended by itself
  std::string incompleteReason;  // why not
  std::uint64_t bytesReceived = 0;
  std::string sessionPath;       // empty when nothing was recorded
  // Raw bytes safely in the session: bytesReceived, unless writing the
  // session failed (a full disk): then the run ends there as incomplete, like
  // a vanished port, and everything received is still analysed.
  std::uint64_t sessionBytes = 0;
  Recording recording;           // decoded; empty test points when nothing decodable arrived
  Status recordingStatus;        // ok, or why the stream gave no usable test point
  Result<analysis::DelayReport> report = Status(StatusCode::kInsufficientData, "not analysed");
};

Result<AcquisitionResult> acquire(ByteSource& source, const AcquisitionOptions& options,
                                  const std::atomic<bool>* stop,
                                  const std::function<void(AcquisitionBatch&&)>& observer = {});

// The report context of a finished run: options.reportContext with the
// run's state (incomplete, why, how much of the plan was recorded), so that
// every report of an incomplete run says so in its verdict.
analysis::ReportContext reportContextOf(const AcquisitionResult& run, const AcquisitionOptions& options);


}  // namespace fog::acquisition

#include "core/acquisition/acquisition.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/common/version.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace fog::acquisition {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string fixed1(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

// Same verdicts as protocol::decodeRecording, so live, replayed and decoded
// data fail alike.
Status usability(bool anyFrames, const Recording& rec, std::uint64_t bytes) {
  if (!anyFrames)
    return corruptData("no valid sampling-board frames found in " + std::to_string(bytes) +
                       " bytes; is this a fogbench raw stream, or is the baud rate wrong?");
  const bool usable = std::any_of(rec.testPoints.begin(), rec.testPoints.end(),
                                  [](const TestPointData& tp) { return !tp.table.empty() && !tp.imu.empty(); });
  if (!usable) return insufficientData("the stream holds no test point with both table and IMU samples");
  return Status::ok();
}

}  // namespace

analysis::ReportContext reportContextOf(const AcquisitionResult& run, const AcquisitionOptions& options) {
  analysis::ReportContext context = options.reportContext;
  if (run.complete) return context;
  context.incompleteReason = run.incompleteReason.empty() ? std::string("the run ended early") : run.incompleteReason;
  double last = 0.0;
  for (const auto& tp : run.recording.testPoints) {
    if (!tp.table.empty()) last = std::max(last, tp.table.back().timeS);
    if (!tp.imu.empty()) last = std::max(last, tp.imu.back().timeS);
  }
  context.recordedS = last;
  if (!options.info.plan.points.empty()) context.plannedS = options.info.plan.totalDurationS();
  return context;
}

// The end of a recorded run: the decoded samples and the session's final
// state go to the file, then the run's result (with its settings). A file
// that cannot be written at the end (a full disk) makes the run incomplete,
// as during the run; only a failure to store the result is an error.
static Status finishSession(std::unique_ptr<session::SessionWriter> writer, const Status& sessionFailure, bool storeSamples,
                     const AcquisitionOptions& options, AcquisitionResult& result) {
  result.sessionPath = options.sessionPath;
  Status written = sessionFailure;
  if (written.isOk() && storeSamples) written = writer->storeRecording(result.recording);
  if (written.isOk()) written = writer->finish(result.complete, result.incompleteReason);
  if (!written.isOk()) {
    if (sessionFailure.isOk())
      result.incompleteReason = "the session file could not be written at the end of the run (" + written.message() + ")";
    result.complete = false;
    // Best effort: mark the session incomplete with the reason (a full
    // disk may refuse even that; it then reads as interrupted). Nothing
    // else is written: decoded samples can be rebuilt from the raw stream.
    (void)writer->finishAfterFailure(result.incompleteReason);
    result.sessionBytes = writer->committedBytes();
    return Status::ok();
  }
  result.sessionBytes = writer->committedBytes();
  writer.reset();  // closed before the result is added
  if (!result.report) return Status::ok();
  // The hash of the raw stream just finished: what every later analysis of
  // the session states too (a stream that cannot be read back states none).
  std::string inputSha256;
  if (auto reader = session::SessionReader::open(options.sessionPath))
    if (auto sha = (*reader)->rawSha256()) inputSha256 = std::move(*sha);
  const auto audit = session::makeAudit(options.info.operatorName, "acquisition", options.auditCommand, inputSha256);
  return session::addResult(
      options.sessionPath,
      session::analysisSettingsJson(options.constants, options.reportContext.imuDelayLimitMs, "acquisition", {},
                                    &audit, options.reportContext.coverageK),
      analysis::formatReportJson(*result.report, reportContextOf(result, options)));
}

Result<AcquisitionResult> acquire(ByteSource& source, const AcquisitionOptions& options,
                                  const std::atomic<bool>* stop,
                                  const std::function<void(AcquisitionBatch&&)>& observer) {
  std::unique_ptr<session::SessionWriter> writer;
  if (!options.sessionPath.empty()) {
    SessionInfo info = options.info;
    if (info.source.empty()) info.source = source.description();
    FOG_ASSIGN_OR_RETURN(auto created, session::SessionWriter::create(options.sessionPath, info));
    writer = std::move(created);
  }

  protocol::Decoder decoder;
  // A run that cuts the stream itself gets the whole stream, whatever test
  // points the board's STATUS frames mark.
  protocol::RecordingBuilder builder(!options.segment);
  std::vector<std::uint8_t> bytes;
  std::vector<protocol::DecodedFrame> decoded;
  AcquisitionBatch batch;
  AcquisitionResult result;
  const auto started = Clock::now();
  auto lastBatch = started;
  auto lastByte = started;
  bool ended = false;
  std::uint64_t samples = 0;   // table and IMU frames decoded (the memory budget)
  bool boardRecorded = false;  // a STATUS with phase recording has been seen
  Status sessionFailure;       // writing the session failed (a full disk): the run ends

  auto deliver = [&](Clock::time_point now) {
    lastBatch = now;
    if (!observer) {
      batch.frames.clear();
      return;
    }
    batch.health = decoder.health();
    batch.bytesReceived = result.bytesReceived;
    batch.bytesCommitted = writer ? writer->committedBytes() : 0;
    batch.silentForS = now - lastByte >= options.stallWarning ? seconds(now - lastByte) : 0.0;
    observer(std::move(batch));
    batch = AcquisitionBatch{};
  };

  while (!ended) {
    if (stop && stop->load()) {
      result.incompleteReason = "stopped by the operator after " + fixed1(seconds(Clock::now() - started)) + " s";
      break;
    }
    bytes.clear();
    auto got = source.read(bytes, options.readTimeout);
    const auto now = Clock::now();
    if (!got) {
      result.incompleteReason = got.status().message() + " (after " + fixed1(seconds(now - started)) + " s)";
      break;
    }
    ended = got->endOfStream;
    if (!bytes.empty()) {
      lastByte = now;
      result.bytesReceived += bytes.size();
      if (writer) {
        // Stored before anything else happens to them.
        if (auto s = writer->appendRaw(bytes.data(), bytes.size()); !s.isOk()) sessionFailure = s;
      }
      decoded.clear();
      decoder.push(bytes, decoded);
      builder.add(decoded);
      for (const auto& d : decoded)
        samples += !std::holds_alternative<protocol::StatusPayload>(d.frame.payload);
      batch.frames.insert(batch.frames.end(), decoded.begin(), decoded.end());
      if (options.endWhenBoardDone)
        for (const auto& d : decoded) {
          const auto* status = std::get_if<protocol::StatusPayload>(&d.frame.payload);
          if (!status) continue;
          if (status->phase == protocol::TestPhase::kRecording) boardRecorded = true;
          if (status->phase == protocol::TestPhase::kDone && boardRecorded) ended = true;
        }
    } else if (writer) {
      // A quiet line still commits what is buffered on time.
      if (auto s = writer->appendRaw(nullptr, 0); !s.isOk()) sessionFailure = s;
    }
    if (!sessionFailure.isOk()) {
      // Like a vanished port: the run ends, what the session holds stays, and
      // everything received (decoded above) is analysed.
      result.incompleteReason = "the session file could not be written after " +
                                fixed1(seconds(now - started)) + " s (" + sessionFailure.message() + ")";
      break;
    }
    if (writer && options.drainTableLog && sessionFailure.isOk()) {
      if (auto lines = options.drainTableLog(); !lines.empty())
        if (auto s = writer->appendTableLog(lines); !s.isOk()) sessionFailure = s;
    }
    if (samples >= options.maxSamples && !ended) {
      // Bounded by design: whatever the source sends, a run never holds more
      // samples than its memory budget (test_plan.h).
      result.incompleteReason = "the run reached its memory budget of " + std::to_string(options.maxSamples) +
                                " table and IMU samples after " + fixed1(seconds(now - started)) +
                                " s; everything recorded is kept";
      break;
    }
    if (now - lastBatch >= options.batchInterval) deliver(now);
    if (options.shouldEnd && !ended) {
      if (auto end = options.shouldEnd()) {
        result.incompleteReason = *end;
        ended = true;
        break;
      }
    }
    if (!ended && options.stallLimit.count() > 0 && now - lastByte >= options.stallLimit) {
      result.incompleteReason = "no data for " + fixed1(seconds(now - lastByte)) + " s from " +
                                source.description() + " (after " + fixed1(seconds(now - started)) + " s)";
      break;
    }
  }
  result.complete = ended && result.incompleteReason.empty();
  if (writer && options.drainTableLog && sessionFailure.isOk())
    if (auto lines = options.drainTableLog(); !lines.empty()) (void)writer->appendTableLog(lines);
  deliver(Clock::now());

  const bool anyFrames = builder.framesAdded() > 0;
  auto built = builder.finish(decoder.health(), options.constants.pulseEquivalentDeg);
  // A stream whose pulses cannot be turned into degrees has no recording to
  // store: its raw bytes are kept, and reading the session says why.
  const bool builtOk = built.isOk();
  if (builtOk) {
    result.recording = std::move(*built);
    if (options.segment) result.recording = options.segment(result.recording);
    result.recordingStatus = usability(anyFrames, result.recording, result.bytesReceived);
  } else {
    result.recordingStatus = built.status();
  }
  if (result.recordingStatus.isOk()) result.report = analysis::analyzeRecording(result.recording, options.constants);
  else result.report = result.recordingStatus;

  if (writer) FOG_RETURN_IF_ERROR(finishSession(std::move(writer), sessionFailure, anyFrames && builtOk, options, result));
  return result;
}

}  // namespace fog::acquisition

#include "core/session/session_api.h"

#include <utility>

#include "core/common/text.h"
#include "core/protocol/recording_builder.h"
#include "core/session/raw_stream_file.h"

namespace fog::session {

namespace {

// The records of a session's rows; constants a row does not state are the
// session's own.
std::vector<StoredResultRecord> recordsOf(const std::vector<StoredResult>& stored, const SessionInfo& info) {
  return readStoredResults(stored, info.bench);
}

// The reader's refusal without what the note says itself: its "session
// 'S.fbs': " and its advice to analyse the raw stream (which is being done).
std::string damageOf(std::string message, const std::string& path) {
  const std::string prefix = "session '" + path + "': ", advice = "; analyse the raw stream instead";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  if (message.size() >= advice.size() && message.compare(message.size() - advice.size(), advice.size(), advice) == 0)
    message.erase(message.size() - advice.size());
  return message;
}

Result<OpenedSession> openSessionFile(const std::string& path, const OpenOptions& options) {
  FOG_ASSIGN_OR_RETURN(auto reader, SessionReader::open(path));
  OpenedSession s;
  s.path = path;
  s.isSession = true;
  s.info = reader->info();
  s.complete = reader->complete();
  s.incompleteReason = reader->incompleteReason();
  s.beingRecorded = reader->beingRecorded();
  s.rawByteCount = reader->rawByteCount();
  if (options.decode) {
    const double pulse = options.pulseEquivalentDeg > 0.0       ? options.pulseEquivalentDeg
                         : s.info.bench.pulseEquivalentDeg > 0.0 ? 0.0
                                                                 : options.fallbackPulseEquivalentDeg;
    auto recording = reader->recording(pulse);
    if (!recording && recording.status().code() == StatusCode::kCorruptData && reader->hasStoredRecording()) {
      // The decoded samples are a copy of what the raw stream gives; when
      // they are damaged and the stream is intact, the stream is the truth.
      auto raw = reader->rawBytes();
      if (!raw) return recording.status();
      auto decoded = protocol::decodeRecording(*raw, pulse > 0.0 ? pulse : s.info.bench.pulseEquivalentDeg);
      if (!decoded) return recording.status();
      s.damage = damageOf(recording.status().message(), path);
      recording = std::move(decoded);
      if (options.rawBytes) s.rawBytes = std::move(*raw);
    }
    if (!recording) return recording.status();
    s.recording = std::move(*recording);
    // Analysed from the stored samples: the raw stream they were decoded
    // from must still vouch for them (a damaged one is said first).
    if (s.damage.empty())
      if (Status raw = reader->checkRawStream(); !raw.isOk()) s.rawDamage = damageOf(raw.message(), path);
  }
  if (options.rawBytes && s.rawBytes.empty()) {
    FOG_ASSIGN_OR_RETURN(s.rawBytes, reader->rawBytes());
  }
  FOG_ASSIGN_OR_RETURN(s.stored, reader->results());
  s.results = recordsOf(s.stored, s.info);
  return s;
}

}  // namespace

OpenOptions OpenOptions::session() {
  OpenOptions o;
  o.sessionOnly = true;
  return o;
}

OpenOptions OpenOptions::sessionStream() {
  OpenOptions o = session();
  o.rawBytes = true;
  o.decode = false;  // a replay decodes the bytes as they are fed
  return o;
}

OpenOptions OpenOptions::sessionRecords() {
  OpenOptions o = session();
  o.decode = false;
  return o;
}

OpenOptions OpenOptions::withRawBytes() {
  OpenOptions o;
  o.rawBytes = true;
  return o;
}

std::string OpenedSession::sourceLine(const std::string& what) const {
  if (!isSession) return "raw stream " + toValidUtf8(path);  // a file name need not be UTF-8
  std::string s = what + " " + toValidUtf8(path);
  if (!info.source.empty()) s += " (" + info.source + ")";
  if (!complete) s += " [incomplete: " + incompleteReason + "]";
  if (!damage.empty()) s += " [damaged session, analysed from the raw stream it holds]";
  if (!rawDamage.empty()) s += " [damaged session: its raw stream fails its checksum]";
  return s;
}

std::string OpenedSession::damageNote() const {
  if (!rawDamage.empty())
    return toValidUtf8(path) + " is a damaged session: its raw board stream, the session's source of truth, is "
           "damaged (" + rawDamage + "); its stored decoded samples are analysed, but nothing vouches for them. "
           "Restore the file from a backup";
  if (damage.empty()) return {};
  return toValidUtf8(path) + " is a damaged session (" + damage +
         "); analysed from the raw board stream it holds, which is intact (every chunk passes its checksum) and is "
         "the session's source of truth. Restore the file from a backup to have its decoded samples back";
}

Result<OpenedSession> openSessionOrStream(const std::string& path, const OpenOptions& options) {
  // isSqliteFile also holds a session whose header is damaged: the reader
  // refuses it by name rather than the decoder reading its pages.
  if (options.sessionOnly || isSqliteFile(path)) return openSessionFile(path, options);
  FOG_ASSIGN_OR_RETURN(auto stream, readRawStreamFile(path, options.pulseEquivalentDeg > 0.0
                                                                 ? options.pulseEquivalentDeg
                                                                 : options.fallbackPulseEquivalentDeg));
  OpenedSession s;
  s.path = path;
  s.info.bench.pulseEquivalentDeg = 0.0;  // only the stream or the command line can tell
  s.recording = std::move(stream.recording);
  s.rawByteCount = stream.bytes.size();
  // Not kept unless asked: a long stream's bytes beside its analysis would
  // cost the memory budget of docs/reliability.md up to 160 MiB.
  if (options.rawBytes) s.rawBytes = std::move(stream.bytes);
  return s;
}

NewResult analyseAndStore(const OpenedSession& session, const AnalysisSettings& settings, bool store) {
  NewResult out;
  out.context.source = session.sourceLine();
  out.context.imuDelayLimitMs = settings.imuDelayLimitMs;
  out.context.coverageK = settings.coverageK;
  if (!session.complete) out.context.incompleteReason = session.incompleteReason;
  out.results = session.results;
  out.report = analysis::analyzeRecording(session.recording, settings.constants);
  if (!store || !session.isSession || !out.report) return out;
  if (session.beingRecorded) {
    // Never compete with the recorder for the write lock.
    // addResult's words, so the GUI shows them translated.
    out.notStored = "session '" + session.path +
                    "' is being recorded right now; analyse it again when the recording has finished";
    return out;
  }
  // The data analysed, by the hash of the raw stream (the source of truth,
  // never changed once committed): the same for every analysis of the
  // session. A damaged stream has none to state ("" reads "not known").
  std::string inputSha256;
  if (auto reader = SessionReader::open(session.path))
    if (auto sha = (*reader)->rawSha256()) inputSha256 = std::move(*sha);
  const AnalysisAudit audit = makeAudit(settings.operatorName, settings.tool.empty() ? settings.producedBy : settings.tool, settings.command, inputSha256);
  out.storeStatus = addResult(session.path,
                              analysisSettingsJson(settings.constants, settings.imuDelayLimitMs, settings.producedBy,
                                                   session.info.imported, &audit, settings.coverageK),
                              analysis::formatReportJson(*out.report, out.context));
  if (!out.storeStatus.isOk()) return out;
  out.stored = true;
  // The records again, the new one among them (its id is the file's).
  auto reader = SessionReader::open(session.path);
  if (!reader) {
    out.storeStatus = reader.status();
    return out;
  }
  auto rows = (*reader)->results();
  if (!rows) {
    out.storeStatus = rows.status();
    return out;
  }
  out.results = recordsOf(*rows, session.info);
  return out;
}

std::string describeResult(const std::vector<StoredResultRecord>& results, const StoredResultRecord& record) {
  std::size_t number = 0;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].id == record.id) number = i + 1;
  return "result " + std::to_string(number) + " of " + std::to_string(results.size()) + ", stored " +
         record.createdUtc + " by " + (record.analysedBy.empty() ? "analysis" : record.analysedBy) + " (fogbench " +
         (record.softwareVersion.empty() ? "version not stated" : record.softwareVersion) + ")";
}

ShownResult showResult(const OpenedSession& session, std::int64_t resultId, const BenchConstants& fallback,
                       double fallbackLimitMs, double fallbackCoverageK) {
  ShownResult shown;
  const StoredResultRecord* chosen = newestUsable(session.results);
  for (const auto& r : session.results)
    if (resultId != 0 && r.id == resultId && r.usable) chosen = &r;
  shown.constants = fallback;
  shown.context.source = session.sourceLine();
  shown.context.imuDelayLimitMs = fallbackLimitMs;
  shown.context.coverageK = fallbackCoverageK;
  if (chosen) {
    shown.record = *chosen;
    shown.constants = chosen->constants;
    shown.context.imuDelayLimitMs = chosen->imuDelayLimitMs;
    shown.context.coverageK = chosen->coverageK;
    for (std::size_t i = 0; i < session.results.size(); ++i)
      if (session.results[i].id == chosen->id) shown.number = static_cast<int>(i) + 1;
    shown.description = describeResult(session.results, *chosen);
  } else if (!session.complete) {
    // No record states the verdict: the data's own incompleteness does.
    shown.context.incompleteReason = session.incompleteReason;
  }
  shown.report = analysis::analyzeRecording(session.recording, shown.constants);
  if (shown.record && shown.report) shown.differences = differencesFromRecord(*shown.record, *shown.report);
  shown.verdict = judgeShown(shown.record ? &*shown.record : nullptr, shown.report ? &*shown.report : nullptr,
                             session.complete, session.incompleteReason, shown.context.imuDelayLimitMs,
                             shown.context.coverageK);
  return shown;
}

}  // namespace fog::session

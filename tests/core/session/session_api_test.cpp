// The session API (session_api.h): one way into a session file or a raw
// stream, re-analyse and store, and the result shown, for the CLI and the GUI.

#include "core/session/session_api.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

using fog::test::ScratchDir;

using fog::test::runSql;

// A finished session of the short run, its decoded samples stored.
std::string simulatedSession(const ScratchDir& dir, const std::string& name, bool complete = true) {
  SessionInfo info;
  info.source = "simulator, seed 3";
  info.plan = fog::test::shortPlan();
  return fog::test::recordedSession(dir, name, info, complete);
}

// The same, opened as every caller opens it.
Result<OpenedSession> openSimulated(const ScratchDir& dir, const std::string& name, bool complete = true) {
  return openSessionOrStream(simulatedSession(dir, name, complete));
}

// Settings as a caller gives them; a board delay other than the default
// tells two results apart.
AnalysisSettings settingsWithLimit(double limitMs, double boardDelayMs = BenchConstants{}.boardDelayMs) {
  AnalysisSettings s;
  s.imuDelayLimitMs = limitMs;
  s.constants.boardDelayMs = boardDelayMs;
  s.producedBy = "session_api_test";
  return s;
}

TEST(SessionApi, OpensASessionWithItsIdentityRecordingAndNoResults) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "s.fbs");
  auto s = openSessionOrStream(path);
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_TRUE(s->isSession);
  EXPECT_EQ(s->info.source, "simulator, seed 3");
  EXPECT_TRUE(s->complete);
  EXPECT_TRUE(s->damage.empty());
  EXPECT_TRUE(s->damageNote().empty());
  EXPECT_FALSE(s->recording.testPoints.empty());
  EXPECT_TRUE(s->rawBytes.empty()) << "a session's bytes are read only when asked for";
  EXPECT_EQ(s->rawByteCount, fog::test::shortRun().bytes.size());
  EXPECT_TRUE(s->results.empty());
  EXPECT_EQ(s->sourceLine(), "session " + path + " (simulator, seed 3)");
}

TEST(SessionApi, ASessionsStreamIsReadUndecodedForAReplay) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "replay.fbs");
  auto s = openSessionOrStream(path, OpenOptions::sessionStream());
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_TRUE(s->rawBytes == fog::test::shortRun().bytes);
  EXPECT_TRUE(s->recording.testPoints.empty()) << "not decoded: the replay decodes as it feeds";
  EXPECT_EQ(s->info.source, "simulator, seed 3");
}

TEST(SessionApi, OpensARawStreamFileWithoutIdentityOrPulseEquivalent) {
  ScratchDir dir;
  const std::string path = dir.file("run.bin");
  const auto& bytes = fog::test::shortRun().bytes;
  fog::test::writeFile(path, bytes);
  auto s = openSessionOrStream(path, OpenOptions::withRawBytes());
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_FALSE(s->isSession);
  EXPECT_EQ(s->rawByteCount, bytes.size());
  EXPECT_EQ(s->info.bench.pulseEquivalentDeg, 0.0) << "only the stream or the command line states it";
  EXPECT_TRUE(s->rawBytes == bytes);
  EXPECT_EQ(s->sourceLine(), "raw stream " + path);
  fog::test::expectSameRecording(s->recording, *protocol::decodeRecording(bytes));
  auto withoutBytes = openSessionOrStream(path);
  ASSERT_TRUE(withoutBytes.isOk());
  EXPECT_TRUE(withoutBytes->rawBytes.empty()) << "kept only when asked for";
  EXPECT_EQ(withoutBytes->rawByteCount, bytes.size());

  auto refused = openSessionOrStream(path, OpenOptions::session());
  ASSERT_FALSE(refused.isOk());
  EXPECT_NE(refused.status().message().find("not a fogbench session"), std::string::npos) << refused.status().message();
}

TEST(SessionApi, ASessionWithADamagedHeaderIsRefusedNeverReadAsARawStream) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "hit.fbs");
  {
    std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
    const char zeros[16] = {};
    f.write(zeros, sizeof zeros);
  }
  auto s = openSessionOrStream(path);
  ASSERT_FALSE(s.isOk()) << "a damaged session was decoded as a raw stream";
  EXPECT_NE(s.status().message().find("SQLite header"), std::string::npos) << s.status().message();
  EXPECT_NE(s.status().message().find("not analysed as a raw stream"), std::string::npos) << s.status().message();
}

TEST(SessionApi, DamagedDecodedSamplesAreReadFromTheIntactRawStreamAndSaySo) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "samples.fbs");
  runSql(path, "UPDATE decoded SET counter_bits = 4000");
  auto reader = SessionReader::open(path);
  ASSERT_TRUE(reader.isOk());
  ASSERT_FALSE((*reader)->recording().isOk()) << "the reader itself still refuses the damaged samples";
  reader->reset();

  auto s = openSessionOrStream(path);
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_NE(s->damage.find("decoded samples are damaged"), std::string::npos) << s->damage;
  const std::string note = s->damageNote();
  EXPECT_EQ(note.rfind(path + " is a damaged session (", 0), 0u) << note;
  EXPECT_NE(note.find("analysed from the raw board stream it holds"), std::string::npos) << note;
  EXPECT_NE(s->sourceLine().find("[damaged session, analysed from the raw stream it holds]"), std::string::npos);
  // The same recording as the stream gives.
  const auto fromStream = protocol::decodeRecording(fog::test::shortRun().bytes);
  fog::test::expectSameRecording(s->recording, *fromStream);
}

TEST(SessionApi, ADamagedRawStreamChunkIsNotPapedOver) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "both.fbs");
  runSql(path, "UPDATE decoded SET counter_bits = 4000; UPDATE raw_chunk SET data_fnv1a = data_fnv1a + 1 WHERE seq = 0");
  auto s = openSessionOrStream(path);
  ASSERT_FALSE(s.isOk()) << "both copies damaged: nothing to analyse";
  EXPECT_NE(s.status().message().find("decoded samples are damaged"), std::string::npos) << s.status().message();
}

TEST(SessionApi, ADamagedRawStreamUnderIntactSamplesIsSaidFirst) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "raw.fbs");
  runSql(path, "UPDATE raw_chunk SET data_fnv1a = data_fnv1a + 1 WHERE seq = 0");
  auto s = openSessionOrStream(path);
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_TRUE(s->damage.empty());
  EXPECT_NE(s->rawDamage.find("raw stream chunk 0"), std::string::npos) << s->rawDamage;
  const std::string note = s->damageNote();
  EXPECT_EQ(note.rfind(path + " is a damaged session: its raw board stream", 0), 0u) << note;
  EXPECT_NE(note.find("nothing vouches for them"), std::string::npos) << note;
  EXPECT_NE(s->sourceLine().find("[damaged session: its raw stream fails its checksum]"), std::string::npos);
  // An intact one says nothing.
  auto clean = openSessionOrStream(simulatedSession(dir, "clean.fbs"));
  ASSERT_TRUE(clean.isOk());
  EXPECT_TRUE(clean->rawDamage.empty());
  EXPECT_TRUE(clean->damageNote().empty());
}

TEST(SessionApi, TheShownResultCarriesTheVerdictShown) {
  ScratchDir dir;
  auto s = openSimulated(dir, "shown.fbs");
  ASSERT_TRUE(s.isOk());
  // Nothing stored: judged now with the fallback limit, not stored.
  auto none = showResult(*s, 0, BenchConstants{}, 0.8);
  EXPECT_FALSE(none.verdict.stored);
  ASSERT_TRUE(none.report.isOk());
  EXPECT_EQ(none.verdict.points.size(), none.report->points.size());
  // A stored result with a tight limit: its FAIL is shown whatever the fallback.
  auto stored = analyseAndStore(*s, settingsWithLimit(0.01));
  ASSERT_TRUE(stored.stored) << stored.storeStatus.message();
  auto reopened = openSessionOrStream(s->path);
  ASSERT_TRUE(reopened.isOk());
  auto shown = showResult(*reopened, 0, BenchConstants{}, 100.0);
  EXPECT_TRUE(shown.verdict.stored);
  EXPECT_EQ(shown.verdict.verdict, ShownVerdictKind::kFail);
  EXPECT_DOUBLE_EQ(shown.verdict.limitMs, 0.01);
}

TEST(SessionApi, AnalyseAndStoreAddsTheResultWithItsSettings) {
  ScratchDir dir;
  auto s = openSimulated(dir, "store.fbs");
  ASSERT_TRUE(s.isOk()) << s.status().message();
  const std::string path = s->path;
  auto settings = settingsWithLimit(0.6);
  settings.constants.gyroSign = {1, 1, 1};
  const auto result = analyseAndStore(*s, settings);
  ASSERT_TRUE(result.report.isOk()) << result.report.status().message();
  ASSERT_TRUE(result.storeStatus.isOk()) << result.storeStatus.message();
  EXPECT_TRUE(result.stored);
  EXPECT_TRUE(result.notStored.empty());
  EXPECT_EQ(result.context.imuDelayLimitMs, 0.6);
  EXPECT_EQ(result.context.source, s->sourceLine());
  ASSERT_EQ(result.results.size(), 1u);
  const auto& r = result.results.front();
  EXPECT_TRUE(r.usable) << r.problem;
  EXPECT_EQ(r.analysedBy, "session_api_test");
  EXPECT_EQ(r.imuDelayLimitMs, 0.6);
  EXPECT_TRUE(r.limitStated);

  // Read back: the session holds it, and it is the result shown.
  auto again = openSessionOrStream(path);
  ASSERT_TRUE(again.isOk());
  ASSERT_EQ(again->results.size(), 1u);
  const auto shown = showResult(*again, 0, {}, 0.8);
  ASSERT_TRUE(shown.record.has_value());
  EXPECT_EQ(shown.record->id, r.id);
  EXPECT_EQ(shown.number, 1);
  EXPECT_EQ(shown.context.imuDelayLimitMs, 0.6) << "the record's limit, not the fallback";
  EXPECT_TRUE(shown.differences.empty());
  EXPECT_EQ(shown.description.rfind("result 1 of 1, stored ", 0), 0u) << shown.description;
  EXPECT_NE(shown.description.find("by session_api_test"), std::string::npos) << shown.description;
}

TEST(SessionApi, NotAskedToStoreOrARawStreamStoresNothing) {
  ScratchDir dir;
  auto s = openSimulated(dir, "nostore.fbs");
  ASSERT_TRUE(s.isOk()) << s.status().message();
  const std::string path = s->path;
  const auto result = analyseAndStore(*s, settingsWithLimit(0.8), false);
  ASSERT_TRUE(result.report.isOk());
  EXPECT_FALSE(result.stored);
  EXPECT_TRUE(result.results.empty());
  auto reread = openSessionOrStream(path);
  ASSERT_TRUE(reread.isOk());
  EXPECT_TRUE(reread->results.empty());
}

TEST(SessionApi, AnIncompleteSessionStaysIncompleteInItsNewResult) {
  ScratchDir dir;
  auto s = openSimulated(dir, "stopped.fbs", false);
  ASSERT_TRUE(s.isOk()) << s.status().message();
  const std::string path = s->path;
  EXPECT_FALSE(s->complete);
  EXPECT_NE(s->sourceLine().find("[incomplete: stopped by the operator]"), std::string::npos) << s->sourceLine();
  const auto result = analyseAndStore(*s, settingsWithLimit(0.8));
  ASSERT_TRUE(result.stored) << result.storeStatus.message();
  EXPECT_EQ(result.context.incompleteReason, "stopped by the operator");
  ASSERT_EQ(result.results.size(), 1u);
  EXPECT_EQ(result.results.front().verdict, "incomplete");

  // Shown without a record: the session's incompleteness judges.
  const auto none = showResult(*s, 0, {}, 0.7);
  EXPECT_FALSE(none.record.has_value());
  EXPECT_EQ(none.number, 0);
  EXPECT_EQ(none.context.incompleteReason, "stopped by the operator");
  EXPECT_EQ(none.context.imuDelayLimitMs, 0.7);
  EXPECT_TRUE(none.description.empty());
}

TEST(SessionApi, ShowResultTakesTheAskedForRecordAndItsConstants) {
  ScratchDir dir;
  auto s = openSimulated(dir, "two.fbs");
  ASSERT_TRUE(s.isOk()) << s.status().message();
  const std::string path = s->path;
  ASSERT_TRUE(analyseAndStore(*s, settingsWithLimit(0.8, 0.25)).stored);
  ASSERT_TRUE(analyseAndStore(*s, settingsWithLimit(0.9, 0.30)).stored);
  auto both = openSessionOrStream(path);
  ASSERT_TRUE(both.isOk());
  ASSERT_EQ(both->results.size(), 2u);

  const auto newest = showResult(*both, 0, {}, 0.8);
  ASSERT_TRUE(newest.record);
  EXPECT_EQ(newest.number, 2);
  EXPECT_DOUBLE_EQ(newest.constants.boardDelayMs, 0.30);
  EXPECT_EQ(newest.context.imuDelayLimitMs, 0.9);

  const auto older = showResult(*both, both->results.front().id, {}, 0.8);
  ASSERT_TRUE(older.record);
  EXPECT_EQ(older.number, 1);
  EXPECT_DOUBLE_EQ(older.constants.boardDelayMs, 0.25);
  ASSERT_TRUE(older.report.isOk());
  EXPECT_DOUBLE_EQ(older.report->constants.boardDelayMs, 0.25) << "re-analysed with the record's constants";
  EXPECT_EQ(describeResult(both->results, *older.record), older.description);
}

// The SHA-256 of `bytes` as coreutils' sha256sum prints it: computed outside
// fogbench, so the audit's hash is checked against an independent one.
std::string sha256sumOf(const ScratchDir& dir, const std::vector<std::uint8_t>& bytes) {
  const std::string path = dir.file("stream.bin");
  fog::test::writeFile(path, bytes);
  std::FILE* p = ::popen(("sha256sum '" + path + "'").c_str(), "r");
  if (!p) return "sha256sum did not run";
  char out[65] = {};
  const std::size_t n = std::fread(out, 1, 64, p);
  ::pclose(p);
  return std::string(out, n);
}

TEST(SessionApi, EveryStoredAnalysisCarriesItsAuditEntryWithTheSameInputHash) {
  ScratchDir dir;
  auto s = openSimulated(dir, "audit.fbs");
  ASSERT_TRUE(s.isOk()) << s.status().message();
  auto first = settingsWithLimit(0.8, 0.25);
  first.producedBy = "fogbench-cli analyze";
  first.operatorName = "Wang Fang";
  first.command = "fogbench-cli analyze audit.fbs --board-delay-ms 0.25";
  ASSERT_TRUE(analyseAndStore(*s, first).stored);
  auto second = settingsWithLimit(0.8, 0.31);
  second.producedBy = "fogbench GUI";
  second.tool = "fogbench GUI Results";
  second.command = "Results view";  // no operator named: the login name
  const auto result = analyseAndStore(*s, second);
  ASSERT_TRUE(result.stored) << result.storeStatus.message();
  ASSERT_EQ(result.results.size(), 2u);

  const std::string expected = sha256sumOf(dir, fog::test::shortRun().bytes);
  ASSERT_EQ(expected.size(), 64u) << expected;
  const auto& a = result.results[0];
  const auto& b = result.results[1];
  ASSERT_TRUE(a.audit && b.audit);
  EXPECT_EQ(a.audit->who, "Wang Fang");
  EXPECT_EQ(a.audit->whoSource, "operator");
  EXPECT_EQ(a.audit->tool, "fogbench-cli analyze");
  EXPECT_EQ(a.audit->command, first.command);
  EXPECT_DOUBLE_EQ(a.constants.boardDelayMs, 0.25);
  EXPECT_EQ(b.audit->who, loginName());
  EXPECT_FALSE(b.audit->who.empty());
  EXPECT_EQ(b.audit->whoSource, "login");
  EXPECT_EQ(b.audit->tool, "fogbench GUI Results");
  EXPECT_EQ(b.analysedBy, "fogbench GUI");  // what analysed_by said before the trail, unchanged
  EXPECT_DOUBLE_EQ(b.constants.boardDelayMs, 0.31);
  // Both analysed the same data: the raw stream's hash, as sha256sum gives it.
  EXPECT_EQ(a.audit->inputSha256, expected);
  EXPECT_EQ(b.audit->inputSha256, expected);

  // The trail: one line each, in order, with who, tool, constants, hash and verdict.
  const auto lines = auditTrailLines(result.results);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("#1 ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("by Wang Fang (operator) fogbench-cli analyze [" + first.command + "]"), std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("board 0.250 ± "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("input " + expected.substr(0, 12)), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("(login) fogbench GUI Results [Results view]"), std::string::npos) << lines[1];
  EXPECT_NE(lines[1].find("board 0.310 ± "), std::string::npos) << lines[1];
  std::string verdict = a.verdict;
  for (auto& c : verdict) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  ASSERT_FALSE(verdict.empty());
  EXPECT_EQ(lines[0].substr(lines[0].size() - verdict.size()), verdict) << lines[0];
}

TEST(SessionApi, TheRawStreamHashIsSha256sums) {
  ScratchDir dir;
  const auto path = simulatedSession(dir, "hash.fbs");
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk());
  auto sha = (*r)->rawSha256();
  ASSERT_TRUE(sha.isOk()) << sha.status().message();
  EXPECT_EQ(*sha, sha256sumOf(dir, fog::test::shortRun().bytes));
}

}  // namespace
}  // namespace fog::session

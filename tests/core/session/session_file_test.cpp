// Session files: round trip, results, read-only review, and every kind of
// wrong file.

#include "core/session/session_file.h"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "core/analysis/delay_analysis.h"
#include "core/protocol/recording_builder.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

using fog::test::ScratchDir;
namespace fs = std::filesystem;

SessionInfo fullInfo() {
  SessionInfo info;
  info.operatorName = "A. Müller";
  info.imuModel = "FOG-IMU 9000";
  info.imuSerial = "SN-0042";
  info.source = "simulator, seed 3";
  info.softwareVersion = "9.8.7";
  info.createdUtc = "2026-11-22T02:45:00Z";
  info.notes = "line one\nline two, with 'quotes' and \"doubles\"";
  info.bench.tableReadDelayMs = 0.051;
  info.bench.tableReadDelayStdMs = 0.002;
  info.bench.boardDelayMs = 0.281;
  info.bench.boardDelayStdMs = 0.003;
  info.bench.latitudeDeg = 47.5;
  info.bench.pulseEquivalentDeg = 4.5e-5;
  info.bench.counterHz = 12e6;
  info.bench.counterBits = 24;
  info.plan = fog::test::shortPlan();
  return info;
}

// Writes the short run as a live recorder would: raw bytes in small chunks,
// then the decoded samples, then finish.
std::string writeSession(const ScratchDir& dir, const std::string& name, bool storeDecoded = true) {
  const std::string path = dir.file(name);
  auto w = SessionWriter::create(path, fullInfo());
  EXPECT_TRUE(w.isOk()) << w.status().message();
  if (!w) return path;
  const auto& bytes = fog::test::shortRun().bytes;
  for (std::size_t at = 0; at < bytes.size(); at += 997)
    EXPECT_TRUE((*w)->appendRaw(bytes.data() + at, std::min<std::size_t>(997, bytes.size() - at)).isOk());
  if (storeDecoded) {
    auto rec = protocol::decodeRecording(bytes);
    EXPECT_TRUE(rec.isOk());
    EXPECT_TRUE((*w)->storeRecording(*rec).isOk());
  }
  EXPECT_TRUE((*w)->finish(true, "").isOk());
  return path;
}

TEST(SessionFile, RoundTripKeepsMetadataRawBytesAndSamplesExactly) {
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  const auto& in = fullInfo();
  const auto& got = (*r)->info();
  EXPECT_EQ(got.operatorName, in.operatorName);
  EXPECT_EQ(got.imuModel, in.imuModel);
  EXPECT_EQ(got.imuSerial, in.imuSerial);
  EXPECT_EQ(got.source, in.source);
  EXPECT_EQ(got.softwareVersion, in.softwareVersion);
  EXPECT_EQ(got.createdUtc, in.createdUtc);
  EXPECT_EQ(got.notes, in.notes);
  EXPECT_EQ(got.bench.tableReadDelayMs, in.bench.tableReadDelayMs);
  EXPECT_EQ(got.bench.tableReadDelayStdMs, in.bench.tableReadDelayStdMs);
  EXPECT_EQ(got.bench.boardDelayMs, in.bench.boardDelayMs);
  EXPECT_EQ(got.bench.boardDelayStdMs, in.bench.boardDelayStdMs);
  EXPECT_EQ(got.bench.latitudeDeg, in.bench.latitudeDeg);
  EXPECT_EQ(got.bench.pulseEquivalentDeg, in.bench.pulseEquivalentDeg);
  EXPECT_EQ(got.bench.counterHz, in.bench.counterHz);
  EXPECT_EQ(got.bench.counterBits, in.bench.counterBits);
  EXPECT_EQ(testPlanToJson(got.plan), testPlanToJson(in.plan));
  EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);
  EXPECT_TRUE((*r)->complete());
  EXPECT_EQ((*r)->incompleteReason(), "");

  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();
  EXPECT_TRUE(*raw == fog::test::shortRun().bytes);
  EXPECT_EQ((*r)->rawByteCount(), fog::test::shortRun().bytes.size());
  EXPECT_TRUE((*r)->hasStoredRecording());
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk()) << rec.status().message();
  fog::test::expectSameRecording(*rec, *protocol::decodeRecording(fog::test::shortRun().bytes));
  // A finished session is one self-contained file.
  EXPECT_FALSE(fs::exists(path + "-wal"));
  EXPECT_FALSE(fs::exists(path + "-shm"));
}

// The IMU frame is a bench constant: stored with the session, read back.
TEST(SessionFile, TheStatedImuFrameRoundTrips) {
  ScratchDir dir;
  for (const char* text : {"", "NED", "ENU", "FRD:-30", "RFU:12.5", "RFU"}) {
    SessionInfo info = fullInfo();
    info.bench.imuFrame = *imuFrameFromText(text);
    const auto path = dir.file(std::string("frame") + text + ".fbs");
    {
      auto w = SessionWriter::create(path, info);
      ASSERT_TRUE(w.isOk()) << w.status().message();
      ASSERT_TRUE((*w)->finish(true, "").isOk());
    }
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->info().bench.imuFrame, info.bench.imuFrame) << text;
    EXPECT_EQ(imuFrameToText((*r)->info().bench.imuFrame), text);
  }
}

// A frame whose text would not read back (a heading beyond +-360, made in
// code) is refused before a file exists: recorded, it made the session
// unreadable.
TEST(SessionFile, AFrameThatWouldNotReadBackIsRefusedBeforeAnythingIsWritten) {
  ScratchDir dir;
  SessionInfo info = fullInfo();
  info.bench.imuFrame.convention = ImuFrame::Convention::kForwardRightDown;
  info.bench.imuFrame.forwardHeadingDeg = -360.5;
  const auto path = dir.file("bad-frame.fbs");
  auto w = SessionWriter::create(path, info);
  ASSERT_FALSE(w.isOk());
  EXPECT_NE(w.status().message().find("IMU frame \"FRD:-360.5\" cannot be stored"), std::string::npos)
      << w.status().message();
  EXPECT_FALSE(fs::exists(path));
}

// The gyro signs are bench constants: stored with the session, read back.
TEST(SessionFile, TheGyroSignsRoundTripWithTheBenchConstants) {
  ScratchDir dir;
  SessionInfo info = fullInfo();
  info.bench.gyroSign = {-1, 1, -1};
  const auto path = dir.file("signs.fbs");
  {
    auto w = SessionWriter::create(path, info);
    ASSERT_TRUE(w.isOk()) << w.status().message();
    ASSERT_TRUE((*w)->finish(true, "").isOk());
  }
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->info().bench.gyroSign, (std::array<int, kAxisCount>{-1, 1, -1}));
  // The metadata checksum covers them: one flipped sign is damage, not a new sign.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE session SET gyro_sign_y = -1", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  auto damaged = SessionReader::open(path);
  ASSERT_FALSE(damaged.isOk());
  EXPECT_NE(damaged.status().message().find("fails its checksum"), std::string::npos) << damaged.status().message();
}

// Sessions stored before the builder resolved the pulse equivalent kept raw
// pulse counts (pulse_equivalent_deg 0) for a stream that did not state it;
// they read in degrees through the session's bench constant, as they were
// analysed, or say what to do when there is none.
TEST(SessionFile, StoredRawPulsesOfAnOlderSessionReadInDegrees) {
  ScratchDir dir;
  Recording pulses = *protocol::decodeRecording(fog::test::shortRun().bytes);
  const double stated = pulses.pulseEquivalentDeg;
  ASSERT_GT(stated, 0.0);
  for (auto& tp : pulses.testPoints)
    for (auto& m : tp.imu)
      for (double& v : m.incrementDeg) v = std::round(v / stated);
  pulses.pulseEquivalentDeg = 0.0;
  auto write = [&](const std::string& name, double benchPulse) {
    SessionInfo info = fullInfo();
    info.bench.pulseEquivalentDeg = benchPulse;
    const auto path = dir.file(name);
    auto w = SessionWriter::create(path, info);
    EXPECT_TRUE(w.isOk());
    EXPECT_TRUE((*w)->storeRecording(pulses).isOk());
    EXPECT_TRUE((*w)->finish(true, "").isOk());
    return path;
  };
  auto r = SessionReader::open(write("old.fbs", 2.5e-5));
  ASSERT_TRUE(r.isOk()) << r.status().message();
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk()) << rec.status().message();
  EXPECT_EQ(rec->pulseEquivalentDeg, 2.5e-5);
  const auto& m = rec->testPoints.at(0).imu.at(10);
  EXPECT_EQ(m.incrementDeg[0], pulses.testPoints.at(0).imu.at(10).incrementDeg[0] * 2.5e-5);
  // Given one (--pulse-equivalent-deg), it stands in for the session's.
  EXPECT_EQ((*r)->recording(1e-4)->pulseEquivalentDeg, 1e-4);

  auto none = SessionReader::open(write("none.fbs", 0.0));
  ASSERT_TRUE(none.isOk());
  auto refused = (*none)->recording();
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(refused.status().message().find("give --pulse-equivalent-deg or set it in the bench constants"),
            std::string::npos);
}

TEST(SessionFile, EmptyMetadataGetsCreationTimeAndSoftwareVersion) {
  ScratchDir dir;
  const auto path = dir.file("b.fbs");
  ASSERT_TRUE(SessionWriter::create(path, SessionInfo{}).isOk());  // destroyed unfinished
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->info().createdUtc.size(), 20u);  // 2026-11-22T02:45:00Z
  EXPECT_EQ((*r)->info().createdUtc.back(), 'Z');
  EXPECT_FALSE((*r)->info().softwareVersion.empty());
  EXPECT_EQ((*r)->rawByteCount(), 0u);
}

TEST(SessionFile, TheTableLogIsKeptInOrderBesideTheRawStream) {
  ScratchDir dir;
  const auto path = dir.file("table.fbs");
  {
    auto w = SessionWriter::create(path, SessionInfo{});
    ASSERT_TRUE(w.isOk()) << w.status().message();
    const std::uint8_t bytes[] = {1, 2, 3};
    ASSERT_TRUE((*w)->appendRaw(bytes, 3).isOk());
    ASSERT_TRUE((*w)->appendTableLog({{0.1, "command", "AXIS:X:SWING 1,3,0"}, {0.2, "reply", "0,\"No error\""}}).isOk());
    EXPECT_EQ((*w)->committedBytes(), 3u);  // the log never runs ahead of the stream
    ASSERT_TRUE((*w)->appendTableLog({{0.3, "status", "X swinging"}}).isOk());
    ASSERT_TRUE((*w)->finish(true, "").isOk());
  }
  ASSERT_TRUE(appendTableLog(path, {{9.0, "step", "table at rest"}}).isOk());
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  auto log = (*r)->tableLog();
  ASSERT_TRUE(log.isOk()) << log.status().message();
  ASSERT_EQ(log->size(), 4u);
  EXPECT_EQ((*log)[0].text, "AXIS:X:SWING 1,3,0");
  EXPECT_EQ((*log)[1].text, "0,\"No error\"");
  EXPECT_EQ((*log)[2].kind, "status");
  EXPECT_EQ((*log)[3].text, "table at rest");
  EXPECT_DOUBLE_EQ((*log)[3].elapsedS, 9.0);
  EXPECT_EQ((*r)->rawByteCount(), 3u);
}

TEST(SessionFile, AnalysisOfTheReopenedSessionIsBitIdentical) {
  ScratchDir dir;
  const auto withSamples = writeSession(dir, "samples.fbs", true);
  const auto rawOnly = writeSession(dir, "raw-only.fbs", false);
  const auto memory = protocol::decodeRecording(fog::test::shortRun().bytes);
  ASSERT_TRUE(memory.isOk());
  const auto expected = analysis::analyzeRecording(*memory, BenchConstants{});
  ASSERT_TRUE(expected.isOk()) << expected.status().message();
  for (const auto& path : {withSamples, rawOnly}) {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->hasStoredRecording(), path == withSamples);
    auto rec = (*r)->recording();
    ASSERT_TRUE(rec.isOk()) << rec.status().message();
    const auto got = analysis::analyzeRecording(*rec, BenchConstants{});
    ASSERT_TRUE(got.isOk()) << got.status().message();
    ASSERT_EQ(got->points.size(), expected->points.size());
    for (std::size_t i = 0; i < got->points.size(); ++i) {
      EXPECT_TRUE(fog::test::sameBits(got->points[i].lagMs, expected->points[i].lagMs)) << path;
      EXPECT_TRUE(fog::test::sameBits(got->points[i].lagStdMs, expected->points[i].lagStdMs)) << path;
      EXPECT_TRUE(fog::test::sameBits(got->points[i].imuDelayMs, expected->points[i].imuDelayMs)) << path;
    }
  }
}

TEST(SessionFile, CreateRefusesToOverwriteAnything) {
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  const auto before = fog::test::readFile(path);
  auto again = SessionWriter::create(path, SessionInfo{});
  ASSERT_FALSE(again.isOk());
  EXPECT_NE(again.status().message().find("already exists"), std::string::npos) << again.status().message();
  EXPECT_TRUE(fog::test::readFile(path) == before);

  const auto text = dir.file("notes.txt");
  fog::test::writeFile(text, {'h', 'i'});
  EXPECT_FALSE(SessionWriter::create(text, SessionInfo{}).isOk());
  EXPECT_EQ(fog::test::readFile(text).size(), 2u);

  // A stale WAL beside a new name would be replayed into the new file.
  fog::test::writeFile(dir.file("c.fbs-wal"), {1, 2, 3});
  auto stale = SessionWriter::create(dir.file("c.fbs"), SessionInfo{});
  ASSERT_FALSE(stale.isOk());
  EXPECT_NE(stale.status().message().find("leftover"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir.file("c.fbs")));

  auto noDir = SessionWriter::create(dir.file("no/such/folder/x.fbs"), SessionInfo{});
  ASSERT_FALSE(noDir.isOk());
  EXPECT_NE(noDir.status().message().find("folder exists"), std::string::npos) << noDir.status().message();
}

TEST(SessionFile, IncompleteAndInterruptedSessionsSaySo) {
  ScratchDir dir;
  const auto a = dir.file("stopped.fbs");
  {
    auto w = SessionWriter::create(a, SessionInfo{});
    ASSERT_TRUE(w.isOk());
    const auto& bytes = fog::test::shortRun().bytes;
    ASSERT_TRUE((*w)->appendRaw(bytes.data(), 5000).isOk());
    ASSERT_TRUE((*w)->finish(false, "port vanished at 12.3 s").isOk());
    EXPECT_FALSE((*w)->appendRaw(bytes.data(), 10).isOk());  // finished: refuses more
  }
  auto r = SessionReader::open(a);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
  EXPECT_EQ((*r)->incompleteReason(), "port vanished at 12.3 s");
  EXPECT_EQ((*r)->rawByteCount(), 5000u);

  const auto b = dir.file("dropped.fbs");
  {
    auto w = SessionWriter::create(b, SessionInfo{});
    ASSERT_TRUE(w.isOk());
    const auto& bytes = fog::test::shortRun().bytes;
    ASSERT_TRUE((*w)->appendRaw(bytes.data(), bytes.size()).isOk());
  }  // destroyed without finish: like a crash, but buffered bytes are committed
  auto rb = SessionReader::open(b);
  ASSERT_TRUE(rb.isOk()) << rb.status().message();
  EXPECT_FALSE((*rb)->complete());
  EXPECT_NE((*rb)->incompleteReason().find("interrupted"), std::string::npos);
  EXPECT_FALSE((*rb)->hasStoredRecording());
  auto raw = (*rb)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  EXPECT_TRUE(*raw == fog::test::shortRun().bytes);
  auto rec = (*rb)->recording();  // decoded from the raw stream
  ASSERT_TRUE(rec.isOk()) << rec.status().message();
  fog::test::expectSameRecording(*rec, *protocol::decodeRecording(fog::test::shortRun().bytes));
}

TEST(SessionFile, RawBytesAreCommittedByTimeAndVisibleToALiveReader) {
  ScratchDir dir;
  const auto path = dir.file("live.fbs");
  auto w = SessionWriter::create(path, SessionInfo{});
  ASSERT_TRUE(w.isOk());
  const auto& bytes = fog::test::shortRun().bytes;
  ASSERT_TRUE((*w)->appendRaw(bytes.data(), 1000).isOk());
  EXPECT_EQ((*w)->committedBytes(), 0u);  // buffered: younger than the commit interval
  std::this_thread::sleep_for(kCommitInterval + std::chrono::milliseconds(20));
  ASSERT_TRUE((*w)->appendRaw(bytes.data() + 1000, 500).isOk());
  EXPECT_EQ((*w)->committedBytes(), 1500u);  // the oldest byte was old enough
  EXPECT_EQ((*w)->commits(), 1u);

  auto r = SessionReader::open(path);  // while the writer still records
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE((*r)->complete());
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), bytes.begin()));
  EXPECT_EQ(raw->size(), 1500u);

  ASSERT_TRUE((*w)->appendRaw(bytes.data() + 1500, 10).isOk());
  ASSERT_TRUE((*w)->flush().isOk());
  EXPECT_EQ((*w)->committedBytes(), 1510u);
}

TEST(SessionFile, ReanalysisAddsResultRowsAndNeverTouchesTheData) {
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  ASSERT_TRUE(addResult(path, R"({"board_delay_ms":0.28})", R"({"lag_ms":0.466})").isOk());
  ASSERT_TRUE(addResult(path, R"({"board_delay_ms":0.30})", R"({"lag_ms":0.467})").isOk());
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk());
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 2u);
  EXPECT_LT((*results)[0].id, (*results)[1].id);
  EXPECT_EQ((*results)[0].settingsJson, R"({"board_delay_ms":0.28})");
  EXPECT_EQ((*results)[1].settingsJson, R"({"board_delay_ms":0.30})");
  EXPECT_EQ((*results)[1].reportJson, R"({"lag_ms":0.467})");
  EXPECT_EQ((*results)[1].createdUtc.size(), 20u);
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  EXPECT_TRUE(*raw == fog::test::shortRun().bytes);
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk());
  fog::test::expectSameRecording(*rec, *protocol::decodeRecording(fog::test::shortRun().bytes));
}

TEST(SessionFile, ReviewIsReadOnly) {
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  ASSERT_TRUE(addResult(path, "{}", "{}").isOk());
  const auto before = fog::test::readFile(path);
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk());
    EXPECT_TRUE((*r)->isReadOnly());
    EXPECT_TRUE((*r)->rawBytes().isOk());
    EXPECT_TRUE((*r)->recording().isOk());
    EXPECT_TRUE((*r)->results().isOk());
    // The reader's connection refuses writes: SQLite reports it read-only.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, "DELETE FROM raw_chunk", nullptr, nullptr, nullptr), SQLITE_READONLY);
    sqlite3_close(db);
  }
  EXPECT_TRUE(fog::test::readFile(path) == before);  // not one byte changed
  EXPECT_FALSE(fs::exists(path + "-journal"));
  EXPECT_FALSE(fs::exists(path + "-wal"));
  // And it opens a file the user may not write (permission bits; root ignores
  // them, so this also holds there).
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_TRUE((*r)->rawBytes().isOk());
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
}

// --- wrong files -----------------------------------------------------------

void expectRefused(const std::string& path, const std::string& needle) {
  auto r = SessionReader::open(path);
  ASSERT_FALSE(r.isOk()) << path << " opened";
  const auto& m = r.status().message();
  EXPECT_NE(m.find(needle), std::string::npos) << m;
  EXPECT_NE(m.find(path), std::string::npos) << "the message names the file: " << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
  const auto before = fs::exists(path) ? fog::test::readFile(path) : std::vector<std::uint8_t>{};
  EXPECT_FALSE(addResult(path, "{}", "{}").isOk());
  if (fs::exists(path)) {
    EXPECT_TRUE(fog::test::readFile(path) == before) << "addResult changed " << path;
  }
}

void makeDb(const std::string& path, const char* sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  EXPECT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

TEST(SessionFileErrors, MissingFile) {
  ScratchDir dir;
  expectRefused(dir.file("nope.fbs"), "no such file");
  EXPECT_FALSE(looksLikeSession(dir.file("nope.fbs")));
  EXPECT_FALSE(fs::exists(dir.file("nope.fbs")));  // addResult did not create it
}

TEST(SessionFileErrors, EmptyFile) {
  ScratchDir dir;
  fog::test::writeFile(dir.file("empty.fbs"), {});
  expectRefused(dir.file("empty.fbs"), "is empty (0 bytes)");
  EXPECT_FALSE(looksLikeSession(dir.file("empty.fbs")));
}

TEST(SessionFileErrors, TextFile) {
  ScratchDir dir;
  const std::string text = "operator,imu\nme,FOG\n";
  fog::test::writeFile(dir.file("notes.fbs"), {text.begin(), text.end()});
  expectRefused(dir.file("notes.fbs"), "not an SQLite database");
  EXPECT_FALSE(looksLikeSession(dir.file("notes.fbs")));
  EXPECT_FALSE(isSqliteFile(dir.file("notes.fbs")));
}

TEST(SessionFileErrors, RandomBytes) {
  ScratchDir dir;
  std::mt19937 rng(5);
  std::vector<std::uint8_t> junk(200000);
  for (auto& b : junk) b = static_cast<std::uint8_t>(rng());
  fog::test::writeFile(dir.file("junk.fbs"), junk);
  expectRefused(dir.file("junk.fbs"), "not an SQLite database");
  // A raw sampling-board stream is not a session either.
  fog::test::writeFile(dir.file("run.bin"), fog::test::shortRun().bytes);
  expectRefused(dir.file("run.bin"), "not an SQLite database");
}

TEST(SessionFileErrors, ForeignSqliteDatabase) {
  ScratchDir dir;
  makeDb(dir.file("other.db"), "CREATE TABLE t(x); INSERT INTO t VALUES (1);");
  expectRefused(dir.file("other.db"), "an SQLite database but not a fogbench session");
  EXPECT_FALSE(looksLikeSession(dir.file("other.db")));
  EXPECT_TRUE(isSqliteFile(dir.file("other.db")));
}

TEST(SessionFileErrors, NewerSchemaSaysUpdateFogbench) {
  ScratchDir dir;
  const auto path = writeSession(dir, "future.fbs");
  makeDb(path, ("PRAGMA user_version = " + std::to_string(kSchemaVersion + 1)).c_str());
  EXPECT_TRUE(looksLikeSession(path));  // it is a session, just not one this build can read
  expectRefused(path, "was written by a newer fogbench (schema " + std::to_string(kSchemaVersion + 1) +
                          "; this one reads up to " + std::to_string(kSchemaVersion) + "): update fogbench");
}

TEST(SessionFileErrors, SessionIdWithoutSchema) {
  ScratchDir dir;
  makeDb(dir.file("half.fbs"), "PRAGMA application_id = 1179600706; CREATE TABLE t(x);");
  expectRefused(dir.file("half.fbs"), "has no session schema");
}

TEST(SessionFileErrors, TruncatedCopyOfARealSession) {
  ScratchDir dir;
  const auto path = writeSession(dir, "full.fbs");
  const auto bytes = fog::test::readFile(path);
  ASSERT_GT(bytes.size(), 100000u);
  fog::test::writeFile(dir.file("half.fbs"), {bytes.begin(), bytes.begin() + static_cast<long>(bytes.size() / 2)});
  expectRefused(dir.file("half.fbs"), "is truncated");
  EXPECT_TRUE(looksLikeSession(dir.file("half.fbs")));  // listed as a (damaged) session, not skipped
  fog::test::writeFile(dir.file("stub.fbs"), {bytes.begin(), bytes.begin() + 60});
  expectRefused(dir.file("stub.fbs"), "not an SQLite database");
}

TEST(SessionFileErrors, DamagedRawBytesFailTheirChecksum) {
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  auto bytes = fog::test::readFile(path);
  // Find a stretch of the raw stream inside the file and flip one byte of it:
  // SQLite's own checks cannot see damage inside a blob.
  const auto& stream = fog::test::shortRun().bytes;
  const auto at = std::search(bytes.begin(), bytes.end(), stream.begin() + 200000, stream.begin() + 200064);
  ASSERT_NE(at, bytes.end());
  *(at + 10) ^= 0x40;
  fog::test::writeFile(path, bytes);
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  auto raw = (*r)->rawBytes();
  ASSERT_FALSE(raw.isOk());
  EXPECT_NE(raw.status().message().find("fails its checksum"), std::string::npos) << raw.status().message();
}

TEST(SessionFileErrors, SmashedPagesNeverCrash) {
  // Overwrite 4 KiB at many places of a real session: whatever SQLite or the
  // checks say, every call returns; and no call may hand back a raw stream
  // that differs from the one recorded.
  ScratchDir dir;
  const auto path = writeSession(dir, "a.fbs");
  const auto good = fog::test::readFile(path);
  std::mt19937 rng(9);
  int detected = 0;
  for (int trial = 0; trial < 12; ++trial) {
    auto bytes = good;
    const std::size_t at = 100 + (static_cast<std::size_t>(rng()) % (bytes.size() - 4200));
    for (std::size_t i = 0; i < 4096; ++i) bytes[at + i] = static_cast<std::uint8_t>(rng());
    const auto copy = dir.file("smashed" + std::to_string(trial) + ".fbs");
    fog::test::writeFile(copy, bytes);
    auto r = SessionReader::open(copy);
    if (!r) {
      ++detected;
      continue;
    }
    auto raw = (*r)->rawBytes();
    if (raw) {
      EXPECT_TRUE(*raw == fog::test::shortRun().bytes) << "damage passed as data at offset " << at;
    } else {
      ++detected;
    }
    (void)(*r)->recording();
    (void)(*r)->results();
  }
  EXPECT_GT(detected, 0);
}

}  // namespace
}  // namespace fog::session

// The fault suite of issue 15: each case asserts that nothing recorded is
// lost and that the message says what happened and what to do.
//  - analysis in a loop while another process records the session;
//  - a session left with its -wal after a crash during a checkpoint or a
//    full disk;
//  - two recorders racing to create one file;
//  - crafted sessions (valid checksums, hostile counts).

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <latch>
#include <sstream>
#include <string>
#include <thread>

#include "core/acquisition/acquisition.h"
#include "core/acquisition/replay_source.h"
#include "full_disk_vfs.h"
#include "core/protocol/decoder.h"
#include "core/protocol/recording_builder.h"
#include "record_helper_stream.h"
#include "core/session/session_file.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

using fog::test::ScratchDir;
namespace fs = std::filesystem;

// The record helper as a child process; its stdout is collected by a thread.
class HelperProcess {
 public:
  HelperProcess(const std::string& path, const std::string& seconds) {
    int fd[2];
    if (::pipe(fd) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(fd[1], STDOUT_FILENO);
      ::dup2(fd[1], STDERR_FILENO);
      ::close(fd[0]);
      ::close(fd[1]);
      ::execl(FOG_RECORD_HELPER, FOG_RECORD_HELPER, path.c_str(), seconds.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fd[1]);
    reader_ = std::thread([this, in = fd[0]] {
      char buf[4096];
      for (ssize_t n; (n = ::read(in, buf, sizeof buf)) > 0;) {
        std::lock_guard<std::mutex> lock(mutex_);
        text_.append(buf, static_cast<std::size_t>(n));
      }
      ::close(in);
    });
  }
  ~HelperProcess() {
    if (pid_ > 0 && !waited_) {
      ::kill(pid_, SIGKILL);
      (void)wait();
    }
  }
  bool started() const { return pid_ > 0; }
  bool running() {
    if (waited_) return false;
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      waited_ = true;
      status_ = status;
      if (reader_.joinable()) reader_.join();
      return false;
    }
    return true;
  }
  int wait() {
    if (!waited_) {
      ::waitpid(pid_, &status_, 0);
      waited_ = true;
    }
    if (reader_.joinable()) reader_.join();
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
  }
  std::string text() {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }

 private:
  pid_t pid_ = -1;
  bool waited_ = false;
  int status_ = 0;
  std::thread reader_;
  std::mutex mutex_;
  std::string text_;
};

// Board time (s) of the last complete frame within the first `size` bytes.
double streamTimeS(const std::vector<std::uint8_t>& stream, std::size_t size) {
  protocol::Decoder d;
  std::vector<protocol::DecodedFrame> frames;
  d.push(std::span<const std::uint8_t>(stream.data(), size), frames);
  if (frames.empty()) return 0.0;
  return static_cast<double>(frames.back().ticks - frames.front().ticks) / 10e6;  // default 10 MHz counter
}

// --- 1. a reader never disturbs the recorder ---------------------------------

TEST(SessionFaults, AnalysisInALoopDuringARecordingLosesNothing) {
  ScratchDir dir;
  const std::string path = dir.file("live.fbs");
  auto expected = model::simulate(fog::test::recordHelperConfig(), fog::test::recordHelperPlan());
  ASSERT_TRUE(expected.isOk());
  const auto& stream = expected->bytes;

  HelperProcess helper(path, "4");
  ASSERT_TRUE(helper.started());
  // What `analyze` does, as often as it can while the helper records: open
  // read-only, read the raw stream (and decode it), store a result.
  int opened = 0, analysed = 0, stored = 0, refused = 0;
  std::string refusal;
  while (helper.running()) {
    if (!fs::exists(path)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    auto r = SessionReader::open(path);
    if (!r) {
      // Only possible before the creating transaction committed.
      const auto& m = r.status().message();
      EXPECT_TRUE(m.find("schema") != std::string::npos || m.find("empty") != std::string::npos) << m;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    ++opened;
    auto raw = (*r)->rawBytes();
    ASSERT_TRUE(raw.isOk()) << raw.status().message();
    ASSERT_LE(raw->size(), stream.size());
    EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin())) << "a live reader saw a wrong prefix";
    if ((*r)->recording().isOk()) ++analysed;
    const bool live = (*r)->beingRecorded();
    if (live) {
      EXPECT_NE((*r)->incompleteReason().find("being recorded"), std::string::npos);
    }
    r->reset();
    auto s = addResult(path, "{}", "{\"loop\":" + std::to_string(opened) + "}");
    if (s.isOk()) {
      ++stored;
    } else {
      // Refusing to store is allowed, but must say so clearly.
      ++refused;
      refusal = s.message();
      EXPECT_NE(s.message().find("not stored"), std::string::npos) << s.message();
    }
  }
  // Like the kill -9 test, the recording must have kept its real-time pace.
  const int rc = helper.wait();
  const auto text = helper.text();
  ASSERT_EQ(rc, 0) << "the recorder failed while being analysed:\n" << text.substr(text.rfind('\n', text.size() - 2) + 1);
  unsigned long long finished = 0;
  const auto at = text.rfind("finished ");
  ASSERT_NE(at, std::string::npos) << text;
  ASSERT_EQ(std::sscanf(text.c_str() + at, "finished %llu", &finished), 1);

  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_TRUE((*r)->complete()) << (*r)->incompleteReason();
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();
  EXPECT_EQ(raw->size(), finished) << "bytes were lost";
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin()));
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  EXPECT_EQ(results->size(), static_cast<std::size_t>(stored));
  // A recorder that was never starved produced ~4 s of stream (not ~0.2 s).
  const double recordedS = streamTimeS(stream, raw->size());
  EXPECT_GT(recordedS, 3.0) << "the recorder was held up";
  // Finished: the result is stored now.
  r->reset();
  EXPECT_TRUE(addResult(path, "{}", "{}").isOk());
  std::printf("[ live analysis ] %d opens, %d analyses, %d results stored, %d refused during a 4-s recording of "
              "%llu bytes (%.2f s of stream); nothing lost%s%s\n",
              opened, analysed, stored, refused, finished, recordedS, refused ? "; refusal: " : "", refusal.c_str());
  EXPECT_GT(opened, 5);
}


// --- 2. a -wal left by a crash during a checkpoint or a full disk ------------

// A recorder's session after kill -9 in the middle of a checkpoint (or a
// checkpoint cut short by a full disk): the main file's header already states
// the new page count, but the file has not grown to it; every page is still
// in the -wal. SQLite reads it all; so must fogbench.
TEST(SessionFaults, ASessionCutShortDuringACheckpointOpensFromItsWal) {
  ScratchDir dir;
  const std::string path = dir.file("recording.fbs");
  const std::string crashed = dir.file("crashed.fbs");
  const auto& bytes = fog::test::shortRun().bytes;
  {
    SessionInfo info;
    info.operatorName = "checkpoint crash";
    auto w = SessionWriter::create(path, info);
    ASSERT_TRUE(w.isOk()) << w.status().message();
    for (std::size_t at = 0; at < bytes.size(); at += 4096)
      ASSERT_TRUE((*w)->appendRaw(bytes.data() + at, std::min<std::size_t>(4096, bytes.size() - at)).isOk());
    ASSERT_TRUE((*w)->flush().isOk());
    // A checkpoint copies the pages into the main file (page 1, with the new
    // page count, first) and leaves the -wal as it is.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "SELECT count(*) FROM raw_chunk", nullptr, nullptr, nullptr), SQLITE_OK);
    int log = 0, done = 0;
    ASSERT_EQ(sqlite3_wal_checkpoint_v2(db, nullptr, SQLITE_CHECKPOINT_PASSIVE, &log, &done), SQLITE_OK);
    EXPECT_GT(done, 0);
    sqlite3_close(db);
    // The files as a kill -9 at this moment leaves them (no -shm: rebuilt).
    fs::copy_file(path, crashed);
    fs::copy_file(path + "-wal", crashed + "-wal");
  }
  // The checkpoint had not finished growing the file.
  const auto full = fs::file_size(crashed);
  fs::resize_file(crashed, full * 6 / 10);

  auto r = SessionReader::open(crashed);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->info().operatorName, "checkpoint crash");
  EXPECT_NE((*r)->incompleteReason().find("interrupted"), std::string::npos);
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();
  EXPECT_TRUE(*raw == bytes) << "stored " << raw->size() << " of " << bytes.size() << " bytes";
  auto rec = (*r)->recording();
  EXPECT_TRUE(rec.isOk()) << rec.status().message();
  r->reset();
  std::printf("[ checkpoint crash ] main file cut to %llu of %llu bytes, -wal %llu bytes: all %zu raw bytes read\n",
              static_cast<unsigned long long>(full * 6 / 10), static_cast<unsigned long long>(full),
              static_cast<unsigned long long>(fs::file_size(crashed + "-wal")), raw->size());
  // Storing a result completes the checkpoint: a whole file again.
  ASSERT_TRUE(addResult(crashed, "{}", "{}").isOk());
  EXPECT_FALSE(fs::exists(crashed + "-wal"));
  auto again = SessionReader::open(crashed);
  ASSERT_TRUE(again.isOk()) << again.status().message();
  auto raw2 = (*again)->rawBytes();
  ASSERT_TRUE(raw2.isOk());
  EXPECT_TRUE(*raw2 == bytes);
}

// A truncated file whose -wal cannot supply the missing pages is still
// refused as truncated.
TEST(SessionFaults, ATruncatedSessionWithAUselessWalIsStillRefused) {
  ScratchDir dir;
  const std::string path = dir.file("a.fbs");
  {
    auto w = SessionWriter::create(path, SessionInfo{});
    ASSERT_TRUE(w.isOk());
    const auto& bytes = fog::test::shortRun().bytes;
    ASSERT_TRUE((*w)->appendRaw(bytes.data(), bytes.size()).isOk());
    ASSERT_TRUE((*w)->finish(true, "").isOk());
  }
  fs::resize_file(path, fs::file_size(path) / 2);
  std::vector<std::uint8_t> junk(5000, 0xA5);
  fog::test::writeFile(path + "-wal", junk);
  auto r = SessionReader::open(path);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("truncated"), std::string::npos) << r.status().message();
}

// --- 3. two recorders racing for one file ------------------------------------

TEST(SessionFaults, TwoRecordersRacingForOneFileNeverHarmTheWinner) {
  ScratchDir dir;
  // The old check-then-create lost the race in a few percent of the rounds.
  constexpr int kRounds = 500;
  const std::vector<std::uint8_t> bytes(fog::test::shortRun().bytes.begin(), fog::test::shortRun().bytes.begin() + 4000);
  int bothRefused = 0;
  for (int round = 0; round < kRounds; ++round) {
    const std::string path = dir.file("race" + std::to_string(round) + ".fbs");
    std::latch go(2);
    Result<std::unique_ptr<SessionWriter>> made[2] = {ioError("not run"), ioError("not run")};
    std::thread racers[2];
    for (int k = 0; k < 2; ++k)
      racers[k] = std::thread([&, k] {
        SessionInfo info;
        info.operatorName = k == 0 ? "first" : "second";
        go.arrive_and_wait();
        made[k] = SessionWriter::create(path, info);
      });
    for (auto& t : racers) t.join();
    const int winners = made[0].isOk() + made[1].isOk();
    ASSERT_LE(winners, 1) << "two recorders own one file";
    if (winners == 0) {  // allowed only with a clear reason each; nothing may remain half-made
      ++bothRefused;
      continue;
    }
    const int w = made[0].isOk() ? 0 : 1;
    const auto& loser = made[1 - w].status().message();
    EXPECT_NE(loser.find("already exists"), std::string::npos) << loser;
    auto& writer = *made[w];
    ASSERT_TRUE(writer->appendRaw(bytes.data(), bytes.size()).isOk());
    ASSERT_TRUE(writer->finish(true, "").isOk()) << "round " << round;
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << "round " << round << ": the winner's session is gone: " << r.status().message();
    EXPECT_EQ((*r)->info().operatorName, w == 0 ? "first" : "second");
    auto raw = (*r)->rawBytes();
    ASSERT_TRUE(raw.isOk());
    EXPECT_TRUE(*raw == bytes);
  }
  EXPECT_LT(bothRefused, kRounds);
}

// --- 4. crafted sessions: hostile counts with valid checksums ----------------

// A complete session with stored samples; `sql` then edits it as an attacker
// would (SQLite and the blob checksums stay valid).
// What turns a session of this schema into one written before schema 6:
// schema 6 added the lot and the bench id.
constexpr const char* kDropIdentity = " ALTER TABLE session DROP COLUMN lot; ALTER TABLE session DROP COLUMN bench_id;";
// ... and before schema 5, which added the stated IMU frame.
constexpr const char* kDropImuFrame =
    " ALTER TABLE session DROP COLUMN lot; ALTER TABLE session DROP COLUMN bench_id;"
    " ALTER TABLE session DROP COLUMN imu_frame;";
// ... and before schema 4, which added the gyro signs and the import settings.
constexpr const char* kDropGyroSigns =
    " ALTER TABLE session DROP COLUMN lot; ALTER TABLE session DROP COLUMN bench_id;"
    " ALTER TABLE session DROP COLUMN imu_frame;"
    " ALTER TABLE session DROP COLUMN gyro_sign_x; ALTER TABLE session DROP COLUMN gyro_sign_y;"
    " ALTER TABLE session DROP COLUMN gyro_sign_z; ALTER TABLE session DROP COLUMN import_json;";

std::string craftedSession(const ScratchDir& dir, const std::string& name, const std::string& sql) {
  const std::string path = fog::test::recordedSession(dir, name);
  fog::test::runSql(path, sql);
  return path;
}

void expectRecordingRefused(const std::string& path, const std::string& needle) {
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  auto rec = (*r)->recording();  // must return, not crash or throw
  ASSERT_FALSE(rec.isOk()) << path << " was read as a recording";
  EXPECT_NE(rec.status().message().find(needle), std::string::npos) << rec.status().message();
  EXPECT_NE(rec.status().message().find("raw stream"), std::string::npos)
      << "the message says what to do: " << rec.status().message();
}

TEST(SessionFaults, ABlockSampleCountThatWrapsTheSizeCheckIsRefused) {
  ScratchDir dir;
  // n * 32 == 2^64 + 65536 * 32: the product wraps to the blob's real size.
  const std::string n = std::to_string((std::uint64_t{1} << 59) + 65536);
  expectRecordingRefused(
      craftedSession(dir, "wrap.fbs", "UPDATE table_block SET samples = " + n + " WHERE block = 0"),
      "block");
}

TEST(SessionFaults, AHugeOrNegativeBlockCountIsRefused) {
  ScratchDir dir;
  expectRecordingRefused(craftedSession(dir, "neg.fbs", "UPDATE imu_block SET samples = -1"), "block");
  expectRecordingRefused(craftedSession(dir, "big.fbs", "UPDATE imu_block SET samples = 9e15"), "block");
}

TEST(SessionFaults, AnAbsurdTestPointSampleCountIsRefusedWithoutAllocating) {
  ScratchDir dir;
  expectRecordingRefused(craftedSession(dir, "table.fbs", "UPDATE test_point SET table_samples = 2000000000"),
                         "sample count");
  expectRecordingRefused(craftedSession(dir, "imu.fbs", "UPDATE test_point SET imu_samples = 9000000000000000000"),
                         "sample count");
}

TEST(SessionFaults, AnAbsurdPointIndexIsRefused) {
  ScratchDir dir;
  expectRecordingRefused(craftedSession(dir, "index.fbs", "UPDATE test_point SET point_index = 1000000000000"),
                         "index");
  expectRecordingRefused(craftedSession(dir, "neg.fbs", "UPDATE test_point SET point_index = -5"), "index");
}

TEST(SessionFaults, ImpossibleRecordingConstantsAreRefused) {
  ScratchDir dir;
  expectRecordingRefused(craftedSession(dir, "bits.fbs", "UPDATE decoded SET counter_bits = 4000"), "counter");
  expectRecordingRefused(craftedSession(dir, "hz.fbs", "UPDATE decoded SET counter_hz = -1"), "counter");
  expectRecordingRefused(craftedSession(dir, "axis.fbs", "UPDATE test_point SET nominal_frequency_hz = 1e400"),
                         "nominal");
}

// --- 5. text that is not UTF-8 ------------------------------------------------

TEST(SessionFaults, Latin1TextInASessionIsReadAsUtf8) {
  ScratchDir dir;
  // As another tool might have written it: Latin-1 bytes in TEXT columns
  // (and no checksums: NULL).
  const auto path = craftedSession(dir, "latin1.fbs",
                                   "UPDATE session SET operator = CAST(X'4DFC6C6C6572' AS TEXT),"
                                   " notes = CAST(X'636166E9' AS TEXT), metadata_fnv1a = NULL;"
                                   "INSERT INTO result (created_utc, settings_json, report_json) VALUES"
                                   " ('2026-01-01T00:00:00Z', '{}', CAST(X'7B2261223A2266FC227D' AS TEXT));");
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->info().operatorName, "Müller");
  EXPECT_EQ((*r)->info().notes, "café");
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 1u);
  EXPECT_EQ(results->front().reportJson, "{\"a\":\"fü\"}");
  // And what a recorder is given is stored as UTF-8.
  SessionInfo info;
  info.operatorName = "M\xFCller";
  const auto made = dir.file("made.fbs");
  {
    auto w = SessionWriter::create(made, info);
    ASSERT_TRUE(w.isOk());
    ASSERT_TRUE((*w)->finish(false, "port \xE9teint").isOk());
  }
  auto m = SessionReader::open(made);
  ASSERT_TRUE(m.isOk());
  EXPECT_EQ((*m)->info().operatorName, "Müller");
  EXPECT_EQ((*m)->incompleteReason(), "port éteint");
}

// --- 6. a session whose SQLite header is damaged ------------------------------

TEST(SessionFaults, ASessionWithADamagedHeaderIsNeverTakenForARawStream) {
  ScratchDir dir;
  const auto path = craftedSession(dir, "hit.fbs", "SELECT 1");
  auto bytes = fog::test::readFile(path);
  std::fill(bytes.begin(), bytes.begin() + 16, std::uint8_t{0});
  fog::test::writeFile(path, bytes);
  EXPECT_TRUE(isSqliteFile(path)) << "a caller would decode it as a raw stream";
  EXPECT_TRUE(looksLikeSession(path)) << "a folder listing would skip it";
  auto r = SessionReader::open(path);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("header"), std::string::npos) << r.status().message();
  EXPECT_NE(r.status().message().find("not analysed as a raw stream"), std::string::npos);
  // A raw stream is still a raw stream.
  const auto raw = dir.file("run.bin");
  fog::test::writeFile(raw, fog::test::shortRun().bytes);
  EXPECT_FALSE(isSqliteFile(raw));
}

// --- 7. a full disk during a recording ----------------------------------------

TEST(SessionFaults, AFullDiskDuringARecordingKeepsWhatWasWrittenAndAnalyses) {
  ScratchDir dir;
  const std::string path = dir.file("full.fbs");
  const auto& stream = fog::test::shortRun().bytes;
  fog::test::FullDiskVfs::install();
  // At 10x real time: commits every 200 ms, as a live recording makes them.
  acquisition::ReplaySource source(stream, 10.0, "replay of the short run");
  acquisition::AcquisitionOptions options;
  options.sessionPath = path;
  options.info.operatorName = "full disk";
  options.info.plan = fog::test::shortPlan();
  // Room for the new session and about 60 % of the stream.
  fog::test::FullDiskVfs::arm(static_cast<long long>(stream.size()) * 6 / 10 + 60000);
  auto run = acquisition::acquire(source, options, nullptr);
  fog::test::FullDiskVfs::disarm();
  ASSERT_TRUE(run.isOk()) << "a full disk ended the run with an error: " << run.status().message();
  EXPECT_GT(fog::test::FullDiskVfs::refusedWrites(), 0) << "the disk never filled up";
  EXPECT_FALSE(run->complete);
  EXPECT_NE(run->incompleteReason.find("could not be written"), std::string::npos) << run->incompleteReason;
  EXPECT_NE(run->incompleteReason.find("disk is full"), std::string::npos) << run->incompleteReason;
  EXPECT_EQ(run->sessionPath, path);
  EXPECT_GT(run->sessionBytes, 0u);
  EXPECT_LT(run->sessionBytes, run->bytesReceived);
  // Everything received was analysed, like after a vanished port.
  ASSERT_TRUE(run->report.isOk()) << run->report.status().message();
  // What the run prints says it is incomplete, and why: its verdict is never
  // a bare PASS (the full disk used to be told on standard error only).
  const auto context = acquisition::reportContextOf(*run, options);
  const std::string text = analysis::formatReportText(*run->report, context);
  EXPECT_NE(text.find("verdict: INCOMPLETE (run stopped after "), std::string::npos) << text;
  EXPECT_NE(text.find(" s of 11.0 s: the session file could not be written"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nverdict: PASS"), std::string::npos) << text;
  const std::string json = analysis::formatReportJson(*run->report, context);
  EXPECT_NE(json.find("\"verdict\": \"incomplete\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"incomplete_reason\": \"the session file could not be written"), std::string::npos);

  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE((*r)->complete());
  EXPECT_FALSE((*r)->incompleteReason().empty());
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();
  EXPECT_EQ(raw->size(), run->sessionBytes) << "committed bytes were lost";
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin()));
  std::printf("[ full disk ] run stopped after %llu of %zu bytes; the session keeps %zu bytes; reason: %s\n",
              static_cast<unsigned long long>(run->bytesReceived), stream.size(), raw->size(),
              (*r)->incompleteReason().c_str());
}

// --- 8. metadata and stored results carry checksums ---------------------------

TEST(SessionFaults, AFlippedBitInTheMetadataFailsItsChecksum) {
  ScratchDir dir;
  // One bit of the table read delay (0.05 ms -> its neighbour in binary64),
  // as a damaged disk sector would leave it: SQLite notices nothing.
  const auto path = craftedSession(dir, "bit.fbs",
                                   "UPDATE session SET table_read_delay_ms ="
                                   " (SELECT table_read_delay_ms FROM session) * 1.0000000000000002");
  auto r = SessionReader::open(path);
  ASSERT_FALSE(r.isOk()) << "damaged bench constants were read as good";
  EXPECT_NE(r.status().message().find("fails its checksum"), std::string::npos) << r.status().message();
  EXPECT_NE(r.status().message().find("restore it from a backup"), std::string::npos);
  const auto plan = craftedSession(dir, "state.fbs", "UPDATE session SET state = 'recording'");
  EXPECT_FALSE(SessionReader::open(plan).isOk());
}

TEST(SessionFaults, ADamagedStoredResultIsMarkedNotTrusted) {
  ScratchDir dir;
  const auto path = craftedSession(dir, "result.fbs", "SELECT 1");
  ASSERT_TRUE(addResult(path, R"({"board_delay_ms":0.28})", R"({"lag_ms":0.466})").isOk());
  ASSERT_TRUE(addResult(path, R"({"board_delay_ms":0.28})", R"({"lag_ms":0.467})").isOk());
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE result SET report_json = '{\"lag_ms\":0.566}' WHERE id = 1", nullptr, nullptr,
                         nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 2u);
  EXPECT_FALSE((*results)[0].intact);
  EXPECT_TRUE((*results)[1].intact);
}

TEST(SessionFaults, ASchemaOneSessionIsReadAndMigratedWhenAResultIsAdded) {
  ScratchDir dir;
  // Schema 1 as the first fogbench wrote it: no checksum columns, no table
  // log, no gyro signs.
  const auto path = craftedSession(dir, "v1.fbs",
                                   "DROP TABLE table_log; ALTER TABLE session DROP COLUMN metadata_fnv1a;"
                                   " ALTER TABLE result DROP COLUMN fnv1a;" + std::string(kDropGyroSigns) +
                                       " PRAGMA user_version = 1;");
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 1);
    EXPECT_TRUE((*r)->recording().isOk());
    auto results = (*r)->results();
    ASSERT_TRUE(results.isOk());
  }
  ASSERT_TRUE(addResult(path, "{}", R"({"lag_ms":0.466})").isOk());
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);  // 1 -> 2 -> 3 -> 4 -> 5
  EXPECT_FALSE((*r)->info().bench.imuFrame.stated());
  EXPECT_EQ((*r)->info().bench.gyroSign, (std::array<int, kAxisCount>{1, 1, 1}));
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 1u);
  EXPECT_TRUE(results->front().intact);
  EXPECT_TRUE((*r)->recording().isOk());
  EXPECT_TRUE((*r)->tableLog()->empty());
}

// metadata_fnv1a as schema 2 and 3 computed it (docs/sessions.md): FNV-1a
// 64 over each metadata column's SQLite type and bytes, written out here
// independently of the reader's code; later schemas add `laterColumns`.
std::int64_t schemaThreeMetadataChecksum(sqlite3* db, const std::string& laterColumns = "") {
  sqlite3_stmt* s = nullptr;
  const std::string sql =
      "SELECT operator, imu_model, imu_serial, source, software_version, created_utc, notes,"
      " table_read_delay_ms, table_read_delay_std_ms, board_delay_ms, board_delay_std_ms,"
      " latitude_deg, pulse_equivalent_deg, counter_hz, counter_bits, test_plan_json, state,"
      " incomplete_reason, finished_utc" + laterColumns + " FROM session WHERE id = 1";
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr), SQLITE_OK);
  EXPECT_EQ(sqlite3_step(s), SQLITE_ROW);
  std::uint64_t h = 0xcbf29ce484222325ULL;
  auto add = [&h](const void* data, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  };
  auto add64 = [&add](std::uint64_t bits) {
    std::uint8_t b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<std::uint8_t>(bits >> (8 * i));
    add(b, 8);
  };
  for (int i = 0; i < sqlite3_column_count(s); ++i) {
    const auto type = static_cast<std::uint8_t>(sqlite3_column_type(s, i));
    add(&type, 1);
    if (type == SQLITE_INTEGER) add64(static_cast<std::uint64_t>(sqlite3_column_int64(s, i)));
    else if (type == SQLITE_FLOAT) add64(std::bit_cast<std::uint64_t>(sqlite3_column_double(s, i)));
    else if (type != SQLITE_NULL) {
      const auto* text = sqlite3_column_text(s, i);
      const auto n = static_cast<std::size_t>(sqlite3_column_bytes(s, i));
      add64(n);
      add(text, n);
    }
  }
  sqlite3_finalize(s);
  return std::bit_cast<std::int64_t>(h);
}

TEST(SessionFaults, ASchemaThreeSessionWithoutGyroSignsReadsPlusOneAndKeepsItsChecksumWhenMigrated) {
  ScratchDir dir;
  // Schema 3 as fogbench wrote it before the gyro signs were kept, with the
  // metadata checksum schema 3 computed.
  const auto path = craftedSession(dir, "v3.fbs", std::string(kDropGyroSigns) + " PRAGMA user_version = 3;");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    const std::string sql = "UPDATE session SET metadata_fnv1a = " + std::to_string(schemaThreeMetadataChecksum(db));
    ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 3);
    EXPECT_EQ((*r)->info().bench.gyroSign, (std::array<int, kAxisCount>{1, 1, 1}));
    EXPECT_TRUE((*r)->recording().isOk());
  }
  ASSERT_TRUE(addResult(path, "{}", R"({"lag_ms":0.466})").isOk());
  // Still checked, now over the signs too: a flipped sign is damage.
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);
  EXPECT_EQ((*r)->info().bench.gyroSign, (std::array<int, kAxisCount>{1, 1, 1}));
  EXPECT_TRUE((*r)->info().imported.empty());
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT metadata_fnv1a IS NOT NULL FROM session", -1, &s, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
    EXPECT_EQ(sqlite3_column_int(s, 0), 1);
    sqlite3_finalize(s);
    sqlite3_close(db);
  }
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  ASSERT_EQ(results->size(), 1u);
  EXPECT_TRUE(results->front().intact);
}

TEST(SessionFaults, ASchemaFourSessionStatesNoFrameAndKeepsItsChecksumWhenMigrated) {
  ScratchDir dir;
  const auto path = craftedSession(dir, "v4.fbs", std::string(kDropImuFrame) + " PRAGMA user_version = 4;");
  auto setChecksum = [&](const std::string& columns) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    const std::string sql =
        "UPDATE session SET metadata_fnv1a = " + std::to_string(schemaThreeMetadataChecksum(db, columns));
    ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  };
  setChecksum(", gyro_sign_x, gyro_sign_y, gyro_sign_z, import_json");
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 4);
    EXPECT_FALSE((*r)->info().bench.imuFrame.stated());
  }
  ASSERT_TRUE(addResult(path, "{}", R"({"lag_ms":0.466})").isOk());
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);
  EXPECT_FALSE((*r)->info().bench.imuFrame.stated());
  // Checked over the frame too: a frame written behind the checksum's back
  // (z up where the bench stated nothing) is damage, not a statement.
  fog::test::runSql(path, "UPDATE session SET imu_frame = 'ENU'");
  auto damaged = SessionReader::open(path);
  ASSERT_FALSE(damaged.isOk());
  EXPECT_NE(damaged.status().message().find("checksum"), std::string::npos) << damaged.status().message();
}

TEST(SessionFaults, ASchemaFiveSessionStatesNoLotNorBenchAndKeepsItsChecksumWhenMigrated) {
  ScratchDir dir;
  const auto path = craftedSession(dir, "v5.fbs", std::string(kDropIdentity) + " PRAGMA user_version = 5;");
  {
    // The checksum schema 5 computed, over its own columns (independently of
    // the reader's code).
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    const std::string sql =
        "UPDATE session SET metadata_fnv1a = " +
        std::to_string(schemaThreeMetadataChecksum(db, ", gyro_sign_x, gyro_sign_y, gyro_sign_z, import_json, imu_frame"));
    ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 5);
    EXPECT_EQ((*r)->info().lot, "");
    EXPECT_EQ((*r)->info().benchId, "");
  }
  ASSERT_TRUE(addResult(path, "{}", R"({"lag_ms":0.466})").isOk());
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 6);
    EXPECT_EQ((*r)->info().lot, "");
    EXPECT_EQ((*r)->info().benchId, "");
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT metadata_fnv1a FROM session", -1, &s, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
    // Checked, and over the new columns too.
    EXPECT_EQ(sqlite3_column_int64(s, 0),
              schemaThreeMetadataChecksum(db, ", gyro_sign_x, gyro_sign_y, gyro_sign_z, import_json, imu_frame, lot, bench_id"));
    sqlite3_finalize(s);
    sqlite3_close(db);
  }
  // A lot written behind the checksum's back is damage, not a statement.
  fog::test::runSql(path, "UPDATE session SET lot = 'L-2026-11'");
  auto damaged = SessionReader::open(path);
  ASSERT_FALSE(damaged.isOk());
  EXPECT_NE(damaged.status().message().find("checksum"), std::string::npos) << damaged.status().message();
}

TEST(SessionFaults, LotAndBenchAreStoredAndAByteFlippedInTheLotFailsTheChecksum) {
  ScratchDir dir;
  SessionInfo info;
  info.lot = "L-2026-11-A";
  info.benchId = "bench-3";
  const auto path = fog::test::recordedSession(dir, "ident.fbs", info);
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);
    EXPECT_EQ((*r)->info().lot, "L-2026-11-A");
    EXPECT_EQ((*r)->info().benchId, "bench-3");
  }
  // One byte of the lot ('A' -> 'B'), the rest of the row untouched.
  fog::test::runSql(path, "UPDATE session SET lot = 'L-2026-11-B'");
  auto damaged = SessionReader::open(path);
  ASSERT_FALSE(damaged.isOk());
  EXPECT_NE(damaged.status().message().find("checksum"), std::string::npos) << damaged.status().message();
  // And the bench id.
  const auto other = fog::test::recordedSession(dir, "ident2.fbs", info);
  fog::test::runSql(other, "UPDATE session SET bench_id = 'bench-4'");
  EXPECT_FALSE(SessionReader::open(other).isOk());
}

TEST(SessionFaults, AnUnreadableStoredFrameIsRefusedWithItsReason) {
  ScratchDir dir;
  const auto path = craftedSession(dir, "frame.fbs", "UPDATE session SET imu_frame = 'SWU', metadata_fnv1a = NULL");
  auto r = SessionReader::open(path);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("IMU frame"), std::string::npos) << r.status().message();
}

TEST(SessionFaults, ASchemaTwoSessionIsReadWithoutATableLogAndMigratedWhenOneIsAdded) {
  ScratchDir dir;
  // Schema 2 as fogbench wrote it before the table log (and the gyro signs,
  // whose columns its metadata checksum never covered: unchecked here).
  const auto path = craftedSession(dir, "v2.fbs",
                                   "DROP TABLE table_log;" + std::string(kDropGyroSigns) +
                                       " UPDATE session SET metadata_fnv1a = NULL; PRAGMA user_version = 2;");
  {
    auto r = SessionReader::open(path);
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->schemaVersion(), 2);
    EXPECT_TRUE((*r)->recording().isOk());
    auto log = (*r)->tableLog();
    ASSERT_TRUE(log.isOk()) << log.status().message();
    EXPECT_TRUE(log->empty());
  }
  ASSERT_TRUE(appendTableLog(path, {{1.5, "command", "AXIS:X:STOP"}, {1.6, "status", "X rest"}}).isOk());
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_EQ((*r)->schemaVersion(), kSchemaVersion);
  auto log = (*r)->tableLog();
  ASSERT_TRUE(log.isOk());
  ASSERT_EQ(log->size(), 2u);
  EXPECT_EQ((*log)[0].text, "AXIS:X:STOP");
  EXPECT_EQ((*log)[1].kind, "status");
  EXPECT_DOUBLE_EQ((*log)[1].elapsedS, 1.6);
  EXPECT_TRUE((*r)->recording().isOk());
  EXPECT_TRUE((*r)->results().isOk());
}

// An imported session keeps what the import applied; a flipped byte in it
// fails the metadata checksum like any other metadata.
TEST(SessionFaults, ImportSettingsAreStoredAndChecked) {
  ScratchDir dir;
  SessionInfo info;
  info.imported.gyroRateConvention = "frame_average";
  info.imported.gyroFramePeriodMs = 2.5;
  info.imported.segmentation = "auto: 10.000000-40.000000";
  // The most windows an import may cut (1 000, as a plan's points) read back
  // whole: a text field's 4 KiB cut would leave the JSON unreadable.
  {
    SessionInfo many = info;
    many.imported.segmentation = "given: ";
    for (int w = 0; w < 1000; ++w)
      many.imported.segmentation += (w ? "," : "") + std::to_string(w * 10) + ".000000-" + std::to_string(w * 10 + 8) + ".000000";
    auto writer = SessionWriter::create(dir.file("many.fbs"), many);
    ASSERT_TRUE(writer.isOk()) << writer.status().message();
    ASSERT_TRUE((*writer)->finish(true, "").isOk());
    writer->reset();
    auto reader = SessionReader::open(dir.file("many.fbs"));
    ASSERT_TRUE(reader.isOk()) << reader.status().message();
    EXPECT_EQ((*reader)->info().imported.segmentation, many.imported.segmentation);
  }
  {
    auto w = SessionWriter::create(dir.file("imported.fbs"), info);
    ASSERT_TRUE(w.isOk()) << w.status().message();
    ASSERT_TRUE((*w)->finish(true, "").isOk());
  }
  {
    auto r = SessionReader::open(dir.file("imported.fbs"));
    ASSERT_TRUE(r.isOk()) << r.status().message();
    EXPECT_EQ((*r)->info().imported.gyroRateConvention, "frame_average");
    EXPECT_EQ((*r)->info().imported.gyroFramePeriodMs, 2.5);
    EXPECT_EQ((*r)->info().imported.segmentation, "auto: 10.000000-40.000000");
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(dir.file("imported.fbs").c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE session SET import_json = replace(import_json, '10.0', '11.0')", nullptr,
                         nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  auto r = SessionReader::open(dir.file("imported.fbs"));
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("checksum"), std::string::npos) << r.status().message();
}

// --- 11. limits -----------------------------------------------------------------

TEST(SessionFaults, NotesAreBoundedWhenWrittenAndWhenRead) {
  ScratchDir dir;
  SessionInfo info;
  info.notes.assign(2u << 20, 'n');
  auto w = SessionWriter::create(dir.file("long.fbs"), info);
  ASSERT_FALSE(w.isOk());
  EXPECT_NE(w.status().message().find("at most"), std::string::npos) << w.status().message();
  EXPECT_FALSE(fs::exists(dir.file("long.fbs")));
  // Written by something else: 20 MB of notes are read cut to 1 MiB.
  const auto path = craftedSession(dir, "crafted.fbs",
                                   "UPDATE session SET notes = CAST(zeroblob(20000000) AS TEXT),"
                                   " metadata_fnv1a = NULL");
  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_LT((*r)->info().notes.size(), (1u << 20) + 100);
  EXPECT_NE((*r)->info().notes.find("notes cut: the file holds 20000000 bytes"), std::string::npos);
}

}  // namespace
}  // namespace fog::session

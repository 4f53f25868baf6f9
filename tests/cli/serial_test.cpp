// A sampling board on a real pseudo-terminal: fogbench-board-emu plays the
// simulator's stream (with faults on request) and fogbench-cli records it
// through the serial source (termios), as it would a board on /dev/ttyUSB0. Each test checks
// what the operator is told (stdout, stderr, exit code) and what the session
// file kept. docs/serial.md lists the faults and the bench's answers.
//
// Not flaky by construction: the emulator runs at 10x real time on short
// plans, the test reads the emulator's own output for the pty name and the
// truth instead of sleeping, and every wait has a generous limit (a
// descheduled process on a loaded CI machine only makes a test slower).

#include <fcntl.h>
#include <gtest/gtest.h>
#include <termios.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "child_process.h"
#include "core/protocol/decoder.h"
#include "core/protocol/host_command.h"
#include "core/session/session_file.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using fog::test::Child;

std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A short plan the emulator plays at 10x: 1 s settling + 12 s at 1 Hz / 3 deg.
const std::vector<std::string> kPlan = {"--axis", "x", "--freq-hz", "1", "--amp-deg", "3", "--duration-s", "12",
                                        "--seed", "3", "--speed", "10"};

struct BenchRun {
  std::string pty;
  double trueLagMs = NAN;
  int cliExit = -1, emuExit = -1;
  std::string cliOut, cliErr, emuOut, emuErr;
  std::string session;  // path
  std::string emulatorRaw;  // what the emulator sent (faults included)
};

class SerialBench : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(FOG_TEST_SCRATCH) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  // Starts the emulator with the plan and `emuArgs`, then fogbench-cli run
  // --source serial on its pty with `cliArgs`; waits for both.
  BenchRun run(const std::vector<std::string>& emuArgs, const std::vector<std::string>& cliArgs) {
    BenchRun r;
    r.session = (dir_ / "s.fbs").string();
    r.emulatorRaw = (dir_ / "sent.bin").string();
    std::vector<std::string> emu = {FOG_BOARD_EMU};
    emu.insert(emu.end(), kPlan.begin(), kPlan.end());
    emu.insert(emu.end(), emuArgs.begin(), emuArgs.end());
    emu.insert(emu.end(), {"--save-raw", r.emulatorRaw});
    Child board(emu);
    r.pty = board.waitForLine("pty: (\\S+)\n");
    const std::string lag = board.waitForLine("truth: point 1 .* lag_ms ([0-9.]+)");
    if (!lag.empty()) r.trueLagMs = std::stod(lag);
    if (r.pty.empty()) {
      r.emuExit = board.finish(10);
      r.emuOut = board.out;
      r.emuErr = board.err;
      return r;
    }
    std::vector<std::string> cli = {FOG_CLI, "run", "--source", "serial", "--port", r.pty, "--out", r.session};
    cli.insert(cli.end(), cliArgs.begin(), cliArgs.end());
    Child host(cli);
    r.cliExit = host.finish();
    r.emuExit = board.finish(30);
    r.cliOut = host.out;
    r.cliErr = host.err;
    r.emuOut = board.out;
    r.emuErr = board.err;
    return r;
  }

  fs::path dir_;
};

std::uint64_t emuCount(const BenchRun& r, const std::string& what) {
  std::smatch m;
  if (!std::regex_search(r.emuOut, m, std::regex("([0-9]+) " + what))) return ~0ull;
  return std::stoull(m[1].str());
}

// The report stored in the session by the run (the latest result).
nlohmann::json storedReport(const std::string& path) {
  auto reader = fog::session::SessionReader::open(path);
  if (!reader) return {};
  auto results = (*reader)->results();
  if (!results || results->empty()) return {};
  return nlohmann::json::parse(results->back().reportJson);
}

// True when `prefix` is the first bytes of `whole`.
bool isPrefix(const std::vector<std::uint8_t>& prefix, const std::vector<std::uint8_t>& whole) {
  return prefix.size() <= whole.size() && std::equal(prefix.begin(), prefix.end(), whole.begin());
}

// Lag tolerance against the emulator's truth: 5 reported standard deviations
// (about 1 us for this plan), never below 2 us.
void expectLagNearTruth(const nlohmann::json& point, double trueLagMs) {
  const double lag = point.at("lag_ms"), sd = point.at("lag_std_ms");
  EXPECT_NEAR(lag, trueLagMs, std::max(5.0 * sd, 0.002)) << "lag std " << sd << " ms";
}

TEST_F(SerialBench, EndToEndLagMatchesTheEmulatorsTruth) {
  const BenchRun r = run({}, {"--operator", "pty test"});
  ASSERT_FALSE(r.pty.empty()) << r.emuErr;
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  EXPECT_EQ(r.emuExit, 0) << r.emuErr;
  EXPECT_TRUE(std::isfinite(r.trueLagMs));
  EXPECT_NE(r.cliOut.find("source: serial " + r.pty + " at 921600 8N1"), std::string::npos) << r.cliOut;
  EXPECT_NE(r.cliOut.find("0 checksum failures, 0 lost, 0 duplicated, 0 bytes skipped"), std::string::npos) << r.cliOut;
  EXPECT_EQ(r.cliErr.find("incomplete"), std::string::npos) << r.cliErr;

  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk()) << reader.status().message();
  EXPECT_TRUE((*reader)->complete()) << (*reader)->incompleteReason();
  EXPECT_EQ((*reader)->info().source, "serial " + r.pty + " at 921600 8N1");
  EXPECT_EQ((*reader)->info().operatorName, "pty test");
  EXPECT_TRUE((*reader)->info().plan.points.empty()) << "no plan was given, none may be stored";
  auto raw = (*reader)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  // Everything the board sent until its "done" is in the session, in order.
  EXPECT_TRUE(isPrefix(*raw, readFile(r.emulatorRaw)));
  EXPECT_GT(raw->size(), 400000u);

  const auto report = storedReport(r.session);
  ASSERT_EQ(report["test_points"].size(), 1u) << report.dump();
  const auto& p = report["test_points"][0];
  expectLagNearTruth(p, r.trueLagMs);
  std::printf("end to end: lag %.6f ms, truth %.6f ms, error %+.2f us, std %.2f us\n", p["lag_ms"].get<double>(),
              r.trueLagMs, (p["lag_ms"].get<double>() - r.trueLagMs) * 1e3, p["lag_std_ms"].get<double>() * 1e3);
}

// The board's stored result reaches the folder's catalog without another
// `catalog index` (docs/catalog.md, "After each analysis").
TEST_F(SerialBench, TheStoredResultReachesTheFoldersCatalog) {
  {
    Child index({FOG_CLI, "catalog", "index", dir_.string()});  // the folder's catalog, empty
    ASSERT_EQ(index.finish(30), 0) << index.err;
  }
  const BenchRun r = run({}, {"--imu-serial", "SN-S"});
  ASSERT_FALSE(r.pty.empty()) << r.emuErr;
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  const std::string catalog = (dir_ / "fogbench-catalog.sqlite").string();
  EXPECT_NE(r.cliOut.find("Catalog updated: SQLite catalog " + catalog), std::string::npos) << r.cliOut << r.cliErr;
  Child unit({FOG_CLI, "catalog", "unit", "SN-S", "--db", catalog, "--json"});
  ASSERT_EQ(unit.finish(30), 0) << unit.err;
  EXPECT_EQ(nlohmann::json::parse(unit.out).at("history").size(), 1u) << unit.out;
}

// fogbench-cli itself sends the host-to-board commands (docs/protocol.md):
// the pulse equivalent the operator gave, start streaming before the run and
// stop streaming after it; the board emulator applies and prints them.
TEST_F(SerialBench, TheHostSendsThePulseEquivalentAndStartsAndStopsTheStream) {
  const BenchRun r = run({"--linger-s", "5"}, {"--pulse-equivalent-deg", "5e-5"});
  ASSERT_FALSE(r.pty.empty()) << r.emuErr;
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  const auto pulse = r.emuOut.find("host command: pulse equivalent 5e-05 deg at stream time");
  const auto start = r.emuOut.find("host command: start streaming at stream time");
  const auto stop = r.emuOut.find("host command: stop streaming at stream time");
  EXPECT_NE(pulse, std::string::npos) << r.emuOut;
  EXPECT_NE(start, std::string::npos) << r.emuOut;
  EXPECT_NE(stop, std::string::npos) << r.emuOut;
  EXPECT_LT(pulse, start);
  EXPECT_LT(start, stop);
  EXPECT_NE(r.cliErr.find("board command: stop streaming"), std::string::npos) << r.cliErr;
  // The board went on as before: the whole plan recorded, the lag right.
  const auto report = storedReport(r.session);
  ASSERT_EQ(report["test_points"].size(), 1u) << report.dump();
  expectLagNearTruth(report["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, ChecksumErrorsAndGarbageAreCountedAndSkipped) {
  const BenchRun r = run({"--corrupt-rate", "2e-5", "--garbage-at-s", "5", "--garbage-bytes", "3000",
                          "--fault-seed", "7"},
                         {});
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  const std::uint64_t corrupted = emuCount(r, "corrupted bytes");
  ASSERT_GT(corrupted, 0u) << r.emuOut;
  EXPECT_EQ(emuCount(r, "garbage bytes"), 3000u);
  const auto report = storedReport(r.session);
  const auto& s = report.at("stream");
  // Each flipped bit costs at most its frame; a garbage burst may hold a
  // false sync, never a frame with a valid CRC.
  EXPECT_GE(s.at("checksum_failures").get<std::uint64_t>(), 1u);
  EXPECT_LE(s.at("checksum_failures").get<std::uint64_t>(), corrupted + 10);
  EXPECT_GE(s.at("bytes_skipped").get<std::uint64_t>(), 3000u);
  // The user sees the counters in the report, and still gets the delay.
  EXPECT_TRUE(std::regex_search(r.cliOut, std::regex("[1-9][0-9]* checksum failures, [0-9]+ lost, 0 duplicated, "
                                                     "[1-9][0-9]+ bytes skipped")))
      << r.cliOut;
  ASSERT_EQ(report["test_points"].size(), 1u);
  expectLagNearTruth(report["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, GapsAndDuplicatesAreReportedPerTestPoint) {
  const BenchRun r = run({"--drop-rate", "0.002", "--duplicate-rate", "0.002", "--fault-seed", "3"},
                         {"--no-board-commands"});
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  EXPECT_EQ(r.emuOut.find("host command:"), std::string::npos) << "--no-board-commands: nothing sent\n" << r.emuOut;
  const std::uint64_t dropped = emuCount(r, "dropped frames"), duplicated = emuCount(r, "duplicated frames");
  ASSERT_GT(dropped, 0u);
  ASSERT_GT(duplicated, 0u);
  const auto report = storedReport(r.session);
  const auto& s = report.at("stream");
  // The host stops at the board's "done"; the emulator counted to its end.
  EXPECT_LE(s.at("lost_frames").get<std::uint64_t>(), dropped);
  EXPECT_GE(s.at("lost_frames").get<std::uint64_t>(), dropped * 8 / 10);
  EXPECT_LE(s.at("duplicate_frames").get<std::uint64_t>(), duplicated);
  EXPECT_GE(s.at("duplicate_frames").get<std::uint64_t>(), duplicated * 8 / 10);
  ASSERT_EQ(report["test_points"].size(), 1u);
  const auto& p = report["test_points"][0];
  const auto& affected = p.at("affected");
  EXPECT_GT(affected.at("lost_imu_frames").get<std::uint64_t>(), 0u);
  EXPECT_GT(affected.at("lost_table_frames").get<std::uint64_t>(), 0u);
  EXPECT_GT(affected.at("duplicate_frames").get<std::uint64_t>(), 0u);
  EXPECT_LE(affected.at("lost_imu_frames").get<std::uint64_t>() + affected.at("lost_table_frames").get<std::uint64_t>(),
            s.at("lost_frames").get<std::uint64_t>());
  EXPECT_LT(affected.at("time_covered").get<double>(), 1.0);
  EXPECT_GT(affected.at("time_covered").get<double>(), 0.99);
  EXPECT_TRUE(std::regex_search(r.cliOut, std::regex("Test point 1:[^]*affected: [0-9]+ table and [0-9]+ IMU frames "
                                                     "lost, [0-9]+ duplicated")))
      << r.cliOut;
  expectLagNearTruth(p, r.trueLagMs);
}

TEST_F(SerialBench, CounterWrapsWithoutAJumpInTime) {
  const BenchRun r = run({"--wrap-after-s", "4"}, {});
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  auto rec = (*reader)->recording();
  ASSERT_TRUE(rec.isOk());
  EXPECT_EQ(rec->health.counterWraps, 1u);
  ASSERT_EQ(rec->testPoints.size(), 1u);
  const auto& table = rec->testPoints[0].table;
  ASSERT_GT(table.size(), 11000u);
  double smallest = 1.0, largest = 0.0;
  for (std::size_t i = 1; i < table.size(); ++i) {
    smallest = std::min(smallest, table[i].timeS - table[i - 1].timeS);
    largest = std::max(largest, table[i].timeS - table[i - 1].timeS);
  }
  // 1 ms table frames stay 1 ms apart across the wrap (to 1 counter tick).
  EXPECT_NEAR(smallest, 1e-3, 2e-7);
  EXPECT_NEAR(largest, 1e-3, 2e-7);
  const auto report = storedReport(r.session);
  EXPECT_EQ(report.at("stream").at("counter_wraps"), 1);
  expectLagNearTruth(report["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, AStallRaisesATimeoutMessageAndTheRunGoesOn) {
  const BenchRun r = run({"--stall-at-s", "6", "--stall-s", "3"}, {"--stall-warning-s", "1", "--stall-timeout-s", "20"});
  ASSERT_EQ(r.cliExit, 0) << r.cliErr;
  EXPECT_NE(r.emuOut.find("stall: nothing sent for 3.0 s"), std::string::npos) << r.emuOut;
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("timeout: no data from " + r.pty + " for [12]\\.[0-9] s")))
      << r.cliErr;
  EXPECT_EQ(r.cliErr.find("incomplete"), std::string::npos) << r.cliErr;
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  EXPECT_TRUE((*reader)->complete());
  expectLagNearTruth(storedReport(r.session)["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, AStallBeyondTheLimitEndsTheRunIncomplete) {
  const BenchRun r = run({"--stall-at-s", "7", "--stall-s", "8"}, {"--stall-warning-s", "1", "--stall-timeout-s", "2"});
  EXPECT_EQ(r.cliExit, 0) << r.cliErr;  // 6 s of data still give a delay
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("timeout: no data from " + r.pty + " for 1\\.[0-9] s")))
      << r.cliErr;
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("run incomplete: no data for 2\\.[0-9] s from serial " + r.pty +
                                                     ".*all kept in " + r.session)))
      << r.cliErr;
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  EXPECT_FALSE((*reader)->complete());
  EXPECT_NE((*reader)->incompleteReason().find("no data for 2."), std::string::npos) << (*reader)->incompleteReason();
  // Everything sent before the stall was kept.
  auto raw = (*reader)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  const auto sent = readFile(r.emulatorRaw);
  EXPECT_TRUE(isPrefix(*raw, sent));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.emuOut, m, std::regex("stall: nothing sent")));
  EXPECT_GT(raw->size(), 250000u);  // 7 s of stream: ~39 kB/s
  expectLagNearTruth(storedReport(r.session)["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, APortThatVanishesEndsTheRunIncompleteAndKeepsEverything) {
  const BenchRun r = run({"--disconnect-at-s", "7"}, {});
  EXPECT_EQ(r.cliExit, 0) << r.cliErr;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.emuOut, m, std::regex("disconnect: closed the port .* after ([0-9]+) bytes")))
      << r.emuOut;
  const std::size_t sentBytes = std::stoull(m[1].str());
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("run incomplete: serial port " + r.pty +
                                                     " vanished.*all kept in " + r.session)))
      << r.cliErr;
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  EXPECT_FALSE((*reader)->complete());
  EXPECT_NE((*reader)->incompleteReason().find("vanished"), std::string::npos) << (*reader)->incompleteReason();
  auto raw = (*reader)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  const auto sent = readFile(r.emulatorRaw);
  EXPECT_EQ(sent.size(), sentBytes);
  EXPECT_TRUE(isPrefix(*raw, sent));
  // What was still in the pty's buffer when it vanished is lost, as with a
  // pulled cable; everything the host had received is kept.
  EXPECT_GT(raw->size(), sentBytes - 70000) << "kept " << raw->size() << " of " << sentBytes;
  const auto report = storedReport(r.session);
  ASSERT_EQ(report["test_points"].size(), 1u);
  expectLagNearTruth(report["test_points"][0], r.trueLagMs);
}

TEST_F(SerialBench, AWrongBaudRateIsReportedAsNoValidFrames) {
  const BenchRun r = run({}, {"--baud", "115200", "--stall-timeout-s", "2"});
  EXPECT_EQ(r.cliExit, 1);
  EXPECT_NE(r.emuOut.find("host: opened at 115200 8N1 (board 921600 8N1)"), std::string::npos) << r.emuOut;
  // Told while it runs, and at the end.
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("bytes from " + r.pty + " but no valid sampling-board frames; "
                                                     "is the baud rate \\(115200\\)")))
      << r.cliErr;
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("no valid sampling-board frames found in [0-9]+ bytes; .*baud "
                                                     "rate wrong")))
      << r.cliErr;
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  auto raw = (*reader)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  EXPECT_GT(raw->size(), 10000u);  // the garbage is kept too: it is what arrived
}

TEST_F(SerialBench, AGapLongerThanAPeriodGivesNoDelayAndSaysWhy) {
  const BenchRun r = run({"--gap-at-s", "6", "--gap-s", "1.5"}, {});
  EXPECT_EQ(r.cliExit, 1);
  EXPECT_GT(emuCount(r, "gap frames"), 2000u) << r.emuOut;
  EXPECT_TRUE(std::regex_search(r.cliErr, std::regex("no test point gave a delay; test point 1: a gap of 1\\.[45][0-9] s "
                                                     "without data is longer than one swing period \\(1\\.00 s\\)")))
      << r.cliErr;
  // The session keeps the data and the run was complete: only the delay is refused.
  auto reader = fog::session::SessionReader::open(r.session);
  ASSERT_TRUE(reader.isOk());
  EXPECT_TRUE((*reader)->complete());
  auto rec = (*reader)->recording();
  ASSERT_TRUE(rec.isOk());
  EXPECT_GT(rec->health.lostFrames, 2000u);
}

TEST_F(SerialBench, AMissingPortIsRefusedWithTheSystemsReason) {
  Child host({FOG_CLI, "run", "--source", "serial", "--port", (dir_ / "no-such-tty").string()});
  EXPECT_EQ(host.finish(), 2);
  EXPECT_TRUE(std::regex_search(host.err, std::regex("cannot open serial port .*no-such-tty: "))) << host.err;
}

// The host-to-board direction (docs/protocol.md, "Host to board"), over the
// emulator's pty with plain POSIX I/O: the pulse equivalent and a test-point
// marker are echoed in STATUS frames, and streaming stops and resumes with
// contiguous sequence numbers.
TEST_F(SerialBench, HostCommandsSetThePulseEquivalentMarkTestPointsAndStopAndStartTheStream) {
  Child board({FOG_BOARD_EMU, "--axis", "x", "--freq-hz", "1", "--amp-deg", "3", "--duration-s", "30", "--seed", "3",
               "--speed", "5", "--linger-s", "1"});
  const std::string pty = board.waitForLine("pty: (\\S+)\n");
  ASSERT_FALSE(pty.empty()) << board.err;
  const int fd = ::open(pty.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  termios t{};
  ASSERT_EQ(::tcgetattr(fd, &t), 0);
  cfmakeraw(&t);
  cfsetspeed(&t, B921600);
  ASSERT_EQ(::tcsetattr(fd, TCSANOW, &t), 0);
  fog::protocol::Decoder decoder;
  std::vector<fog::protocol::DecodedFrame> frames;
  // Reads until `done` says so (checked on every new frame) or 30 s pass.
  auto readUntil = [&](const std::function<bool(const fog::protocol::DecodedFrame&)>& done) {
    const auto giveUp = Clock::now() + std::chrono::seconds(30);
    std::vector<fog::protocol::DecodedFrame> got;
    while (Clock::now() < giveUp) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 200) <= 0) continue;
      std::uint8_t buf[4096];
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n <= 0) continue;
      got.clear();
      decoder.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), got);
      for (const auto& f : got) {
        frames.push_back(f);
        if (done(f)) return true;
      }
    }
    return false;
  };
  auto send = [&](const fog::protocol::HostCommand& c, std::uint16_t seq) {
    std::vector<std::uint8_t> bytes;
    fog::protocol::appendHostCommand(c, seq, bytes);
    ASSERT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  };
  auto status = [](const fog::protocol::DecodedFrame& f) { return std::get_if<fog::protocol::StatusPayload>(&f.frame.payload); };
  auto isData = [](const fog::protocol::DecodedFrame& f) { return f.frame.type != fog::protocol::FrameType::kStatus; };
  // Before any command: the simulator's own pulse equivalent.
  ASSERT_TRUE(readUntil([&](const auto& f) { return status(f) != nullptr; }));
  EXPECT_EQ(status(frames.back())->pulseEquivalentDeg, 5e-5);
  // Pulse equivalent and a marker: echoed from the next STATUS on.
  fog::protocol::HostCommand mark;
  mark.opcode = fog::protocol::HostOpcode::kMarkTestPoint;
  mark.testPoint = 7;
  mark.axis = 2;
  mark.phase = fog::protocol::TestPhase::kRecording;
  mark.nominalFrequencyMicroHz = 2000000;
  mark.nominalAmplitudeMicroDeg = 1500000;
  send(fog::protocol::HostCommand{fog::protocol::HostOpcode::kSetPulseEquivalent, 1e-4}, 0);
  send(mark, 1);
  ASSERT_TRUE(readUntil([&](const auto& f) { return status(f) && status(f)->testPoint == 7; })) << board.out;
  const auto* s = status(frames.back());
  EXPECT_EQ(s->pulseEquivalentDeg, 1e-4);
  EXPECT_EQ(s->axis, 2);
  EXPECT_EQ(s->phase, fog::protocol::TestPhase::kRecording);
  EXPECT_EQ(s->nominalFrequencyMicroHz, 2000000u);
  EXPECT_EQ(s->nominalAmplitudeMicroDeg, 1500000u);
  // Stop: no table or IMU frame stamped after the stop, while STATUS frames go on.
  send(fog::protocol::HostCommand{fog::protocol::HostOpcode::kStopStreaming}, 2);
  const std::string stopAt = board.waitForLine("host command: stop streaming at stream time ([0-9.]+) s", 30);
  ASSERT_FALSE(stopAt.empty()) << board.out;
  const double stopTicks = std::stod(stopAt) * 1e7 + 1e4;  // 1 ms: the printed time is rounded
  std::size_t dataAfterStop = 0, statusAfterStop = 0;
  ASSERT_TRUE(readUntil([&](const auto& f) {
    if (static_cast<double>(f.frame.counter) <= stopTicks) return false;
    if (isData(f)) ++dataAfterStop;
    else ++statusAfterStop;
    return statusAfterStop >= 5;  // half a stream second
  }));
  EXPECT_EQ(dataAfterStop, 0u);
  // Start: data again, nothing counted as lost.
  send(fog::protocol::HostCommand{fog::protocol::HostOpcode::kStartStreaming}, 3);
  const std::string startAt = board.waitForLine("host command: start streaming at stream time ([0-9.]+) s", 30);
  ASSERT_FALSE(startAt.empty()) << board.out;
  std::size_t dataAfterStart = 0;
  ASSERT_TRUE(readUntil([&](const auto& f) { return isData(f) && ++dataAfterStart >= 300; }));
  EXPECT_EQ(decoder.health().lostFrames, 0u);
  EXPECT_EQ(decoder.health().checksumFailures, 0u);
  ::close(fd);
}

}  // namespace

// The bench drives the turntable (docs/table-control.md), over real
// pseudo-terminals and localhost TCP: fogbench-table-emu is the table
// controller (and, on a second pty, the sampling board playing that table's
// motion); fogbench-cli run --table remote:... drives it through a plan while
// it records the board. Each test checks what the operator is told, what the
// session kept (raw stream, test points, the table log) and what the
// emulator says the table did.
//
// Not flaky by construction: the emulators run at 10x real time on plans of
// a few seconds per point, every wait reads the programs' own output with a
// generous limit, and nothing asserts a duration.

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "child_process.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace {

namespace fs = std::filesystem;
using fog::test::Child;

class TableBench : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(FOG_TEST_SCRATCH) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  std::string writePlan(const std::string& json) const {
    const auto path = file("plan.json");
    std::ofstream(path) << json;
    return path;
  }
  fs::path dir_;
};

// Three axes, a few seconds each: X 2 Hz / 2 deg, Y 2 Hz / 1.5 deg, Z 1 Hz / 3 deg
// about 20 deg with Y held at 5 deg (the plan's table position).
const char* kThreeAxisPlan = R"({"points":[
  {"axis":"x","frequency_hz":2,"amplitude_deg":2,"duration_s":4,"settle_s":1.5},
  {"axis":"y","frequency_hz":2,"amplitude_deg":1.5,"duration_s":4,"settle_s":1.5},
  {"axis":"z","frequency_hz":1,"amplitude_deg":3,"duration_s":5,"settle_s":2,"position_deg":[0,5,20]}],
  "rest_between_s":0.5})";

struct Emulator {
  std::unique_ptr<Child> child;
  std::string table, board;
  double trueLagMs = NAN;
};

Emulator startEmulator(std::vector<std::string> extra) {
  std::vector<std::string> argv = {FOG_TABLE_EMU, "--speed", "10", "--seed", "3", "--exit-after-s", "120"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  Emulator e;
  e.child = std::make_unique<Child>(argv);
  e.table = e.child->waitForLine("table: (\\S+)", 30);
  if (std::find(extra.begin(), extra.end(), "none") == extra.end()) {
    e.board = e.child->waitForLine("board: (\\S+)", 30);
    const auto lag = e.child->waitForLine("truth: lag_ms ([0-9.]+)", 30);
    if (!lag.empty()) e.trueLagMs = std::stod(lag);
  }
  return e;
}

std::vector<std::string> cliRun(const Emulator& e, const std::string& plan, const std::string& session,
                                std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {FOG_CLI, "run", "--table", "remote:" + e.table, "--source", "serial", "--port",
                                   e.board, "--plan", plan, "--speed", "10", "--out", session};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

// Ends the emulator (SIGTERM) and collects its output.
void stopEmulator(Emulator& e) {
  ::kill(e.child->pid(), SIGTERM);
  EXPECT_EQ(e.child->finish(30), 0) << e.child->err;
}

std::vector<fog::session::TableLogEntry> tableLog(const std::string& session) {
  auto r = fog::session::SessionReader::open(session);
  EXPECT_TRUE(r.isOk()) << r.status().message();
  if (!r) return {};
  auto log = (*r)->tableLog();
  EXPECT_TRUE(log.isOk());
  return log ? *log : std::vector<fog::session::TableLogEntry>{};
}

bool logHas(const std::vector<fog::session::TableLogEntry>& log, const std::string& kind, const std::string& part) {
  for (const auto& e : log)
    if (e.kind == kind && e.text.find(part) != std::string::npos) return true;
  return false;
}

TEST_F(TableBench, AThreeAxisPlanRunsThroughTheWholeHardwarePathAndMeasuresTheTrueDelay) {
  auto emu = startEmulator({"--link", "tcp"});
  ASSERT_FALSE(emu.table.empty()) << emu.child->err;
  ASSERT_FALSE(std::isnan(emu.trueLagMs));
  const auto session = file("three.fbs");
  const auto catalog = file("lab.sqlite");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session, {"--json", "--db", catalog}));
  ASSERT_EQ(cli.finish(120), 0) << cli.err;
  stopEmulator(emu);
  // The stored result reached the catalog --db names, after the table log
  // was appended: indexing the folder again finds the session unchanged.
  {
    Child units({FOG_CLI, "catalog", "units", "--db", catalog, "--json"});
    ASSERT_EQ(units.finish(30), 0) << units.err;
    const auto listed = nlohmann::json::parse(units.out);
    ASSERT_EQ(listed.size(), 1u) << units.out;
    EXPECT_EQ(listed[0].at("results"), 1) << units.out;
    Child again({FOG_CLI, "catalog", "index", dir_.string(), "--db", catalog, "--json"});
    ASSERT_EQ(again.finish(30), 0) << again.err;
    const auto indexed = nlohmann::json::parse(again.out);
    EXPECT_EQ(indexed.at("files_found"), 1) << again.out;
    EXPECT_EQ(indexed.at("unchanged"), 1) << again.out;
  }
  // What the table did: three swings, in the plan's order.
  EXPECT_NE(emu.child->out.find("swing: X 2 Hz 2 deg about 0 deg started"), std::string::npos) << emu.child->out;
  EXPECT_LT(emu.child->out.find("swing: X 2 Hz"), emu.child->out.find("swing: Y 2 Hz 1.5 deg"));
  EXPECT_LT(emu.child->out.find("swing: Y 2 Hz"), emu.child->out.find("swing: Z 1 Hz 3 deg about 20 deg"));
  EXPECT_EQ(emu.child->out.find("heartbeat:"), std::string::npos) << "the host kept the heartbeat, then released it";
  // The report: three test points on X, Y, Z, each lag within max(5 sigma, 2 us) of the truth.
  const auto report = nlohmann::json::parse(cli.out);
  const auto& points = report.at("test_points");
  ASSERT_EQ(points.size(), 3u) << cli.out;
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& p = points[i];
    EXPECT_EQ(p.at("axis"), axes[i]);
    const double lag = p.at("lag_ms"), sd = p.at("lag_std_ms");
    EXPECT_NEAR(lag, emu.trueLagMs, std::max(5.0 * sd, 0.002)) << "point " << i + 1 << " lag std " << sd << " ms";
    std::printf("point %zu (%s): lag %.6f ms +- %.6f ms, truth %.6f ms, error %+.4f us\n", i + 1, axes[i], lag, sd,
                emu.trueLagMs, (lag - emu.trueLagMs) * 1e3);
  }
  // The session: complete, the plan, the source names both devices, the table log.
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_TRUE((*r)->complete()) << (*r)->incompleteReason();
  EXPECT_EQ((*r)->info().plan.points.size(), 3u);
  EXPECT_NE((*r)->info().source.find("table remote tcp:127.0.0.1:"), std::string::npos) << (*r)->info().source;
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk());
  ASSERT_EQ(rec->testPoints.size(), 3u);
  EXPECT_EQ(rec->testPoints[2].axis, fog::Axis::kZ);
  EXPECT_NEAR(rec->testPoints[2].table.back().timeS - rec->testPoints[2].table.front().timeS, 5.0, 0.01);
  // Z swung about 20 deg with Y held at 5 deg, as the plan placed the table.
  double zMin = 1e9, zMax = -1e9;
  for (const auto& t : rec->testPoints[2].table) {
    zMin = std::min(zMin, t.angleDeg[2]);
    zMax = std::max(zMax, t.angleDeg[2]);
    ASSERT_NEAR(t.angleDeg[1], 5.0, 1e-3);
  }
  EXPECT_NEAR(0.5 * (zMin + zMax), 20.0, 0.01);
  EXPECT_NEAR(0.5 * (zMax - zMin), 3.0, 0.01);
  const auto log = tableLog(session);
  EXPECT_TRUE(logHas(log, "command", "AXIS:X:SWING 2,2,0"));
  EXPECT_TRUE(logHas(log, "command", "AXIS:Z:START"));
  EXPECT_TRUE(logHas(log, "command", "AXIS:Y:POS 5"));
  EXPECT_TRUE(logHas(log, "command", "AXIS:Z:SWING 1,3,20"));
  EXPECT_TRUE(logHas(log, "command", "AXIS:Y:STOP"));
  EXPECT_TRUE(logHas(log, "reply", "fogbench,table-emu"));
  EXPECT_TRUE(logHas(log, "status", "Y swinging"));
  EXPECT_TRUE(logHas(log, "step", "swing verified"));
  EXPECT_TRUE(logHas(log, "step", "plan done: 3 points"));
  EXPECT_TRUE(logHas(log, "command", "SYST:HEART:TIM 0"));  // released: the table is at rest
  // The host-to-board direction (docs/protocol.md): the board was told to
  // stream, where the plan stood at each point, and to stop; it echoed the
  // markers, so the raw stream cut by its own STATUS frames gives the three
  // points too.
  const std::string& emuOut = emu.child->out;
  const auto at = [&](const std::string& part) { return emuOut.find("host command: " + part); };
  EXPECT_NE(at("start streaming"), std::string::npos) << emuOut;
  EXPECT_NE(at("mark test point 0 axis 0 phase 2 2.000000 Hz 2.000000 deg"), std::string::npos) << emuOut;
  EXPECT_NE(at("mark test point 2 axis 2 phase 2 1.000000 Hz 3.000000 deg"), std::string::npos) << emuOut;
  EXPECT_LT(at("mark test point 0 axis 0 phase 1"), at("mark test point 0 axis 0 phase 2"));
  EXPECT_LT(at("mark test point 0 axis 0 phase 2"), at("mark test point 0 axis 0 phase 0"));
  EXPECT_LT(at("mark test point 2 axis 2 phase 0"), at("mark test point 65535 axis 0 phase 3"));
  EXPECT_LT(at("mark test point 65535 axis 0 phase 3"), at("stop streaming"));
  EXPECT_NE(at("stop streaming"), std::string::npos) << emuOut;
  EXPECT_TRUE(logHas(log, "board", "mark test point 2 (Y 2 Hz / 1.5 deg) recording"));
  EXPECT_TRUE(logHas(log, "board", "stop streaming"));
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  auto byMarkers = fog::protocol::decodeRecording(*raw);
  ASSERT_TRUE(byMarkers.isOk()) << byMarkers.status().message();
  ASSERT_EQ(byMarkers->testPoints.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(byMarkers->testPoints[i].index, static_cast<int>(i));
    EXPECT_EQ(byMarkers->testPoints[i].axis, rec->testPoints[i].axis);
    // "Recording" is marked once the swing is verified, which is after the
    // start of the checked stretch the bench's cut begins with (at most the
    // check's 2 periods or 1 s, plus the link's latency: 3.4 s seen once in
    // the ASan build with two tests in parallel, so 5 s), and lasts until
    // the runner ends the point, after the cut's end.
    const auto& marked = byMarkers->testPoints[i].table;
    const auto& cut = rec->testPoints[i].table;
    EXPECT_GE(marked.front().timeS, cut.front().timeS) << "point " << i + 1;
    EXPECT_LE(marked.front().timeS, cut.front().timeS + 5.0) << "point " << i + 1;
    EXPECT_GE(marked.back().timeS, cut.back().timeS) << "point " << i + 1;
  }
}

TEST_F(TableBench, ACommandTheControllerRefusesEndsTheRunWithItsErrorAndTheTableAtRest) {
  // Over a pseudo-terminal this time: the table link as a serial line.
  auto emu = startEmulator({"--link", "pty", "--refuse", "AXIS:Y:START"});
  ASSERT_FALSE(emu.table.empty()) << emu.child->err;
  const auto session = file("refused.fbs");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session));
  const int code = cli.finish(120);
  stopEmulator(emu);
  EXPECT_EQ(code, 0) << "point 1 was recorded and gives a delay\n" << cli.err;
  EXPECT_NE(cli.err.find("run incomplete: table: point 2 (Y 2 Hz / 1.5 deg): the table controller refused "
                         "'AXIS:Y:START': 204,\"Refused by the controller; AXIS:Y:START refused (injected fault)\""),
            std::string::npos)
      << cli.err;
  EXPECT_NE(cli.err.find("table step: table at rest"), std::string::npos) << cli.err;
  EXPECT_NE(emu.child->out.find("refused: AXIS:Y:START"), std::string::npos);
  EXPECT_EQ(emu.child->out.find("swing: Y"), std::string::npos) << "Y never moved";
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
  EXPECT_NE((*r)->incompleteReason().find("refused 'AXIS:Y:START'"), std::string::npos);
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk());
  ASSERT_EQ(rec->testPoints.size(), 1u);
  EXPECT_EQ(rec->testPoints[0].axis, fog::Axis::kX);
  const auto log = tableLog(session);
  EXPECT_TRUE(logHas(log, "reply", "204,\"Refused by the controller"));
  EXPECT_TRUE(logHas(log, "command", "STOP"));
}

TEST_F(TableBench, ALinkLostMidSwingLeavesTheHeartbeatToStopTheTableAndKeepsTheData) {
  auto emu = startEmulator({"--link", "tcp", "--drop-link-after-start-s", "3"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("lost.fbs");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session, {"--table-heartbeat-s", "1"}));
  const int code = cli.finish(120);
  // The host cannot stop the table any more: the controller's watchdog does.
  EXPECT_FALSE(emu.child->waitForLine("(heartbeat: host quiet for more than 1 s; table brought to rest)", 30).empty())
      << emu.child->out;
  stopEmulator(emu);
  EXPECT_NE(emu.child->out.find("link: dropped"), std::string::npos);
  // The watchdog acted after the link was dropped, not before.
  EXPECT_LT(emu.child->out.find("link: dropped"), emu.child->out.find("heartbeat: host quiet"));
  EXPECT_TRUE(code == 0 || code == 1) << code << cli.err;
  EXPECT_NE(cli.err.find("run incomplete: table: point 1 (X 2 Hz / 2 deg): table link tcp:127.0.0.1:"), std::string::npos)
      << cli.err;
  EXPECT_NE(cli.err.find("emergency stop failed too"), std::string::npos) << cli.err;
  EXPECT_NE(cli.err.find("connection closed by the controller"), std::string::npos) << cli.err;
  EXPECT_NE(cli.err.find("WARNING: the table was not seen at rest"), std::string::npos) << cli.err;
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
  EXPECT_GT((*r)->rawByteCount(), 50000u) << "the board's stream is kept";
  EXPECT_TRUE(logHas(tableLog(session), "event", "out of step"));
}

TEST_F(TableBench, TheBoardVanishingMidSwingEndsTheRunAndTheBenchStopsTheTable) {
  auto emu = startEmulator({"--link", "tcp", "--board-vanish-after-start-s", "3"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("board-lost.fbs");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session));
  const int code = cli.finish(120);
  // The bench still reaches the table: it stops it itself (no heartbeat needed).
  ASSERT_FALSE(emu.child->waitForLine("(board: vanished)", 30).empty()) << emu.child->out;
  stopEmulator(emu);
  EXPECT_TRUE(code == 0 || code == 1) << cli.err;
  EXPECT_NE(cli.err.find("run incomplete: serial port"), std::string::npos) << cli.err;
  EXPECT_NE(cli.err.find("the board's stream ended"), std::string::npos) << cli.err;
  EXPECT_NE(cli.err.find("table step: table at rest"), std::string::npos) << cli.err;
  EXPECT_EQ(emu.child->out.find("heartbeat:"), std::string::npos) << emu.child->out;
  EXPECT_EQ(emu.child->out.find("swing: Y"), std::string::npos);
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
  EXPECT_GT((*r)->rawByteCount(), 50000u);
  const auto log = tableLog(session);
  EXPECT_TRUE(logHas(log, "command", "STOP"));
  EXPECT_TRUE(logHas(log, "step", "table at rest"));
}

TEST_F(TableBench, APlanBeyondTheTablesLimitsIsRefusedBeforeAnyMotion) {
  auto emu = startEmulator({"--link", "tcp", "--max-amplitude-deg", "20"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("limits.fbs");
  const auto plan = writePlan(R"({"points":[
    {"axis":"x","frequency_hz":1,"amplitude_deg":3,"duration_s":4,"settle_s":1},
    {"axis":"y","frequency_hz":0.5,"amplitude_deg":25,"duration_s":6,"settle_s":1}]})");
  Child cli(cliRun(emu, plan, session));
  EXPECT_EQ(cli.finish(60), 2);
  stopEmulator(emu);
  EXPECT_NE(cli.err.find("test point 2 (Y 0.5 Hz / 25 deg): amplitude is beyond the table's 20 deg on Y; the plan "
                         "was refused before any motion"),
            std::string::npos)
      << cli.err;
  EXPECT_FALSE(fs::exists(session)) << "nothing is recorded for a plan the table cannot run";
  EXPECT_EQ(emu.child->out.find("swing:"), std::string::npos);
  EXPECT_NE(emu.child->out.find("0 swings started"), std::string::npos) << emu.child->out;
}

// The frequency-response preset (issue 32) is made for the bench's default
// limits (its top points need 2400 deg/s^2, 80 % of 3000); a controller that
// allows 2000 deg/s^2 refuses it, whole, before anything moves. (The preset
// running through the table path is tests/core/table/response_plan_test.cpp.)
TEST_F(TableBench, TheResponsePresetBeyondTheControllersAccelerationIsRefusedBeforeAnyMotion) {
  auto emu = startEmulator({"--link", "tcp", "--max-accel-deg-s2", "2000"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("response.fbs");
  std::vector<std::string> argv = {FOG_CLI, "run", "--table", "remote:" + emu.table, "--source", "serial", "--port",
                                   emu.board, "--preset", "response", "--speed", "10", "--out", session};
  Child cli(argv);
  EXPECT_EQ(cli.finish(60), 2);
  stopEmulator(emu);
  EXPECT_NE(cli.err.find("fogbench-cli: test point 15 (X 2.66525 Hz / 8.558 deg): peak acceleration 2399.98 deg/s^2 "
                         "is beyond the table's 2000 deg/s^2 on X; the plan was refused before any motion"),
            std::string::npos)
      << cli.err;
  EXPECT_FALSE(fs::exists(session)) << "nothing is recorded for a plan the table cannot run";
  EXPECT_EQ(emu.child->out.find("swing:"), std::string::npos) << emu.child->out;
  EXPECT_NE(emu.child->out.find("0 swings started"), std::string::npos) << emu.child->out;
}

TEST_F(TableBench, CtrlCMidSwingBringsTheTableToRestAndKeepsTheSession) {
  auto emu = startEmulator({"--link", "tcp"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("stopped.fbs");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session));
  ASSERT_FALSE(emu.child->waitForLine("(swing: Y)", 60).empty()) << emu.child->out;
  ::kill(cli.pid(), SIGINT);
  const int code = cli.finish(60);
  stopEmulator(emu);
  EXPECT_EQ(code, 0) << "point 1 gives a delay\n" << cli.err;
  EXPECT_NE(cli.err.find("stopped by the operator"), std::string::npos) << cli.err;
  EXPECT_NE(cli.err.find("table step: table at rest"), std::string::npos) << cli.err;
  EXPECT_EQ(emu.child->out.find("swing: Z"), std::string::npos);
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
  EXPECT_TRUE(logHas(tableLog(session), "command", "STOP"));
}

TEST_F(TableBench, AnInterlockTrippedMidSwingStopsTheRun) {
  auto emu = startEmulator({"--link", "tcp", "--interlock-after-start-s", "2"});
  ASSERT_FALSE(emu.table.empty());
  const auto session = file("interlock.fbs");
  Child cli(cliRun(emu, writePlan(kThreeAxisPlan), session));
  const int code = cli.finish(60);
  stopEmulator(emu);
  EXPECT_TRUE(code == 0 || code == 1) << cli.err;
  EXPECT_NE(cli.err.find("the table controller reports interlock open"), std::string::npos) << cli.err;
  EXPECT_NE(emu.child->out.find("interlock: tripped"), std::string::npos);
  EXPECT_EQ(emu.child->out.find("swing: Y"), std::string::npos) << "nothing starts while the interlock is open";
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE((*r)->complete());
}

// A tiny client of the controller's protocol (the test's own hands on the
// emulated table).
class ProtocolClient {
 public:
  explicit ProtocolClient(const std::string& address) {
    if (address.rfind("tcp:127.0.0.1:", 0) != 0) return;
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_port = htons(static_cast<std::uint16_t>(std::stoi(address.substr(14))));
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) {
      ::close(fd_);
      fd_ = -1;
      return;
    }
    timeval tv{5, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  }
  ~ProtocolClient() {
    if (fd_ >= 0) ::close(fd_);
  }
  bool connected() const { return fd_ >= 0; }
  // Sends a line; for a query, returns its reply ("<no reply>" after 5 s).
  std::string ask(const std::string& line) {
    const std::string out = line + "\n";
    if (::send(fd_, out.data(), out.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(out.size())) return "<send failed>";
    if (line.find('?') == std::string::npos) return std::string();
    for (;;) {
      const auto nl = pending_.find('\n');
      if (nl != std::string::npos) {
        std::string reply = pending_.substr(0, nl);
        pending_.erase(0, nl + 1);
        return reply;
      }
      char buf[512];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) return std::string("<no reply>");
      pending_.append(buf, static_cast<std::size_t>(n));
    }
  }

 private:
  int fd_ = -1;
  std::string pending_;
};

// The manual driver over the whole path: the bench prints what to set, a
// scripted operator sets it on the (emulated) controller by hand, and the
// bench decides from the board's table angle alone when to record. The
// emulator's board sends no test-point markers.
TEST_F(TableBench, AManualTableFollowsThePrintedInstructionsAndIsCheckedFromTheStream) {
  auto emu = startEmulator({"--link", "tcp"});
  ASSERT_FALSE(emu.table.empty());
  ProtocolClient hands(emu.table);
  ASSERT_TRUE(hands.connected());
  const auto session = file("manual.fbs");
  const auto plan = writePlan(R"({"points":[
    {"axis":"x","frequency_hz":2,"amplitude_deg":2,"duration_s":4,"settle_s":1},
    {"axis":"z","frequency_hz":1,"amplitude_deg":3,"duration_s":4,"settle_s":1.5}],"rest_between_s":0.5})");
  Child cli({FOG_CLI, "run", "--table", "manual", "--source", "serial", "--port", emu.board, "--plan", plan,
             "--speed", "10", "--out", session, "--json"});
  const std::regex bring("bring the ([XYZ]) axis to ([-0-9.e]+) deg"),
      swing("set the ([XYZ]) axis to swing sinusoidally at ([0-9.e]+) Hz, amplitude ([0-9.e]+) deg about ([-0-9.e]+) deg"),
      stopAxis("stop the ([XYZ]) axis"), stopAll("stop every axis");
  std::size_t seen = 0;
  std::vector<std::string> told;
  auto act = [&] {
    for (auto nl = cli.err.find('\n', seen); nl != std::string::npos; nl = cli.err.find('\n', seen)) {
      const std::string line = cli.err.substr(seen, nl - seen);
      seen = nl + 1;
      const auto at = line.find("table operator: ");
      if (at == std::string::npos) continue;
      told.push_back(line.substr(at + 16));
      std::smatch m;
      if (std::regex_search(line, m, swing)) {
        hands.ask("AXIS:" + m[1].str() + ":SWING " + m[2].str() + "," + m[3].str() + "," + m[4].str());
        hands.ask("AXIS:" + m[1].str() + ":START");
      } else if (std::regex_search(line, m, bring)) {
        hands.ask("AXIS:" + m[1].str() + ":POS " + m[2].str());
      } else if (std::regex_search(line, m, stopAxis)) {
        hands.ask("AXIS:" + m[1].str() + ":STOP");
      } else if (std::regex_search(line, m, stopAll)) {
        hands.ask("STOP");
      }
      EXPECT_EQ(hands.ask("SYST:ERR?"), "0,\"No error\"") << "after: " << line;
    }
  };
  const auto giveUp = fog::test::Clock::now() + std::chrono::seconds(120);
  while (cli.pumpFor(0.02) && fog::test::Clock::now() < giveUp) act();
  ASSERT_EQ(cli.finish(10), 0) << cli.err;
  stopEmulator(emu);
  ASSERT_GE(told.size(), 6u);
  EXPECT_EQ(told[1], "On the table controller: set the X axis to swing sinusoidally at 2 Hz, amplitude 2 deg about 0 deg, "
                     "and start it. The bench records once the table-angle stream shows that swing.");
  EXPECT_NE(emu.child->out.find("swing: Z 1 Hz 3 deg"), std::string::npos);
  const auto report = nlohmann::json::parse(cli.out);
  const auto& points = report.at("test_points");
  ASSERT_EQ(points.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const double lag = points[i].at("lag_ms"), sd = points[i].at("lag_std_ms");
    EXPECT_NEAR(lag, emu.trueLagMs, std::max(5.0 * sd, 0.002)) << "point " << i + 1;
  }
  EXPECT_EQ(points[1].at("axis"), "z");
  auto r = fog::session::SessionReader::open(session);
  ASSERT_TRUE(r.isOk());
  EXPECT_TRUE((*r)->complete()) << (*r)->incompleteReason();
  EXPECT_NE((*r)->info().source.find("table manual"), std::string::npos);
  const auto log = tableLog(session);
  EXPECT_TRUE(logHas(log, "operator", "swing sinusoidally at 1 Hz, amplitude 3 deg"));
  EXPECT_TRUE(logHas(log, "step", "swing verified"));
}

// The controller's watchdog, over its own protocol: a host that goes quiet
// mid-swing gets its table stopped, and is told why.
TEST_F(TableBench, TheHeartbeatStopsTheTableWhenTheHostGoesQuiet) {
  auto emu = startEmulator({"--link", "tcp", "--board", "none"});
  ProtocolClient hands(emu.table);
  ASSERT_TRUE(hands.connected()) << emu.table;
  auto ask = [&](const std::string& line) { return hands.ask(line); };
  ask("SYST:HEART:TIM 0.5");
  ask("AXIS:X:SWING 1,3,0");
  ask("AXIS:X:START");
  EXPECT_EQ(ask("SYST:ERR?"), "0,\"No error\"");
  EXPECT_EQ(ask("AXIS:X:MODE?"), "SWING");
  // Quiet from here on: the emulator's own account says when it acted.
  ASSERT_FALSE(emu.child->waitForLine("(heartbeat: host quiet for more than 0.5 s; table brought to rest)", 30).empty())
      << emu.child->out;
  std::string mode;
  for (int i = 0; i < 100 && mode != "REST"; ++i) {
    mode = ask("AXIS:X:MODE?");
    if (mode != "REST") std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(mode, "REST");
  EXPECT_EQ(ask("SYST:STAT?"), "0,0,1,NONE");
  EXPECT_EQ(ask("SYST:ERR?"),
            "203,\"Heartbeat lost; the host was quiet for more than 0.5 s; table brought to rest\"");
  // Motion stays refused until the host clears the fault.
  ask("AXIS:X:START");
  EXPECT_EQ(ask("SYST:ERR?"), "203,\"Heartbeat lost\"");
  ask("*CLS");
  EXPECT_EQ(ask("SYST:STAT?"), "0,0,0,NONE");
  stopEmulator(emu);
}

}  // namespace

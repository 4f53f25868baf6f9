#include "core/table/remote_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "core/table/emulated_table.h"
#include "loopback_link.h"

namespace fog::table {
namespace {

using testing::ServerLink;

// Answers every query with the next scripted reply (raw bytes), or nothing.
class ScriptedLink : public ByteTransport {
 public:
  std::string description() const override { return "scripted"; }
  Status write(std::string_view bytes) override {
    written += bytes;
    for (char c : bytes)
      if (c == '\n' && !script.empty()) {
        out_ += script.front();
        script.pop_front();
      }
    return Status::ok();
  }
  Result<std::size_t> read(std::string& out, std::chrono::milliseconds) override {
    const std::size_t n = out_.size();
    out += out_;
    out_.clear();
    return n;
  }
  std::deque<std::string> script;
  std::string written;

 private:
  std::string out_;
};

struct Remote {
  double now = 0.0;
  EmulatedTable table;
  TableServer server;
  ServerLink* link = nullptr;
  std::vector<std::pair<std::string, std::string>> log;
  std::unique_ptr<RemoteTable> remote;
  explicit Remote(ServerFaults faults = {}) : server(table, faults) {
    auto l = std::make_unique<ServerLink>(server, now);
    link = l.get();
    auto r = RemoteTable::connect(std::move(l), RemoteOptions{std::chrono::milliseconds(50), 2.0},
                                  [this](const std::string& k, const std::string& t) { log.emplace_back(k, t); });
    EXPECT_TRUE(r.isOk()) << r.status().message();
    if (r) remote = std::move(*r);
  }
};

TEST(RemoteTable, ConnectsIdentifiesAndSetsTheHeartbeat) {
  Remote r;
  ASSERT_TRUE(r.remote);
  EXPECT_NE(r.remote->description().find("fogbench,table-emu"), std::string::npos);
  EXPECT_EQ(r.remote->query("SYST:HEART:TIM?").value(), "2");
}

TEST(RemoteTable, DrivesASwingAndReadsItsState) {
  Remote r;
  ASSERT_TRUE(r.remote->configureSwing(Axis::kY, {2.0, 1.5, 0.0}).isOk());
  ASSERT_TRUE(r.remote->startSwing(Axis::kY).isOk());
  r.now = 10.125;  // ramped up long ago; a quarter period past a whole number
  auto s = r.remote->state();
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_EQ(s->axis(Axis::kY).mode, AxisMode::kSwinging);
  EXPECT_NEAR(s->axis(Axis::kY).positionDeg, 1.5 * std::sin(2 * M_PI * 2.0 * (10.125 - 0.002)), 1e-6);
  EXPECT_EQ(s->axis(Axis::kX).mode, AxisMode::kRest);
  ASSERT_TRUE(r.remote->stop(Axis::kY).isOk());
  r.now = 12.0;
  s = r.remote->state();
  EXPECT_EQ(s->axis(Axis::kY).mode, AxisMode::kRest);
  EXPECT_EQ(s->axis(Axis::kY).rateDegPerS, 0.0);
  // The log holds the commands and a status line per change, not the polls.
  bool sawSwing = false, sawStatus = false;
  for (const auto& [kind, text] : r.log) {
    sawSwing |= kind == "command" && text == "AXIS:Y:SWING 2,1.5,0";
    sawStatus |= kind == "status" && text.find("Y swinging") != std::string::npos;
    EXPECT_NE(text, "SYST:STAT?");
  }
  EXPECT_TRUE(sawSwing);
  EXPECT_TRUE(sawStatus);
}

// The plan's start phase reaches the controller (a fourth SWING argument)
// and the emulated table's swing runs at that phase.
TEST(RemoteTable, TheStartPhaseIsCommandedAndTheSwingStartsThere) {
  Remote r;
  ASSERT_TRUE(r.remote->configureSwing(Axis::kX, {1.0, 2.0, 0.0, 90.0}).isOk());
  EXPECT_EQ(r.remote->query("AXIS:X:SWING?").value(), "1,2,0,90");
  ASSERT_TRUE(r.remote->startSwing(Axis::kX).isOk());
  r.now = 5.002;  // whole periods after the start, plus the servo lag: sin(90 deg)
  auto s = r.remote->state();
  ASSERT_TRUE(s.isOk()) << s.status().message();
  EXPECT_NEAR(s->axis(Axis::kX).positionDeg, 2.0, 1e-6);
  r.now = 5.252;  // a quarter period later: sin(180 deg)
  s = r.remote->state();
  EXPECT_NEAR(s->axis(Axis::kX).positionDeg, 0.0, 1e-6);
  // Without a phase the command keeps its three arguments.
  ASSERT_TRUE(r.remote->configureSwing(Axis::kY, {2.0, 1.0, 0.0}).isOk());
  bool withPhase = false, withoutPhase = false;
  for (const auto& [kind, text] : r.log) {
    withPhase |= kind == "command" && text == "AXIS:X:SWING 1,2,0,90";
    withoutPhase |= kind == "command" && text == "AXIS:Y:SWING 2,1,0";
  }
  EXPECT_TRUE(withPhase);
  EXPECT_TRUE(withoutPhase);
}

TEST(RemoteTable, ARefusedCommandComesBackWithTheControllersErrorAndTheQueueIsDrained) {
  ServerFaults f;
  f.refuseHeader = "AXIS:Y:START";
  Remote r(f);
  ASSERT_TRUE(r.remote->configureSwing(Axis::kY, {2.0, 1.5, 0.0}).isOk());
  auto s = r.remote->startSwing(Axis::kY);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "the table controller refused 'AXIS:Y:START': 204,\"Refused by the controller; AXIS:Y:START "
                         "refused (injected fault)\"");
  EXPECT_EQ(r.remote->query("SYST:ERR?").value(), "0,\"No error\"");
  // Out of range settings: the controller's own limits.
  auto big = r.remote->configureSwing(Axis::kX, {1.0, 90.0, 0.0});
  EXPECT_EQ(big.code(), StatusCode::kOutOfRange);
  EXPECT_NE(big.message().find("-222,\"Data out of range; amplitude beyond 45 deg\""), std::string::npos) << big.message();
  auto unknown = r.remote->command("AXIS:X:FLY 3");
  EXPECT_NE(unknown.message().find("-113,\"Undefined header"), std::string::npos);
}

TEST(RemoteTable, ReadsTheLimits) {
  Remote r;
  auto l = r.remote->limits();
  ASSERT_TRUE(l.isOk()) << l.status().message();
  EXPECT_EQ(l->axes[2].maxRateDegPerS, 400.0);
  EXPECT_EQ(l->maxPositionDeg, 180.0);
}

Result<std::unique_ptr<RemoteTable>> scripted(std::deque<std::string> replies, ScriptedLink** out = nullptr) {
  auto link = std::make_unique<ScriptedLink>();
  link->script = {"acme,table,7,1.0\n", "0,\"No error\"\n"};  // *IDN?, heartbeat confirmation
  for (auto& r : replies) link->script.push_back(r);
  if (out) *out = link.get();
  return RemoteTable::connect(std::move(link), RemoteOptions{std::chrono::milliseconds(30), 2.0});
}

TEST(RemoteTable, MalformedRepliesGiveAClearErrorNeverACrash) {
  struct Case {
    std::string reply;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {"0,0,0\n", "is not INTERLOCK,ESTOP,HEARTBEAT_LOST,FAULTS"},
      {"0,0,2,NONE\n", "'2' is not 0 or 1"},
      {std::string(400, 'x'), "longer than 256 bytes"},
      {"0,0,0,NONE\nFLY,1,2\n", "unknown axis mode 'FLY'"},
      {"0,0,0,NONE\nREST,abc,0\n", "'abc' is not a finite decimal number"},
      {"0,0,0,NONE\nREST,1\n", "is not MODE,POSITION_DEG,RATE_DEG_S"},
      {"0,0,0,NONE\nREST,1,nan\n", "not a finite decimal number"},
      {std::string("0,0,\x01,NONE\n"), "control or non-ASCII byte"},
  };
  for (const auto& c : cases) {
    auto t = scripted({c.reply});
    ASSERT_TRUE(t.isOk()) << t.status().message();
    auto s = (*t)->state();
    ASSERT_FALSE(s.isOk()) << c.reply;
    EXPECT_NE(s.status().message().find(c.expect), std::string::npos) << s.status().message();
    // Out of step: later calls fail at once, naming why.
    EXPECT_FALSE((*t)->moveTo(Axis::kX, 0.0).isOk());
  }
}

TEST(RemoteTable, SilenceIsABoundedTimeout) {
  auto t = scripted({});
  ASSERT_TRUE(t.isOk());
  auto s = (*t)->state();
  EXPECT_EQ(s.status().code(), StatusCode::kIoError);
  EXPECT_NE(s.status().message().find("no reply from the table controller at scripted to 'SYST:STAT?' within 30 ms"),
            std::string::npos)
      << s.status().message();
}

TEST(RemoteTable, AnIdentityThatIsNotAControllersIsRefused) {
  auto link = std::make_unique<ScriptedLink>();
  link->script = {"hello\n"};
  auto t = RemoteTable::connect(std::move(link), RemoteOptions{std::chrono::milliseconds(30), 2.0});
  EXPECT_FALSE(t.isOk());
  EXPECT_NE(t.status().message().find("not MAKER,MODEL,SERIAL,VERSION"), std::string::npos);
}

TEST(RemoteTable, StopStillGoesOutWhenTheLinkIsOutOfStep) {
  ScriptedLink* link = nullptr;
  auto t = scripted({"garbage\n"}, &link);
  ASSERT_TRUE(t.isOk());
  EXPECT_FALSE((*t)->state().isOk());
  EXPECT_FALSE((*t)->stopAll().isOk());
  EXPECT_NE(link->written.rfind("STOP\n"), std::string::npos);
}

TEST(RemoteTable, ALostLinkIsAnIoError) {
  Remote r;
  r.link->closed = true;
  auto s = r.remote->state();
  EXPECT_EQ(s.status().code(), StatusCode::kIoError);
  EXPECT_NE(s.status().message().find("lost"), std::string::npos);
}

}  // namespace
}  // namespace fog::table

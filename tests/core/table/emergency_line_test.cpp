#include "core/table/emergency_line.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <thread>

#include "fake_tcp_controller.h"

namespace fog::table {
namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// A controller that answers: the emergency stop is written, arrives on a
// connection of its own, and is confirmed by SYST:STAT? (nothing is taken
// from the error queue).
TEST(EmergencyLine, SendsOnAConnectionOfItsOwnAndReadsTheConfirmation) {
  fogtest::FakeTableController controller;
  ASSERT_TRUE(controller.listening());
  const auto out = sendEmergencyStop(controller.address());
  EXPECT_TRUE(out.sent) << out.why;
  EXPECT_TRUE(out.confirmed) << out.why;
  EXPECT_LT(out.sentAfterMs, 50.0);
  const auto lines = controller.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].text, "SYST:ESTOP");
  EXPECT_EQ(lines[1].text, "SYST:STAT?");
}

// A controller that takes the connection and never answers: the emergency
// stop is still written at once; the confirmation gives up after its timeout.
TEST(EmergencyLine, AHungControllerGetsItAndTheConfirmationTimesOut) {
  fogtest::FakeTableController controller(/*hangFromStart=*/true);
  EmergencyLineOptions options;
  options.confirmTimeout = std::chrono::milliseconds(200);
  const auto start = Clock::now();
  const auto out = sendEmergencyStop(controller.address(), options);
  const double tookMs = msBetween(start, Clock::now());
  EXPECT_TRUE(out.sent) << out.why;
  EXPECT_FALSE(out.confirmed);
  EXPECT_NE(out.why.find("no answer to SYST:STAT? within 200 ms"), std::string::npos) << out.why;
  EXPECT_GE(tookMs, 190.0);  // (poll() waits whole milliseconds)
  EXPECT_LT(tookMs, 1000.0);
  const auto estop = controller.firstLine("SYST:ESTOP");
  ASSERT_FALSE(estop.text.empty());
  EXPECT_LT(msBetween(start, estop.at), 50.0);
}

// Nobody listens: not sent, with the system's reason, at once.
TEST(EmergencyLine, NoControllerIsAClearFailure) {
  int port = 0;
  {
    fogtest::FakeTableController gone;
    port = std::stoi(gone.address().substr(gone.address().rfind(':') + 1));
  }
  const auto out = sendEmergencyStop("tcp:127.0.0.1:" + std::to_string(port));
  EXPECT_FALSE(out.sent);
  EXPECT_NE(out.why.find("cannot connect"), std::string::npos) << out.why;
  EXPECT_LT(out.sentAfterMs, 1000.0);
}

// fire() returns at once and the outcome comes on the line's thread.
TEST(EmergencyLine, FireNeverBlocksAndReportsOnItsOwnThread) {
  fogtest::FakeTableController controller(/*hangFromStart=*/true);
  std::mutex m;
  std::condition_variable cv;
  std::vector<EmergencyOutcome> outcomes;
  EmergencyLineOptions options;
  options.confirmTimeout = std::chrono::milliseconds(300);
  EmergencyLine line(
      [&](const EmergencyOutcome& o) {
        std::lock_guard<std::mutex> lock(m);
        outcomes.push_back(o);
        cv.notify_all();
      },
      options);
  const auto start = Clock::now();
  line.fire(controller.address());
  EXPECT_LT(msBetween(start, Clock::now()), 20.0);
  std::unique_lock<std::mutex> lock(m);
  ASSERT_TRUE(cv.wait_for(lock, std::chrono::seconds(5), [&] { return !outcomes.empty(); }));
  EXPECT_TRUE(outcomes[0].sent);
  EXPECT_FALSE(outcomes[0].confirmed);
  EXPECT_EQ(outcomes[0].address, controller.address());
}

// Armed, the line holds a connection of its own and a fire only writes on
// it: a controller that has hung and takes no new connection (a full queue
// of connections to accept, a controller with one session) still gets the
// emergency stop; without the armed connection it would not.
TEST(EmergencyLine, AnArmedLineStillReachesAControllerThatTakesNoNewConnection) {
  fogtest::FakeTableController controller;
  std::mutex m;
  std::condition_variable cv;
  std::vector<EmergencyOutcome> outcomes;
  EmergencyLineOptions options;
  options.confirmTimeout = std::chrono::milliseconds(200);
  EmergencyLine line(
      [&](const EmergencyOutcome& o) {
        std::lock_guard<std::mutex> lock(m);
        outcomes.push_back(o);
        cv.notify_all();
      },
      options);
  line.arm(controller.address());
  const auto waitFor = [](const auto& done) {
    for (int i = 0; i < 500 && !done(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  };
  waitFor([&] { return !line.armedAt().empty(); });
  ASSERT_EQ(line.armedAt(), controller.address());
  waitFor([&] { return controller.connections() >= 1; });
  ASSERT_EQ(controller.connections(), 1);
  controller.hang();
  controller.stopListening();
  const auto start = Clock::now();
  line.fire(controller.address());
  std::unique_lock<std::mutex> lock(m);
  ASSERT_TRUE(cv.wait_for(lock, std::chrono::seconds(5), [&] { return !outcomes.empty(); }));
  EXPECT_TRUE(outcomes[0].sent) << outcomes[0].why;
  EXPECT_TRUE(outcomes[0].armedLink);
  EXPECT_FALSE(outcomes[0].confirmed);  // hung: no answer to SYST:STAT?
  const auto estop = controller.firstLine("SYST:ESTOP");
  ASSERT_FALSE(estop.text.empty());
  EXPECT_EQ(estop.connection, 1);
  EXPECT_LT(msBetween(start, estop.at), 50.0);
  // The same fire from a line that holds no connection: refused.
  const auto unarmed = sendEmergencyStop(controller.address());
  EXPECT_FALSE(unarmed.sent);
  EXPECT_NE(unarmed.why.find("cannot connect"), std::string::npos) << unarmed.why;
}


// The outcomes a line reports, collected on its thread.
struct Outcomes {
  std::mutex m;
  std::condition_variable cv;
  std::vector<EmergencyOutcome> got;
  EmergencyLine::DoneFn fn() {
    return [this](const EmergencyOutcome& o) {
      std::lock_guard<std::mutex> lock(m);
      got.push_back(o);
      cv.notify_all();
    };
  }
  bool waitFor(std::size_t n) {
    std::unique_lock<std::mutex> lock(m);
    return cv.wait_for(lock, std::chrono::seconds(5), [&] { return got.size() >= n; });
  }
};

// The ordinary stop on the line: "STOP" written at once on the armed
// connection of a controller that has hung, and not confirmed there (the
// panel's own link confirms it when the controller answers): no SYST:STAT?.
TEST(EmergencyLine, AnOrdinaryStopGoesOutAtOnceOnTheArmedConnection) {
  fogtest::FakeTableController controller;
  Outcomes outcomes;
  EmergencyLine line(outcomes.fn());
  line.arm(controller.address());
  for (int i = 0; i < 500 && line.armedAt().empty(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(line.armedAt(), controller.address());
  controller.hang();
  const auto start = Clock::now();
  line.fire(controller.address(), LineCommand::kStopAll);
  ASSERT_TRUE(outcomes.waitFor(1));
  const EmergencyOutcome o = outcomes.got[0];
  EXPECT_EQ(o.command, LineCommand::kStopAll);
  EXPECT_TRUE(o.sent) << o.why;
  EXPECT_TRUE(o.armedLink);
  EXPECT_FALSE(o.confirmed);
  EXPECT_TRUE(o.why.empty()) << o.why;
  // (the fake's own thread reads and times the line a moment after the write)
  for (int i = 0; i < 500 && controller.firstLine("STOP").text.empty(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const auto stop = controller.firstLine("STOP");
  ASSERT_FALSE(stop.text.empty());
  EXPECT_LT(msBetween(start, stop.at), 50.0);
  EXPECT_TRUE(controller.firstLine("SYST:ESTOP").text.empty());
  EXPECT_TRUE(controller.firstLine("SYST:STAT?").text.empty());
}

// Fires that arrive while a send is under way merge into one more send: an
// emergency stop takes the place of a pending ordinary stop, and a stop
// asked after a pending emergency stop leaves it one.
TEST(EmergencyLine, AnEmergencyStopTakesThePlaceOfAPendingStopNeverTheOtherWayRound) {
  fogtest::FakeTableController controller(/*hangFromStart=*/true);
  EmergencyLineOptions options;
  options.confirmTimeout = std::chrono::milliseconds(300);  // each emergency stop's send waits this long
  Outcomes outcomes;
  EmergencyLine line(outcomes.fn(), options);
  for (const LineCommand second : {LineCommand::kStopAll, LineCommand::kEmergencyStop}) {
    const std::size_t before = outcomes.got.size();
    line.fire(controller.address());  // under way for 300 ms, waiting for its confirmation
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    line.fire(controller.address(), second);
    line.fire(controller.address(), second == LineCommand::kStopAll ? LineCommand::kEmergencyStop
                                                                     : LineCommand::kStopAll);
    ASSERT_TRUE(outcomes.waitFor(before + 2));
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // no third send
    std::lock_guard<std::mutex> lock(outcomes.m);
    ASSERT_EQ(outcomes.got.size(), before + 2);
    EXPECT_EQ(outcomes.got[before + 1].command, LineCommand::kEmergencyStop);
    EXPECT_TRUE(outcomes.got[before + 1].sent) << outcomes.got[before + 1].why;
  }
  EXPECT_TRUE(controller.firstLine("STOP").text.empty());
}

}  // namespace
}  // namespace fog::table

#include "core/table/plan_runner.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "fake_table.h"

namespace fog::table {
namespace {

using testing::FakeClock;
using testing::FakeController;
using testing::ScriptedRecorder;

TestPlan threeAxisPlan() {
  TestPlan plan;
  plan.restBetweenS = 1.0;
  plan.points = {TestPoint{Axis::kX, 1.0, 3.0, 4.0, 2.0}, TestPoint{Axis::kY, 2.0, 2.0, 3.0, 1.0},
                 TestPoint{Axis::kZ, 0.5, 5.0, 6.0, 2.0}};
  return plan;
}

struct Bench {
  FakeClock clock;
  FakeController table{clock};
  ScriptedRecorder recorder{clock};
  std::vector<std::string> lines;
  PlanRunner runner{table, clock, recorder, RunnerOptions{}, [this](const std::string& l) { lines.push_back(l); }};
};

TEST(PlanRunner, RunsEachPointInOrderPositionSwingRecordStopRest) {
  Bench b;
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  EXPECT_EQ(r.pointsDone, 3);
  EXPECT_TRUE(r.tableAtRest);
  EXPECT_EQ(b.table.log, (std::vector<std::string>{"move x", "swing x", "start x", "stop x", "move y", "swing y",
                                                   "start y", "stop y", "move z", "swing z", "start z", "stop z",
                                                   "release"}));
  EXPECT_EQ(b.recorder.began, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(b.recorder.ended, (std::vector<int>{0, 1, 2}));
  // Recording begins after positioning (0.5 s) and the settle time (2 s).
  EXPECT_GE(b.recorder.beganAt[0], 0.5 + 2.0);
  EXPECT_LT(b.recorder.beganAt[0], 0.5 + 2.0 + 0.2);
  // ... and the next point only after the stop, the rest (1 s) and positioning.
  EXPECT_GE(b.recorder.beganAt[1], b.recorder.beganAt[0] + 4.0 + 0.5 + 1.0 + 0.5 + 1.0);
  EXPECT_EQ(b.table.swing.frequencyHz, 0.5);
  EXPECT_FALSE(b.table.anyMoving());
}

// The plan's start phase is part of the swing commanded (brought within
// -180 .. 180 deg: 450 deg is 90 deg).
TEST(PlanRunner, CommandsThePointsStartPhase) {
  Bench b;
  TestPlan plan = threeAxisPlan();
  plan.points.resize(1);
  plan.points[0].startPhaseDeg = 450.0;
  auto r = b.runner.run(plan, nullptr);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  EXPECT_EQ(b.table.swing.startPhaseDeg, 90.0);
  EXPECT_EQ(b.table.swing.frequencyHz, 1.0);
}

TEST(PlanRunner, SendsHeartbeatsWhileItWaits) {
  Bench b;
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  ASSERT_TRUE(r.status.isOk());
  ASSERT_GT(b.table.heartbeatTimes.size(), 10u);
  double largestGap = 0.0;
  for (std::size_t i = 1; i < b.table.heartbeatTimes.size(); ++i)
    largestGap = std::max(largestGap, b.table.heartbeatTimes[i] - b.table.heartbeatTimes[i - 1]);
  EXPECT_LE(largestGap, RunnerOptions{}.heartbeatIntervalS + RunnerOptions{}.pollIntervalS + 1e-9);
}

TEST(PlanRunner, APlanBeyondTheLimitsIsRefusedBeforeAnyMotion) {
  Bench b;
  b.table.tableLimits.axes[1].maxRateDegPerS = 20.0;  // Y: 2 Hz * 2 deg needs 25.1 deg/s
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  EXPECT_EQ(r.status.code(), StatusCode::kOutOfRange);
  EXPECT_NE(r.status.message().find("test point 2 (Y 2 Hz / 2 deg): peak rate 25.1327 deg/s is beyond the table's 20 deg/s"),
            std::string::npos)
      << r.status.message();
  EXPECT_TRUE(b.table.log.empty()) << "no command may reach the table";
  EXPECT_EQ(r.pointsDone, 0);
}

TEST(PlanRunner, ARefusedCommandStopsTheRunAndBringsTheTableToRest) {
  Bench b;
  b.table.refuseWhat = "start";
  TestPlan plan = threeAxisPlan();
  auto r = b.runner.run(plan, nullptr);
  EXPECT_FALSE(r.status.isOk());
  EXPECT_EQ(r.status.message(), "point 1 (X 1 Hz / 3 deg): the table controller refused 'start'");
  EXPECT_EQ(b.table.log.back(), "stopAll");
  EXPECT_TRUE(r.tableAtRest);
  EXPECT_TRUE(b.recorder.began.empty());
}

TEST(PlanRunner, TheStopFlagStopsTheTableMidSwing) {
  Bench b;
  std::atomic<bool> stop{false};
  b.recorder.neverDone = true;
  // The flag is raised from the recorder's side once recording has begun.
  struct Raise : ScriptedRecorder {
    using ScriptedRecorder::ScriptedRecorder;
    std::atomic<bool>* flag = nullptr;
    RecorderProgress poll() override {
      if (clock_.now > beganAt.back() + 1.0) flag->store(true);
      return {};
    }
  } rec(b.clock);
  rec.flag = &stop;
  PlanRunner runner(b.table, b.clock, rec);
  auto r = runner.run(threeAxisPlan(), &stop);
  EXPECT_EQ(r.status.message(), "stopped by the operator");
  EXPECT_TRUE(r.tableAtRest);
  EXPECT_FALSE(b.table.anyMoving());
  EXPECT_EQ(rec.ended, (std::vector<int>{0}));
}

// The GUI's emergency stop while the runner holds the controller: the next
// step ends the run and sends the emergency stop, not the decelerating stop.
TEST(PlanRunner, TheEmergencyFlagEmergencyStopsTheTableMidSwing) {
  Bench b;
  std::atomic<bool> emergency{false};
  struct Raise : ScriptedRecorder {
    using ScriptedRecorder::ScriptedRecorder;
    std::atomic<bool>* flag = nullptr;
    RecorderProgress poll() override {
      if (clock_.now > beganAt.back() + 1.0) flag->store(true);
      return {};
    }
  } rec(b.clock);
  rec.flag = &emergency;
  PlanRunner runner(b.table, b.clock, rec);
  runner.setEmergencyFlag(&emergency);
  auto r = runner.run(threeAxisPlan(), nullptr);
  EXPECT_EQ(r.status.message(), "emergency stop by the operator");
  EXPECT_TRUE(r.tableAtRest);
  EXPECT_EQ(b.table.log.back(), "estop");
  EXPECT_TRUE(std::find(b.table.log.begin(), b.table.log.end(), "stopAll") == b.table.log.end())
      << "an emergency stop is not the decelerating stop";
  EXPECT_EQ(std::count_if(b.table.log.begin(), b.table.log.end(), [](const std::string& s) { return s.rfind("start", 0) == 0; }),
            1);  // the first point's swing only
  // Raised 1 s into the recording (after a 0.5 s move and 2 s of settling),
  // honoured at the next poll: long before the 4-s recording would end.
  EXPECT_LT(b.clock.now, 0.5 + 2.0 + 1.0 + 2 * RunnerOptions{}.pollIntervalS + 1e-9);
  EXPECT_EQ(rec.ended, (std::vector<int>{0}));
}

TEST(PlanRunner, AnInterlockStopsTheRunAndNothingElseStarts) {
  Bench b;
  b.table.base.interlockOpen = true;
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  EXPECT_NE(r.status.message().find("interlock open"), std::string::npos) << r.status.message();
  EXPECT_TRUE(std::none_of(b.table.log.begin(), b.table.log.end(),
                           [](const std::string& s) { return s.rfind("start", 0) == 0 || s.rfind("move", 0) == 0; }));
}

// The remote driver reads the controller's flags before the axes: an
// interlock that trips between the two reads shows the axis at rest with no
// reason. The runner reads the state once more and names the controller's.
TEST(PlanRunner, AnAxisTheControllerStoppedIsReportedWithTheControllersReason) {
  struct Tripping : FakeController {
    using FakeController::FakeController;
    double tripAtS = 4.0;  // mid-recording of point 1 (0.5 s move, 2 s settle, 4 s duration)
    int readsSinceTrip = 0;
    Result<TableState> state() override {
      if (clock_.now < tripAtS) return FakeController::state();
      for (auto& c : cmd) c = {AxisMode::kRest, c.target, c.since};  // the controller stopped the table
      auto s = FakeController::state();
      if (s) s->interlockOpen = readsSinceTrip++ > 0;  // the first read's flags predate the trip
      return s;
    }
  };
  FakeClock clock;
  Tripping table(clock);
  ScriptedRecorder recorder(clock);
  PlanRunner runner(table, clock, recorder);
  auto r = runner.run(threeAxisPlan(), nullptr);
  EXPECT_EQ(r.status.message(), "point 1 (X 1 Hz / 3 deg): the table controller reports interlock open");
  EXPECT_EQ(table.readsSinceTrip, 3) << "the read that saw the stop, the one after it, and the final rest check";
  EXPECT_EQ(r.pointsDone, 0);
}

TEST(PlanRunner, ALostLinkTriesStopThenEmergencyStop) {
  Bench b;
  b.table.failStateAfter = 8;  // mid-swing
  b.table.failStopAll = true;
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  EXPECT_EQ(r.status.code(), StatusCode::kIoError);
  EXPECT_FALSE(r.tableAtRest);
  ASSERT_GE(b.table.log.size(), 2u);
  EXPECT_EQ(b.table.log[b.table.log.size() - 2], "stopAll");
  EXPECT_EQ(b.table.log.back(), "estop");
}

TEST(PlanRunner, TheBoardStreamFailingStopsTheTable) {
  Bench b;
  b.recorder.failure = "serial port vanished";
  b.recorder.failAtS = 3.0;
  auto r = b.runner.run(threeAxisPlan(), nullptr);
  EXPECT_NE(r.status.message().find("serial port vanished"), std::string::npos);
  EXPECT_EQ(b.table.log.back(), "stopAll");
  EXPECT_TRUE(r.tableAtRest);
}

TEST(PlanRunner, ARecordingThatNeverCompletesTimesOut) {
  Bench b;
  b.recorder.neverDone = true;
  RunnerOptions o;
  o.recordMarginS = 5.0;
  PlanRunner runner(b.table, b.clock, b.recorder, o);
  auto r = runner.run(threeAxisPlan(), nullptr);
  EXPECT_NE(r.status.message().find("not recorded within 9 s"), std::string::npos) << r.status.message();
  EXPECT_TRUE(r.tableAtRest);
}

TEST(PlanRunner, TheTableGoesToEachPointsPositionAndSwingsAboutIt) {
  Bench b;
  TestPlan plan;
  TestPoint p{Axis::kY, 1.0, 2.0, 3.0, 1.0};
  p.positionDeg = {10.0, -4.0, -5.0};
  plan.points = {p};
  auto r = b.runner.run(plan, nullptr);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  EXPECT_EQ(b.table.log, (std::vector<std::string>{"move x", "move y", "move z", "swing y", "start y", "stop y", "release"}));
  EXPECT_EQ(b.table.swing.centreDeg, -4.0);
  EXPECT_EQ(b.table.cmd[0].target, 10.0);
  EXPECT_EQ(b.table.cmd[2].target, -5.0);
  bool said = false;
  for (const auto& l : b.lines) said |= l.find("move X to 10 deg, Y to -4 deg, Z to -5 deg") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(PlanRunner, APositionBeyondTheTablesRangeIsRefusedBeforeAnyMotion) {
  Bench b;
  b.table.tableLimits.maxPositionDeg = 90.0;
  TestPlan plan = threeAxisPlan();
  plan.points[2].positionDeg = {0.0, 0.0, 88.0};  // 88 + 5 deg of swing
  auto r = b.runner.run(plan, nullptr);
  EXPECT_EQ(r.status.code(), StatusCode::kOutOfRange);
  EXPECT_NE(r.status.message().find("test point 3 (Z 0.5 Hz / 5 deg): the swing leaves the table's +-90 deg"),
            std::string::npos)
      << r.status.message();
  EXPECT_TRUE(b.table.log.empty());
}

TEST(PlanRunner, AStaticPointHoldsTheAxisAtRest) {
  Bench b;
  TestPlan plan;
  plan.points = {TestPoint::staticSegment(Axis::kY, 10.0)};
  auto r = b.runner.run(plan, nullptr);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  EXPECT_EQ(b.table.log, (std::vector<std::string>{"move y", "release"}));
}

}  // namespace
}  // namespace fog::table

#pragma once
// Test doubles for the plan runner: a fake controller that models motion
// instantly on a fake clock, a clock that advances only when slept on, and a
// scripted recorder.

#include <string>
#include <vector>

#include "core/table/plan_runner.h"

namespace fog::table::testing {

class FakeClock : public RunnerClock {
 public:
  double nowS() override { return now; }
  void sleepS(double s) override {
    if (s > 0.0) now += s;
    ++sleeps;
  }
  double now = 0.0;
  int sleeps = 0;
};

// A table whose axes reach their commanded state after `moveS` seconds.
class FakeController : public TableController {
 public:
  explicit FakeController(FakeClock& clock) : clock_(clock) {}
  std::string description() const override { return "fake"; }
  Result<std::string> identify() override { return std::string("fake,table,1,1"); }
  Result<TableLimits> limits() override { return tableLimits; }
  Result<TableState> state() override {
    ++stateCalls;
    if (failStateAfter >= 0 && stateCalls > failStateAfter) return ioError("link lost (fake)");
    TableState s = base;
    for (int a = 0; a < kAxisCount; ++a) {
      auto& ax = s.axes[static_cast<std::size_t>(a)];
      const auto& c = cmd[static_cast<std::size_t>(a)];
      const bool settled = clock_.now >= c.since + moveS;
      ax.mode = c.mode == AxisMode::kPositioning || c.mode == AxisMode::kStopping
                    ? (settled ? AxisMode::kRest : c.mode)
                    : c.mode;
      ax.positionDeg = c.mode == AxisMode::kPositioning && !settled ? c.target + 1.0 : c.target;
      ax.rateDegPerS = ax.mode == AxisMode::kRest || ax.mode == AxisMode::kEmergencyStop ? 0.0 : 5.0;
    }
    return s;
  }
  Status configureSwing(Axis a, const SwingSpec& s) override {
    log.push_back(std::string("swing ") + axisName(a));
    swing = s;
    return refuse("swing");
  }
  Status moveTo(Axis a, double p) override {
    log.push_back(std::string("move ") + axisName(a));
    if (auto s = refuse("move"); !s.isOk()) return s;
    cmd[static_cast<std::size_t>(a)] = {AxisMode::kPositioning, p, clock_.now};
    return Status::ok();
  }
  Status startSwing(Axis a) override {
    log.push_back(std::string("start ") + axisName(a));
    if (auto s = refuse("start"); !s.isOk()) return s;
    cmd[static_cast<std::size_t>(a)] = {AxisMode::kSwinging, 0.0, clock_.now};
    return Status::ok();
  }
  Status stop(Axis a) override {
    log.push_back(std::string("stop ") + axisName(a));
    cmd[static_cast<std::size_t>(a)] = {AxisMode::kStopping, 0.0, clock_.now};
    return Status::ok();
  }
  Status stopAll() override {
    log.push_back("stopAll");
    if (failStopAll) return ioError("link lost (fake)");
    for (auto& c : cmd)
      if (c.mode != AxisMode::kRest) c = {AxisMode::kStopping, 0.0, clock_.now};
    return Status::ok();
  }
  // Every axis stops at once and latches (at rest in the runner's eyes).
  Status emergencyStop() override {
    log.push_back("estop");
    for (auto& c : cmd) c = {AxisMode::kEmergencyStop, c.target, clock_.now};
    base.emergencyStopped = true;
    return Status::ok();
  }
  Status keepAlive() override {
    ++heartbeats;
    heartbeatTimes.push_back(clock_.now);
    return Status::ok();
  }

  Status release() override {
    log.push_back("release");
    return Status::ok();
  }
  Status refuse(const std::string& what) {
    if (what == refuseWhat && refuseCount-- > 0) return invalidArgument("the table controller refused '" + what + "'");
    return Status::ok();
  }
  bool anyMoving() const {
    for (const auto& c : cmd)
      if (c.mode == AxisMode::kSwinging) return true;
    return false;
  }

  struct Cmd {
    AxisMode mode = AxisMode::kRest;
    double target = 0.0;
    double since = 0.0;
  };
  FakeClock& clock_;
  std::array<Cmd, kAxisCount> cmd{};
  TableState base;
  TableLimits tableLimits;
  SwingSpec swing;
  double moveS = 0.5;
  std::vector<std::string> log;
  std::string refuseWhat;
  int refuseCount = 1;
  int stateCalls = 0;
  int failStateAfter = -1;
  bool failStopAll = false;
  int heartbeats = 0;
  std::vector<double> heartbeatTimes;
};

// Records a point `recordS` after begin(), on the fake clock.
class ScriptedRecorder : public PointRecorder {
 public:
  explicit ScriptedRecorder(FakeClock& clock) : clock_(clock) {}
  Status begin(int index, const TestPoint& point) override {
    began.push_back(index);
    beganAt.push_back(clock_.now);
    until_ = clock_.now + point.durationS;
    return Status::ok();
  }
  RecorderProgress poll() override {
    RecorderProgress p;
    if (!failure.empty() && clock_.now >= failAtS) p.failure = ioError(failure);
    p.done = neverDone ? false : clock_.now >= until_;
    return p;
  }
  void end(int index) override { ended.push_back(index); }

  FakeClock& clock_;
  double until_ = 0.0;
  std::vector<int> began, ended;
  std::vector<double> beganAt;
  std::string failure;
  double failAtS = 0.0;
  bool neverDone = false;
};

}  // namespace fog::table::testing

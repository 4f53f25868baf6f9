// The frequency-response preset (issue 32) through the table path, in
// process: the plan runner -> the remote driver -> the protocol -> the
// emulated controller and table (fogbench-table-emu's parts, its default
// limits). The board's table angle (the emulated table's actual angle at
// 1 kHz) reaches the stream recorder kLatencyS late, as it does over a
// serial port (at --speed 10 the host sees the stream some 0.1 .. 0.5 table
// seconds late). A fake clock: the 13-minute plan runs in about a second.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "core/common/units.h"
#include "core/table/emulated_table.h"
#include "core/table/plan_runner.h"
#include "core/table/remote_table.h"
#include "core/table/scpi.h"
#include "core/table/stream_recorder.h"
#include "fake_table.h"
#include "loopback_link.h"

namespace fog::table {
namespace {

constexpr double kLatencyS = 0.4;
constexpr double kSampleS = 1e-3;

// Plan time = table time = board time; sleeping delivers the board's table
// samples up to now - latencyS(now) to the recorder (and keeps them).
class StreamingClock : public testing::FakeClock {
 public:
  StreamingClock(const EmulatedTable& table, StreamPointRecorder& recorder) : table_(table), recorder_(recorder) {}
  void sleepS(double s) override {
    FakeClock::sleepS(s);
    std::vector<TableSample> batch;
    for (; next_ <= now - latencyS(now); next_ += kSampleS) {
      TableSample x;
      x.timeS = next_;
      for (int a = 0; a < kAxisCount; ++a)
        x.angleDeg[static_cast<std::size_t>(a)] = table_.angleDeg(static_cast<Axis>(a), next_);
      batch.push_back(x);
      const double rate = table_.rateDegPerS(Axis::kX, next_);
      if (havePrevious_) peakAccelDegPerS2 = std::max(peakAccelDegPerS2, std::abs(rate - previousRate_) / kSampleS);
      peakRateDegPerS = std::max(peakRateDegPerS, std::abs(rate));
      previousRate_ = rate;
      havePrevious_ = true;
    }
    recorder_.addTableSamples(batch);
    samples.insert(samples.end(), batch.begin(), batch.end());
  }
  std::function<double(double)> latencyS = [](double) { return kLatencyS; };  // at host time `now`
  std::vector<TableSample> samples;
  double peakRateDegPerS = 0.0, peakAccelDegPerS2 = 0.0;  // X, over the whole run (ramps and stops too)

 private:
  const EmulatedTable& table_;
  StreamPointRecorder& recorder_;
  double next_ = 0.0, previousRate_ = 0.0;
  bool havePrevious_ = false;
};

// The controller as the runner sees it, with what it was asked and when.
class Witness : public TableController {
 public:
  Witness(TableController& inner, testing::FakeClock& clock) : inner_(inner), clock_(clock) {}
  std::string description() const override { return inner_.description(); }
  Result<std::string> identify() override { return inner_.identify(); }
  Result<TableLimits> limits() override { return inner_.limits(); }
  Result<TableState> state() override { return inner_.state(); }
  Status configureSwing(Axis axis, const SwingSpec& swing) override {
    motion.push_back("swing");
    swings.push_back(swing);
    return inner_.configureSwing(axis, swing);
  }
  Status moveTo(Axis axis, double positionDeg) override {
    motion.push_back("move");
    return inner_.moveTo(axis, positionDeg);
  }
  Status startSwing(Axis axis) override {
    motion.push_back("start");
    startedAtS.push_back(clock_.now);
    return inner_.startSwing(axis);
  }
  Status stop(Axis axis) override {
    motion.push_back("stop");
    return inner_.stop(axis);
  }
  Status stopAll() override {
    motion.push_back("stopAll");
    return inner_.stopAll();
  }
  Status emergencyStop() override {
    motion.push_back("estop");
    return inner_.emergencyStop();
  }
  Status keepAlive() override { return inner_.keepAlive(); }
  Status release() override { return inner_.release(); }
  double swingRampS(const SwingSpec& swing) const override { return inner_.swingRampS(swing); }

  std::vector<std::string> motion;
  std::vector<SwingSpec> swings;
  std::vector<double> startedAtS;

 private:
  TableController& inner_;
  testing::FakeClock& clock_;
};

struct EmulatorBench {
  EmulatedTable table;
  TableServer server{table};
  StreamPointRecorder recorder;
  StreamingClock clock{table, recorder};
  testing::ServerLink* link = nullptr;
  std::unique_ptr<RemoteTable> remote;
  std::unique_ptr<Witness> witness;
  std::vector<std::string> lines;

  explicit EmulatorBench(EmulatedTableParams params = {}) : table(params) {
    auto l = std::make_unique<testing::ServerLink>(server, clock.now);
    link = l.get();
    auto r = RemoteTable::connect(std::move(l), RemoteOptions{std::chrono::milliseconds(50), 2.0});
    EXPECT_TRUE(r.isOk()) << r.status().message();
    if (r) remote = std::move(*r);
    witness = std::make_unique<Witness>(*remote, clock);
    recorder.setHostClock(&clock);  // as fogbench-cli and the window do
  }
  RunnerResult run(const TestPlan& plan) {
    PlanRunner runner(*witness, clock, recorder, RunnerOptions{}, [this](const std::string& l) { lines.push_back(l); });
    return runner.run(plan, nullptr);
  }
};

TestPlan responsePreset() {
  auto plan = presetPlan("response");
  EXPECT_TRUE(plan.isOk()) << plan.status().message();
  return plan ? *plan : TestPlan{};
}

std::vector<double> swingArguments(const std::string& line) {
  std::vector<double> v;
  std::stringstream in(line.substr(line.find(' ') + 1));
  for (std::string field; std::getline(in, field, ',');) v.push_back(std::stod(field));
  return v;
}

// Every point of the response plan is commanded as planned (frequency,
// amplitude, centre, phase), the emulator swings it, and each point's
// recorded window is steady swing after the controller's one-period ramp
// and the plan's settle time, lasting the plan's duration.
TEST(ResponsePlanOnTheEmulator, RunsEndToEndAndEveryPointIsSwungAsPlanned) {
  const TestPlan plan = responsePreset();
  ASSERT_EQ(plan.points.size(), 20u);
  EmulatorBench b;
  ASSERT_TRUE(b.remote);
  const auto r = b.run(plan);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  EXPECT_EQ(r.pointsDone, 20);
  EXPECT_TRUE(r.tableAtRest);
  EXPECT_EQ(b.server.swingsStarted(), 20);

  // The controller interface: exactly the plan's swings.
  ASSERT_EQ(b.witness->swings.size(), plan.points.size());
  ASSERT_EQ(b.witness->startedAtS.size(), plan.points.size());
  // The wire: AXIS:X:SWING F,A,C with 9 significant digits (scpi::formatNumber).
  std::vector<std::vector<double>> wire;
  for (const auto& line : b.link->sent)
    if (line.rfind("AXIS:X:SWING ", 0) == 0) wire.push_back(swingArguments(line));
  ASSERT_EQ(wire.size(), plan.points.size());
  const auto windows = b.recorder.windows();
  ASSERT_EQ(windows.size(), plan.points.size());
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i + 1));
    const TestPoint& p = plan.points[i];
    const SwingSpec& s = b.witness->swings[i];
    EXPECT_EQ(s.frequencyHz, p.frequencyHz);
    EXPECT_EQ(s.amplitudeDeg, p.amplitudeDeg);
    EXPECT_EQ(s.centreDeg, p.positionDeg[0]);
    EXPECT_EQ(s.startPhaseDeg, 0.0);
    ASSERT_EQ(wire[i].size(), 3u);
    EXPECT_NEAR(wire[i][0], p.frequencyHz, 5e-9 * p.frequencyHz);
    EXPECT_EQ(wire[i][1], p.amplitudeDeg);
    EXPECT_EQ(wire[i][2], 0.0);

    // The dwell: the ramp (one period), then the settle time, then the
    // recorded duration. The window starts where the stream stood when the
    // settle time ended (kLatencyS behind), so after the ramp.
    const PointWindow& w = windows[i];
    EXPECT_EQ(w.index, static_cast<int>(i));
    EXPECT_TRUE(w.complete);
    EXPECT_NEAR(w.endS - w.startS, p.durationS, 1e-9);
    const double rampS = 1.0 / p.frequencyHz, swingStartS = b.witness->startedAtS[i];
    EXPECT_GE(w.startS, swingStartS + rampS + b.table.params().servoLagS) << "the window holds part of the ramp";
    EXPECT_NEAR(w.startS - swingStartS, rampS + p.settleS - kLatencyS, 0.1);

    // What the emulated table did in the window: the planned steady swing.
    std::vector<TableSample> in;
    for (const auto& x : b.clock.samples)
      if (x.timeS >= w.startS && x.timeS < w.endS) in.push_back(x);
    const auto fit = fitSwing(in, Axis::kX, p.frequencyHz);
    ASSERT_TRUE(fit.ok);
    EXPECT_NEAR(fit.amplitudeDeg, p.amplitudeDeg, 1e-6 * p.amplitudeDeg);
    EXPECT_NEAR(fit.frequencyHz, p.frequencyHz, 1e-7 * p.frequencyHz);
    EXPECT_NEAR(fit.centreDeg, 0.0, 1e-6);
    EXPECT_LT(std::abs(fit.amplitudeDriftDeg), 1e-6 * p.amplitudeDeg);
  }
  // The motion stayed within the emulator's limits (its defaults: 400 deg/s,
  // 3000 deg/s^2), ramps and stops included.
  const auto& lim = b.table.params().limits.axes[0];
  EXPECT_LT(b.clock.peakRateDegPerS, lim.maxRateDegPerS);
  EXPECT_LT(b.clock.peakAccelDegPerS2, lim.maxAccelDegPerS2);
  std::printf("response plan on the emulator: %.1f table s, peak rate %.1f deg/s (limit %g), peak acceleration %.0f "
              "deg/s^2 (limit %g)\n",
              b.clock.now, b.clock.peakRateDegPerS, lim.maxRateDegPerS, b.clock.peakAccelDegPerS2,
              lim.maxAccelDegPerS2);
}

// The board's stream stalls (3 s late) from 1.5 s into the 2-s ramp until
// after the settle time has ended (a busy host; an emulator at --speed 10 on
// a loaded machine): at begin() the newest sample is from inside the ramp.
// The check still starts after the ramp: the recorder maps the host's time
// to board time by the least delay it has seen. (Without the host clock the
// window starts in the ramp, as the 0.365 Hz point did once by hand.)
TEST(ResponsePlanOnTheEmulator, AStreamLaterThanTheSettleTimeStillRecordsAfterTheRamp) {
  TestPlan plan;
  plan.points = {TestPoint{Axis::kX, 0.5, 5.0, 8.0, 2.0}};  // ramp 2 s, settle 2 s
  EmulatorBench b;
  ASSERT_TRUE(b.remote);
  b.clock.latencyS = [](double now) { return now >= 1.5 && now < 4.5 ? 3.0 : kLatencyS; };
  const auto r = b.run(plan);
  ASSERT_TRUE(r.status.isOk()) << r.status.message();
  ASSERT_EQ(b.witness->startedAtS.size(), 1u);
  const double swingStartS = b.witness->startedAtS[0];
  EXPECT_LT(swingStartS, 0.1) << "the stall is timed for a swing started at once";
  const auto windows = b.recorder.windows();
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_TRUE(windows[0].complete);
  EXPECT_GE(windows[0].startS, swingStartS + 2.0 + b.table.params().servoLagS) << "the window holds part of the ramp";
  std::vector<TableSample> in;
  for (const auto& x : b.clock.samples)
    if (x.timeS >= windows[0].startS && x.timeS < windows[0].endS) in.push_back(x);
  const auto fit = fitSwing(in, Axis::kX, 0.5);
  ASSERT_TRUE(fit.ok);
  EXPECT_LT(std::abs(fit.amplitudeDriftDeg), 1e-6 * 5.0);
}

// A response plan (made for the bench's default limits) on a controller with
// lower rate or acceleration limits: refused before any command that moves
// the table; the link carried only queries and the connect's set-up.
void expectRefusedBeforeAnyMotion(EmulatedTableParams params, const std::string& why) {
  EmulatorBench b(params);
  ASSERT_TRUE(b.remote);
  const auto r = b.run(responsePreset());
  EXPECT_EQ(r.status.code(), StatusCode::kOutOfRange);
  EXPECT_EQ(r.status.message(), why);
  EXPECT_EQ(r.pointsDone, 0);
  EXPECT_TRUE(b.witness->motion.empty()) << b.witness->motion.front();
  for (const auto& line : b.link->sent)
    EXPECT_TRUE(line.back() == '?' || line == "*CLS" || line == "SYST:HEART:TIM 2") << "sent: " << line;
  EXPECT_EQ(b.server.swingsStarted(), 0);
  for (int a = 0; a < kAxisCount; ++a) {
    EXPECT_EQ(b.table.mode(static_cast<Axis>(a), b.clock.now), AxisMode::kRest);
    EXPECT_EQ(b.table.angleDeg(static_cast<Axis>(a), b.clock.now), 0.0);
  }
}

TEST(ResponsePlanOnTheEmulator, APointBeyondTheAccelerationLimitIsRefusedBeforeAnyMotion) {
  EmulatedTableParams params;
  params.limits.axes[0].maxAccelDegPerS2 = 2000.0;  // the plan's points 15 .. 20 need 2400
  expectRefusedBeforeAnyMotion(params,
                               "test point 15 (X 2.66525 Hz / 8.558 deg): peak acceleration 2399.98 deg/s^2 is beyond "
                               "the table's 2000 deg/s^2 on X; the plan was refused before any motion");
}

TEST(ResponsePlanOnTheEmulator, APointBeyondTheRateLimitIsRefusedBeforeAnyMotion) {
  EmulatedTableParams params;
  params.limits.axes[0].maxRateDegPerS = 100.0;  // point 14 (2.006 Hz / 10 deg) needs 126
  expectRefusedBeforeAnyMotion(params,
                               "test point 14 (X 2.00631 Hz / 10 deg): peak rate 126.06 deg/s is beyond the table's "
                               "100 deg/s on X; the plan was refused before any motion");
}

}  // namespace
}  // namespace fog::table

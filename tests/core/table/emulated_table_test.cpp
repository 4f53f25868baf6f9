#include "core/table/emulated_table.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fog::table {
namespace {

TEST(EmulatedTable, SwingRampsUpThenFollowsTheSineWithTheServoLag) {
  EmulatedTable t;
  ASSERT_TRUE(t.startSwing(Axis::kX, {1.0, 3.0, 0.0}, 1.0).isOk());
  EXPECT_EQ(t.mode(Axis::kX, 1.5), AxisMode::kSwinging);
  // Ramp: rate continuous from rest.
  EXPECT_NEAR(t.rateDegPerS(Axis::kX, 1.002), 0.0, 1e-9);
  EXPECT_LT(std::abs(t.angleDeg(Axis::kX, 1.5)), 3.0 * 0.5 + 1e-6);
  // After the ramp (1 period): the planned sine, delayed by the servo lag.
  for (double tt : {3.1, 4.37, 7.9}) {
    EXPECT_NEAR(t.angleDeg(Axis::kX, tt), 3.0 * std::sin(2 * M_PI * (tt - 0.002 - 1.0)), 1e-12);
  }
  // The other axes hold.
  EXPECT_EQ(t.angleDeg(Axis::kY, 5.0), 0.0);
}

// A start phase: from rest at the centre, the amplitude ramps up smoothly
// (no jump in rate at either end of the ramp), then the swing runs at that
// phase: centre + A sin(w (t - t0) + phase).
TEST(EmulatedTable, TheSwingStartsAtThePlannedPhase) {
  EmulatedTable t;
  ASSERT_TRUE(t.startSwing(Axis::kZ, {0.5, 4.0, 0.0, 90.0}, 1.0).isOk());
  EXPECT_NEAR(t.angleDeg(Axis::kZ, 1.002), 0.0, 1e-12);
  EXPECT_NEAR(t.rateDegPerS(Axis::kZ, 1.002), 0.0, 1e-9);
  // The ramp ends after one period (2 s): the rate is continuous across it.
  const double end = 1.0 + 2.0 + 0.002;
  EXPECT_NEAR(t.rateDegPerS(Axis::kZ, end - 1e-6), t.rateDegPerS(Axis::kZ, end + 1e-6), 1e-3);
  double worstStep = 0.0;
  for (double tt = 1.002; tt < end + 0.5; tt += 0.001)
    worstStep = std::max(worstStep, std::abs(t.rateDegPerS(Axis::kZ, tt + 0.001) - t.rateDegPerS(Axis::kZ, tt)));
  EXPECT_LT(worstStep, 0.1);  // deg/s per ms: bounded acceleration, no jump
  // Whole periods after the start the swing is at its phase: 4 sin(90 deg).
  for (double k : {2.0, 3.0, 10.0}) EXPECT_NEAR(t.angleDeg(Axis::kZ, 1.002 + 2.0 * k), 4.0, 1e-9);
  for (double tt : {5.3, 8.77}) EXPECT_NEAR(t.angleDeg(Axis::kZ, tt), 4.0 * std::cos(M_PI * (tt - 1.002)), 1e-9);
}

TEST(TableServer, TheSwingCommandTakesAStartPhase) {
  EmulatedTable t;
  TableServer s(t);
  std::vector<std::string> events;
  s.setEventSink([&](const std::string& e) { events.push_back(e); });
  (void)s.handleLine("AXIS:X:SWING 1,3,0,-90", 0.0, 0.0);
  EXPECT_EQ(s.handleLine("AXIS:X:SWING?", 0.0, 0.0).value(), "1,3,0,-90");
  EXPECT_EQ(s.handleLine("SYST:ERR?", 0.0, 0.0).value(), "0,\"No error\"");
  (void)s.handleLine("AXIS:X:START", 0.0, 0.0);
  ASSERT_FALSE(events.empty());
  EXPECT_NE(events.back().find("swing: X 1 Hz 3 deg about 0 deg phase -90 deg started"), std::string::npos) << events.back();
  EXPECT_NEAR(t.angleDeg(Axis::kX, 4.002), -3.0, 1e-9);
  (void)s.handleLine("AXIS:Y:SWING 1,3,0,400", 0.0, 0.0);
  EXPECT_EQ(s.handleLine("SYST:ERR?", 0.0, 0.0).value(),
            "-222,\"Data out of range; start phase must be within -360 .. 360 deg\"");
  (void)s.handleLine("AXIS:Y:SWING 1,3,0,0,5", 0.0, 0.0);
  EXPECT_EQ(s.handleLine("SYST:ERR?", 0.0, 0.0).value().rfind("-108,", 0), 0u);
}

TEST(EmulatedTable, StopDeceleratesWithinTheBoundAndComesToRest) {
  EmulatedTable t;
  ASSERT_TRUE(t.startSwing(Axis::kZ, {1.0, 3.0, 0.0}, 0.0).isOk());
  t.stop(Axis::kZ, 3.0, 100.0);  // at a zero crossing: full rate 18.85 deg/s
  const double v0 = 2 * M_PI * 3.0;
  EXPECT_NEAR(t.rateDegPerS(Axis::kZ, 3.002), v0, 1e-9);
  EXPECT_EQ(t.mode(Axis::kZ, 3.05), AxisMode::kStopping);
  double worst = 0.0;
  for (double tt = 3.003; tt < 3.3; tt += 0.001)
    worst = std::max(worst, std::abs(t.rateDegPerS(Axis::kZ, tt + 0.001) - t.rateDegPerS(Axis::kZ, tt)) / 0.001);
  EXPECT_LE(worst, 100.0 + 1e-6);
  EXPECT_EQ(t.mode(Axis::kZ, 3.3), AxisMode::kRest);
  EXPECT_NEAR(t.angleDeg(Axis::kZ, 3.3), v0 * v0 / (2 * 100.0), 1e-9);
}

TEST(EmulatedTable, AMoveIsATrapezoidToTheTarget) {
  EmulatedTable t;
  ASSERT_TRUE(t.moveTo(Axis::kY, 10.0, 0.0).isOk());
  EXPECT_EQ(t.mode(Axis::kY, 0.2), AxisMode::kPositioning);
  EXPECT_LE(std::abs(t.rateDegPerS(Axis::kY, 0.3)), 20.0 + 1e-9);
  EXPECT_EQ(t.mode(Axis::kY, 5.0), AxisMode::kRest);
  EXPECT_DOUBLE_EQ(t.angleDeg(Axis::kY, 5.0), 10.0);
  // A swing must start at its centre.
  EXPECT_FALSE(t.startSwing(Axis::kY, {1.0, 1.0, 0.0}, 6.0).isOk());
}

TEST(TableServer, TheHeartbeatStopsTheTableWhenTheHostGoesQuiet) {
  EmulatedTable t;
  TableServer s(t);
  std::vector<std::string> events;
  s.setEventSink([&](const std::string& e) { events.push_back(e); });
  (void)s.handleLine("SYST:HEART:TIM 0.5", 0.0, 0.0);
  (void)s.handleLine("AXIS:X:SWING 1,3,0", 0.0, 0.0);
  (void)s.handleLine("AXIS:X:START", 0.0, 0.0);
  s.tick(0.3, 0.3);
  (void)s.handleLine("SYST:HEART", 0.4, 0.4);
  s.tick(0.8, 0.8);
  EXPECT_FALSE(s.heartbeatLost());
  EXPECT_EQ(t.mode(Axis::kX, 0.8), AxisMode::kSwinging);
  s.tick(1.0, 1.0);  // 0.6 s since the last line
  EXPECT_TRUE(s.heartbeatLost());
  EXPECT_EQ(t.mode(Axis::kX, 5.0), AxisMode::kRest);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_NE(events[1].find("heartbeat: host quiet"), std::string::npos);
  // Motion is refused until *CLS.
  (void)s.handleLine("AXIS:X:START", 5.0, 5.0);
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 5.0, 5.0),
            "203,\"Heartbeat lost; the host was quiet for more than 0.5 s; table brought to rest\"");
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 5.0, 5.0), "203,\"Heartbeat lost\"");
  EXPECT_EQ(*s.handleLine("SYST:STAT?", 5.0, 5.0), "0,0,1,NONE");
  (void)s.handleLine("*CLS", 5.0, 5.0);
  EXPECT_EQ(*s.handleLine("SYST:STAT?", 5.0, 5.0), "0,0,0,NONE");
}

TEST(TableServer, UnknownAndMalformedLinesGoToTheErrorQueue) {
  EmulatedTable t;
  TableServer s(t);
  EXPECT_FALSE(s.handleLine("AXIS:X:FLY 1", 0, 0).has_value());
  EXPECT_EQ(*s.handleLine("AXIS:Q:POS?", 0, 0), "");
  (void)s.handleLine("AXIS:X:SWING 1,2", 0, 0);
  (void)s.handleLine("AXIS::X", 0, 0);
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 0, 0), "-113,\"Undefined header; AXIS:X:FLY 1\"");
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 0, 0), "-113,\"Undefined header; AXIS:Q:POS?\"");
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 0, 0), "-109,\"Missing parameter\"");
  EXPECT_EQ(s.handleLine("SYST:ERR?", 0, 0)->rfind("-102,\"Syntax error; empty keyword", 0), 0u);
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 0, 0), "0,\"No error\"");
}

TEST(TableServer, TheInterlockStopsTheTableAndRefusesMotion) {
  EmulatedTable t;
  ServerFaults f;
  f.interlockAfterStartS = 2.0;
  TableServer s(t, f);
  (void)s.handleLine("AXIS:Z:SWING 0.5,4,0", 0, 0);
  (void)s.handleLine("AXIS:Z:START", 1.0, 1.0);
  s.tick(2.9, 2.9);
  EXPECT_FALSE(s.interlockOpen());
  s.tick(3.0, 3.0);
  EXPECT_TRUE(s.interlockOpen());
  EXPECT_EQ(*s.handleLine("SYST:STAT?", 3.0, 3.0), "1,0,0,NONE");
  EXPECT_EQ(t.mode(Axis::kZ, 4.0), AxisMode::kRest);
  (void)s.handleLine("AXIS:Z:START", 4.0, 4.0);
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 4.0, 4.0), "201,\"Interlock open; tripped; table stopped\"");
  EXPECT_EQ(*s.handleLine("SYST:ERR?", 4.0, 4.0), "201,\"Interlock open\"");
}

}  // namespace
}  // namespace fog::table

#include "model/simulator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/units.h"
#include "model/turntable.h"
#include "protocol/recording_builder.h"

namespace fog::model {
namespace {

TestPlan shortPlan() {
  TestPlan plan;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 4.0, 1.0, 0.0});
  return plan;
}

TEST(Simulator, SameSeedGivesBitIdenticalBytes) {
  SimConfig c;
  c.seed = 42;
  auto a = simulate(c, shortPlan());
  auto b = simulate(c, shortPlan());
  ASSERT_TRUE(a.isOk() && b.isOk());
  EXPECT_EQ(a->bytes, b->bytes);
  c.seed = 43;
  auto d = simulate(c, shortPlan());
  ASSERT_TRUE(d.isOk());
  EXPECT_NE(a->bytes, d->bytes);
}

TEST(Simulator, ChunkedAdvanceEqualsOneRun) {
  SimConfig c;
  auto whole = simulate(c, shortPlan());
  ASSERT_TRUE(whole.isOk());
  auto sim = Simulator::create(c, shortPlan());
  ASSERT_TRUE(sim.isOk());
  std::vector<std::uint8_t> bytes;
  while ((*sim)->advance((*sim)->timeS() + 0.0137, bytes)) {
  }
  EXPECT_EQ(bytes, whole->bytes);
}

TEST(Simulator, ChunkedAdvanceLandingOnTheEndEqualsOneRun) {
  // Steps that land exactly on the end of the plan must still emit the frames
  // stamped at that instant (a paced source steps to round times).
  SimConfig c;
  auto whole = simulate(c, shortPlan());
  ASSERT_TRUE(whole.isOk());
  auto sim = Simulator::create(c, shortPlan());
  ASSERT_TRUE(sim.isOk());
  const double step = (*sim)->endS() / 8.0;
  std::vector<std::uint8_t> bytes;
  for (int i = 1; (*sim)->advance(step * i, bytes); ++i) {
  }
  EXPECT_EQ(bytes, whole->bytes);
}

TEST(Simulator, RefusesImpossibleConfigurations) {
  SimConfig c;
  c.fog.setOwnDelayS(0.9e-3);  // beyond one 0.5 ms pulse update period
  auto r = Simulator::create(c, shortPlan());
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("pulse update"), std::string::npos) << r.status().message();

  c = SimConfig{};
  c.samplingBoard.counterBits = 16;  // wraps every 6.5 ms at 10 MHz
  r = Simulator::create(c, shortPlan());
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("wraps"), std::string::npos);

  TestPlan plan = shortPlan();
  plan.points[0].amplitudeDeg = 0.0;
  r = Simulator::create(SimConfig{}, plan);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("amplitude"), std::string::npos);
}

TEST(SimConfig, DefaultsAreThePapers) {
  const SimConfig c;
  EXPECT_NEAR(c.imuBoard.boardDelayS(), 0.28e-3, 1e-12);
  EXPECT_NEAR(c.trueGyroDelayS(), 0.2358e-3, 1e-12);
  EXPECT_NEAR(c.trueImuDelayS(), 0.5158e-3, 1e-12);
  EXPECT_NEAR(c.trueLagS(), 0.4658e-3, 1e-12);
  EXPECT_NEAR(c.fog.eigenPeriodS(), 3.34e-6, 0.01e-6);
  EXPECT_DOUBLE_EQ(c.encoder.samplePeriodS, 1e-3);
  EXPECT_DOUBLE_EQ(c.imuBoard.framePeriodS, 2e-3);
}

TEST(EarthParams, ProjectionOnUpAndNorthAxes) {
  EarthParams e;
  e.latitudeDeg = 30.0;
  EXPECT_NEAR(e.projectionDegPerH(Axis::kZ), kEarthRateDegPerH * 0.5, 1e-9);
  EXPECT_NEAR(e.projectionDegPerH(Axis::kY), kEarthRateDegPerH * std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(e.projectionDegPerH(Axis::kX), 0.0, 1e-12);
}

TEST(Turntable, SwingIsAnalyticAndContinuousBetweenPoints) {
  TestPlan plan;
  plan.restBetweenS = 0.5;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 2.25, 0.0, 0.0});  // ends at a quarter period: +3 deg
  plan.points.push_back({Axis::kX, 0.5, 2.0, 4.0, 0.0, 0.0});
  TurntableParams params;
  params.frequencyErrorPpm = 0.0;
  Turntable table(plan, params);
  const auto& s = table.schedule();
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(table.anglesDeg(s[0].swingStartS + 0.25)[0], 3.0, 1e-12);
  // Holds its last angle while resting, then swings about it.
  EXPECT_NEAR(table.anglesDeg(s[0].recordEndS + 0.25)[0], 3.0, 1e-9);
  EXPECT_NEAR(table.anglesDeg(s[1].swingStartS)[0], 3.0, 1e-9);
  EXPECT_NEAR(table.anglesDeg(s[1].swingStartS + 0.5)[0], 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(table.anglesDeg(s[1].swingStartS + 0.5)[1], 0.0);
}

// With every noise off, the pulses summed over a long run equal the motion
// to within one pulse: the quantisation remainder is carried, never lost.
TEST(Simulator, PulseQuantisationDoesNotAccumulate) {
  SimConfig c;
  c.fog.arwDegPerSqrtH = 0.0;
  c.fog.biasInstabilityDegPerH = 0.0;
  c.fog.biasDegPerH = {0.0, 0.0, 0.0};
  c.earth.latitudeDeg = 0.0;
  c.earth.axisEnu[0] = {1, 0, 0};
  c.fog.pulseEquivalentDeg = 3.3e-4;
  TestPlan plan;
  plan.points.push_back({Axis::kX, 0.7, 5.0, 30.0, 0.0, 0.0});
  auto run = simulate(c, plan);
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), 1u);
  const auto& tp = rec->testPoints[0];
  double sum = 0.0;
  for (std::size_t k = 1; k < tp.imu.size(); ++k) sum += tp.imu[k].incrementDeg[0];
  Turntable table(plan, c.turntable);
  const double lag = c.fog.ownDelayS() + c.imuBoard.boardDelayS();
  const double expected = table.anglesDeg(tp.imu.back().timeS - lag)[0] - table.anglesDeg(tp.imu.front().timeS - lag)[0];
  EXPECT_NEAR(sum, expected, 1.0001 * c.fog.pulseEquivalentDeg);
  EXPECT_GT(tp.imu.size(), 14000u);
}

TEST(Simulator, EmitsTheTestPointsAsStatusSegments) {
  TestPlan plan = shortPlan();
  plan.points.push_back({Axis::kZ, 0.5, 2.0, 6.0, 1.0, 0.0});
  auto run = simulate(SimConfig{}, plan);
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk());
  ASSERT_EQ(rec->testPoints.size(), 2u);
  EXPECT_EQ(rec->testPoints[1].axis, Axis::kZ);
  EXPECT_DOUBLE_EQ(rec->testPoints[1].nominalFrequencyHz, 0.5);
  // 6 s of recording at 1 kHz table and 500 Hz IMU.
  EXPECT_NEAR(static_cast<double>(rec->testPoints[1].table.size()), 6000.0, 2.0);
  EXPECT_NEAR(static_cast<double>(rec->testPoints[1].imu.size()), 3000.0, 2.0);
  EXPECT_EQ(rec->health.checksumFailures, 0u);
  EXPECT_EQ(rec->health.lostFrames, 0u);
}

}  // namespace
}  // namespace fog::model

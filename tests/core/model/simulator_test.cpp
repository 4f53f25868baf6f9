#include "core/model/simulator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/common/units.h"
#include "core/model/attitude.h"
#include "core/model/turntable.h"
#include "core/protocol/recording_builder.h"

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

// Drops every 7th IMU frame and every 11th table frame (a lossy link).
class DropSome : public Effect {
 public:
  std::string name() const override { return "drop_some"; }
  void onImuStamp(double&, bool& drop) override { drop = ++imu_ % 7 == 0; }
  void onTableStamp(double&, bool& drop) override { drop = ++table_ % 11 == 0; }

 private:
  int imu_ = 0, table_ = 0;
};

// A gyro-stage effect that leaves the motion as planned (a scale error of
// 1e-3 on the sensed angle, and the stamps of DropSome).
class ScaleAndDrop : public DropSome {
 public:
  bool changesTableMotion() const override { return false; }
  void onGyroAngle(const GyroContext& c, std::array<double, kAxisCount>& sensed) override {
    for (int a = 0; a < kAxisCount; ++a) sensed[a] += 1e-3 * c.bodyAngleDeg[a];
  }
};

// The same, not saying whether it moves the table (the default: it may).
class ScaleAndDropUnstated : public ScaleAndDrop {
 public:
  bool changesTableMotion() const override { return Effect::changesTableMotion(); }
};

// The run's bytes with `effect`, recording into or playing `tape`.
std::vector<std::uint8_t> runWith(const SimConfig& c, std::unique_ptr<Effect> effect, MotionTape* record,
                                  const MotionTape* play, bool* matched = nullptr) {
  auto sim = Simulator::create(c, shortPlan());
  EXPECT_TRUE(sim.isOk());
  if (effect) (*sim)->addEffect(std::move(effect));
  (*sim)->recordMotionTape(record);
  (*sim)->playMotionTape(play);
  std::vector<std::uint8_t> bytes;
  (*sim)->runToEnd(bytes);
  if (matched) *matched = (*sim)->tapeMatched();
  return bytes;
}

// The diagnosis' signature replays play the first replay's motion tape: the
// stream must be bit for bit the one the stage computed gives.
TEST(MotionTape, PlayedGivesTheStreamComputedGives) {
  SimConfig c;
  c.seed = 7;
  MotionTape tape;
  const auto nominal = runWith(c, nullptr, &tape, nullptr);
  EXPECT_EQ(nominal, runWith(c, nullptr, nullptr, nullptr));
  ASSERT_FALSE(tape.senses.empty());
  bool matched = false;
  EXPECT_EQ(runWith(c, std::make_unique<ScaleAndDrop>(), nullptr, &tape, &matched),
            runWith(c, std::make_unique<ScaleAndDrop>(), nullptr, nullptr));
  EXPECT_TRUE(matched);
  // An effect that may move the table does not play it (same bytes as computed).
  EXPECT_EQ(runWith(c, std::make_unique<ScaleAndDropUnstated>(), nullptr, &tape, &matched),
            runWith(c, std::make_unique<ScaleAndDropUnstated>(), nullptr, nullptr));
  // Another chain's tape is noticed.
  c.fog.arwDegPerSqrtH *= 2.0;
  c.imuBoard.firstSampleS += 1e-4;
  runWith(c, nullptr, nullptr, &tape, &matched);
  EXPECT_FALSE(matched);
}

TEST(SimulatorFrames, GiveTheRecordingTheirBytesGive) {
  // The frame overload (a diagnosis replay) must be the byte stream without
  // the encoding: the same frames, lost ones and counter wraps included.
  SimConfig c;
  c.seed = 5;
  c.samplingBoard.counterBits = 24;  // wraps every 1.7 s at 10 MHz
  auto bytesRun = Simulator::create(c, shortPlan());
  auto framesRun = Simulator::create(c, shortPlan());
  ASSERT_TRUE(bytesRun.isOk() && framesRun.isOk());
  (*bytesRun)->addEffect(std::make_unique<DropSome>());
  (*framesRun)->addEffect(std::make_unique<DropSome>());
  std::vector<std::uint8_t> bytes;
  protocol::StreamDecoder fromFrames;
  std::vector<std::uint8_t> encoded;
  std::vector<protocol::Frame> frames;
  for (double until = 0.7;; until += 0.7) {
    const bool more = (*bytesRun)->advance(until, bytes);
    EXPECT_EQ(more, (*framesRun)->advance(until, frames));
    for (const auto& f : frames) protocol::appendFrame(f, encoded);
    fromFrames.push(std::span<const protocol::Frame>(frames));
    frames.clear();
    if (!more) break;
  }
  EXPECT_EQ(encoded, bytes);
  auto a = protocol::decodeRecording(bytes);
  auto b = fromFrames.finish();
  ASSERT_TRUE(a.isOk() && b.isOk());
  EXPECT_GT(a->health.lostFrames, 100u);
  EXPECT_GE(a->health.counterWraps, 3u);
  EXPECT_EQ(a->health.lostFrames, b->health.lostFrames);
  EXPECT_EQ(a->health.counterWraps, b->health.counterWraps);
  EXPECT_EQ(a->health.imuFrames, b->health.imuFrames);
  EXPECT_EQ(a->health.tableFrames, b->health.tableFrames);
  EXPECT_EQ(a->health.statusFrames, b->health.statusFrames);
  EXPECT_EQ(a->pulseEquivalentDeg, b->pulseEquivalentDeg);
  ASSERT_EQ(a->testPoints.size(), b->testPoints.size());
  for (std::size_t i = 0; i < a->testPoints.size(); ++i) {
    const auto& x = a->testPoints[i];
    const auto& y = b->testPoints[i];
    ASSERT_EQ(x.table.size(), y.table.size());
    ASSERT_EQ(x.imu.size(), y.imu.size());
    for (std::size_t k = 0; k < x.table.size(); ++k) {
      EXPECT_EQ(x.table[k].timeS, y.table[k].timeS);
      EXPECT_EQ(x.table[k].angleDeg, y.table[k].angleDeg);
    }
    for (std::size_t k = 0; k < x.imu.size(); ++k) {
      EXPECT_EQ(x.imu[k].timeS, y.imu[k].timeS);
      EXPECT_EQ(x.imu[k].incrementDeg, y.imu[k].incrementDeg);
      EXPECT_EQ(x.imu[k].lostBefore, y.imu[k].lostBefore);
    }
  }
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

// North-east-down, the table's x axis at the heading from north: at 30 deg
// latitude x (north) senses Omega cos 30, z (down) -Omega sin 30; turned to
// heading 90, x points east and y south.
TEST(EarthParams, ProjectionAtTheTablesZero) {
  EarthParams e;
  e.latitudeDeg = 30.0;
  EXPECT_NEAR(e.projectionDegPerH(Axis::kX), kEarthRateDegPerH * std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(e.projectionDegPerH(Axis::kY), 0.0, 1e-12);
  EXPECT_NEAR(e.projectionDegPerH(Axis::kZ), -kEarthRateDegPerH * 0.5, 1e-9);
  e.headingDeg = 90.0;
  EXPECT_NEAR(e.projectionDegPerH(Axis::kX), 0.0, 1e-9);
  EXPECT_NEAR(e.projectionDegPerH(Axis::kY), -kEarthRateDegPerH * std::sqrt(3.0) / 2.0, 1e-9);
  TurntableParams table;
  const Attitude att(e, table);
  const Eigen::Vector3d w = att.earthRateBodyDegPerH(att.bodyToTable({0.0, 0.0, 0.0}));
  EXPECT_NEAR(w[1], e.projectionDegPerH(Axis::kY), 1e-9);
  EXPECT_NEAR(w[2], e.projectionDegPerH(Axis::kZ), 1e-9);
}

// A table whose z axis points up (east-north-up at heading 90): the Earth
// rate reads (0, Omega cos(lat), +Omega sin(lat)) in its axes and the
// specific force at rest is +1 g along z; the stated frame sets both
// (applyImuFrame), and the projection agrees with the attitude.
TEST(Attitude, AZUpTableSeesTheEarthRateAndGravityTurnedOver) {
  EarthParams e;
  e.latitudeDeg = 30.0;
  applyImuFrame(*imuFrameFromText("ENU"), e);
  EXPECT_TRUE(e.zUp);
  EXPECT_EQ(e.headingDeg, 90.0);
  const Attitude att(e, TurntableParams{});
  const Eigen::Matrix3d level = att.bodyToTable({0.0, 0.0, 0.0});
  const Eigen::Vector3d w = att.earthRateBodyDegPerH(level);
  EXPECT_TRUE(w.isApprox(Eigen::Vector3d(0.0, kEarthRateDegPerH * std::sqrt(3.0) / 2.0, kEarthRateDegPerH * 0.5),
                         1e-12))
      << w.transpose();
  EXPECT_TRUE(att.specificForceBodyG(level).isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  for (Axis a : {Axis::kX, Axis::kY, Axis::kZ})
    EXPECT_NEAR(w[static_cast<int>(a)], e.projectionDegPerH(a), 1e-9) << axisName(a);
  // RFU with forward at 300 deg: x (right) at 390 = 30 deg, within (-180, 180].
  EarthParams r;
  applyImuFrame(*imuFrameFromText("RFU:300"), r);
  EXPECT_TRUE(r.zUp);
  EXPECT_NEAR(r.headingDeg, 30.0, 1e-12);
  // Unstated, or stating only the vertical, leaves the heading as it was.
  EarthParams u;
  u.headingDeg = 12.0;
  applyImuFrame(*imuFrameFromText("FRD"), u);
  EXPECT_FALSE(u.zUp);
  EXPECT_EQ(u.headingDeg, 12.0);
}

// Outer z, middle y, inner x: the inner axis is always along gyro x; the
// middle axis turns with the inner one; the outer with both.
TEST(Attitude, TableAxesInTheBodyFrame) {
  const Attitude att(EarthParams{}, TurntableParams{});
  const TableAngles at{90.0, 0.0, 0.0};  // inner x at 90 deg
  EXPECT_TRUE(att.tableAxisInBody(Axis::kX, at).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
  // R_x(90)^T e_y = (0, 0, -1)... the middle axis y seen from the body after
  // the inner frame turned +90 deg about x is body -z.
  EXPECT_TRUE(att.tableAxisInBody(Axis::kY, at).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  // A turn of one axis is a rotation of exactly its angle about its body direction.
  const TableAngles a0{10.0, 20.0, 30.0}, a1{10.0, 20.5, 30.0};
  const Eigen::Vector3d r = att.rotationBetweenDeg(att.bodyToTable(a0), att.bodyToTable(a1));
  EXPECT_TRUE(r.isApprox(0.5 * att.tableAxisInBody(Axis::kY, a0), 1e-12)) << r.transpose();
  // Gravity: level, the specific force is up (-z in north-east-down).
  EXPECT_TRUE(att.specificForceBodyG(att.bodyToTable({0, 0, 0})).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
}

TEST(Turntable, SwingsAboutItsPositionAndMovesOneAxisAtATime) {
  TestPlan plan;
  plan.restBetweenS = 2.0;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 2.25, 0.0, 0.0});  // ends at a quarter period: +3 deg
  TestPoint second{Axis::kY, 0.5, 2.0, 4.0, 0.0, 0.0};
  second.positionDeg = {0.0, 5.0, 30.0};  // swing Y about 5 deg with Z at 30 deg
  plan.points.push_back(second);
  ASSERT_TRUE(plan.validate(TurntableLimits{}).isOk());
  TurntableParams params;
  params.frequencyErrorPpm = 0.0;
  Turntable table(plan, params);
  const auto& s = table.schedule();
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(table.anglesDeg(s[0].swingStartS + 0.25)[0], 3.0, 1e-12);
  // The rest after point 1 moves X back to 0, then Y to 5, then Z to 30,
  // each in a third of it, one after the other.
  const double r0 = s[0].recordEndS;
  EXPECT_NEAR(table.anglesDeg(r0 + 1e-9)[0], 3.0, 1e-6);
  const auto third = table.anglesDeg(r0 + 2.0 / 3.0);
  EXPECT_NEAR(third[0], 0.0, 1e-9);
  EXPECT_NEAR(third[1], 0.0, 1e-9);
  const auto mid = table.anglesDeg(r0 + 1.0);  // half-way through the Y move
  EXPECT_NEAR(mid[1], 2.5, 1e-9);
  EXPECT_DOUBLE_EQ(mid[2], 0.0);
  const auto start = table.anglesDeg(s[1].swingStartS);
  EXPECT_NEAR(start[1], 5.0, 1e-9);
  EXPECT_NEAR(start[2], 30.0, 1e-9);
  EXPECT_NEAR(table.anglesDeg(s[1].swingStartS + 0.5)[1], 7.0, 1e-9);  // 5 + 2 sin(pi/2)
  // After the last point the table returns to zero.
  const auto end = table.anglesDeg(table.endS());
  for (double v : end) EXPECT_NEAR(v, 0.0, 1e-9);
}

TEST(TestPlan, MovesBetweenPointsAreCheckedAgainstTheLimits) {
  TestPlan plan;
  plan.restBetweenS = 0.2;
  TestPoint p{Axis::kX, 1.0, 3.0, 10.0, 1.0, 0.0};
  p.positionDeg = {0.0, 0.0, 90.0};
  plan.points.push_back(p);
  const Status s = plan.validate(TurntableLimits{});
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("rest_between_s >="), std::string::npos) << s.message();
  plan.restBetweenS = 2.0;
  EXPECT_TRUE(plan.validate(TurntableLimits{}).isOk());
  plan.restBetweenS = 0.0;
  EXPECT_NE(plan.validate(TurntableLimits{}).message().find("no rest time"), std::string::npos);
  const auto json = testPlanToJson(TestPlan{{p}, 2.0});
  auto back = testPlanFromJson(json);
  ASSERT_TRUE(back.isOk()) << json;
  EXPECT_EQ(back->points[0].positionDeg[2], 90.0);
}

// The Earth rate turns in the body frame as the table swings: swinging X by
// theta at latitude L and heading h, gyro z senses
//   -sin(theta) * (-Omega cos L sin h) + cos(theta) * (-Omega sin L),
// a term in phase with the angle of Omega cos L sin h sin A (1.9 deg/h at
// 40 deg, heading 30, 10 deg). Noise off, pulses of 1e-7 deg: the summed
// increments of gyro z match that integral, taken here on a 0.1-ms grid,
// to 2e-6 deg.
TEST(Simulator, EarthRateIsRotatedIntoTheBodyFrame) {
  SimConfig c;
  c.fog.arwDegPerSqrtH = 0.0;
  c.fog.biasInstabilityDegPerH = 0.0;
  c.fog.biasDegPerH = {0.0, 0.0, 0.0};
  c.earth.latitudeDeg = 40.0;
  c.earth.headingDeg = 30.0;
  c.fog.pulseEquivalentDeg = 1e-7;
  TestPlan plan;
  plan.points.push_back({Axis::kX, 0.1, 10.0, 40.0, 0.0, 0.0});
  auto run = simulate(c, plan);
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk());
  const auto& tp = rec->testPoints.at(0);
  const double lag = c.fog.ownDelayS() + c.imuBoard.boardDelayS();
  const double om = kEarthRateDegPerH / kSecondsPerHour, lat = 40.0 * kRadPerDeg, h = 30.0 * kRadPerDeg;
  Turntable table(plan, c.turntable);
  const double t0 = tp.imu.front().timeS - lag, t1 = tp.imu.back().timeS - lag;
  double expected = 0.0;
  const int steps = static_cast<int>((t1 - t0) / 1e-4);
  for (int k = 0; k < steps; ++k) {
    const double t = t0 + (k + 0.5) * (t1 - t0) / steps;
    const double th = table.anglesDeg(t)[0] * kRadPerDeg;
    expected += (std::sin(th) * om * std::cos(lat) * std::sin(h) - std::cos(th) * om * std::sin(lat)) * (t1 - t0) / steps;
  }
  double sum = 0.0;
  for (std::size_t k = 1; k < tp.imu.size(); ++k) sum += tp.imu[k].incrementDeg[2];
  EXPECT_NEAR(sum, expected, 2e-6);
  EXPECT_GT(std::abs(expected), 0.05);
}

// With every noise off, the pulses summed over a long run equal the motion
// to within one pulse: the quantisation remainder is carried, never lost.
TEST(Simulator, PulseQuantisationDoesNotAccumulate) {
  SimConfig c;
  c.fog.arwDegPerSqrtH = 0.0;
  c.fog.biasInstabilityDegPerH = 0.0;
  c.fog.biasDegPerH = {0.0, 0.0, 0.0};
  c.earth.latitudeDeg = 0.0;
  c.earth.headingDeg = 90.0;  // x east: no Earth rate on it
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

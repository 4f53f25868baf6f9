// The nominal chain's stated constants (docs/simulator.md, "Stated constants
// of the chain"), each against its closed form: the gyro's pulse register,
// the boxcar, the first- and second-order rate filters, the table's base
// tilt, axis non-orthogonality, encoder eccentricity and lost table frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "core/common/units.h"
#include "core/diagnosis/effects.h"
#include "core/model/attitude.h"
#include "core/model/simulator.h"
#include "core/model/turntable.h"
#include "core/protocol/recording_builder.h"

namespace fog::model {
namespace {

// A chain without noise, with fine pulses and encoder steps, so that a
// figure is the chain's alone.
SimConfig quiet() {
  SimConfig c;
  c.fog.arwDegPerSqrtH = 0.0;
  c.fog.biasInstabilityDegPerH = 0.0;
  c.fog.biasDegPerH = {0.0, 0.0, 0.0};
  c.fog.pulseEquivalentDeg = 1e-7;
  c.encoder.quantumDeg = 0.0;
  return c;
}

TestPlan swing(Axis axis, double hz, double ampDeg, double durationS) {
  TestPlan plan;
  plan.points.push_back({axis, hz, ampDeg, durationS, 2.0, 0.0});
  return plan;
}

TestPointData record(const SimConfig& c, const TestPlan& plan) {
  auto run = simulate(c, plan);
  EXPECT_TRUE(run.isOk()) << run.status().toString();
  auto rec = protocol::decodeRecording(run->bytes);
  EXPECT_TRUE(rec.isOk()) << rec.status().toString();
  return rec->testPoints.at(0);
}

// Amplitude and phase of the fundamental: y = a + b t + R sin(w t + phi).
struct Sine {
  double amplitude = 0.0, phaseRad = 0.0;
};
Sine fitSine(const std::vector<double>& t, const std::vector<double>& y, double w) {
  const auto n = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd a(n, 4);
  Eigen::VectorXd b(n);
  const double tm = t[t.size() / 2];
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    a.row(k) << 1.0, t[i] - tm, std::sin(w * t[i]), std::cos(w * t[i]);
    b[k] = y[i];
  }
  const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
  return {std::hypot(x[2], x[3]), std::atan2(x[3], x[2])};
}

// The gyro's response to the swing: its lag behind the recorded table angle
// (s) and its gain (gyro amplitude / table amplitude).
struct Response {
  double lagS = 0.0, gain = 0.0;
};
Response response(const SimConfig& c, const TestPlan& plan) {
  const TestPointData tp = record(c, plan);
  const Axis axis = plan.points[0].axis;
  const auto a = static_cast<std::size_t>(axis);
  const double w = kTwoPi * plan.points[0].frequencyHz * (1.0 + c.turntable.frequencyErrorPpm * 1e-6);
  std::vector<double> tt, yt, tg, yg;
  for (const auto& s : tp.table) tt.push_back(s.timeS), yt.push_back(s.angleDeg[a]);
  double sum = 0.0;
  for (const auto& s : tp.imu) tg.push_back(s.timeS), yg.push_back(sum += s.incrementDeg[a]);
  const Sine table = fitSine(tt, yt, w), gyro = fitSine(tg, yg, w);
  return {std::remainder(table.phaseRad - gyro.phaseRad, kTwoPi) / w, gyro.amplitude / table.amplitude};
}

// The response a constant adds: against the same chain with it off.
Response added(const SimConfig& off, const SimConfig& on, const TestPlan& plan) {
  const Response a = response(off, plan), b = response(on, plan);
  return {b.lagS - a.lagS, b.gain / a.gain};
}

void print(const char* what, double measured, double expected, const char* unit) {
  std::printf("%s: measured %.9g %s, closed form %.9g %s\n", what, measured, unit, expected, unit);
}

TEST(ChainConstants, OffByDefault) {
  const SimConfig c;
  EXPECT_EQ(c.fog.registerPeriodS, 0.0);
  EXPECT_EQ(c.fog.boxcarS, 0.0);
  EXPECT_EQ(c.fog.rateFilterTimeConstantS, 0.0);
  EXPECT_EQ(c.fog.rateFilterNaturalHz, 0.0);
  EXPECT_EQ(c.turntable.baseTiltDeg, 0.0);
  EXPECT_EQ(c.turntable.nonOrthogonalityArcsec[0], 0.0);
  EXPECT_EQ(c.encoder.eccentricityUm, 0.0);
  EXPECT_EQ(c.encoder.lostPerMille, 0.0);
  EXPECT_EQ(c.fog.filterDelayS(), 0.0);
  EXPECT_EQ(c.trueGyroDelayS(), c.fog.ownDelayS());
}

TEST(ChainConstants, ImpossibleValuesAreRefused) {
  auto refused = [](auto change, const char* words) {
    SimConfig c;
    change(c);
    const Status s = c.validate();
    EXPECT_FALSE(s.isOk()) << words;
    EXPECT_NE(s.message().find(words), std::string::npos) << s.message();
  };
  refused([](SimConfig& c) { c.fog.registerPeriodS = -1e-3; }, "pulse register period");
  refused([](SimConfig& c) { c.fog.registerPeriodS = 0.5e-3, c.fog.registerOffsetS = 0.5e-3; }, "pulse register offset");
  refused([](SimConfig& c) { c.fog.boxcarS = std::nan(""); }, "boxcar length");
  refused([](SimConfig& c) { c.fog.rateFilterTimeConstantS = 2.0; }, "rate filter time constant");
  refused([](SimConfig& c) { c.fog.rateFilterNaturalHz = -40.0; }, "rate filter natural frequency");
  refused([](SimConfig& c) { c.fog.rateFilterDamping = 0.0; }, "rate filter damping");
  refused([](SimConfig& c) { c.turntable.baseTiltDeg = 91.0; }, "base tilt");
  refused([](SimConfig& c) { c.turntable.nonOrthogonalityArcsec[1] = 1e9; }, "non-orthogonality");
  refused([](SimConfig& c) { c.encoder.eccentricityUm = -1.0; }, "encoder eccentricity");
  refused([](SimConfig& c) { c.encoder.eccentricityRadiusMm = 0.0; }, "read-head radius");
  refused([](SimConfig& c) { c.encoder.lostPerMille = 1000.0; }, "lost table frames");
}

// Locked clocks (IMU frames every 4 register periods): the board always
// reads (u0 - offset) mod P after an update, u0 the instant it would read
// without the register. Unlocked (the IMU crystal 1000 ppm fast, 120
// cycles of the hold in the record): the hold runs through [0, P), P / 2 on
// average.
TEST(ChainConstants, RegisterUpdateAddsItsHold) {
  const TestPlan plan = swing(Axis::kX, 0.5, 5.0, 60.0);
  SimConfig off = quiet(), on = off;
  on.fog.registerPeriodS = 0.5e-3;
  on.fog.registerOffsetS = 0.2e-3;
  const double u0 = off.imuBoard.firstSampleS - off.fog.ownDelayS();
  const double locked = std::fmod(u0 - on.fog.registerOffsetS + 10.0 * on.fog.registerPeriodS, on.fog.registerPeriodS);
  const Response l = added(off, on, plan);
  print("register 0.5 ms, offset 0.2 ms, locked: added lag", l.lagS * 1e6, locked * 1e6, "us");
  EXPECT_NEAR(l.lagS, locked, 0.05e-6);
  EXPECT_NEAR(l.gain, 1.0, 1e-6);

  off.imuBoard.clockErrorPpm = on.imuBoard.clockErrorPpm = 1000.0;
  const Response u = added(off, on, plan);
  print("register 0.5 ms, unlocked (IMU +1000 ppm): added lag", u.lagS * 1e6, 250.0, "us");
  EXPECT_NEAR(u.lagS, on.fog.registerPeriodS / 2.0, 2e-6);
  EXPECT_DOUBLE_EQ(on.fog.filterDelayS(), 0.25e-3);
}

// A boxcar over T: delay T / 2, gain sinc(pi f T).
TEST(ChainConstants, BoxcarDelaysByHalfItsLengthAndScalesBySinc) {
  for (const auto& [hz, amp, t] : {std::tuple{1.0, 3.0, 2e-3}, std::tuple{2.0, 3.0, 20e-3}}) {
    const TestPlan plan = swing(Axis::kX, hz, amp, 20.0);
    const SimConfig off = quiet();
    SimConfig on = off;
    on.fog.boxcarS = t;
    const Response r = added(off, on, plan);
    const double f = hz * (1.0 + off.turntable.frequencyErrorPpm * 1e-6), x = kPi * f * t;
    print("boxcar: added lag", r.lagS * 1e6, t / 2.0 * 1e6, "us");
    print("boxcar: gain", r.gain, std::sin(x) / x, "");
    EXPECT_NEAR(r.lagS, t / 2.0, 0.05e-6 + 1e-5 * t);
    EXPECT_NEAR(r.gain, std::sin(x) / x, 2e-6);
  }
}

// A first-order rate filter: phase atan(w T), gain 1 / sqrt(1 + (w T)^2).
TEST(ChainConstants, FirstOrderFilterPhaseIsAtanOmegaT) {
  const TestPlan plan = swing(Axis::kX, 2.0, 3.0, 20.0);
  const SimConfig off = quiet();
  SimConfig on = off;
  on.fog.rateFilterTimeConstantS = 3e-3;
  const Response r = added(off, on, plan);
  const double w = kTwoPi * 2.0 * (1.0 + off.turntable.frequencyErrorPpm * 1e-6), wt = w * 3e-3;
  print("first order 3 ms at 2 Hz: added lag", r.lagS * 1e6, std::atan(wt) / w * 1e6, "us");
  print("first order: gain", r.gain, 1.0 / std::sqrt(1.0 + wt * wt), "");
  // The filter takes the angle between 2-ms samples as the polynomial
  // through the last six: its error is of order (w h)^6, far below 0.01 us.
  EXPECT_NEAR(r.lagS, std::atan(wt) / w, 0.01e-6);
  EXPECT_NEAR(r.gain, 1.0 / std::sqrt(1.0 + wt * wt), 2e-6);
  EXPECT_DOUBLE_EQ(on.trueGyroDelayS(), on.fog.ownDelayS() + 3e-3);
}

// The chain's first-order filter and the diagnosis library's first_order_lag
// are one filter (model::FirstOrderFilter, solved exactly for the polynomial
// through the last six 2-ms samples): alone in the chain, at 1 Hz, the two
// give the same gyro angle at every frame. (With the chain's filter on the
// quadratic through three, they were up to a pulse apart.)
TEST(ChainConstants, FirstOrderFilterIsTheLibrarysFirstOrderLag) {
  const TestPlan plan = swing(Axis::kY, 1.0, 3.0, 6.0);
  SimConfig nominal;
  nominal.fog.rateFilterTimeConstantS = 3e-3;
  auto a = simulate(nominal, plan);
  std::vector<std::unique_ptr<Effect>> effects;
  effects.push_back(diagnosis::makeEffect(diagnosis::EffectId::kFirstOrderLag, {3.0}));
  auto b = simulate(SimConfig{}, plan, std::move(effects));
  ASSERT_TRUE(a.isOk() && b.isOk());
  auto ra = protocol::decodeRecording(a->bytes), rb = protocol::decodeRecording(b->bytes);
  ASSERT_TRUE(ra.isOk() && rb.isOk());
  const auto& ia = ra->testPoints.at(0).imu;
  const auto& ib = rb->testPoints.at(0).imu;
  ASSERT_EQ(ia.size(), ib.size());
  ASSERT_GT(ia.size(), 2000u);
  const double pulse = nominal.fog.pulseEquivalentDeg;
  double sumA = 0.0, sumB = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < ia.size(); ++k) {
    sumA += ia[k].incrementDeg[1];
    sumB += ib[k].incrementDeg[1];
    worst = std::max(worst, std::abs(sumA - sumB));
  }
  std::printf("chain filter against the library's lag: at most %.3g deg apart (pulse %.3g deg)\n", worst, pulse);
  EXPECT_EQ(worst, 0.0);
}

// A second-order rate filter: phase atan2(2 zeta r, 1 - r^2), gain
// 1 / sqrt((1 - r^2)^2 + (2 zeta r)^2), r = f / f_n.
TEST(ChainConstants, SecondOrderFilterPhaseAndGain) {
  for (const auto& [fn, zeta, hz, amp] : {std::tuple{40.0, 0.15, 5.0, 0.5}, std::tuple{40.0, 0.7, 5.0, 0.5},
                                          std::tuple{10.0, 2.0, 2.0, 2.0}}) {
    const TestPlan plan = swing(Axis::kX, hz, amp, 10.0);
    const SimConfig off = quiet();
    SimConfig on = off;
    on.fog.rateFilterNaturalHz = fn;
    on.fog.rateFilterDamping = zeta;
    const Response r = added(off, on, plan);
    const double f = hz * (1.0 + off.turntable.frequencyErrorPpm * 1e-6), w = kTwoPi * f, q = f / fn;
    const double phase = std::atan2(2.0 * zeta * q, 1.0 - q * q);
    const double gain = 1.0 / std::hypot(1.0 - q * q, 2.0 * zeta * q);
    char what[96];
    std::snprintf(what, sizeof what, "second order %.0f Hz, zeta %.2f at %.0f Hz: added lag", fn, zeta, hz);
    print(what, r.lagS * 1e6, phase / w * 1e6, "us");
    print("second order: gain", r.gain, gain, "");
    // The quadratic between 2-ms samples: 0.33 us at 5 Hz, (w h)^3 order.
    EXPECT_NEAR(r.lagS, phase / w, 0.5e-6);
    EXPECT_NEAR(r.gain, gain, 1e-5);
  }
}

// A base tilted by b about east turns the Earth rate as a latitude lat - b
// would (x: Omega cos(lat - b), z: -Omega sin(lat - b)); about north by b
// it gives y -Omega sin(lat) sin(b) and z -Omega sin(lat) cos(b). Gravity
// turns with it.
TEST(ChainConstants, BaseTiltTurnsTheEarthRateAndGravity) {
  const double lat = 40.0, b = 2.0, om = kEarthRateDegPerH;
  for (double az : {0.0, 90.0}) {
    SimConfig c = quiet();
    c.earth.latitudeDeg = lat;
    c.turntable.baseTiltDeg = b;
    c.turntable.baseTiltAzimuthDeg = az;
    const Attitude att(c.earth, c.turntable);
    const Eigen::Matrix3d i = att.bodyToTable(TableAngles{});
    const Eigen::Vector3d e = att.earthRateBodyDegPerH(i), f = att.specificForceBodyG(i);
    const double L = lat * kRadPerDeg, B = b * kRadPerDeg;
    const Eigen::Vector3d expected =
        az == 0.0 ? Eigen::Vector3d(om * std::cos(L), -om * std::sin(L) * std::sin(B), -om * std::sin(L) * std::cos(B))
                  : Eigen::Vector3d(om * std::cos(L - B), 0.0, -om * std::sin(L - B));
    const Eigen::Vector3d gravity = az == 0.0 ? Eigen::Vector3d(0.0, -std::sin(B), -std::cos(B))
                                              : Eigen::Vector3d(std::sin(B), 0.0, -std::cos(B));
    EXPECT_LT((e - expected).norm(), 1e-12) << e.transpose();
    EXPECT_LT((f - gravity).norm(), 1e-15) << f.transpose();
    // What the gyros sense at rest, from the stream.
    TestPlan plan;
    TestPoint p;
    p.kind = TestPointKind::kStatic;
    p.frequencyHz = 0.0;
    p.amplitudeDeg = 0.0;
    p.durationS = 20.0;
    p.settleS = 1.0;
    plan.points.push_back(p);
    const TestPointData tp = record(c, plan);
    const double span = tp.imu.back().timeS - tp.imu.front().timeS;
    for (int a = 0; a < kAxisCount; ++a) {
      double sum = 0.0;
      for (std::size_t k = 1; k < tp.imu.size(); ++k) sum += tp.imu[k].incrementDeg[static_cast<std::size_t>(a)];
      const double rate = sum / span * kSecondsPerHour;
      std::printf("tilt %.0f deg about azimuth %.0f: gyro %d senses %.6f deg/h, closed form %.6f\n", b, az, a, rate,
                  expected[a]);
      EXPECT_NEAR(rate, expected[a], 2e-4);
    }
  }
}

// The middle axis leaning d toward the outer one: a swing of the middle
// axis is sensed by the outer axis' gyro tan(d) of the swing axis' gyro; the
// inner leaning toward the middle: likewise for an inner swing.
TEST(ChainConstants, NonOrthogonalAxesCoupleByTheTangentOfTheirLean) {
  for (const auto& [swingAxis, other, lean] : {std::tuple{Axis::kY, Axis::kZ, 100.0}, std::tuple{Axis::kX, Axis::kY, -60.0}}) {
    SimConfig c = quiet();
    c.earth.latitudeDeg = 90.0;  // the Earth rate along z: even in a swing, no fundamental
    c.turntable.nonOrthogonalityArcsec = {100.0, -60.0};
    const TestPointData tp = record(c, swing(swingAxis, 1.0, 3.0, 10.0));
    // Regress the other gyro's angle on the swing gyro's (with a constant and a trend).
    const auto n = static_cast<Eigen::Index>(tp.imu.size());
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd y(n);
    double s = 0.0, o = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto& f = tp.imu[static_cast<std::size_t>(k)];
      s += f.incrementDeg[static_cast<std::size_t>(swingAxis)];
      o += f.incrementDeg[static_cast<std::size_t>(other)];
      a.row(k) << 1.0, f.timeS - tp.imu.front().timeS, s;
      y[k] = o;
    }
    const double k = a.colPivHouseholderQr().solve(y)[2];
    const double expected = std::tan(lean / kArcsecPerDeg * kRadPerDeg);
    print("non-orthogonality: coupling", k * 1e6, expected * 1e6, "ppm");
    EXPECT_NEAR(k, expected, 2e-3 * std::abs(expected));
  }
}

// Eccentricity e at radius r: the reading is off by (e / r) sin(theta + phase),
// e / r at its peak.
TEST(ChainConstants, EccentricityReadingErrorPeaksAtEOverR) {
  SimConfig c = quiet();
  c.encoder.eccentricityUm = 10.0;
  c.encoder.eccentricityRadiusMm = 100.0;
  c.encoder.eccentricityPhaseDeg = 60.0;
  const TestPlan plan = swing(Axis::kZ, 0.1, 40.0, 20.0);
  const TestPointData tp = record(c, plan);
  const Turntable table(plan, c.turntable);
  const double peak = 10e-6 / 100e-3 * kDegPerRad;
  EXPECT_NEAR(c.encoder.eccentricityPeakDeg(), peak, 1e-15);
  double most = 0.0, worst = 0.0;
  for (const auto& s : tp.table) {
    const double truth = table.anglesDeg(s.timeS - c.encoder.readDelayS)[2];
    const double err = s.angleDeg[2] - truth;
    most = std::max(most, err);
    worst = std::max(worst, std::abs(err - peak * std::sin((truth + 60.0) * kRadPerDeg)));
  }
  print("eccentricity 10 um at 100 mm: largest reading error", most * kArcsecPerDeg, peak * kArcsecPerDeg, "arcsec");
  EXPECT_NEAR(most, peak, 1e-6);  // the reading travels in micro-degrees
  EXPECT_LT(worst, 0.6e-6);
}

// Lost table frames: the count lost is binomial, within 3 sigma of N p.
TEST(ChainConstants, LostTableFramesMatchTheirRate) {
  for (double perMille : {1.0, 5.0, 50.0}) {
    SimConfig c = quiet();
    c.encoder.lostPerMille = perMille;
    auto run = simulate(c, swing(Axis::kX, 1.0, 3.0, 30.0));
    ASSERT_TRUE(run.isOk());
    auto rec = protocol::decodeRecording(run->bytes);
    ASSERT_TRUE(rec.isOk());
    const double n = static_cast<double>(rec->health.tableFrames + rec->health.lostFrames);
    const double lost = static_cast<double>(rec->health.lostFrames), p = perMille * 1e-3;
    const double sigma = std::sqrt(n * p * (1.0 - p));
    std::printf("lost %.0f per mille: %.0f of %.0f frames, expected %.1f +- %.1f\n", perMille, lost, n, n * p, sigma);
    EXPECT_LT(std::abs(lost - n * p), 3.0 * sigma);
  }
}

}  // namespace
}  // namespace fog::model

// Self-consistency regression set: a few short sessions (the
// self-consistency plan, blindCheckPlan(), two minutes of data) simulated
// with one of the library's own effects (or an outside one) that the
// diagnosis is not told about, and diagnosed with the same library. Not
// blind: the effect is the library's own model, so a factor or sign between
// the library and a standard's definition cannot show here (the reference
// checks in tests/independent can). A change that breaks naming, fitting,
// held-out shrink or the "unexplained" answer fails here.

#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/diagnosis/blind_check.h"
#include "core/diagnosis/diagnosis.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis {
namespace {

// A session of `plan` simulated with `effects`, diagnosed without being told them.
Diagnosis diagnoseSimulated(const model::SimConfig& c, const TestPlan& plan,
                            std::vector<std::unique_ptr<model::Effect>> effects, const DiagnosisOptions& options = {}) {
  auto run = model::simulate(c, plan, std::move(effects));
  EXPECT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  EXPECT_TRUE(rec.isOk());
  SessionInfo info;
  info.plan = plan;
  auto d = diagnose(*rec, &info, {}, options);
  EXPECT_TRUE(d.isOk()) << d.status().toString();
  return *d;
}

// The self-consistency plan (blindCheckPlan()) with a gyro delay of 0.31 ms.
Diagnosis diagnoseWith(std::vector<std::unique_ptr<model::Effect>> effects, std::uint64_t seed) {
  model::SimConfig c;
  c.seed = seed;
  c.fog.setOwnDelayS(0.31e-3);
  return diagnoseSimulated(c, blindCheckPlan(), std::move(effects));
}

Diagnosis diagnoseWith(EffectId id, std::vector<double> params, std::uint64_t seed) {
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeEffect(id, params));
  return diagnoseWith(std::move(e), seed);
}

const EffectFit& fitOf(const Diagnosis& d, const std::string& name) {
  for (const auto& e : d.effects)
    if (e.name == name) return e;
  ADD_FAILURE() << name << " not ranked";
  return d.effects.front();
}

TEST(Diagnosis, CleanSessionHasNoGapAndNoVerdict) {
  const Diagnosis d = diagnoseWith({}, 21);
  EXPECT_EQ(d.verdict, "none") << d.verdictReason << "\n" << formatDiagnosisText(d);
  EXPECT_FALSE(d.gapSignificant);
  // The z-scores are calibrated: rms near 1 on every measured channel (the
  // table's was 1.46 while its replays had no spread, the gyro's ~0.2-0.6
  // against its overstated white-noise standard errors).
  for (const auto& g : d.gapBefore) {
    EXPECT_LT(g.rmsZ, 1.3) << channelName(g.channel);
    if (g.channel != Channel::kTiming) {  // the simulator's clocks have no jitter: few timing cells count
      EXPECT_GT(g.rmsZ, 0.7) << channelName(g.channel);
    }
  }
  // The replay is calibrated to the session: its delay is the measured lag.
  EXPECT_NEAR(d.calibration.lagMs, 0.31 + 0.28 - 0.05, 0.002);
  EXPECT_NEAR(d.calibration.tableFrequencyErrorPpm, -8.37, 0.5);
  EXPECT_NEAR(d.calibration.arwDegPerSqrtH, 0.004, 0.0015);
  ASSERT_GE(d.aliasGroups.size(), 1u);
  EXPECT_EQ(d.aliasGroups[0].name, "constant delay");
  // No frame is lost: the lost-frame cells are 0 in the recording and in
  // every replay, carry no information and are no degrees of freedom.
  int uninformative = 0, informative = 0;
  for (const auto& c : d.gapMap) {
    if (c.informative) {
      ++informative;
      continue;
    }
    ++uninformative;
    EXPECT_LT(std::abs(c.z), 1.0);
  }
  EXPECT_GT(uninformative, 0);
  EXPECT_EQ(d.cells, informative);
  int perChannel = 0;
  for (const auto& g : d.gapBefore) perChannel += g.cells;
  EXPECT_EQ(perChannel, informative);
  for (const auto& g : d.gapBefore) {
    if (g.channel != Channel::kTiming) {
      EXPECT_GT(g.cells, 0) << channelName(g.channel);
    }
  }
}

// 200 ppm scale-factor error (~10x its threshold in this plan): named,
// recovered within 5 %, and the held-out gap closes by >= 80 %.
TEST(Diagnosis, ScaleFactorErrorIsNamedFittedAndClosesTheHeldOutGap) {
  const Diagnosis d = diagnoseWith(EffectId::kScaleFactorError, {200.0}, 22);
  EXPECT_EQ(d.verdict, "scale_factor_error") << d.verdictReason;
  const EffectFit& f = fitOf(d, "scale_factor_error");
  EXPECT_NEAR(f.values[0], 200.0, 10.0);
  EXPECT_GT(f.standardErrors[0], 0.0);
  EXPECT_GE(f.heldOutShrink, 0.8);
  EXPECT_TRUE(d.gapSignificant);
  const auto j = nlohmann::json::parse(formatDiagnosisJson(d));
  EXPECT_EQ(j["verdict"], "scale_factor_error");
  for (const char* c : {"table", "gyro", "gyro-table", "timing"}) {
    EXPECT_TRUE(j["gap"][c].contains("before")) << c;
    EXPECT_TRUE(j["gap"][c].contains("after")) << c;
  }
  EXPECT_LT(j["gap"]["gyro-table"]["after"].get<double>(), j["gap"]["gyro-table"]["before"].get<double>());
  const auto& top = j["effects"][0];
  for (const char* k : {"name", "parameters", "heldout_shrink", "score"}) EXPECT_TRUE(top.contains(k)) << k;
}

// Gyro y sensing 150 urad of a rotation about x, gyro z -100 urad of one
// about y: the other gyros see each swing in phase. The terms of the Z axis,
// which the plan never swings, have no signature and stay at 0.
TEST(Diagnosis, MisalignmentIsNamedAndRecovered) {
  const Diagnosis d = diagnoseWith(EffectId::kMisalignment, {0.0, 0.0, 150.0, 0.0, 0.0, -100.0}, 23);
  EXPECT_EQ(d.verdict, "misalignment") << d.verdictReason;
  const EffectFit& f = fitOf(d, "misalignment");
  EXPECT_NEAR(f.values[2], 150.0, 10.0);   // m_yx
  EXPECT_NEAR(f.values[5], -100.0, 10.0);  // m_zy
  EXPECT_NEAR(f.values[0], 0.0, 10.0);     // m_xy: Y swings too, so it is fitted
  EXPECT_EQ(f.values[1], 0.0);             // m_xz: Z never moves
  EXPECT_EQ(f.standardErrors[3], 0.0);     // m_yz
}

// g-sensitivity along each gyro's own axis: a swing about X tilts gravity
// into the Y gyro (in quadrature with the angle there) and out of Z.
TEST(Diagnosis, GSensitivityIsNamedFromTheCrossAxes) {
  const Diagnosis d = diagnoseWith(EffectId::kGSensitivity, {40.0}, 24);
  EXPECT_EQ(d.verdict, "g_sensitivity") << d.verdictReason;
  EXPECT_NEAR(fitOf(d, "g_sensitivity").values[0], 40.0, 2.0);
  // Its alias: the frame turned over with k' = -k - 2 Omega sin(40 deg) / g = -59.3 deg/h/g.
  EXPECT_NE(d.verdictReason.find("with the IMU's z axis up instead, a g-sensitivity of -5"), std::string::npos)
      << d.verdictReason;
  EXPECT_NE(d.verdictReason.find("swing data cannot tell them apart"), std::string::npos);
}

TEST(Diagnosis, ClockDriftIsNamedAndRecovered) {
  const Diagnosis d = diagnoseWith(EffectId::kClockDrift, {0.5}, 25);
  EXPECT_EQ(d.verdict, "clock_drift") << d.verdictReason;
  EXPECT_NEAR(fitOf(d, "clock_drift").values[0], 0.5, 0.05);
}

// A small drift is fitted at its size: the signature is taken at 1 ppm. At
// the former 10 ppm (3.6 ms of drift over the paper's two points) the
// signature was not linear: 0.013 ppm read 0.003 +- 0.0007 and the stated
// threshold was ~20x too small (docs/diagnosis.md).
TEST(Diagnosis, ASmallClockDriftIsFittedAtItsSizeOnThePapersPlan) {
  model::SimConfig c;
  c.seed = 1;
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeEffect(EffectId::kClockDrift, {0.013}));
  DiagnosisOptions options;
  options.threads = 2;
  const Diagnosis d = diagnoseSimulated(c, *presetPlan("paper"), std::move(e), options);
  const EffectFit& f = fitOf(d, "clock_drift");
  EXPECT_NEAR(f.values[0], 0.013, 3.0 * f.standardErrors[0]) << f.values[0] << " +- " << f.standardErrors[0];
}

// An eccentric grating read by one head (10 um at 100 mm, 100 urad) gives
// the encoder's reading a 2nd and a 3rd harmonic that a table distortion
// (a motion) fits in the table channel, closing its gap; but the gyros do
// not see them. The verdict is "unexplained" with the reading error as its
// reason (alpha 1.16 +- 0.11 on this seed, 10.6 sigma from a motion), the
// distortion kept as the table channel's partial explanation. It was named
// table_harmonic_distortion.
TEST(Diagnosis, AnEccentricGratingIsAReadingErrorNotATableMotion) {
  model::SimConfig c;
  c.seed = 7;
  c.encoder.eccentricityUm = 10.0;
  c.encoder.eccentricityPhaseDeg = 90.0;
  DiagnosisOptions options;
  options.threads = 2;
  const Diagnosis d = diagnoseSimulated(c, *presetPlan("paper"), {}, options);
  EXPECT_EQ(d.verdict, "unexplained") << d.verdictReason;
  EXPECT_NE(d.verdictReason.find("in the encoder's reading only"), std::string::npos) << d.verdictReason;
  EXPECT_TRUE(d.verdictEffects.empty());
  EXPECT_TRUE(fitOf(d, "table_harmonic_distortion").kept);
}

// A table distortion is a motion: at a 2nd harmonic of 10 ppm of the
// fundamental at 10 deg (h2) the gyros see it and it is named without a
// caveat; at 1 ppm the paper's plan cannot tell it
// from a reading error (alpha -0.12 +- 0.43 on this seed) and the verdict
// says so while naming it.
TEST(Diagnosis, ATableDistortionIsNamedAndSaysWhenTheGyrosCannotTellItFromAReadingError) {
  for (const double h2 : {10.0, 1.0}) {
    model::SimConfig c;
    c.seed = 7;
    std::vector<std::unique_ptr<model::Effect>> e;
    e.push_back(makeEffect(EffectId::kTableHarmonicDistortion, {h2, 0.0}));
    DiagnosisOptions options;
    options.threads = 2;
    const Diagnosis d = diagnoseSimulated(c, *presetPlan("paper"), std::move(e), options);
    EXPECT_EQ(d.verdict, "table_harmonic_distortion") << h2 << ": " << d.verdictReason;
    const bool caveat = d.verdictReason.find("reading error with the same harmonics is not excluded") != std::string::npos;
    EXPECT_EQ(caveat, h2 < 5.0) << h2 << ": " << d.verdictReason;
  }
}

// The quick preset swings X only, so the Earth rate the gyros see shows
// sin h of the table's heading but not the sign of cos h: h and 180 - h fit
// alike. The tie went to whichever rounded lower, and 3 of the first 6 seeds
// reported a table at heading 0 as -179.7, -178.3 and 165.1 deg. The
// convention cos h >= 0 is now applied and said.
TEST(Diagnosis, AnXOnlyPlanGivesTheHeadingWithCosHTakenPositive) {
  for (std::uint64_t seed : {2u, 3u}) {
    model::SimConfig c;
    c.seed = seed;
    const Diagnosis d = diagnoseSimulated(c, *presetPlan("quick"), {});
    EXPECT_NEAR(d.calibration.headingDeg, c.earth.headingDeg, 3.0 * d.calibration.headingStdDeg) << "seed " << seed;
    EXPECT_TRUE(std::any_of(d.notes.begin(), d.notes.end(), [](const std::string& n) {
      return n.find("cos h is taken >= 0") != std::string::npos;
    })) << "seed " << seed;
  }
}

// A lab whose IMU's z axis points up (east-north-up). Unstated, the data
// show it and the replays use it (no false g-sensitivity of -2 Omega
// sin(lat) / g = -19.3 deg/h/g, which a z-down replay used to fit at 100 %
// of the held-out gap); stated, it is confirmed; stated wrongly, the verdict
// says so and names no effect.
TEST(Diagnosis, TheImuFrameIsFoundCheckedAndAContradictedOneNamesNoEffect) {
  model::SimConfig c;
  c.seed = 31;
  c.fog.setOwnDelayS(0.31e-3);
  c.earth.zUp = true;
  c.earth.headingDeg = 90.0;
  auto run = model::simulate(c, blindCheckPlan(), {});
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk());
  SessionInfo info;
  info.plan = blindCheckPlan();
  auto diagnoseStating = [&](const char* frame) {
    BenchConstants constants;
    constants.imuFrame = *imuFrameFromText(frame);
    auto d = diagnose(*rec, &info, constants);
    EXPECT_TRUE(d.isOk()) << d.status().toString();
    return *d;
  };
  for (const char* frame : {"", "ENU", "RFU:0"}) {
    const Diagnosis d = diagnoseStating(frame);
    const FrameCheck& f = d.calibration.frame;
    EXPECT_TRUE(f.checked && f.decisive && f.zUp && !f.contradicted) << frame;
    // The vertical Earth rate is the z-up frame's, measured to a few %.
    EXPECT_NEAR(std::abs(f.verticalRatio), 1.0, std::max(0.05, 5.0 * f.verticalRatioStd)) << frame;
    EXPECT_NEAR(d.calibration.headingDeg, 90.0, std::max(3.0, 3.0 * d.calibration.headingStdDeg)) << frame;
    EXPECT_EQ(d.verdict, "none") << frame << ": " << d.verdictReason;
  }
  for (const char* frame : {"NED", "FRD:90"}) {
    const Diagnosis d = diagnoseStating(frame);
    EXPECT_TRUE(d.calibration.frame.contradicted) << frame;
    EXPECT_EQ(d.verdict, "frame_contradicted") << frame;
    EXPECT_TRUE(d.verdictEffects.empty());
    EXPECT_NE(d.verdictReason.find("the data show the IMU's z axis up; the bench constants state down"),
              std::string::npos)
        << d.verdictReason;
    EXPECT_TRUE(std::none_of(d.effects.begin(), d.effects.end(), [](const EffectFit& e) { return e.kept; }));
    const auto json = nlohmann::json::parse(formatDiagnosisJson(d));
    EXPECT_EQ(json["verdict"], "frame_contradicted");
    EXPECT_EQ(json["calibration"]["imu_frame"]["stated"], frame);
    EXPECT_EQ(json["calibration"]["imu_frame"]["z_up"], true);
  }
}

// A plan that swings Y only shows cos h but not the sign of sin h; with z
// up found from the data (unstated), the heading is taken with sin h >= 0
// and the biases are fitted at that heading: the y bias came out off by
// 2 Omega cos(lat) sin(h) (~20 deg/h) when they were fitted at the negated
// one.
TEST(Diagnosis, AYOnlyPlanWithZUpGivesTheBiasesAtTheHeadingReported) {
  model::SimConfig c;
  c.seed = 35;
  c.earth.zUp = true;
  c.earth.headingDeg = 60.0;
  c.fog.biasDegPerH = {0.4, -0.7, 0.2};
  TestPlan plan;
  plan.restBetweenS = 3.0;
  plan.points.push_back({Axis::kY, 1.0, 3.0, 30.0, 2.0, 0.0});
  plan.points.push_back({Axis::kY, 0.1, 10.0, 60.0, 2.0, 0.0});
  const Diagnosis d = diagnoseSimulated(c, plan, {});
  const Calibration& cal = d.calibration;
  EXPECT_TRUE(cal.frame.zUp);
  EXPECT_NEAR(cal.headingDeg, 60.0, std::max(5.0, 3.0 * cal.headingStdDeg));
  for (int a = 0; a < kAxisCount; ++a)
    EXPECT_NEAR(cal.biasDegPerH[static_cast<std::size_t>(a)], c.fog.biasDegPerH[static_cast<std::size_t>(a)], 0.5)
        << axisName(static_cast<Axis>(a));
  EXPECT_EQ(d.verdict, "none") << d.verdictReason;
}

// Table samples lost at random (2 per mille) are not in the library (its
// dropped frames are the IMU's): the timing cells of the lost table samples
// carry the gap and the answer is "unexplained". They were skipped with
// the stamp intervals' gaps, and a reference session with lost table rows
// was answered "none".
TEST(Diagnosis, LostTableSamplesAreAGapNoEffectCloses) {
  model::SimConfig c;
  c.seed = 33;
  c.fog.setOwnDelayS(0.31e-3);
  c.encoder.lostPerMille = 2.0;
  const Diagnosis d = diagnoseSimulated(c, blindCheckPlan(), {});
  EXPECT_EQ(d.verdict, "unexplained") << d.verdictReason;
  double lost = 0.0;
  for (const auto& cell : d.gapMap)
    if (cell.key.quantity == Quantity::kTableLost) {
      lost += cell.real;
      EXPECT_EQ(cell.simMean, 0.0);
    }
  EXPECT_GT(lost, 100.0);  // ~2 per mille of the session's ~129 000 table samples
  ASSERT_GE(d.gapBefore.size(), 4u);
  EXPECT_GT(d.gapBefore[static_cast<std::size_t>(Channel::kTiming)].rmsZ, 5.0);
}

// The replay quantises the table at the readings' own quantum: the
// harmonics a swing's quantisation leaves depend on its amplitude in quanta
// to better than 0.1 %, and sqrt(12) sigma of the residual is 0.16 % off
// (0.4223 arcsec for 0.4216): two clean reference sessions were answered
// "unexplained" on their table channel (5.4 and 5.8 sigma).
TEST(Diagnosis, TheReplayQuantisesTheTableAtTheReadingsOwnQuantum) {
  model::SimConfig c;
  c.seed = 5;
  c.fog.setOwnDelayS(0.31e-3);
  c.encoder.quantumDeg = 1.1711e-4;  // 0.4216 arcsec, not a whole number of the transport's micro-degrees
  const Diagnosis d = diagnoseSimulated(c, blindCheckPlan(), {});
  EXPECT_NEAR(d.calibration.config.encoder.quantumDeg / 1.1711e-4, 1.0, 2e-5) << d.calibration.config.encoder.quantumDeg;
  EXPECT_EQ(d.verdict, "none") << d.verdictReason;
}

// A large stamp jitter (2 us rms on the IMU stamps, 4 us^2) is named and
// fitted. Its variance cells' spread grows with it and the mean interval's
// formal error is what the jitter leaves of it; held to the clean replay's
// spread, the fitted jitter (3.99 +- 0.01 us^2, closing 100 %) left "1276
// sigma" in the timing cells and the answer was "unexplained".
TEST(Diagnosis, ALargeStampJitterIsNamedAndFitted) {
  const Diagnosis d = diagnoseWith(EffectId::kTimestampJitter, {4.0}, 34);
  EXPECT_EQ(d.verdict, "timestamp_jitter") << d.verdictReason;
  const EffectFit& f = fitOf(d, "timestamp_jitter");
  EXPECT_NEAR(f.values[0], 4.0, std::max(0.1, 5.0 * f.standardErrors[0]));
}

// A gyro bias step half-way through is not in the library: a ramp closes
// ~90 % of its held-out gap but leaves a remainder of many sigma in the gyro
// trends, so the answer is "unexplained" (with the ramp as a partial
// explanation). (A 7.3 Hz gyro vibration is tested below.)
TEST(Diagnosis, OutOfLibraryBiasStepIsUnexplained) {
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeOutsideEffect(OutsideEffect::kBiasStep, 4.0));
  const Diagnosis d = diagnoseWith(std::move(e), 26);
  EXPECT_TRUE(d.gapSignificant);
  EXPECT_EQ(d.verdict, "unexplained") << d.verdictReason << "\n" << formatDiagnosisText(d);
  EXPECT_NE(d.verdictReason.find("gyro channel"), std::string::npos) << d.verdictReason;
}

// Regression set for the fixes of the self-consistency check's misses (docs/diagnosis.md).

// bias_drift: the signature used to be taken at 0.1 deg/h per min, where the
// re-drawn pulse quantisation outweighed the trend ramp (fit pulled to ~0,
// never kept). 0.5 deg/h per min is ~3x its threshold in this plan.
TEST(Diagnosis, BiasDriftIsNamedAndRecovered) {
  const Diagnosis d = diagnoseWith(EffectId::kBiasDrift, {0.5}, 27);
  EXPECT_EQ(d.verdict, "bias_drift") << d.verdictReason;
  EXPECT_NEAR(fitOf(d, "bias_drift").values[0], 0.5, 0.15);
}

// dropped_frames: the recording loses a random set of frames that no replay
// can reproduce; the replay loses the expected share evenly and the lost-frame
// cells carry the recording's Poisson spread, so the rate explains the gap
// (it used to leave a "significant" remainder and answer "unexplained").
TEST(Diagnosis, DroppedFramesAreNamedNotUnexplained) {
  const Diagnosis d = diagnoseWith(EffectId::kDroppedFrames, {2.0}, 28);
  EXPECT_EQ(d.verdict, "dropped_frames") << d.verdictReason;
  EXPECT_NEAR(fitOf(d, "dropped_frames").values[0], 2.0, 0.3);
}

// first_order_lag: fitted as tau^2 (it acts through its square once the delay
// is calibrated away), with the gyro-table cells against the replays' own
// spread it is told from a scale-factor error by the 0.1 Hz point, and a lag
// of 2 ms (the measured lag > the IMU frame period) no longer makes the
// calibrated replay invalid.
TEST(Diagnosis, FirstOrderLagIsNamedAndRecovered) {
  const Diagnosis d = diagnoseWith(EffectId::kFirstOrderLag, {2.0}, 29);
  EXPECT_EQ(d.verdict, "first_order_lag") << d.verdictReason;
  EXPECT_NEAR(fitOf(d, "first_order_lag").values[0], 2.0, 0.1);
}

// A 7.3 Hz gyro vibration is outside the library: a lag closes its gyro
// residual gap but opens one in the gyro-table harmonics (the channel check
// refuses it) or leaves a significant remainder: "unexplained" either way.
TEST(Diagnosis, OutOfLibraryGyroVibrationIsUnexplainedNotALag) {
  std::vector<std::unique_ptr<model::Effect>> e;
  e.push_back(makeOutsideEffect(OutsideEffect::kGyroVibration, 3e-4));
  const Diagnosis d = diagnoseWith(std::move(e), 30);
  EXPECT_TRUE(d.gapSignificant);
  EXPECT_EQ(d.verdict, "unexplained") << d.verdictReason;
  EXPECT_NE(d.verdict, "first_order_lag");
}

// encoder_cyclic_error below the encoder's quantum (0.36 arcsec): the table
// residual variance takes up the error's harmonics above the fifth, which
// grow with its square; the one-sided signature at 1 arcsec put a chord
// through that and overstated it ~20x at 0.05 arcsec, so the fit came out
// skewed (0.020 cos + -0.013 sin for 0.05 cos) and the verdict
// "unexplained". Central differences leave the square to the exact
// evaluation.
TEST(Diagnosis, SubQuantumEncoderCyclicErrorIsNamedAndRecovered) {
  const Diagnosis d = diagnoseWith(EffectId::kEncoderCyclicError, {0.0, 0.05}, 31);
  EXPECT_EQ(d.verdict, "encoder_cyclic_error") << d.verdictReason;
  const EffectFit& f = fitOf(d, "encoder_cyclic_error");
  EXPECT_NEAR(f.values[0], 0.0, 0.005);
  EXPECT_NEAR(f.values[1], 0.05, 0.005);
  EXPECT_GT(f.heldOutShrink, 0.9);
}

// The GUI's progress bar and Cancel: the fraction only grows and ends at 1,
// every stage is reported in order; a cancel stops the diagnosis at once
// with kCancelled and no verdict.
TEST(Diagnosis, ReportsProgressAndStopsWhenCancelled) {
  model::SimConfig c;
  c.seed = 31;
  const TestPlan plan = blindCheckPlan();
  auto run = model::simulate(c, plan);
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk());
  SessionInfo info;
  info.plan = plan;

  DiagnosisOptions options;
  std::vector<double> fractions;
  std::vector<std::string> stages;
  int concurrent = 0, maxConcurrent = 0;
  options.progress = [&](double f, const std::string& stage) {
    maxConcurrent = std::max(maxConcurrent, ++concurrent);
    fractions.push_back(f);
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    --concurrent;
    return true;
  };
  auto d = diagnose(*rec, &info, {}, options);
  ASSERT_TRUE(d.isOk()) << d.status().toString();
  ASSERT_GE(fractions.size(), 20u);  // at least once per replay
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GE(fractions.front(), 0.0);
  EXPECT_EQ(maxConcurrent, 1);
  const std::vector<std::string> expected = {"calibration", "replays", "effects", "refinement", "pairs", "verdict"};
  EXPECT_EQ(stages, expected);
  // Halfway through the replays stage the bar is neither at the start nor
  // at the end: the fraction counts the work.
  const auto mid = std::find_if(fractions.begin(), fractions.end(), [](double f) { return f > 0.3 && f < 0.7; });
  EXPECT_NE(mid, fractions.end());

  int callsAfterCancel = 0;
  bool cancelledOnce = false;
  options.progress = [&](double f, const std::string&) {
    if (cancelledOnce) ++callsAfterCancel;
    if (f > 0.2) cancelledOnce = true;
    return !cancelledOnce;
  };
  auto stopped = diagnose(*rec, &info, {}, options);
  ASSERT_FALSE(stopped.isOk());
  EXPECT_EQ(stopped.status().code(), StatusCode::kCancelled);
  EXPECT_NE(stopped.status().message().find("cancelled"), std::string::npos);
  EXPECT_EQ(callsAfterCancel, 0);
}

// A session whose diagnosis would need more than the memory budget even on
// one thread is refused before anything runs, saying why and what fits.
TEST(Diagnosis, ASessionTooLargeForTheMemoryBudgetIsRefused) {
  Recording rec;
  TestPointData tp;
  const auto samples = static_cast<std::size_t>(kDiagnosisMemoryBudgetBytes / 3.0 / sizeof(TableSample)) + 1000;
  tp.table.resize(samples);
  tp.imu.resize(10);
  rec.testPoints.push_back(std::move(tp));
  auto d = diagnose(rec, nullptr, {}, {});
  ASSERT_FALSE(d.isOk());
  EXPECT_EQ(d.status().code(), StatusCode::kOutOfRange) << d.status().toString();
  EXPECT_NE(d.status().message().find("MB limit"), std::string::npos) << d.status().toString();
}

}  // namespace
}  // namespace fog::diagnosis

// Rules the plan and the analysis share, through the whole chain (simulator
// -> bytes -> decoder -> analysis), issue 39:
//  - the gyro's scale against the bench's tolerance (the "gain" check): a
//    scale 0.5 % off passes, 2 % off is invalid; a gyro whose resonance
//    raises its gain 43 % at 11 Hz is not (its fitted dynamics are out);
//  - one rule for a point's minimum periods: a point the plan accepts
//    (exactly two periods, any start phase) is analysed, one below is
//    refused by both in the same words;
//  - moves compared with a tolerance: a plan with rest_between_s 0 whose
//    points start and end where the next begins, to rounding, is accepted
//    and runs.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/gain_check.h"
#include "core/analysis/verdict.h"
#include "core/diagnosis/effects.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog {
namespace {

Result<Recording> simulated(const model::SimConfig& config, const TestPlan& plan,
                            std::vector<std::unique_ptr<model::Effect>> effects = {}) {
  auto run = model::simulate(config, plan, std::move(effects));
  if (!run) return run.status();
  return protocol::decodeRecording(run->bytes);
}

const analysis::ValidityCheck& checkOf(const analysis::TestPointResult& p, const std::string& id) {
  for (const auto& c : p.checks)
    if (c.id == id) return c;
  ADD_FAILURE() << "no check " << id;
  static const analysis::ValidityCheck none;
  return none;
}

TestPlan quick() {
  TestPlan plan;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 20.0, 2.0, 0.0});
  return plan;
}

// ---- the gain check -------------------------------------------------------

// A scale factor error (the diagnosis library's effect) of 0.5 % passes the
// default 1 % tolerance, 2 % does not; a tolerance of 3 % stated passes it.
TEST(GainCheck, HalfAPercentPassesTwoPercentIsInvalid) {
  struct Case {
    double ppm, tolerance;
    bool passes;
    const char* words;
  } cases[] = {
      {5000.0, 0.01, true, "the gyro's amplitude matches the table's (gyro/table ratio 1.0050, within 1 ± 1 %)"},
      {-5000.0, 0.01, true, "(gyro/table ratio 0.9950, within 1 ± 1 %)"},
      {20000.0, 0.01, false,
       "the gyro reads 2.00 % more than the table (gyro/table ratio 1.0200, outside 1 ± 1 %): its scale is not the "
       "one the bench states"},
      {-20000.0, 0.01, false, "the gyro reads 2.00 % less than the table (gyro/table ratio 0.9800, outside 1 ± 1 %)"},
      {20000.0, 0.03, true, "(gyro/table ratio 1.0200, within 1 ± 3 %)"},
  };
  for (const auto& k : cases) {
    std::vector<std::unique_ptr<model::Effect>> effects;
    effects.push_back(diagnosis::makeEffect(diagnosis::EffectId::kScaleFactorError, {k.ppm}));
    auto rec = simulated(model::SimConfig{}, quick(), std::move(effects));
    ASSERT_TRUE(rec.isOk()) << rec.status().toString();
    BenchConstants constants;
    constants.gainToleranceFraction = k.tolerance;
    auto report = analysis::analyzeRecording(*rec, constants);
    ASSERT_TRUE(report.isOk()) << report.status().toString();
    const auto& point = report->points.at(0);
    const auto& gain = checkOf(point, "gain");
    std::printf("  %+.0f ppm, tolerance %g: %s\n", k.ppm, k.tolerance, gain.detail.c_str());
    EXPECT_EQ(gain.passed, k.passes) << gain.detail;
    EXPECT_TRUE(gain.judged);
    EXPECT_NE(gain.detail.find(k.words), std::string::npos) << gain.detail;
    // Listed after axis_sign, and it decides the verdict.
    EXPECT_EQ(point.checks.at(0).id, "axis_sign");
    EXPECT_EQ(point.checks.at(1).id, "gain");
    const auto verdict = analysis::judgeReport(*report, analysis::kDefaultImuDelayLimitMs);
    EXPECT_EQ(verdict.verdict == analysis::Verdict::kInvalid, !k.passes);
  }
}

// The frequency response's gains away from 1 are its measurand: a gyro with
// a lightly damped resonance at 20 Hz reads 1.43 x the table at 11 Hz, one
// with a 20-ms first-order lag 0.97 x at 2 Hz. With the axis' fitted
// dynamics taken out the scale is 1 within 1e-3, and every point passes.
TEST(GainCheck, TheFittedDynamicsAreTakenOut) {
  model::SimConfig resonant;
  resonant.fog.rateFilterNaturalHz = 20.0;
  resonant.fog.rateFilterDamping = 0.05;
  auto rec = simulated(resonant, *presetPlan("response"));
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  auto report = analysis::analyzeRecording(*rec, BenchConstants{});
  ASSERT_TRUE(report.isOk()) << report.status().toString();
  double largest = 0.0;
  for (const auto& p : report->points) {
    const auto& gain = checkOf(p, "gain");
    EXPECT_TRUE(gain.passed) << p.nominalFrequencyHz << " Hz: " << gain.detail;
    largest = std::max(largest, p.magnitudeRatio);
  }
  std::printf("  resonance: largest gyro/table ratio %.4f; at 11 Hz: %s\n", largest,
              checkOf(report->points.back(), "gain").detail.c_str());
  EXPECT_GT(largest, 1.4);
  EXPECT_NE(checkOf(report->points.back(), "gain").detail.find("where the fitted second_order response's own gain is"),
            std::string::npos);

  // Two frequencies, a 20-ms first-order lag (PaperReproduction's): 0.998
  // and 0.970; both pass, and the frequency test still pools both.
  TestPlan two;
  two.points.push_back({Axis::kX, 0.5, 5.0, 40.0, 2.0, 0.0});
  two.points.push_back({Axis::kX, 2.0, 1.5, 20.0, 1.0, 0.0});
  std::vector<std::unique_ptr<model::Effect>> effects;
  effects.push_back(diagnosis::makeEffect(diagnosis::EffectId::kFirstOrderLag, {20.0}));
  auto lagged = simulated(model::SimConfig{}, two, std::move(effects));
  ASSERT_TRUE(lagged.isOk());
  auto lagReport = analysis::analyzeRecording(*lagged, BenchConstants{});
  ASSERT_TRUE(lagReport.isOk());
  for (const auto& p : lagReport->points) {
    const auto& gain = checkOf(p, "gain");
    std::printf("  first-order lag, %.1f Hz: %s\n", p.nominalFrequencyHz, gain.detail.c_str());
    EXPECT_TRUE(gain.passed) << gain.detail;
  }
  EXPECT_LT(lagReport->points.at(1).magnitudeRatio, 0.98);
  ASSERT_EQ(lagReport->consistency.size(), 1u);
  EXPECT_EQ(lagReport->consistency[0].points, 2);
}

// The check's words, on a point made by hand: a gross factor names the
// constants; dynamics measured elsewhere are taken out.
TEST(GainCheck, ItsWordsSayWhatIsWrongAndWhatToDo) {
  analysis::TestPointResult p;
  p.magnitudeRatio = 499.9995;
  p.joint.frequencyHz = 1.0;
  auto c = analysis::gainCheck(p, {}, 0.01);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.detail.rfind("the gyro reads 500× the table (gyro/table ratio 499.9995, outside 1 ± 1 %): the pulse "
                           "equivalent or the frame period is wrong",
                           0),
            0u)
      << c.detail;
  p.magnitudeRatio = 1.0 / 500.0;
  EXPECT_NE(analysis::gainCheck(p, {}, 0.01).detail.find("the gyro reads 1/500 of the table"), std::string::npos);
  // A ratio of 0.9 where the axis' fitted first-order response gives 0.9.
  p.magnitudeRatio = 0.9;
  c = analysis::gainCheck(p, {0.9, "first_order"}, 0.01);
  EXPECT_TRUE(c.passed) << c.detail;
  EXPECT_EQ(c.detail, "the gyro's amplitude matches the table's (gyro/table ratio 0.9000 at 1 Hz, where the fitted "
                      "first_order response's own gain is 0.9000: scale 1.0000, within 1 ± 1 %)");
  // Without a response, a ratio below 1 may be the gyro's dynamics: it says how to tell.
  p.magnitudeRatio = 0.97;
  c = analysis::gainCheck(p, {}, 0.01);
  EXPECT_FALSE(c.passed);
  EXPECT_NE(c.detail.find("measure its frequency response (run --preset response)"), std::string::npos) << c.detail;
  EXPECT_NE(c.detail.find("state its tolerance (--gain-tolerance)"), std::string::npos) << c.detail;
  // A reversed axis' ratio is judged by its magnitude (axis_sign says the sign).
  p.magnitudeRatio = -1.0;
  EXPECT_TRUE(analysis::gainCheck(p, {}, 0.01).passed);
}

// ---- one rule for the minimum periods ---------------------------------------

// A point of exactly two periods passes the plan and is analysed, whatever
// its start phase (at 60, 90, 120 deg ... the analysis refused it: its
// samples span 1.998 periods).
TEST(MinimumPeriods, APointThePlanAcceptsIsAnalysed) {
  for (double phase = 0.0; phase < 360.0; phase += 30.0) {
    TestPlan plan;
    plan.points.push_back({Axis::kX, 1.0, 3.0, 2.0, 1.0, phase});
    ASSERT_TRUE(plan.validate(TurntableLimits{}).isOk()) << plan.validate(TurntableLimits{}).message();
    auto rec = simulated(model::SimConfig{}, plan);
    ASSERT_TRUE(rec.isOk()) << rec.status().toString();
    auto report = analysis::analyzeRecording(*rec, BenchConstants{});
    ASSERT_TRUE(report.isOk()) << phase << " deg: " << report.status().message();
    EXPECT_EQ(report->points.size(), 1u) << phase << " deg";
  }
}

// One below: the plan refuses it, and a recording cut to it (the plan's
// point would not run) is refused by the analysis, in the same words.
TEST(MinimumPeriods, OneBelowIsRefusedByBothInTheSameWords) {
  const std::string words = "swing periods, under two swing periods: a delay needs at least two whole periods";
  EXPECT_EQ(tooFewSwingPeriods(2.0), "");
  EXPECT_EQ(tooFewSwingPeriods(2.0 - 1e-12), "");  // rounding
  EXPECT_EQ(tooFewSwingPeriods(1.9989), "covers 1.99 " + words);  // rounded down, never "2.00"
  TestPlan plan;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 1.9, 1.0, 90.0});
  const Status refused = plan.validate(TurntableLimits{});
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.message(), "test point 1: duration 1.9 s covers 1.90 " + words + " (2 s)");

  plan.points[0].durationS = 2.0;
  auto rec = simulated(model::SimConfig{}, plan);
  ASSERT_TRUE(rec.isOk());
  auto& point = rec->testPoints.at(0);
  const double end = point.table.front().timeS + 1.9;
  std::erase_if(point.table, [end](const TableSample& s) { return s.timeS >= end; });
  std::erase_if(point.imu, [end](const ImuSample& s) { return s.timeS >= end; });
  auto report = analysis::analyzeRecording(*rec, BenchConstants{});
  ASSERT_FALSE(report.isOk());
  EXPECT_EQ(report.status().code(), StatusCode::kInsufficientData);
  std::printf("  the plan: %s\n  the analysis: %s\n", refused.message().c_str(), report.status().message().c_str());
  // (The table's own frequency estimate finds it first when the record
  // is short of the planned periods: "the table angle covers ...".)
  EXPECT_NE(report.status().message().find("test point 1: the "), std::string::npos) << report.status().message();
  const std::string& why = report.status().message();
  EXPECT_TRUE(why.find(" covers 1.90 ") != std::string::npos || why.find(" covers 1.89 ") != std::string::npos) << why;
  EXPECT_NE(report.status().message().find(words), std::string::npos) << report.status().message();
}

// ---- moves with a tolerance -----------------------------------------------

// Whole periods end where they start (to 7e-15 deg of rounding): with
// rest_between_s 0 the plan is accepted, and it runs.
TEST(PlanMotion, RestZeroBetweenPointsThatMeetToRoundingRuns) {
  TestPlan plan;
  plan.restBetweenS = 0.0;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 10.0, 1.0, 0.0});
  plan.points.push_back({Axis::kX, 2.0, 1.5, 5.0, 0.5, 0.0});
  const double end = plan.endAnglesDeg(0)[0];
  std::printf("  the first point ends %.3g deg from where the second starts\n", end - plan.startAnglesDeg(1)[0]);
  EXPECT_NE(end, 0.0);  // rounding: what the plan once refused
  ASSERT_TRUE(plan.validate(TurntableLimits{}).isOk()) << plan.validate(TurntableLimits{}).message();
  auto rec = simulated(model::SimConfig{}, plan);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  auto report = analysis::analyzeRecording(*rec, BenchConstants{});
  ASSERT_TRUE(report.isOk()) << report.status().toString();
  ASSERT_EQ(report->points.size(), 2u);
  const auto verdict = analysis::judgeReport(*report, analysis::kDefaultImuDelayLimitMs);
  EXPECT_EQ(verdict.verdict, analysis::Verdict::kPass) << (verdict.reasons.empty() ? "" : verdict.reasons.front());

  // A real move still needs its rest.
  plan.points[1].positionDeg[2] = 1e-3;
  const Status s = plan.validate(TurntableLimits{});
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("the move to test point 2 turns the table by 0.001 deg with no rest time"),
            std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace fog

#include "core/common/test_plan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fog {
namespace {

TEST(TestPlan, PaperConditionsAreValid) {
  std::string why;
  why = TestPlan::paperSlow().validate(TurntableLimits{}).message();
  EXPECT_TRUE(why.empty()) << why;
  why = TestPlan::paperFast().validate(TurntableLimits{}).message();
  EXPECT_TRUE(why.empty()) << why;
}

TEST(TestPlan, RefusesNonPositiveFrequencyAndAmplitude) {
  TestPoint p;
  std::string why;
  p.frequencyHz = 0.0;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("frequency must be > 0"), std::string::npos) << why;
  p = TestPoint{};
  p.amplitudeDeg = -1.0;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("amplitude must be > 0"), std::string::npos) << why;
}

TEST(TestPlan, RefusesDurationUnderTwoPeriods) {
  TestPoint p;
  p.frequencyHz = 0.1;
  p.durationS = 19.9;
  std::string why;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("under two swing periods"), std::string::npos) << why;
  p.durationS = 20.0;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_TRUE(why.empty()) << why;
}

TEST(TestPlan, RefusesMotionBeyondTableLimits) {
  TestPoint p;
  p.frequencyHz = 10.0;
  p.amplitudeDeg = 10.0;  // 628 deg/s peak
  p.durationS = 10.0;
  std::string why;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("peak rate"), std::string::npos) << why;
}

// Issue 39: a whole-period swing ends where it started only to rounding
// (7e-15 deg), and rest_between_s 0 was refused over that "move". Angles
// are compared to within kMotionToleranceDeg; a real move still needs rest.
TEST(TestPlan, MovesAreComparedWithATolerance) {
  TestPlan plan = *testPlanFromJson(R"({"rest_between_s": 0, "points": [
      {"axis": "x", "frequency_hz": 1, "amplitude_deg": 3, "duration_s": 10, "settle_s": 1},
      {"axis": "x", "frequency_hz": 2, "amplitude_deg": 1.5, "duration_s": 5, "settle_s": 0.5}]})");
  EXPECT_NE(plan.endAnglesDeg(1)[0], 0.0);  // rounding: what was refused
  EXPECT_LT(std::abs(plan.endAnglesDeg(1)[0]), 1e-12);
  EXPECT_TRUE(plan.validate(TurntableLimits{}).isOk()) << plan.validate(TurntableLimits{}).message();
  // A quarter period more ends at 1.5 deg: the return to zero needs its rest.
  plan.points[1].durationS = 5.125;
  const std::string why = plan.validate(TurntableLimits{}).message();
  EXPECT_NE(why.find("the return to zero after the last point turns the table by 1.5 deg with no rest time"),
            std::string::npos)
      << why;
  // A position 2e-6 deg away is a move, 5e-7 deg is not.
  plan.points[1].durationS = 5.0;
  plan.points[1].positionDeg[1] = 2e-6;
  EXPECT_FALSE(plan.validate(TurntableLimits{}).isOk());
  plan.points[1].positionDeg[1] = 5e-7;
  EXPECT_TRUE(plan.validate(TurntableLimits{}).isOk()) << plan.validate(TurntableLimits{}).message();
}

TEST(TestPlan, JsonRoundTrip) {
  TestPlan plan = TestPlan::paperSlow();
  plan.points.push_back({Axis::kZ, 1.0, 3.0, 60.0, 2.0, 0.0});
  auto back = testPlanFromJson(testPlanToJson(plan));
  ASSERT_TRUE(back.isOk()) << back.status().toString();
  ASSERT_EQ(back->points.size(), 2u);
  EXPECT_EQ(back->points[1].axis, Axis::kZ);
  EXPECT_DOUBLE_EQ(back->points[1].frequencyHz, 1.0);
  EXPECT_DOUBLE_EQ(back->points[0].durationS, 294.0);
}

TEST(TestPlan, JsonPeriodsSetDuration) {
  auto plan = testPlanFromJson(R"({"points":[{"periods":30,"frequency_hz":0.5}]})");
  ASSERT_TRUE(plan.isOk()) << plan.status().toString();
  EXPECT_DOUBLE_EQ(plan->points[0].durationS, 60.0);
}

// The import fuzzer's find: periods over a zero frequency made an infinite
// duration that was written back as null, so the plan did not read back.
// Every plan that parses writes JSON that parses again.
TEST(TestPlan, PeriodsWithoutAFrequencyOrBeyondAnyNumberAreRefused) {
  for (const char* text : {R"({"points":[{"periods":5,"frequency_hz":0}]})",
                           R"({"points":[{"periods":1e300,"frequency_hz":1e-300}]})",
                           R"({"points":[{"duration_s":1e400}]})",
                           R"({"points":[{"position_deg":[0,1e999,0]}]})",
                           R"({"rest_between_s":-1e999,"points":[]})"}) {
    auto plan = testPlanFromJson(text);
    EXPECT_FALSE(plan.isOk()) << text;
    if (!plan.isOk()) {
      EXPECT_FALSE(plan.status().message().empty());
    }
  }
  auto zero = testPlanFromJson(R"({"points":[{"periods":5,"frequency_hz":0}]})");
  EXPECT_NE(zero.status().message().find("frequency_hz\" > 0"), std::string::npos) << zero.status().toString();
}

TEST(TestPlan, JsonErrorsSayWhatIsWrong) {
  EXPECT_EQ(testPlanFromJson("{").status().code(), StatusCode::kInvalidArgument);
  auto typo = testPlanFromJson(R"({"points":[{"frequncy_hz":1}]})");
  ASSERT_FALSE(typo.isOk());
  EXPECT_NE(typo.status().message().find("frequncy_hz"), std::string::npos);
  auto axis = testPlanFromJson(R"({"points":[{"axis":"w"}]})");
  ASSERT_FALSE(axis.isOk());
  EXPECT_NE(axis.status().message().find("axis"), std::string::npos);
}

TEST(TestPlan, StaticSegmentValidatesWithoutFrequencyOrAmplitude) {
  const TestPoint p = TestPoint::staticSegment(Axis::kY, 600.0, 2.0);
  std::string why;
  why = p.validate(TurntableLimits{}).message();
  EXPECT_TRUE(why.empty()) << why;
  EXPECT_TRUE(p.isStatic());
  EXPECT_EQ(p.periodS(), 0.0);
  TestPoint bad = p;
  bad.frequencyHz = 0.1;
  why = bad.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("static segment has no frequency"), std::string::npos) << why;
  bad = p;
  bad.durationS = 0.0;
  why = bad.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("duration > 0"), std::string::npos) << why;
  EXPECT_EQ(TestPoint{}.kind, TestPointKind::kSwing);  // the default stays a swing
}

TEST(TestPlan, StaticSegmentJsonRoundTripAndSwingJsonUnchanged) {
  TestPlan plan = TestPlan::paperSlow();
  const std::string swingOnly = testPlanToJson(plan);
  EXPECT_EQ(swingOnly.find("kind"), std::string::npos);  // old readers still read swing plans
  plan.points.push_back(TestPoint::staticSegment(Axis::kX, 600.0, 1.0));
  const std::string json = testPlanToJson(plan);
  EXPECT_NE(json.find("\"static\""), std::string::npos);
  auto back = testPlanFromJson(json);
  ASSERT_TRUE(back.isOk()) << back.status().toString();
  ASSERT_EQ(back->points.size(), 2u);
  EXPECT_EQ(back->points[0].kind, TestPointKind::kSwing);
  EXPECT_EQ(back->points[1].kind, TestPointKind::kStatic);
  EXPECT_EQ(back->points[1].frequencyHz, 0.0);
  EXPECT_EQ(back->points[1].amplitudeDeg, 0.0);
  EXPECT_DOUBLE_EQ(back->points[1].durationS, 600.0);
  std::string why;
  why = back->validate(TurntableLimits{}).message();
  EXPECT_TRUE(why.empty()) << why;
}

TEST(TestPlan, StaticSegmentJsonRefusesSwingKeysAndBadKinds) {
  auto withFrequency = testPlanFromJson(R"({"points":[{"kind":"static","duration_s":60,"frequency_hz":1}]})");
  ASSERT_TRUE(withFrequency.isOk());
  std::string why;
  why = withFrequency->validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_FALSE(testPlanFromJson(R"({"points":[{"kind":"still","duration_s":60}]})").isOk());
  EXPECT_FALSE(testPlanFromJson(R"({"points":[{"kind":"static","periods":3}]})").isOk());
}

}  // namespace
}  // namespace fog

namespace fog {
namespace {

TEST(TestPlanPresets, EveryNamedPlanIsValidAndUnknownNamesAreExplained) {
  TurntableLimits limits;
  for (const auto& name : presetPlanNames()) {
    auto plan = presetPlan(name);
    ASSERT_TRUE(plan.isOk()) << name;
    std::string why;
    why = plan->validate(limits).message();
    EXPECT_TRUE(why.empty()) << name << ": " << why;
  }
  EXPECT_EQ(presetPlan("paper")->points.size(), 2u);
  EXPECT_TRUE(presetPlan("noise")->points.front().isStatic());
  EXPECT_DOUBLE_EQ(presetPlan("quick")->points.front().durationS, 20.0);
  auto bad = presetPlan("papr");
  ASSERT_FALSE(bad.isOk());
  EXPECT_NE(bad.status().message().find("paper, paper-slow, paper-fast, quick, noise"), std::string::npos);
}

}  // namespace
}  // namespace fog

namespace fog {
namespace {

// Issue 15: a plan is bounded in points and total time (every sample of a
// run is held in memory); a stored plan of a million points is refused.
TEST(TestPlanLimits, TooManyPointsOrTooLongInAllIsRefused) {
  TestPlan tenDays;
  for (int i = 0; i < 10; ++i) tenDays.points.push_back({Axis::kX, 0.1, 10.0, 86000.0, 5.0, 0.0});
  std::string why;
  why = tenDays.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("at most 1 h"), std::string::npos) << why;

  // The memory budget (test_plan.h): 1 h in all is allowed, a second more is not.
  TestPlan hour;
  hour.points.push_back({Axis::kX, 1.0, 3.0, 3600.0 - 5.0 - 1.0, 5.0, 0.0});
  EXPECT_TRUE(hour.validate(TurntableLimits{}).isOk()) << hour.validate(TurntableLimits{}).message();
  hour.points.front().durationS += 1.0;
  why = hour.validate(TurntableLimits{}).message();
  EXPECT_NE(why.find("at most 1 h (every sample is held in memory)"), std::string::npos) << why;

  TestPlan many;
  for (std::size_t i = 0; i <= kMaxPlanPoints; ++i) many.points.push_back({Axis::kX, 1.0, 3.0, 2.0, 0.0, 0.0});
  many.restBetweenS = 0.0;
  why = many.validate(TurntableLimits{}).message();
  EXPECT_FALSE(why.empty());
  EXPECT_NE(why.find("at most 1000"), std::string::npos) << why;

  std::string json = R"({"points":[)";
  for (std::size_t i = 0; i <= kMaxPlanPoints; ++i)
    json += std::string(i ? "," : "") + R"({"axis":"x","frequency_hz":1,"amplitude_deg":3,"duration_s":2})";
  json += "]}";
  auto parsed = testPlanFromJson(json);
  ASSERT_FALSE(parsed.isOk());
  EXPECT_NE(parsed.status().message().find("at most 1000"), std::string::npos) << parsed.status().message();
}

}  // namespace
}  // namespace fog

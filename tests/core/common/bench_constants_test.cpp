// The bench constants' ranges, checked in one place (checkBenchConstants)
// for the command line, the GUI's dialog and the importer: issue 39's
// `analyze S --board-delay-ms 1e308 --read-delay-ms -0.2` stored a PASS.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/bench_constants.h"

namespace fog {
namespace {

using Field = BenchConstantProblem::Field;

TEST(BenchConstants, TheDefaultsAreInRange) {
  EXPECT_TRUE(checkBenchConstants(BenchConstants{}).isOk());
  EXPECT_TRUE(benchConstantProblems(BenchConstants{}).empty());
  EXPECT_DOUBLE_EQ(BenchConstants{}.gainToleranceFraction, 0.01);
}

TEST(BenchConstants, TheIssuesDelaysAreRefusedSayingWhatIsWrong) {
  BenchConstants c;
  c.boardDelayMs = 1e308;
  c.tableReadDelayMs = -0.2;
  const auto problems = benchConstantProblems(c);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].field, Field::kTableReadDelay);
  EXPECT_EQ(problems[0].message,
            "the table read delay must be within 0 .. 1000 ms, not -0.2: a delay is never negative (a stamp cannot "
            "precede what it stamps); check its sign and what it is measured from");
  EXPECT_EQ(problems[1].field, Field::kBoardDelay);
  EXPECT_EQ(problems[1].message,
            "the processing-board delay must be within 0 .. 1000 ms, not 1e+308: bench delays are a fraction of a "
            "frame or a few frames; check the value and that it is in milliseconds");
  const Status s = checkBenchConstants(c);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), problems[0].message);
  EXPECT_STREQ(benchConstantOption(Field::kBoardDelay), "--board-delay-ms");
  EXPECT_STREQ(benchConstantKey(Field::kBoardDelay), "board_delay_ms");
}

TEST(BenchConstants, EveryConstantHasItsRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  struct Case {
    void (*set)(BenchConstants&, double);
    double bad, good;
    Field field;
    const char* words;
  } cases[] = {
      {[](BenchConstants& c, double v) { c.tableReadDelayMs = v; }, 1000.5, 1000.0, Field::kTableReadDelay,
       "the table read delay must be within 0 .. 1000 ms"},
      {[](BenchConstants& c, double v) { c.tableReadDelayStdMs = v; }, -1e-9, 0.0, Field::kTableReadDelayStd,
       "an uncertainty is never negative"},
      {[](BenchConstants& c, double v) { c.boardDelayMs = v; }, nan, 0.0, Field::kBoardDelay, "not a number"},
      {[](BenchConstants& c, double v) { c.boardDelayStdMs = v; }, inf, 0.5, Field::kBoardDelayStd,
       "the processing-board delay's uncertainty must be within 0 .. 1000 ms"},
      {[](BenchConstants& c, double v) { c.latitudeDeg = v; }, 90.5, -90.0, Field::kLatitude,
       "the latitude must be within -90 .. 90 deg, not 90.5"},
      {[](BenchConstants& c, double v) { c.pulseEquivalentDeg = v; }, 1e-300, 1e-9, Field::kPulseEquivalent,
       "the pulse equivalent must be within 1e-9 .. 1 deg per pulse"},
      {[](BenchConstants& c, double v) { c.pulseEquivalentDeg = v; }, 1.5, 0.0, Field::kPulseEquivalent,
       "not arcseconds or radians"},
      {[](BenchConstants& c, double v) { c.counterHz = v; }, 0.0, 1e12, Field::kCounterHz,
       "counter frequency must be above 0"},
      {[](BenchConstants& c, double v) { c.counterBits = static_cast<int>(v); }, 65, 64, Field::kCounterBits,
       "counter width must be 1 .. 64 bits, not 65"},
      {[](BenchConstants& c, double v) { c.gyroSign[1] = static_cast<int>(v); }, 0, -1, Field::kGyroSign,
       "the gyro sign of axis Y must be 1 or -1, not 0"},
      {[](BenchConstants& c, double v) { c.gainToleranceFraction = v; }, 1.0, 0.999, Field::kGainTolerance,
       "the gain tolerance must be a fraction from 1e-6 up to (not including) 1, not 1: it is the gyro's stated "
       "scale tolerance (0.01 = 1 %)"},
      {[](BenchConstants& c, double v) { c.gainToleranceFraction = v; }, 0.0, 1e-6, Field::kGainTolerance,
       "the gain tolerance must be a fraction"},
  };
  for (const auto& k : cases) {
    BenchConstants c;
    k.set(c, k.bad);
    const auto problems = benchConstantProblems(c);
    ASSERT_EQ(problems.size(), 1u) << k.words;
    EXPECT_EQ(problems[0].field, k.field) << k.words;
    EXPECT_NE(problems[0].message.find(k.words), std::string::npos) << problems[0].message;
    EXPECT_NE(std::string(benchConstantKey(k.field)), "");
    k.set(c, k.good);
    EXPECT_TRUE(checkBenchConstants(c).isOk()) << k.words << ": " << checkBenchConstants(c).message();
  }
}

}  // namespace
}  // namespace fog

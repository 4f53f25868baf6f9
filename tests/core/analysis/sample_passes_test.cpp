// How many times analyzeTestPoint walks each sample (core/analysis/
// sample_passes.h): the analysis' time is passes x samples, and the way it
// grew from 46 to 95 ms was passes added quietly (the table's 4-parameter
// residuals computed twice, the checks walking the samples again). These
// tests fail when a pass is added; no timing is asserted.

#include "core/analysis/sample_passes.h"

#include <gtest/gtest.h>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/sine_fit.h"
#include <optional>

#include "synthetic.h"

namespace fog::analysis {
namespace {

using testing::makeSynthetic;
using testing::SyntheticSpec;

SamplePassCounts passesOf(const auto& work) {
  const SamplePassCounts before = samplePassCounts();
  work();
  const SamplePassCounts after = samplePassCounts();
  return {after.table - before.table, after.gyro - before.gyro};
}

// The counter sees a pass where one is made, on the stream it is made on.
TEST(SamplePasses, OneResidualPassCountsOnce) {
  const auto data = makeSynthetic(SyntheticSpec{});
  auto ch = makeChannels(data, 1.0);
  ASSERT_TRUE(ch.isOk());
  const SineFit fit = fitTableLinear(ch->table, kTwoPi * 1.0, ch->referenceS);
  const auto table = passesOf([&] { tableResiduals(ch->table, fit); });
  EXPECT_EQ(table.table, 1u);
  EXPECT_EQ(table.gyro, 0u);
  const auto gyro = passesOf([&] { cumulativeGyroAngle(ch->gyro); });
  EXPECT_EQ(gyro.table, 0u);
  EXPECT_EQ(gyro.gyro, 1u);
}

// A steady 1 Hz swing of 20 s (20 000 table samples, 10 000 increments):
// every stage of analyzeTestPoint and every validity check runs. Its passes,
// by stage (table / gyro):
//   samples' own checks 1 / 1, coverage 2 / 2, channels 1 / 2
//   swing frequency (binning)                                  1 / 0
//   table fits: linear 1, 4-parameter 2 (Gauss-Newton steps)    3 / 0
//   gyro noise: start fit, its residuals with their shared sums,
//     white rate, block rate and weighting blocks together,
//     Cholesky factor                                           0 / 4
//   gyro fits: nominal 1, 4-parameter 2, residual RMS 1         0 / 4
//   the 4-parameter fits' residuals, once each (the table's
//     with the per-period track's table sums)                   1 / 2
//   joint fit 2, per-period track 0 / 1                         2 / 3
//   errors that repeat every period: all lags in one pass       1 / 1
//   steady_sine: smoothed residual 1 / 1, harmonics 1 / 0        2 / 1
// 14 / 20 in all (15 / 20 until the track's table sums came with the table
// residual; 15 / 24 until the gyro noise's residuals, their sums and
// their three block views were each taken in one pass; 15 / 25 until the
// gyro fit's residual RMS was summed as the residuals were computed; 17 / 27
// until the repeating errors' correlation was read from the
// residual's second differences, whose mean telescopes). Before the stages shared their results the same analysis
// walked the table 35 and the gyro 51 times, counted the same way (the table residuals twice, one
// pass per period lag, the gyro noise's sums three times over, the gyro
// angle residual in four passes). A pass added anywhere (or a fit taking
// another Gauss-Newton step on this data) fails this test: say why here
// when raising a limit.
constexpr std::uint64_t kMaxTablePasses = 14;
constexpr std::uint64_t kMaxGyroPasses = 20;

TEST(SamplePasses, AnalyzeTestPointWalksTheSamplesAFixedNumberOfTimes) {
  const auto data = makeSynthetic(SyntheticSpec{});
  std::optional<Result<TestPointResult>> r;
  const auto passes = passesOf([&] { r.emplace(analyzeTestPoint(data, BenchConstants{})); });
  ASSERT_TRUE(r->isOk()) << r->status().toString();
  ASSERT_EQ((*r)->checks.size(), 5u);  // every check ran (uncertainty_below_bound walks no sample)
  EXPECT_LE(passes.table, kMaxTablePasses) << "table passes";
  EXPECT_LE(passes.gyro, kMaxGyroPasses) << "gyro passes";
  // The counter is wired: the fits alone walk each stream more than a few times.
  EXPECT_GE(passes.table, 5u);
  EXPECT_GE(passes.gyro, 5u);
}

}  // namespace
}  // namespace fog::analysis

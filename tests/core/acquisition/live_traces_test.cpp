// LiveTraces: what the live plots show, from decoded frames as they arrive.

#include "core/acquisition/live_traces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/model/simulator.h"
#include "session_test_util.h"

namespace fog::acquisition {
namespace {

std::vector<protocol::DecodedFrame> decodeAll(const std::vector<std::uint8_t>& bytes) {
  protocol::Decoder d;
  std::vector<protocol::DecodedFrame> frames;
  d.push(bytes, frames);
  return frames;
}

// 1 Hz / 3 deg on Z for 8 s; a large bias (36 deg/h) so a trend left in
// would show: over 8 s it would add 0.08 deg.
Result<model::SimulatedRun> biasedShortRun() {
  model::SimConfig config;
  config.fog.biasDegPerH = {0.0, 0.0, 36.0};
  return model::simulate(config, fog::test::shortPlan());
}

TEST(LiveTraces, FollowsTheTestPointAndRemovesTheGyroTrend) {
  auto run = biasedShortRun();
  ASSERT_TRUE(run.isOk());
  const auto frames = decodeAll(run->bytes);

  LiveTraces live(5.0);
  // In pieces, as the GUI drains them.
  for (std::size_t at = 0; at < frames.size(); at += 50)
    live.add(std::span(frames).subspan(at, std::min<std::size_t>(50, frames.size() - at)));

  EXPECT_EQ(live.testPoint(), 0);
  EXPECT_EQ(live.axis(), Axis::kZ);
  EXPECT_DOUBLE_EQ(live.nominalFrequencyHz(), 1.0);
  EXPECT_EQ(live.framesSeen(), frames.size());
  EXPECT_NEAR(live.streamTimeS(), static_cast<double>(frames.back().ticks - frames.front().ticks) / 10e6, 1e-12);
  // 1 s at rest, then 2 s of settling.
  EXPECT_NEAR(live.recordingStartS(), 3.0, 0.11);

  // The trend: the truth's bias + Earth rate, within 2 %.
  const double truthTrend = run->truth.at(0).gyroTrendDegPerS;
  EXPECT_NEAR(live.gyroTrendDegPerS(), truthTrend, 0.02 * std::abs(truthTrend));

  // The window keeps the last 5 s; the detrended gyro swings like the table:
  // same mean (within 0.005 deg) and amplitude (within 0.5 %).
  ASSERT_FALSE(live.table().empty());
  EXPECT_GE(live.table().front().timeS, live.streamTimeS() - 5.0);
  const auto gyro = live.gyroDetrended();
  ASSERT_GT(gyro.size(), 2000u);
  EXPECT_GE(gyro.front().timeS, live.streamTimeS() - 5.0);
  auto stats = [](const auto& points, double fromS, double toS) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (const auto& p : points)
      if (p.timeS >= fromS && p.timeS < toS) {
        sum += p.angleDeg;
        sum2 += p.angleDeg * p.angleDeg;
        ++n;
      }
    const double mean = sum / n;
    return std::pair{mean, std::sqrt(sum2 / n - mean * mean)};
  };
  // Whole periods inside the recording phase (the stream's tail is run-out).
  const double from = std::ceil(live.streamTimeS() - 4.5), to = from + 3.0;
  const auto [tableMean, tableRms] = stats(live.table(), from, to);
  const auto [gyroMean, gyroRms] = stats(gyro, from, to);
  EXPECT_NEAR(tableRms, 3.0 / std::sqrt(2.0), 0.01);
  EXPECT_NEAR(gyroRms, tableRms, 0.005 * tableRms);
  EXPECT_NEAR(gyroMean, tableMean, 0.005);
}

TEST(LiveTraces, ClearStartsAfresh) {
  const auto frames = decodeAll(fog::test::shortRun().bytes);
  LiveTraces live(5.0);
  live.add(frames);
  live.clear();
  EXPECT_EQ(live.testPoint(), -1);
  EXPECT_TRUE(live.table().empty());
  EXPECT_TRUE(live.gyroDetrended().empty());
  EXPECT_TRUE(std::isnan(live.gyroTrendDegPerS()));
}

// The trend shown as a number comes from the recording phase only, once it
// holds two whole periods: before, the operator reads "-", not a partial
// fit's hundreds of deg/h.
TEST(LiveTraces, TheTrendIsShownOnlyOverTwoWholePeriodsOfRecording) {
  auto run = biasedShortRun();
  ASSERT_TRUE(run.isOk());
  const auto frames = decodeAll(run->bytes);
  LiveTraces live(5.0);
  bool sawRecording = false, sawNumber = false;
  for (std::size_t at = 0; at < frames.size(); at += 50) {
    live.add(std::span(frames).subspan(at, std::min<std::size_t>(50, frames.size() - at)));
    const double trend = live.gyroTrendDegPerS();
    const bool recordedTwoPeriods =
        live.recordingStartS() >= 0.0 && live.streamTimeS() - live.recordingStartS() >= 2.0 / live.nominalFrequencyHz() + 0.01;
    sawRecording |= live.recordingStartS() >= 0.0;
    if (live.recordingStartS() < 0.0 || live.streamTimeS() - live.recordingStartS() < 2.0 / live.nominalFrequencyHz() - 0.01) {
      EXPECT_TRUE(std::isnan(trend)) << "at " << live.streamTimeS() << " s: " << trend;
    }
    if (recordedTwoPeriods) {
      ASSERT_FALSE(std::isnan(trend)) << "at " << live.streamTimeS() << " s";
      sawNumber = true;
      // Within 25 % of the truth from the first value on (36 deg/h + Earth rate).
      EXPECT_NEAR(trend, run->truth.at(0).gyroTrendDegPerS, 0.25 * std::abs(run->truth.at(0).gyroTrendDegPerS));
    }
  }
  EXPECT_TRUE(sawRecording && sawNumber);
}

}  // namespace
}  // namespace fog::acquisition

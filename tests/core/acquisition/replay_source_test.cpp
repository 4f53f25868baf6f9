// ReplaySource: a recorded stream through the same acquisition path as a live
// source, paced by its own board counter or as fast as possible.

#include "core/acquisition/replay_source.h"

#include <gtest/gtest.h>

#include <chrono>

#include "core/acquisition/acquisition.h"
#include "core/protocol/recording_builder.h"
#include "session_test_util.h"

namespace fog::acquisition {
namespace {

double secondsToAcquire(ByteSource& source, AcquisitionResult* out) {
  const auto start = std::chrono::steady_clock::now();
  auto r = acquire(source, AcquisitionOptions{}, nullptr);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(r.isOk()) << r.status().message();
  if (r && out) *out = std::move(*r);
  return took;
}

TEST(ReplaySource, HandsOutEveryByteOnceInOrder) {
  const auto& bytes = fog::test::shortRun().bytes;
  ReplaySource source(bytes, 0.0, "test");
  std::vector<std::uint8_t> seen;
  for (int guard = 0; guard < 100000; ++guard) {
    auto r = source.read(seen, std::chrono::milliseconds(10));
    ASSERT_TRUE(r.isOk());
    if (r->endOfStream) break;
  }
  EXPECT_TRUE(seen == bytes);
  EXPECT_EQ(source.bytesRead(), bytes.size());
  EXPECT_EQ(source.description(), "replay of test at as fast as possible");
}

TEST(ReplaySource, AsFastAsPossibleGivesTheSameRecordingAsDecoding) {
  const auto& bytes = fog::test::shortRun().bytes;
  ReplaySource source(bytes, 0.0, "test");
  AcquisitionResult r;
  secondsToAcquire(source, &r);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.bytesReceived, bytes.size());
  auto direct = protocol::decodeRecording(bytes);
  ASSERT_TRUE(direct.isOk());
  ASSERT_TRUE(r.recordingStatus.isOk());
  fog::test::expectSameRecording(r.recording, *direct);
}

TEST(ReplaySource, RealTimePacingTakesAboutTheStreamsDuration) {
  // The first 2 s of the 12-s stream at 1x: at least 1.5 s of wall-clock time
  // (no upper bound: a busy machine may be late).
  const auto& all = fog::test::shortRun().bytes;
  ReplaySource source(std::vector<std::uint8_t>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(all.size() / 6)),
                      1.0, "test");
  EXPECT_GE(secondsToAcquire(source, nullptr), 1.5);
}

// A wall clock that advances only when the source waits on it: the pacing
// is then exact and free of the machine's load.
struct FakeWall {
  std::chrono::steady_clock::time_point time{};
  WallClock clock() {
    return {[this] { return time; },
            [this](std::chrono::duration<double> d) {
              time += std::chrono::duration_cast<std::chrono::steady_clock::duration>(d);
            }};
  }
  double seconds() const { return std::chrono::duration<double>(time.time_since_epoch()).count(); }
};

// Releases everything, as the acquisition would, and returns the wall-clock
// seconds the pacing waited.
double pacedSeconds(const std::vector<std::uint8_t>& bytes, double speed) {
  FakeWall wall;
  ReplaySource source(bytes, speed, "test", wall.clock());
  std::vector<std::uint8_t> seen;
  for (int guard = 0; guard < 1000000; ++guard) {
    auto r = source.read(seen, std::chrono::milliseconds(50));
    EXPECT_TRUE(r.isOk());
    if (!r || r->endOfStream) break;
  }
  EXPECT_TRUE(seen == bytes);
  return wall.seconds();
}

TEST(ReplaySource, SpeedUpShortensThePacing) {
  // The 12-s stream takes 12 s at 1x and 1.2 s at 10x of (fake) wall time:
  // the release follows the board's counter to within one chunk (< 0.1 s of
  // stream), so a speed that were ignored, or applied twice, fails.
  const auto& bytes = fog::test::shortRun().bytes;
  const double streamS = 12.0;
  EXPECT_NEAR(pacedSeconds(bytes, 1.0), streamS, 0.1);
  EXPECT_NEAR(pacedSeconds(bytes, 10.0), streamS / 10.0, 0.01);
  ReplaySource fast(bytes, 10.0, "test");
  AcquisitionResult r;
  secondsToAcquire(fast, &r);
  fog::test::expectSameRecording(r.recording, *protocol::decodeRecording(bytes));
}

TEST(ReplaySource, GarbageFailsLikeDecoding) {
  std::vector<std::uint8_t> junk(5000, 0x11);
  ReplaySource source(junk, 0.0, "junk");
  AcquisitionResult r;
  secondsToAcquire(source, &r);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.recordingStatus.code(), StatusCode::kCorruptData);
  EXPECT_EQ(r.recordingStatus.message(), protocol::decodeRecording(junk).status().message());
  EXPECT_FALSE(r.report.isOk());
}

}  // namespace
}  // namespace fog::acquisition

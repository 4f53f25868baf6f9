// Replay: the same decoder path as a live source, paced or as fast as possible.

#include "session/replay.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>

#include "protocol/recording_builder.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

TEST(Replay, AsFastAsPossibleGivesTheSameRecordingAsDecoding) {
  const auto& bytes = fog::test::shortRun().bytes;
  std::vector<std::uint8_t> seen;
  std::size_t frames = 0;
  ReplayOptions o;
  o.speed = 0.0;
  o.chunkBytes = 777;  // chunk borders fall inside frames
  auto r = replay(bytes, o, [&](const ReplayChunk& c) {
    seen.insert(seen.end(), c.bytes.begin(), c.bytes.end());
    frames += c.frames.size();
    EXPECT_EQ(c.bytesFed, seen.size());
    EXPECT_EQ(c.totalBytes, bytes.size());
  });
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE(r->cancelled);
  EXPECT_EQ(r->bytesFed, bytes.size());
  EXPECT_TRUE(seen == bytes);  // every byte, once, in order
  auto direct = protocol::decodeRecording(bytes);
  ASSERT_TRUE(direct.isOk());
  EXPECT_EQ(frames, direct->health.tableFrames + direct->health.imuFrames + direct->health.statusFrames);
  fog::test::expectSameRecording(r->recording, *direct);
  // Board time of the whole stream: first to last frame.
  protocol::Decoder d;
  std::vector<protocol::DecodedFrame> all;
  d.push(bytes, all);
  EXPECT_DOUBLE_EQ(r->streamDurationS, static_cast<double>(all.back().ticks - all.front().ticks) / 10e6);
}

TEST(Replay, RealTimePacingTakesAboutTheStreamsDuration) {
  // The first 2 s of the stream at 1x: at least 1.5 s (no upper bound: a busy
  // machine may be late).
  const auto& all = fog::test::shortRun().bytes;
  // The stream is 12 s long (settling, recording and the table's run-out).
  const std::span<const std::uint8_t> twoSeconds(all.data(), all.size() / 6);
  ReplayOptions o;
  o.speed = 1.0;
  const auto start = std::chrono::steady_clock::now();
  auto r = replay(twoSeconds, o);
  const double tookS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_NEAR(r->streamDurationS, 2.0, 0.2);
  EXPECT_GE(tookS, 1.5);
}

TEST(Replay, SpeedUpShortensThePacing) {
  const auto& bytes = fog::test::shortRun().bytes;
  ReplayOptions o;
  o.speed = 10.0;  // 12 s of stream: at least 1.2 s
  const auto start = std::chrono::steady_clock::now();
  auto r = replay(bytes, o);
  const double tookS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.isOk());
  EXPECT_GE(tookS, 0.9);
  fog::test::expectSameRecording(r->recording, *protocol::decodeRecording(bytes));
}

TEST(Replay, CancelStopsEarly) {
  const auto& bytes = fog::test::shortRun().bytes;
  std::atomic<bool> cancel{false};
  ReplayOptions o;
  o.speed = 0.0;
  o.chunkBytes = 1000;
  o.cancel = &cancel;
  std::size_t chunks = 0;
  auto r = replay(bytes, o, [&](const ReplayChunk&) {
    if (++chunks == 3) cancel = true;
  });
  ASSERT_TRUE(r.isOk());
  EXPECT_TRUE(r->cancelled);
  EXPECT_EQ(chunks, 3u);
  EXPECT_EQ(r->bytesFed, 3000u);
}

TEST(Replay, GarbageFailsLikeDecoding) {
  std::vector<std::uint8_t> junk(5000, 0x11);
  ReplayOptions o;
  o.speed = 0.0;
  auto r = replay(junk, o);
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(r.status().code(), StatusCode::kCorruptData);
  EXPECT_EQ(r.status().message(), protocol::decodeRecording(junk).status().message());
}

}  // namespace
}  // namespace fog::session

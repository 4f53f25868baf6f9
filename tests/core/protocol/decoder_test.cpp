#include "core/protocol/decoder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "test_streams.h"

namespace fog::protocol {
namespace {

using testing::decodeAll;
using testing::encode;
using testing::imuFrame;
using testing::imuWith;
using testing::sameFrame;
using testing::statusFrame;
using testing::tableAt;
using testing::tableFrame;

// A realistic mix: status, then table every 1 ms and IMU every 2 ms at 10 MHz.
std::vector<Frame> mixedFrames(int milliseconds) {
  std::vector<Frame> frames;
  StatusPayload s;
  s.pulseEquivalentDeg = 5e-5;
  frames.push_back(statusFrame(0, 0, s));
  std::uint16_t imuSeq = 0;
  for (int ms = 0; ms < milliseconds; ++ms) {
    const auto counter = static_cast<std::uint32_t>(ms * 10000 + 500);
    frames.push_back(tableFrame(static_cast<std::uint16_t>(ms), counter, tableAt(ms * 7, -ms, 3)));
    if (ms % 2 == 0) frames.push_back(imuFrame(imuSeq++, counter + 2800, imuWith(ms, -ms, 1)));
  }
  return frames;
}

void expectSameFrames(const std::vector<DecodedFrame>& got, const std::vector<Frame>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(sameFrame(got[i].frame, want[i])) << "frame " << i;
}

void expectSameHealth(const StreamHealth& a, const StreamHealth& b) {
  EXPECT_EQ(a.tableFrames, b.tableFrames);
  EXPECT_EQ(a.imuFrames, b.imuFrames);
  EXPECT_EQ(a.statusFrames, b.statusFrames);
  EXPECT_EQ(a.checksumFailures, b.checksumFailures);
  EXPECT_EQ(a.bytesSkipped, b.bytesSkipped);
  EXPECT_EQ(a.lostFrames, b.lostFrames);
  EXPECT_EQ(a.duplicateFrames, b.duplicateFrames);
  EXPECT_EQ(a.outOfOrderFrames, b.outOfOrderFrames);
  EXPECT_EQ(a.counterWraps, b.counterWraps);
}

TEST(Decoder, CleanStreamDecodesEveryFrameWithCleanHealth) {
  const auto frames = mixedFrames(100);
  Decoder d;
  const auto out = decodeAll(encode(frames), &d);
  expectSameFrames(out, frames);
  EXPECT_EQ(d.health().tableFrames, 100u);
  EXPECT_EQ(d.health().imuFrames, 50u);
  EXPECT_EQ(d.health().statusFrames, 1u);
  EXPECT_EQ(d.health().bytesSkipped, 0u);
  EXPECT_EQ(d.health().lostFrames, 0u);
  EXPECT_EQ(d.pendingBytes(), 0u);
  EXPECT_EQ(out.back().ticks, 99 * 10000 + 500);  // last is the table frame at 99 ms
}

TEST(Decoder, BytewisePushEqualsWholePush) {
  auto bytes = encode(mixedFrames(50));
  bytes.insert(bytes.begin() + 100, {0x00, 0xA5, 0x5A, 0x09, 0xA5});  // some garbage inside
  Decoder whole;
  const auto a = decodeAll(bytes, &whole);
  Decoder bytewise;
  std::vector<DecodedFrame> b;
  for (const std::uint8_t byte : bytes) {
    bytewise.push({&byte, 1}, b);
    EXPECT_LT(bytewise.pendingBytes(), kMaxFrameBytes);
  }
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(sameFrame(a[i].frame, b[i].frame)) << i;
    EXPECT_EQ(a[i].ticks, b[i].ticks) << i;
  }
  expectSameHealth(whole.health(), bytewise.health());
  EXPECT_GT(whole.health().bytesSkipped, 0u);
}

TEST(Decoder, RandomChunkSplitsEqualWholePush) {
  const auto frames = mixedFrames(200);
  const auto bytes = encode(frames);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    Decoder d;
    std::vector<DecodedFrame> out;
    std::size_t at = 0;
    while (at < bytes.size()) {
      const std::size_t n = std::min<std::size_t>(rng() % 90, bytes.size() - at);
      d.push(std::span(bytes).subspan(at, n), out);
      at += n;
    }
    expectSameFrames(out, frames);
    EXPECT_EQ(d.health().bytesSkipped, 0u);
  }
}

TEST(Decoder, GarbageBeforeAndBetweenFramesIsSkippedAndCounted) {
  const std::vector<Frame> frames = {tableFrame(0, 100), tableFrame(1, 200), imuFrame(0, 250)};
  std::vector<std::uint8_t> bytes = {1, 2, 3, 4, 5, 6, 7};
  appendFrame(frames[0], bytes);
  bytes.insert(bytes.end(), {0xA5, 0x5A, 0x07, 0x0D, 0x11});  // false sync, unknown type
  appendFrame(frames[1], bytes);
  bytes.insert(bytes.end(), {0xA5, 0x5A, 0x01, 0x0D});  // IMU type with the table length
  appendFrame(frames[2], bytes);
  Decoder d;
  const auto out = decodeAll(bytes, &d);
  expectSameFrames(out, frames);
  EXPECT_EQ(d.health().bytesSkipped, 7u + 5u + 4u);
  EXPECT_EQ(d.health().checksumFailures, 0u);
}

TEST(Decoder, BadChecksumResynchronisesOnTheNextFrame) {
  auto bytes = encode({tableFrame(0, 100), tableFrame(1, 200), tableFrame(2, 300)});
  bytes[25 + 12] ^= 0x10;  // payload byte of the second frame
  Decoder d;
  const auto out = decodeAll(bytes, &d);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].frame.sequence, 0);
  EXPECT_EQ(out[1].frame.sequence, 2);
  EXPECT_EQ(out[1].lostBefore, 1u);
  EXPECT_EQ(d.health().checksumFailures, 1u);
  EXPECT_EQ(d.health().bytesSkipped, 25u);
  EXPECT_EQ(d.health().lostFrames, 1u);
}

// Every single-bit error in a frame is caught (by the CRC, or because the
// sync/type/length no longer match): the damaged frame is never emitted and
// its neighbours are still decoded intact.
TEST(Decoder, SingleBitFlipsInEveryByteNeverProduceAWrongFrame) {
  StatusPayload s;
  s.counterBits = 24;
  s.pulseEquivalentDeg = 5e-5;
  s.testPoint = 3;
  s.phase = TestPhase::kRecording;
  const std::vector<std::vector<Frame>> cases = {
      {imuFrame(0, 100, imuWith(1, 2, 3)), imuFrame(1, 200, imuWith(-4, 5, 6)), imuFrame(2, 300, imuWith(7, 8, 9))},
      {tableFrame(0, 100, tableAt(11)), tableFrame(1, 200, tableAt(12)), tableFrame(2, 300, tableAt(13))},
      {statusFrame(0, 100, s), statusFrame(1, 200, s), statusFrame(2, 300, s)},
  };
  for (const auto& frames : cases) {
    const auto clean = encode(frames);
    const std::size_t size = clean.size() / 3;
    for (std::size_t i = size; i < 2 * size; ++i) {
      for (int bit = 0; bit < 8; ++bit) {
        auto bytes = clean;
        bytes[i] ^= static_cast<std::uint8_t>(1u << bit);
        Decoder d;
        const auto out = decodeAll(bytes, &d);
        SCOPED_TRACE(::testing::Message() << "byte " << i - size << " bit " << bit);
        ASSERT_EQ(out.size(), 2u);
        EXPECT_TRUE(sameFrame(out[0].frame, frames[0]));
        EXPECT_TRUE(sameFrame(out[1].frame, frames[2]));
        EXPECT_EQ(out[1].lostBefore, 1u);
        EXPECT_GT(d.health().checksumFailures + d.health().bytesSkipped, 0u);
      }
    }
  }
}

TEST(Decoder, TruncatedTailWaitsInPendingBytesAndEmitsNothing) {
  const std::vector<Frame> frames = {tableFrame(0, 100), imuFrame(0, 150), tableFrame(1, 200)};
  const auto bytes = encode(frames);
  const std::size_t cut = bytes.size() - 10;
  Decoder d;
  std::vector<DecodedFrame> out;
  d.push(std::span(bytes).first(cut), out);
  EXPECT_EQ(out.size(), 2u);
  EXPECT_EQ(d.pendingBytes(), 25u - 10u);
  EXPECT_EQ(d.health().bytesSkipped, 0u);
  d.push(std::span(bytes).subspan(cut), out);
  expectSameFrames(out, frames);
  EXPECT_EQ(d.pendingBytes(), 0u);
}

TEST(Decoder, ReorderedFrameIsCountedOutOfOrderAndDropped) {
  const auto a = tableFrame(0, 100), b = tableFrame(1, 200), c = tableFrame(2, 300);
  Decoder d;
  const auto out = decodeAll(encode({a, c, b}), &d);
  expectSameFrames(out, {a, c});
  EXPECT_EQ(d.health().outOfOrderFrames, 1u);
  EXPECT_EQ(d.health().lostFrames, 1u);
}

TEST(Decoder, DuplicateFrameIsCountedAndDropped) {
  const auto a = imuFrame(0, 100), b = imuFrame(1, 200), c = imuFrame(2, 300);
  Decoder d;
  const auto out = decodeAll(encode({a, b, b, c}), &d);
  expectSameFrames(out, {a, b, c});
  EXPECT_EQ(d.health().duplicateFrames, 1u);
  EXPECT_EQ(d.health().lostFrames, 0u);
  EXPECT_EQ(d.health().outOfOrderFrames, 0u);
}

TEST(Decoder, SequenceGapsAreLostFramesPerType) {
  Decoder d;
  const auto out = decodeAll(encode({tableFrame(0, 100), imuFrame(10, 110), tableFrame(5, 200), imuFrame(11, 210)}), &d);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].lostBefore, 0u);
  EXPECT_EQ(out[1].lostBefore, 0u);  // first IMU frame: nothing to compare with
  EXPECT_EQ(out[2].lostBefore, 4u);
  EXPECT_EQ(out[3].lostBefore, 0u);
  EXPECT_EQ(d.health().lostFrames, 4u);
}

TEST(Decoder, SequenceGapAcrossThe16BitWrap) {
  Decoder d;
  const auto out = decodeAll(encode({imuFrame(65534, 100), imuFrame(65535, 200), imuFrame(0, 300), imuFrame(3, 400)}), &d);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[2].lostBefore, 0u);
  EXPECT_EQ(out[3].lostBefore, 2u);
  EXPECT_EQ(d.health().lostFrames, 2u);
  EXPECT_EQ(d.health().outOfOrderFrames, 0u);
}

TEST(Decoder, CounterWrapAt32BitsKeepsTicksContinuous) {
  Decoder d;
  const auto out = decodeAll(
      encode({tableFrame(0, 0xFFFFFF00u), tableFrame(1, 0xFFFFFFF0u), tableFrame(2, 0x10u), tableFrame(3, 0x20u)}), &d);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].ticks, 0xFFFFFF00LL);
  EXPECT_EQ(out[1].ticks, 0xFFFFFFF0LL);
  EXPECT_EQ(out[2].ticks, 0x100000010LL);
  EXPECT_EQ(out[3].ticks, 0x100000020LL);
  EXPECT_EQ(d.health().counterWraps, 1u);
  EXPECT_EQ(d.health().outOfOrderFrames, 0u);
}

TEST(Decoder, CounterWidthFromStatusUnwraps16BitCounters) {
  StatusPayload s;
  s.counterBits = 16;
  Decoder d;
  // 65500 -> 100 is a forward step of 136 ticks with a 16-bit counter, but
  // would be time going backwards with the default 32 bits.
  const auto out = decodeAll(encode({statusFrame(0, 65000, s), tableFrame(0, 65500), tableFrame(1, 100),
                                     imuFrame(0, 600), statusFrame(1, 30000, s), tableFrame(2, 40000),
                                     tableFrame(3, 64000), tableFrame(4, 5)}),
                             &d);
  ASSERT_EQ(out.size(), 8u);
  EXPECT_EQ(d.counterBits(), 16);
  const std::vector<std::int64_t> want = {65000, 65500, 65636, 66136, 95536, 105536, 129536, 131077};
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(out[i].ticks, want[i]) << i;
  EXPECT_EQ(d.health().counterWraps, 2u);
  EXPECT_EQ(d.health().outOfOrderFrames, 0u);
}

TEST(Decoder, TimeGoingBackwardsIsDroppedAndItsDataCountsAsLost) {
  Decoder d;
  const auto out = decodeAll(encode({imuFrame(0, 1000), tableFrame(0, 2000), imuFrame(1, 1500), imuFrame(2, 3000)}), &d);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[2].frame.sequence, 2);
  EXPECT_EQ(out[2].lostBefore, 1u);
  EXPECT_EQ(out[2].ticks, 3000);
  EXPECT_EQ(d.health().outOfOrderFrames, 1u);
}

TEST(Decoder, StatusWithImpossibleCounterWidthKeepsThePreviousWidth) {
  StatusPayload s;
  s.counterBits = 40;
  Decoder d;
  decodeAll(encode({statusFrame(0, 0, s)}), &d);
  EXPECT_EQ(d.counterBits(), 32);
  EXPECT_EQ(d.health().statusFrames, 1u);
}

TEST(Decoder, OneMegabyteOfRandomBytesEndsWithBoundedStateAndNoFrames) {
  std::mt19937 rng(20240601);
  std::vector<std::uint8_t> bytes(1 << 20);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
  // Make false syncs frequent so that the resynchronisation paths are exercised.
  for (std::size_t i = 0; i + 4 < bytes.size(); i += 97) {
    bytes[i] = kSync0;
    bytes[i + 1] = kSync1;
    bytes[i + 2] = static_cast<std::uint8_t>(1 + rng() % 3);
    bytes[i + 3] = static_cast<std::uint8_t>(payloadSize(static_cast<FrameType>(bytes[i + 2])));
  }
  Decoder d;
  std::vector<DecodedFrame> out;
  std::size_t at = 0;
  while (at < bytes.size()) {
    const std::size_t n = std::min<std::size_t>(1 + rng() % 4096, bytes.size() - at);
    d.push(std::span(bytes).subspan(at, n), out);
    ASSERT_LT(d.pendingBytes(), kMaxFrameBytes);
    at += n;
  }
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(d.health().bytesSkipped + d.pendingBytes(), bytes.size());
  EXPECT_GT(d.health().checksumFailures, 10000u);
}

TEST(Decoder, EveryFrameIsRecoveredFromBetweenRandomGarbage) {
  std::mt19937 rng(99);
  const auto frames = mixedFrames(1000);
  std::vector<std::uint8_t> bytes;
  std::uint64_t garbage = 0;
  for (const auto& f : frames) {
    const int n = static_cast<int>(rng() % 40);
    for (int i = 0; i < n; ++i) bytes.push_back(rng() % 4 == 0 ? kSync0 : static_cast<std::uint8_t>(rng()));
    garbage += static_cast<std::uint64_t>(n);
    appendFrame(f, bytes);
  }
  Decoder d;
  const auto out = decodeAll(bytes, &d);
  expectSameFrames(out, frames);
  EXPECT_EQ(d.health().bytesSkipped, garbage);
  EXPECT_EQ(d.health().lostFrames, 0u);
}

}  // namespace
}  // namespace fog::protocol

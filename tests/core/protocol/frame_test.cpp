#include "core/protocol/frame.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/protocol/crc16.h"
#include "core/protocol/decoder.h"
#include "test_streams.h"

namespace fog::protocol {
namespace {

using testing::decodeAll;
using testing::encode;
using testing::sameFrame;

TEST(Frame, SizesFollowTheFormat) {
  EXPECT_EQ(frameSize(FrameType::kImu), 27u);
  EXPECT_EQ(frameSize(FrameType::kTable), 25u);
  EXPECT_EQ(frameSize(FrameType::kStatus), 38u);
  EXPECT_EQ(frameSize(static_cast<FrameType>(4)), 0u);
  EXPECT_EQ(kMaxFrameBytes, 38u);
}

TEST(Frame, TableFrameBytesAreLittleEndianWithCrcOverTypeThroughPayload) {
  TablePayload t;
  t.angleMicroDeg = {1000000, -1, 0x01020304};
  t.flags = 0x80;
  std::vector<std::uint8_t> out;
  appendFrame(Frame{FrameType::kTable, 0x1234, 0xA1B2C3D4u, t}, out);
  const std::vector<std::uint8_t> head = {0xA5, 0x5A, 0x02, 0x0D, 0x34, 0x12, 0xD4, 0xC3, 0xB2, 0xA1,
                                          0x40, 0x42, 0x0F, 0x00,   // 1000000
                                          0xFF, 0xFF, 0xFF, 0xFF,   // -1
                                          0x04, 0x03, 0x02, 0x01,   // 0x01020304
                                          0x80};
  ASSERT_EQ(out.size(), 25u);
  EXPECT_EQ(std::vector<std::uint8_t>(out.begin(), out.begin() + 23), head);
  const std::uint16_t crc = crc16Ccitt(std::span(out).subspan(2, 21));
  EXPECT_EQ(out[23], crc & 0xFF);
  EXPECT_EQ(out[24], crc >> 8);
}

TEST(Frame, StatusPayloadLayoutPutsEachFieldAtItsOffset) {
  StatusPayload s;
  s.counterHz = 10000000;
  s.counterBits = 24;
  s.pulseEquivalentDeg = 1.0;  // 0x3FF0000000000000
  s.testPoint = 0x0102;
  s.axis = 2;
  s.phase = TestPhase::kRecording;
  s.nominalFrequencyMicroHz = 100000;
  s.nominalAmplitudeMicroDeg = 10000000;
  s.flags = 0x5A;
  std::vector<std::uint8_t> out;
  appendFrame(Frame{FrameType::kStatus, 0, 0, s}, out);
  ASSERT_EQ(out.size(), 38u);
  const std::uint8_t* p = out.data() + kHeaderBytes;
  EXPECT_EQ(p[0] | p[1] << 8 | p[2] << 16 | p[3] << 24, 10000000);
  EXPECT_EQ(p[4], 24);
  for (int i = 5; i < 11; ++i) EXPECT_EQ(p[i], 0) << i;
  EXPECT_EQ(p[11], 0xF0);
  EXPECT_EQ(p[12], 0x3F);
  EXPECT_EQ(p[13], 0x02);
  EXPECT_EQ(p[14], 0x01);
  EXPECT_EQ(p[15], 2);
  EXPECT_EQ(p[16], 2);
  EXPECT_EQ(p[17] | p[18] << 8 | p[19] << 16, 100000);
  EXPECT_EQ(p[21] | p[22] << 8 | p[23] << 16, 10000000);
  EXPECT_EQ(p[25], 0x5A);
}

TEST(Frame, ImuRoundTripKeepsEveryField) {
  ImuPayload m;
  m.pulses = {std::numeric_limits<std::int32_t>::min(), -7, std::numeric_limits<std::int32_t>::max()};
  m.temperatureCentiC = -4012;
  m.flags = 0xC3;
  const Frame f{FrameType::kImu, 65535, 0xFFFFFFFFu, m};
  const auto out = decodeAll(encode({f}));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(sameFrame(out[0].frame, f));
}

TEST(Frame, TableRoundTripKeepsEveryField) {
  TablePayload t;
  t.angleMicroDeg = {-180000000, 3000000, 359999999};
  t.flags = 1;
  const Frame f{FrameType::kTable, 42, 123456789u, t};
  const auto out = decodeAll(encode({f}));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(sameFrame(out[0].frame, f));
}

TEST(Frame, StatusRoundTripKeepsEveryFieldIncludingTheDouble) {
  StatusPayload s;
  s.counterHz = 12345678;
  s.counterBits = 16;
  s.pulseEquivalentDeg = 5e-5 / 3.0;
  s.testPoint = 7;
  s.axis = 1;
  s.phase = TestPhase::kSettling;
  s.nominalFrequencyMicroHz = 1000000;
  s.nominalAmplitudeMicroDeg = 3000000;
  s.flags = 9;
  const Frame f{FrameType::kStatus, 3, 500u, s};
  const auto out = decodeAll(encode({f}));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(sameFrame(out[0].frame, f));
  EXPECT_EQ(std::get<StatusPayload>(out[0].frame.payload).pulseEquivalentDeg, 5e-5 / 3.0);
}

TEST(FrameWriter, KeepsOneSequenceCounterPerType) {
  FrameWriter w;
  std::vector<std::uint8_t> bytes;
  w.table(10, {}, bytes);
  w.table(20, {}, bytes);
  w.imu(20, {}, bytes);
  w.status(25, {}, bytes);
  w.table(30, {}, bytes);
  EXPECT_EQ(w.nextSequence(FrameType::kTable), 3);
  EXPECT_EQ(w.nextSequence(FrameType::kImu), 1);
  const auto out = decodeAll(bytes);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[0].frame.sequence, 0);
  EXPECT_EQ(out[1].frame.sequence, 1);
  EXPECT_EQ(out[2].frame.sequence, 0);
  EXPECT_EQ(out[3].frame.sequence, 0);
  EXPECT_EQ(out[4].frame.sequence, 2);
  EXPECT_EQ(out[4].frame.counter, 30u);
}

TEST(FrameWriter, SequenceWrapsAt65536) {
  FrameWriter w;
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 65537; ++i) w.imu(0, {}, bytes);
  EXPECT_EQ(w.nextSequence(FrameType::kImu), 1);
}

}  // namespace
}  // namespace fog::protocol

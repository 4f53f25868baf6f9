#include "core/protocol/recording_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "test_streams.h"

namespace fog::protocol {
namespace {

using testing::imuWith;
using testing::tableAt;

StatusPayload statusFor(std::uint16_t testPoint, TestPhase phase, std::uint8_t axis = 0) {
  StatusPayload s;
  s.counterHz = 1000000;
  s.pulseEquivalentDeg = 5e-5;
  s.testPoint = testPoint;
  s.axis = axis;
  s.phase = phase;
  s.nominalFrequencyMicroHz = 1000000;
  s.nominalAmplitudeMicroDeg = 3000000;
  return s;
}

// Counter in microseconds (counterHz 1 MHz in the status frames).
class StreamBuilder {
 public:
  StreamBuilder& status(std::uint32_t us, const StatusPayload& s) { return w_.status(us, s, bytes), *this; }
  StreamBuilder& table(std::uint32_t us, const TablePayload& t) { return w_.table(us, t, bytes), *this; }
  StreamBuilder& imu(std::uint32_t us, const ImuPayload& m) { return w_.imu(us, m, bytes), *this; }
  StreamBuilder& skipImu() {
    std::vector<std::uint8_t> lost;
    return w_.imu(0, {}, lost), *this;
  }
  std::vector<std::uint8_t> bytes;

 private:
  FrameWriter w_;
};

TEST(RecordingBuilder, StatusFramesSplitTheStreamIntoTestPoints) {
  StreamBuilder s;
  s.status(1000, statusFor(kNoTestPoint, TestPhase::kIdle))
      .table(1500, tableAt(1))  // idle: not collected
      .status(2000, statusFor(0, TestPhase::kSettling, 1))
      .table(2500, tableAt(2))  // settling: not collected
      .status(3000, statusFor(0, TestPhase::kRecording, 1))
      .table(3000, tableAt(0, 1500000))
      .imu(3400, imuWith(10, 20, -30))
      .table(4000, tableAt(0, 2500000))
      .skipImu()
      .skipImu()
      .table(5000, tableAt(0, -250000))
      .imu(5400, imuWith(1, 2, 3));
  auto settle1 = statusFor(1, TestPhase::kSettling, 2);
  auto record1 = statusFor(1, TestPhase::kRecording, 2);
  record1.nominalFrequencyMicroHz = 100000;
  record1.nominalAmplitudeMicroDeg = 10000000;
  s.status(6000, settle1)
      .table(6500, tableAt(9))  // settling: not collected
      .status(7000, record1)
      .table(7000, tableAt(0, 0, 4000000))
      .imu(7400, imuWith(0, 0, 100))
      .status(8000, statusFor(1, TestPhase::kDone, 2))
      .table(8500, tableAt(9));  // done: not collected

  auto rec = decodeRecording(s.bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  EXPECT_EQ(rec->counterHz, 1e6);
  EXPECT_EQ(rec->pulseEquivalentDeg, 5e-5);
  ASSERT_EQ(rec->testPoints.size(), 2u);

  const auto& p0 = rec->testPoints[0];
  EXPECT_EQ(p0.index, 0);
  EXPECT_EQ(p0.axis, Axis::kY);
  EXPECT_DOUBLE_EQ(p0.nominalFrequencyHz, 1.0);
  EXPECT_DOUBLE_EQ(p0.nominalAmplitudeDeg, 3.0);
  ASSERT_EQ(p0.table.size(), 3u);
  EXPECT_DOUBLE_EQ(p0.table[0].timeS, 0.002);  // (3000 - 1000) us
  EXPECT_DOUBLE_EQ(p0.table[1].angleDeg[1], 2.5);
  EXPECT_DOUBLE_EQ(p0.table[2].angleDeg[1], -0.25);
  ASSERT_EQ(p0.imu.size(), 2u);
  EXPECT_DOUBLE_EQ(p0.imu[0].timeS, 0.0024);
  EXPECT_DOUBLE_EQ(p0.imu[0].incrementDeg[0], 10 * 5e-5);
  EXPECT_DOUBLE_EQ(p0.imu[0].incrementDeg[2], -30 * 5e-5);
  EXPECT_DOUBLE_EQ(p0.imu[0].temperatureC, 25.12);
  EXPECT_EQ(p0.imu[0].lostBefore, 0u);
  EXPECT_EQ(p0.imu[1].lostBefore, 2u);

  const auto& p1 = rec->testPoints[1];
  EXPECT_EQ(p1.index, 1);
  EXPECT_EQ(p1.axis, Axis::kZ);
  // Exactly the decimal the board sent (µHz / 1e6), not within 4 ulp: a
  // CSV or report prints the nominal frequency as 0.1, never
  // 0.09999999999999999 (100000 * 1e-6).
  EXPECT_EQ(p1.nominalFrequencyHz, 0.1);
  EXPECT_EQ(p1.nominalAmplitudeDeg, 10.0);
  ASSERT_EQ(p1.table.size(), 1u);
  EXPECT_DOUBLE_EQ(p1.table[0].angleDeg[2], 4.0);
  ASSERT_EQ(p1.imu.size(), 1u);
  EXPECT_DOUBLE_EQ(p1.imu[0].timeS, 0.0064);

  EXPECT_EQ(rec->health.tableFrames, 8u);
  EXPECT_EQ(rec->health.lostFrames, 2u);
}

// A caller that cuts the stream itself (the table-driven run) gets every
// sample, whatever the board's markers say; counter rate and pulse
// equivalent still come from the STATUS frames.
TEST(RecordingBuilder, NotFollowingMarkersKeepsTheWholeStreamAsOneTestPoint) {
  StreamBuilder s;
  s.status(1000, statusFor(0, TestPhase::kSettling, 1))
      .table(1500, tableAt(0, 1000000))
      .status(2000, statusFor(0, TestPhase::kRecording, 1))
      .table(2500, tableAt(0, -2000000))
      .imu(2600, imuWith(4, 0, 0))
      .status(3000, statusFor(0, TestPhase::kIdle, 1))
      .table(3500, tableAt(0, 500000));
  Decoder decoder;
  std::vector<DecodedFrame> frames;
  decoder.push(s.bytes, frames);
  RecordingBuilder marked, whole(false);
  marked.add(frames);
  whole.add(frames);
  const auto byMarkersResult = marked.finish(decoder.health());
  const auto allResult = whole.finish(decoder.health());
  ASSERT_TRUE(byMarkersResult.isOk() && allResult.isOk());
  const Recording& byMarkers = *byMarkersResult;
  const Recording& all = *allResult;
  ASSERT_EQ(byMarkers.testPoints.size(), 1u);
  EXPECT_EQ(byMarkers.testPoints[0].table.size(), 1u);
  ASSERT_EQ(all.testPoints.size(), 1u);
  EXPECT_EQ(all.testPoints[0].table.size(), 3u);
  EXPECT_EQ(all.testPoints[0].axis, Axis::kY);
  EXPECT_DOUBLE_EQ(all.testPoints[0].nominalFrequencyHz, 0.0);
  EXPECT_EQ(all.counterHz, 1e6);
  ASSERT_EQ(all.testPoints[0].imu.size(), 1u);
  EXPECT_DOUBLE_EQ(all.testPoints[0].imu[0].incrementDeg[0], 4 * 5e-5);
}

TEST(RecordingBuilder, RecordingPausedAndResumedOnTheSameTestPointStaysOneTestPoint) {
  StreamBuilder s;
  s.status(0, statusFor(4, TestPhase::kRecording))
      .table(100, tableAt(1))
      .imu(150, imuWith(1))
      .status(200, statusFor(4, TestPhase::kSettling))
      .table(300, tableAt(2))
      .status(400, statusFor(4, TestPhase::kRecording))
      .table(500, tableAt(3));
  auto rec = decodeRecording(s.bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), 1u);
  EXPECT_EQ(rec->testPoints[0].index, 4);
  EXPECT_EQ(rec->testPoints[0].table.size(), 2u);
}

TEST(RecordingBuilder, TestPointsWithoutSamplesAreDropped) {
  StreamBuilder s;
  s.status(0, statusFor(2, TestPhase::kRecording))
      .status(100, statusFor(3, TestPhase::kRecording))
      .table(200, tableAt(1))
      .imu(300, imuWith(1));
  auto rec = decodeRecording(s.bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), 1u);
  EXPECT_EQ(rec->testPoints[0].index, 3);
}

TEST(RecordingBuilder, WithoutRecordingStatusTheWholeStreamIsOneTestPointOnTheLargestSwing) {
  StreamBuilder s;
  // No status at all: 10 MHz default, pulse equivalent from the bench.
  for (int i = 0; i < 100; ++i) {
    const auto t = static_cast<std::uint32_t>(5000 + i * 10000);
    const double phase = 2.0 * std::numbers::pi * i / 50.0;
    s.table(t, tableAt(static_cast<std::int32_t>(2e6 * std::sin(phase)),
                       static_cast<std::int32_t>(-3e6 * std::sin(phase)), 1000000));
    if (i % 2 == 0) s.imu(t + 3000, imuWith(7, -9, 0));
  }
  auto rec = decodeRecording(s.bytes, 2e-4);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), 1u);
  const auto& p = rec->testPoints[0];
  EXPECT_EQ(p.index, 0);
  EXPECT_EQ(p.axis, Axis::kY);
  EXPECT_EQ(p.nominalFrequencyHz, 0.0);
  EXPECT_EQ(p.nominalAmplitudeDeg, 0.0);
  EXPECT_EQ(rec->counterHz, 10e6);
  EXPECT_EQ(rec->pulseEquivalentDeg, 2e-4);
  ASSERT_EQ(p.table.size(), 100u);
  ASSERT_EQ(p.imu.size(), 50u);
  EXPECT_DOUBLE_EQ(p.table[1].timeS, 0.001);
  EXPECT_DOUBLE_EQ(p.imu[0].timeS, 0.0003);
  // The stream states no pulse equivalent: the bench's turns pulses into degrees.
  EXPECT_DOUBLE_EQ(p.imu[0].incrementDeg[0], 7 * 2e-4);
  EXPECT_DOUBLE_EQ(p.imu[0].incrementDeg[1], -9 * 2e-4);
}

// Raw pulse counts never leave the builder: a stream that does not state
// its pulse equivalent, read without a bench constant, is refused in words
// that say what to do.
TEST(RecordingBuilder, AStreamWithoutAPulseEquivalentAndNoBenchConstantIsRefused) {
  StreamBuilder s;
  s.table(1000, tableAt(1)).imu(1500, imuWith(7)).table(2000, tableAt(2));
  auto rec = decodeRecording(s.bytes);
  ASSERT_FALSE(rec.isOk());
  EXPECT_EQ(rec.status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(rec.status().message(),
            "the stream does not state its gyro pulse equivalent (degrees per pulse): give --pulse-equivalent-deg "
            "or set it in the bench constants");
  // A pulse equivalent that is no number is none.
  EXPECT_FALSE(decodeRecording(s.bytes, std::nan("")).isOk());
  EXPECT_FALSE(decodeRecording(s.bytes, -1e-4).isOk());
  // The builder is reset after refusing: the next stream starts afresh.
  Decoder decoder;
  std::vector<DecodedFrame> frames;
  decoder.push(s.bytes, frames);
  RecordingBuilder b;
  b.add(frames);
  EXPECT_FALSE(b.finish(decoder.health()).isOk());
  EXPECT_EQ(b.framesAdded(), 0u);
  b.add(frames);
  auto again = b.finish(decoder.health(), 1e-4);
  ASSERT_TRUE(again.isOk()) << again.status().toString();
  EXPECT_DOUBLE_EQ(again->testPoints.at(0).imu.at(0).incrementDeg[0], 7e-4);
  // A stream of table frames only needs no pulse equivalent.
  StreamBuilder tableOnly;
  tableOnly.table(1000, tableAt(1));
  Decoder d2;
  std::vector<DecodedFrame> f2;
  d2.push(tableOnly.bytes, f2);
  RecordingBuilder t;
  t.add(f2);
  EXPECT_TRUE(t.finish(d2.health()).isOk());
}

TEST(RecordingBuilder, FallbackTakesPulseEquivalentAndCounterFromAnIdleStatus) {
  StreamBuilder s;
  s.table(0, tableAt(0, 0, 1)).imu(100, imuWith(4));
  auto idle = statusFor(kNoTestPoint, TestPhase::kIdle);
  idle.pulseEquivalentDeg = 1e-4;
  s.status(500, idle).table(1000, tableAt(0, 0, -1)).imu(1100, imuWith(6));
  // The stream's statement wins over the bench's constant.
  auto rec = decodeRecording(s.bytes, 3e-3);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), 1u);
  const auto& p = rec->testPoints[0];
  EXPECT_EQ(p.axis, Axis::kZ);
  EXPECT_EQ(rec->pulseEquivalentDeg, 1e-4);
  ASSERT_EQ(p.imu.size(), 2u);
  // The status came after the first IMU frame: its value is applied to both.
  EXPECT_DOUBLE_EQ(p.imu[0].incrementDeg[0], 4e-4);
  EXPECT_DOUBLE_EQ(p.imu[1].incrementDeg[0], 6e-4);
  EXPECT_DOUBLE_EQ(p.imu[1].timeS, 1100 / 1e6);  // counterHz from the status
}

TEST(RecordingBuilder, FinishResetsTheBuilder) {
  StreamBuilder s;
  s.status(0, statusFor(0, TestPhase::kRecording)).table(10, tableAt(1)).imu(20, imuWith(1));
  Decoder d;
  std::vector<DecodedFrame> frames;
  d.push(s.bytes, frames);
  RecordingBuilder b;
  b.add(frames);
  EXPECT_EQ(b.framesAdded(), 3u);
  const Recording first = *b.finish(d.health());
  EXPECT_EQ(first.testPoints.size(), 1u);
  EXPECT_EQ(first.health.tableFrames, 1u);
  EXPECT_EQ(b.framesAdded(), 0u);
  const Recording empty = *b.finish();
  EXPECT_TRUE(empty.testPoints.empty());
}

TEST(DecodeRecording, BytesWithoutAnyFrameAreCorruptDataWithAHint) {
  std::vector<std::uint8_t> bytes(100, 0x55);
  auto rec = decodeRecording(bytes);
  ASSERT_FALSE(rec.isOk());
  EXPECT_EQ(rec.status().code(), StatusCode::kCorruptData);
  EXPECT_EQ(rec.status().message(),
            "no valid sampling-board frames found in 100 bytes; is this a fogbench raw stream, or is the "
            "baud rate wrong?");
}

TEST(DecodeRecording, EmptyInputIsCorruptData) {
  auto rec = decodeRecording({});
  ASSERT_FALSE(rec.isOk());
  EXPECT_EQ(rec.status().code(), StatusCode::kCorruptData);
}

TEST(DecodeRecording, TableWithoutImuIsInsufficientData) {
  StreamBuilder s;
  s.status(0, statusFor(0, TestPhase::kRecording)).table(10, tableAt(1)).table(20, tableAt(2));
  auto rec = decodeRecording(s.bytes);
  ASSERT_FALSE(rec.isOk());
  EXPECT_EQ(rec.status().code(), StatusCode::kInsufficientData);
  EXPECT_NE(rec.status().message().find("2 table, 0 IMU and 1 status frames"), std::string::npos)
      << rec.status().message();
}

TEST(DecodeRecording, TableAndImuInDifferentTestPointsIsInsufficientData) {
  StreamBuilder s;
  s.status(0, statusFor(0, TestPhase::kRecording)).table(10, tableAt(1))
      .status(100, statusFor(1, TestPhase::kRecording)).imu(110, imuWith(1));
  auto rec = decodeRecording(s.bytes);
  ASSERT_FALSE(rec.isOk());
  EXPECT_EQ(rec.status().code(), StatusCode::kInsufficientData);
}

}  // namespace
}  // namespace fog::protocol

namespace fog::protocol {
namespace {

// Damage is attributed to the test point being recorded when it was met:
// the decoder hands each emitted frame the damage since the previous one.
TEST(RecordingBuilder, EachTestPointCountsTheDamageMetWhileItWasRecorded) {
  StreamBuilder s;
  s.status(1000, statusFor(0, TestPhase::kRecording))
      .table(2000, tableAt(1))
      .imu(2400, imuWith(1))
      .table(3000, tableAt(2));
  // Test point 1: one duplicated table frame and a damaged frame.
  const std::vector<std::uint8_t> lastTable(s.bytes.end() - static_cast<std::ptrdiff_t>(frameSize(FrameType::kTable)),
                                            s.bytes.end());
  s.bytes.insert(s.bytes.end(), lastTable.begin(), lastTable.end());
  auto damaged = lastTable;
  damaged[12] ^= 0x10;
  s.bytes.insert(s.bytes.end(), damaged.begin(), damaged.end());
  s.table(4000, tableAt(3)).status(5000, statusFor(1, TestPhase::kRecording));
  // Test point 2: two lost IMU frames and 5 bytes of garbage.
  s.skipImu().skipImu().imu(6400, imuWith(2));
  s.bytes.insert(s.bytes.end(), {0x00, 0x11, 0x22, 0x33, 0x44});
  s.table(7000, tableAt(4)).imu(7400, imuWith(3));

  Decoder decoder;
  RecordingBuilder builder;
  std::vector<DecodedFrame> frames;
  decoder.push(s.bytes, frames);
  const Recording rec = *builder.finish(decoder.health());
  ASSERT_TRUE(rec.testPoints.empty()) << "finish() before add() gives nothing";
  builder.add(frames);
  const Recording r = *builder.finish(decoder.health());
  ASSERT_EQ(r.testPoints.size(), 2u);
  const auto& a = r.testPoints[0].health;
  const auto& b = r.testPoints[1].health;
  EXPECT_EQ(a.tableFrames, 3u);
  EXPECT_EQ(a.imuFrames, 1u);
  EXPECT_EQ(a.duplicateFrames, 1u);
  EXPECT_EQ(a.checksumFailures, 1u);
  EXPECT_EQ(a.lostFrames, 0u);
  EXPECT_EQ(b.tableFrames, 1u);
  EXPECT_EQ(b.imuFrames, 2u);
  EXPECT_EQ(b.lostFrames, 2u);
  EXPECT_EQ(b.duplicateFrames, 0u);
  EXPECT_EQ(b.bytesSkipped, 5u);
  // Together they account for the whole stream's damage.
  EXPECT_EQ(a.duplicateFrames + b.duplicateFrames, r.health.duplicateFrames);
  EXPECT_EQ(a.checksumFailures + b.checksumFailures, r.health.checksumFailures);
  EXPECT_EQ(a.lostFrames + b.lostFrames, r.health.lostFrames);
  EXPECT_EQ(a.bytesSkipped + b.bytesSkipped, r.health.bytesSkipped);
}

// A stream pushed in pieces that cut frames anywhere decodes exactly as the
// whole stream does (the diagnosis' replays decode as they simulate).
TEST(StreamDecoder, PiecesThatCutFramesGiveTheWholeStreamsRecording) {
  StreamBuilder s;
  s.status(1000, statusFor(0, TestPhase::kRecording, 1));
  for (std::uint32_t k = 0; k < 200; ++k) {
    s.table(2000 + 1000 * k, tableAt(0, static_cast<std::int32_t>(1000 * k)));
    if (k % 2 == 0 && k != 100) s.imu(2400 + 1000 * k, imuWith(static_cast<std::int32_t>(k), 1, -1));
    if (k == 100) s.skipImu();
  }
  s.status(300000, statusFor(1, TestPhase::kRecording, 2)).table(300500, tableAt(0, 0, 7)).imu(300700, imuWith(1, 2, 3));
  auto whole = decodeRecording(s.bytes);
  ASSERT_TRUE(whole.isOk()) << whole.status().toString();

  StreamDecoder pieces;
  std::size_t at = 0;
  for (std::size_t len = 1; at < s.bytes.size(); len = len % 7 + 1) {
    const std::size_t n = std::min(len, s.bytes.size() - at);
    pieces.push(std::span(s.bytes).subspan(at, n));
    at += n;
  }
  auto rec = pieces.finish();
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  ASSERT_EQ(rec->testPoints.size(), whole->testPoints.size());
  ASSERT_EQ(rec->testPoints.size(), 2u);
  for (std::size_t p = 0; p < rec->testPoints.size(); ++p) {
    const auto& a = rec->testPoints[p];
    const auto& b = whole->testPoints[p];
    ASSERT_EQ(a.table.size(), b.table.size());
    ASSERT_EQ(a.imu.size(), b.imu.size());
    for (std::size_t i = 0; i < a.table.size(); ++i) {
      EXPECT_EQ(a.table[i].timeS, b.table[i].timeS);
      EXPECT_EQ(a.table[i].angleDeg, b.table[i].angleDeg);
    }
    for (std::size_t i = 0; i < a.imu.size(); ++i) {
      EXPECT_EQ(a.imu[i].timeS, b.imu[i].timeS);
      EXPECT_EQ(a.imu[i].incrementDeg, b.imu[i].incrementDeg);
      EXPECT_EQ(a.imu[i].lostBefore, b.imu[i].lostBefore);
    }
  }
  EXPECT_EQ(rec->testPoints[0].table.size(), 200u);
  EXPECT_EQ(rec->health.lostFrames, 1u);
  EXPECT_EQ(rec->health.lostFrames, whole->health.lostFrames);

  StreamDecoder nothing;
  nothing.push(std::vector<std::uint8_t>(100, 0x55));
  auto none = nothing.finish();
  ASSERT_FALSE(none.isOk());
  EXPECT_NE(none.status().message().find("in 100 bytes"), std::string::npos) << none.status().toString();
}

}  // namespace
}  // namespace fog::protocol

#pragma once
// Turns decoded sampling-board frames into a fog::Recording, split into test
// points by the STATUS frames (docs/protocol.md, "From frames to a recording").
//
//   RecordingBuilder b;
//   b.add(frames);            // as often as frames arrive, in stream order
//   Result<Recording> r = b.finish(decoder.health(), bench.pulseEquivalentDeg);
//
// Rules:
//  - Times are seconds on the board counter: (ticks - ticks of the first frame
//    added) / counterHz, counterHz from the latest STATUS frame (default
//    10 MHz; a STATUS value of 0 is ignored).
//  - While the latest STATUS says phase == kRecording, table and IMU samples go
//    to the current test point; a recording STATUS with a testPoint value other
//    than the current one starts a new TestPointData (index = testPoint, axis,
//    nominal frequency and amplitude from that STATUS; kind kStatic when its
//    flags carry kStatusFlagStatic). Samples in other phases
//    are not collected.
//  - Table: angleDeg = angleMicroDeg * 1e-6. IMU: incrementDeg = pulses *
//    the pulse equivalent: that of the latest STATUS (or of the last STATUS
//    of the stream with a usable value when none was known yet), or, when no
//    STATUS states one (finite, > 0), the bench constant given to finish();
//    temperatureC = centi-degC / 100; lostBefore = the decoder's sequence gap.
//  - No STATUS with phase kRecording in the whole stream: everything becomes
//    one test point, index 0, whose axis is the one with the largest table
//    angle peak-to-peak; nominal frequency and amplitude 0 (unknown).
//  - Recording.pulseEquivalentDeg says what one pulse was (the stream's last
//    statement, else the bench constant): always > 0 when there are IMU
//    samples, and incrementDeg is always in degrees. IMU samples with neither
//    a statement nor a bench constant fail finish() (kInvalidArgument, saying
//    to give the pulse equivalent): raw pulse counts never leave the builder.
//  - Test points without any sample are dropped.
//  - TestPointData::health counts the frames and the damage (lost,
//    duplicated, out-of-order frames, checksum failures, skipped bytes) the
//    decoder met while that test point was being collected.
// Not thread-safe; one builder per stream.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/common/recording.h"
#include "core/common/status.h"
#include "core/protocol/decoder.h"

namespace fog::protocol {

class RecordingBuilder {
 public:
  RecordingBuilder() = default;
  // followMarkers false: the STATUS frames' test points and phases are not
  // used; the whole stream becomes one test point as when it carries none
  // (a caller that cuts the stream itself: the table-driven run).
  explicit RecordingBuilder(bool followMarkers) : followMarkers_(followMarkers) {}

  void add(const DecodedFrame& frame);
  void add(std::span<const DecodedFrame> frames);

  // Number of frames added since construction or the last finish().
  std::size_t framesAdded() const { return framesAdded_; }

  // Builds the recording from everything added, copies `health` (normally the
  // decoder's) into it, and resets the builder for a new stream (also when it
  // fails). benchPulseEquivalentDeg: degrees per pulse for a stream that does
  // not state its own (BenchConstants::pulseEquivalentDeg; 0 = none).
  fog::Result<fog::Recording> finish(const fog::StreamHealth& health = {}, double benchPulseEquivalentDeg = 0.0);

 private:
  bool followMarkers_ = true;
  struct Segment {
    int testPoint = 0;
    Axis axis = Axis::kX;
    double nominalFrequencyHz = 0.0;
    double nominalAmplitudeDeg = 0.0;
    TestPointKind kind = TestPointKind::kSwing;
    // Samples are kept in their final types and converted in place by
    // finish() (no second copy of an hour's samples): until then timeS
    // holds counter ticks since the first frame (exact in a double up to
    // 2^53) and incrementDeg the raw pulse counts.
    std::vector<TableSample> table;
    std::vector<ImuSample> imu;
    // The pulse equivalent in force from imu[index] on, when it was known
    // (0 before the stream states one); one entry per change.
    std::vector<std::pair<std::size_t, double>> pulseEquivalents;
    StreamHealth health;  // frames and damage met while collecting
  };

  void onStatus(const StatusPayload& status);

  std::size_t framesAdded_ = 0;
  bool haveFirst_ = false;
  std::int64_t firstTicks_ = 0;
  double counterHz_ = 10e6;
  int counterBits_ = 32;
  double pulseEquivalentDeg_ = 0.0;  // latest usable value, 0 = none yet
  bool sawRecording_ = false;        // any STATUS with phase kRecording
  bool collecting_ = false;          // latest STATUS says kRecording
  std::vector<Segment> segments_;
  Segment whole_;  // every sample, kept until the first recording STATUS (fallback)
};

// Decodes a complete raw stream and builds its recording. Errors:
// kCorruptData when the bytes hold no valid frame at all; kInsufficientData
// when frames exist but no test point has both table and IMU samples;
// kInvalidArgument when the stream does not state its pulse equivalent and
// benchPulseEquivalentDeg is not > 0 (RecordingBuilder::finish).
fog::Result<fog::Recording> decodeRecording(std::span<const std::uint8_t> bytes,
                                            double benchPulseEquivalentDeg = 0.0);

// The same, for a stream that arrives in pieces: push() them in order, then
// finish() gives what decodeRecording() gives for their concatenation,
// without the bytes ever being held whole (a simulated hour is 140 MB).
class StreamDecoder {
 public:
  // benchPulseEquivalentDeg: as for decodeRecording().
  explicit StreamDecoder(double benchPulseEquivalentDeg = 0.0) : benchPulseEquivalentDeg_(benchPulseEquivalentDeg) {}
  void push(std::span<const std::uint8_t> bytes);
  // Frames that never were bytes (Simulator::advance's frame overload): the
  // recording is the one their encoded bytes would give, without the
  // encoding, checksums and parsing (a replay in the diagnosis).
  void push(std::span<const Frame> frames);
  fog::Result<fog::Recording> finish();

 private:
  double benchPulseEquivalentDeg_ = 0.0;
  Decoder decoder_;
  RecordingBuilder builder_;
  std::vector<DecodedFrame> frames_;
  std::size_t bytes_ = 0;
};

}  // namespace fog::protocol

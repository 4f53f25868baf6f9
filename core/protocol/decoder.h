#pragma once
// Streaming decoder for the sampling-board byte stream (docs/protocol.md).
//
// Push byte chunks as they arrive, split anywhere; complete, valid frames are
// appended to `out` in stream order. The decoder never throws and never
// loops: every step either consumes at least one byte or waits for more.
// It buffers at most one incomplete frame (< kMaxFrameBytes bytes), so memory
// stays bounded whatever the input. One decoder per stream; not thread-safe
// (use it from one thread at a time).
//
// Rules, in the order they are applied:
//  - Bytes before a sync pair 0xA5 0x5A are skipped (health.bytesSkipped).
//  - An unknown type, or a length byte that does not match the type: skip one
//    byte and search again (bytesSkipped).
//  - A CRC mismatch: health.checksumFailures, skip the first sync byte and
//    search again from the next byte (resynchronise); a bad frame is never
//    emitted. All bytes not consumed by a valid frame count in bytesSkipped.
//  - Sequence, per frame type (16 bits, wraps): d = (seq - last) mod 65536.
//    d == 0: duplicate (duplicateFrames), dropped. 1 <= d <= 32768: accepted,
//    d - 1 frames lost (lostFrames, DecodedFrame::lostBefore). d > 32768:
//    stale (outOfOrderFrames), dropped.
//  - Counter (common time base across all types), width from the latest
//    STATUS frame (a STATUS frame's own width applies to itself; default 32
//    bits; widths outside 8..32 are ignored): d = (counter - last) mod 2^bits;
//    d >= 2^(bits-1) means time went backwards (outOfOrderFrames), dropped;
//    otherwise ticks += d, and counterWraps is counted when counter < last.
//    A frame dropped here does not advance its type's sequence, so the next
//    frame of that type reports it in lostBefore (its data is missing).
//  - health.imuFrames/tableFrames/statusFrames count emitted frames only.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/common/recording.h"
#include "core/protocol/frame.h"

namespace fog::protocol {

struct DecodedFrame {
  Frame frame;
  // Board counter unwrapped to 64 bits: the first emitted frame's raw counter
  // value, then continuous (counter wraps removed).
  std::int64_t ticks = 0;
  // Frames of this type lost just before this one (sequence gap).
  std::uint32_t lostBefore = 0;
  // Damage the decoder met since the previous emitted frame (of any type),
  // so that a consumer can tell which part of the stream it hit.
  std::uint32_t duplicatesBefore = 0;
  std::uint32_t checksumFailuresBefore = 0;
  std::uint32_t outOfOrderBefore = 0;
  std::uint64_t bytesSkippedBefore = 0;
};

class Decoder {
 public:
  // Decodes `bytes` (any length, including 0) and appends emitted frames.
  void push(std::span<const std::uint8_t> bytes, std::vector<DecodedFrame>& out);
  // A frame that never was bytes (a simulator's replay): the sequence and
  // counter rules above apply to it as to a decoded one; no checksum, no
  // skipped bytes.
  void push(Frame frame, std::vector<DecodedFrame>& out);

  const fog::StreamHealth& health() const { return health_; }
  // Bytes buffered awaiting the rest of a frame; at the end of the input these
  // are a truncated tail. Always < kMaxFrameBytes.
  std::size_t pendingBytes() const { return pending_.size(); }
  // Counter width in force (from the latest STATUS frame, default 32).
  int counterBits() const { return counterBits_; }

 private:
  // Decodes what it can from data[0, size); returns the bytes consumed. The
  // rest (< kMaxFrameBytes) is an incomplete frame that needs more bytes.
  std::size_t parse(const std::uint8_t* data, std::size_t size, std::vector<DecodedFrame>& out);
  void accept(Frame& frame, std::vector<DecodedFrame>& out);

  fog::StreamHealth health_;
  fog::StreamHealth atLastEmit_;  // health_ when the previous frame was emitted
  std::vector<std::uint8_t> pending_;
  std::array<bool, 3> haveSequence_{};
  std::array<std::uint16_t, 3> lastSequence_{};
  bool haveCounter_ = false;
  std::uint32_t lastCounter_ = 0;
  std::int64_t ticks_ = 0;
  int counterBits_ = 32;
};

}  // namespace fog::protocol

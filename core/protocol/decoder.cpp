#include "core/protocol/decoder.h"

#include <algorithm>
#include <cstring>

#include "core/protocol/crc16.h"

namespace fog::protocol {
namespace {

// Frame size for a type byte and a length byte, 0 when they do not describe a
// valid frame.
std::size_t validFrameSize(std::uint8_t type, std::uint8_t length) {
  if (type < 1 || type > 3) return 0;
  const auto t = static_cast<FrameType>(type);
  return payloadSize(t) == length ? frameSize(t) : 0;
}

std::uint32_t counterMask(int bits) {
  return bits >= 32 ? 0xFFFFFFFFu : (std::uint32_t{1} << bits) - 1u;
}

}  // namespace

void Decoder::push(std::span<const std::uint8_t> bytes, std::vector<DecodedFrame>& out) {
  while (!bytes.empty()) {
    if (pending_.empty()) {
      // Fast path: decode straight from the caller's bytes, keep only the tail.
      const std::size_t used = parse(bytes.data(), bytes.size(), out);
      pending_.assign(bytes.begin() + static_cast<std::ptrdiff_t>(used), bytes.end());
      return;
    }
    // Complete the buffered frame with at most one frame's worth of new bytes.
    // If the parse stops inside the old bytes, fewer than kMaxFrameBytes remain,
    // so all `take` new bytes were needed and the input is exhausted.
    const std::size_t old = pending_.size();
    const std::size_t take = std::min(bytes.size(), kMaxFrameBytes);
    pending_.insert(pending_.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(take));
    const std::size_t used = parse(pending_.data(), pending_.size(), out);
    if (used >= old) {
      pending_.clear();
      bytes = bytes.subspan(used - old);
    } else {
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(used));
      bytes = bytes.subspan(take);
    }
  }
}

std::size_t Decoder::parse(const std::uint8_t* data, std::size_t size, std::vector<DecodedFrame>& out) {
  std::size_t p = 0;
  while (p < size) {
    if (data[p] != kSync0) {
      const void* hit = std::memchr(data + p + 1, kSync0, size - p - 1);
      const std::size_t next = hit ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(hit) - data) : size;
      health_.bytesSkipped += next - p;
      p = next;
      continue;
    }
    const std::size_t left = size - p;
    if (left < 2) break;
    if (data[p + 1] != kSync1) {
      ++health_.bytesSkipped;
      ++p;
      continue;
    }
    if (left < 4) break;
    const std::size_t n = validFrameSize(data[p + 2], data[p + 3]);
    if (n == 0) {
      ++health_.bytesSkipped;
      ++p;
      continue;
    }
    if (left < n) break;
    const std::uint8_t* f = data + p;
    const std::uint16_t stored = static_cast<std::uint16_t>(f[n - 2] | (f[n - 1] << 8));
    if (crc16Ccitt(std::span(f + 2, n - 4)) != stored) {
      ++health_.checksumFailures;
      ++health_.bytesSkipped;
      ++p;
      continue;
    }
    Frame frame;
    frame.type = static_cast<FrameType>(f[2]);
    frame.sequence = static_cast<std::uint16_t>(f[4] | (f[5] << 8));
    frame.counter = static_cast<std::uint32_t>(f[6]) | (static_cast<std::uint32_t>(f[7]) << 8) |
                    (static_cast<std::uint32_t>(f[8]) << 16) | (static_cast<std::uint32_t>(f[9]) << 24);
    decodePayload(frame.type, f + kHeaderBytes, n - kHeaderBytes - kCrcBytes, frame.payload);
    accept(frame, out);
    p += n;
  }
  return p;
}

void Decoder::push(Frame frame, std::vector<DecodedFrame>& out) { accept(frame, out); }

void Decoder::accept(Frame& frame, std::vector<DecodedFrame>& out) {
  const auto ti = static_cast<std::size_t>(frame.type) - 1;
  std::uint32_t lost = 0;
  if (haveSequence_[ti]) {
    const auto d = static_cast<std::uint16_t>(frame.sequence - lastSequence_[ti]);
    if (d == 0) {
      ++health_.duplicateFrames;
      return;
    }
    if (d > 32768u) {
      ++health_.outOfOrderFrames;
      return;
    }
    lost = d - 1u;
  }

  int bits = counterBits_;
  if (frame.type == FrameType::kStatus) {
    const int declared = std::get<StatusPayload>(frame.payload).counterBits;
    if (declared >= 8 && declared <= 32) bits = declared;
  }
  const std::uint32_t mask = counterMask(bits);
  const std::uint32_t counter = frame.counter & mask;
  if (haveCounter_) {
    const std::uint32_t last = lastCounter_ & mask;
    const std::uint32_t d = (counter - last) & mask;
    if (d > (mask >> 1)) {  // d >= 2^(bits-1): time went backwards
      ++health_.outOfOrderFrames;
      return;
    }
    if (counter < last) ++health_.counterWraps;
    ticks_ += d;
  } else {
    ticks_ = counter;
    haveCounter_ = true;
  }
  lastCounter_ = counter;
  counterBits_ = bits;

  haveSequence_[ti] = true;
  lastSequence_[ti] = frame.sequence;
  health_.lostFrames += lost;
  switch (frame.type) {
    case FrameType::kImu: ++health_.imuFrames; break;
    case FrameType::kTable: ++health_.tableFrames; break;
    case FrameType::kStatus: ++health_.statusFrames; break;
  }
  DecodedFrame d{std::move(frame), ticks_, lost};
  d.duplicatesBefore = static_cast<std::uint32_t>(health_.duplicateFrames - atLastEmit_.duplicateFrames);
  d.checksumFailuresBefore = static_cast<std::uint32_t>(health_.checksumFailures - atLastEmit_.checksumFailures);
  d.outOfOrderBefore = static_cast<std::uint32_t>(health_.outOfOrderFrames - atLastEmit_.outOfOrderFrames);
  d.bytesSkippedBefore = health_.bytesSkipped - atLastEmit_.bytesSkipped;
  atLastEmit_ = health_;
  out.push_back(std::move(d));
}

}  // namespace fog::protocol

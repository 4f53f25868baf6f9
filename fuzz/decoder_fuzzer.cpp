// libFuzzer entry for the sampling-board decoder and recording builder.
//
// The input is decoded twice: in one piece and in chunks whose sizes come from
// a generator seeded by the input, and both must agree (frames, the damage
// attributed to each frame, and health).
// Every push must leave fewer than kMaxFrameBytes pending, and
// decodeRecording must return a value or a status, never crash.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "core/protocol/decoder.h"
#include "core/protocol/recording_builder.h"

namespace {

using namespace fog::protocol;

void check(bool ok) {
  if (!ok) std::abort();
}

bool sameHealth(const fog::StreamHealth& a, const fog::StreamHealth& b) {
  return a.tableFrames == b.tableFrames && a.imuFrames == b.imuFrames && a.statusFrames == b.statusFrames &&
         a.checksumFailures == b.checksumFailures && a.bytesSkipped == b.bytesSkipped &&
         a.lostFrames == b.lostFrames && a.duplicateFrames == b.duplicateFrames &&
         a.outOfOrderFrames == b.outOfOrderFrames && a.counterWraps == b.counterWraps;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);

  Decoder whole;
  std::vector<DecodedFrame> wholeFrames;
  whole.push(input, wholeFrames);
  check(whole.pendingBytes() < kMaxFrameBytes);
  check(wholeFrames.size() <= size / frameSize(FrameType::kTable));

  std::uint32_t state = 2166136261u;  // FNV-1a of the input picks the split
  for (const std::uint8_t b : input) state = (state ^ b) * 16777619u;
  Decoder chunked;
  std::vector<DecodedFrame> chunkedFrames;
  std::size_t at = 0;
  while (at < size) {
    state = state * 1664525u + 1013904223u;
    const std::size_t n = std::min<std::size_t>((state >> 24) % 48, size - at);  // 0..47 bytes
    chunked.push(input.subspan(at, n), chunkedFrames);
    check(chunked.pendingBytes() < kMaxFrameBytes);
    at += n;
  }
  check(chunkedFrames.size() == wholeFrames.size());
  for (std::size_t i = 0; i < wholeFrames.size(); ++i) {
    check(chunkedFrames[i].ticks == wholeFrames[i].ticks);
    check(chunkedFrames[i].frame.sequence == wholeFrames[i].frame.sequence);
    check(chunkedFrames[i].frame.counter == wholeFrames[i].frame.counter);
    // Damage is attributed to the same frame however the input is split.
    check(chunkedFrames[i].lostBefore == wholeFrames[i].lostBefore);
    check(chunkedFrames[i].duplicatesBefore == wholeFrames[i].duplicatesBefore);
    check(chunkedFrames[i].checksumFailuresBefore == wholeFrames[i].checksumFailuresBefore);
    check(chunkedFrames[i].outOfOrderBefore == wholeFrames[i].outOfOrderBefore);
    check(chunkedFrames[i].bytesSkippedBefore == wholeFrames[i].bytesSkippedBefore);
  }
  check(sameHealth(whole.health(), chunked.health()));
  check(whole.pendingBytes() == chunked.pendingBytes());

  auto recording = decodeRecording(input);
  if (recording.isOk()) check(!recording->testPoints.empty());
  else check(!recording.status().message().empty());
  return 0;
}

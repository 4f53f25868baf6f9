#pragma once
// Replay of a recorded raw stream through the same protocol::Decoder and
// RecordingBuilder path a live source uses: the bytes are pushed in chunks,
// paced by the board counter stamps of the decoded frames (1x: a 60 s stream
// takes about 60 s), a chosen speed-up, or as fast as possible.
//
//   std::atomic<bool> cancel{false};
//   ReplayOptions o; o.speed = 10.0; o.cancel = &cancel;
//   auto r = replay(bytes, o, [](const ReplayChunk& c) { ... });
//
// Contracts: the bytes are fed in order, each exactly once; at any speed the
// resulting Recording equals protocol::decodeRecording(bytes) (chunking does
// not change decoding). Pacing never runs ahead of the stream's own time
// scaled by the speed; it may run late if the callback or the machine is
// slow (it then catches up without sleeping). Cancel is checked before every
// chunk and during sleeps (every <= 50 ms). Runs in the calling thread.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "common/recording.h"
#include "common/status.h"
#include "protocol/decoder.h"

namespace fog::session {

struct ReplayOptions {
  // Stream seconds per wall-clock second: 1 = real time. <= 0 or infinite:
  // as fast as possible.
  double speed = 1.0;
  std::size_t chunkBytes = 1024;  // about 25 ms of a 1 kHz table + 500 Hz IMU stream
  const std::atomic<bool>* cancel = nullptr;
};

struct ReplayChunk {
  std::span<const std::uint8_t> bytes;                  // the chunk just fed to the decoder
  std::span<const protocol::DecodedFrame> frames;       // the frames it completed
  std::uint64_t bytesFed = 0;                           // including this chunk
  std::uint64_t totalBytes = 0;
  double streamTimeS = 0.0;                             // board time of the latest frame, from the first
};

struct ReplayResult {
  Recording recording;         // meaningful when completed; partial when cancelled
  bool cancelled = false;
  std::uint64_t bytesFed = 0;
  double streamDurationS = 0.0;  // board time from the first to the last frame fed
};

// Errors: as protocol::decodeRecording (no frames: kCorruptData; no usable
// test point: kInsufficientData), unless cancelled (then the partial result is
// returned with cancelled = true and whatever the builder had).
Result<ReplayResult> replay(std::span<const std::uint8_t> bytes, const ReplayOptions& options,
                            const std::function<void(const ReplayChunk&)>& onChunk = {});

}  // namespace fog::session

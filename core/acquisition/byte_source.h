#pragma once
// Where sampling-board bytes come from: the built-in simulator, a serial
// port, or the replay of a recorded session. Every source hands the same byte
// stream (docs/protocol.md) to the same decoder, so nothing downstream knows
// which one it is.
//
// Contract for implementations: read() appends whatever bytes are available
// to `out`, waiting at most `timeout` for the first one; it returns how many
// it appended (0: nothing arrived in time) and whether the stream has ended
// (nothing more will ever come). A source that fails (a port that vanished)
// returns an error Status (kIoError) saying what happened; it is then done.
// Sources are used from one thread at a time (the acquisition thread) and
// never call back into the caller.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace fog::acquisition {

struct ReadOutcome {
  std::size_t bytes = 0;
  bool endOfStream = false;
};

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual Result<ReadOutcome> read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) = 0;
  // For people and for the session's metadata: "simulator, seed 1, real time".
  virtual std::string description() const = 0;

  // The host-to-board direction (docs/protocol.md, "Host to board"; optional).
  // queueForDevice() may be called from any thread: the bytes are queued and
  // written by the reading thread at its next read(); it returns false when
  // this source cannot send (the simulator, a replay, a port opened read-only).
  // flushToDevice() writes what is queued, waiting at most `timeout`; only from
  // the reading thread (after the last read(), before the source is closed).
  // Neither ever waits for an answer: a board that only streams keeps working.
  virtual bool queueForDevice(std::span<const std::uint8_t> bytes) {
    (void)bytes;
    return false;
  }
  virtual void flushToDevice(std::chrono::milliseconds timeout) { (void)timeout; }
};

}  // namespace fog::acquisition

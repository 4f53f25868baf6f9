#pragma once
// A recorded raw stream (a session's, or a saved .bin) as a byte source,
// paced by the board counter stamps of its own frames: at speed 1 it takes as
// long as it took to record, at 20 a twentieth of that, with speed 0 as fast
// as possible. The bytes come out unchanged, in order, each exactly once.

#include <memory>
#include <string>
#include <vector>

#include "core/acquisition/byte_source.h"
#include "core/acquisition/paced_clock.h"
#include "core/protocol/decoder.h"

namespace fog::acquisition {

class ReplaySource : public ByteSource {
 public:
  // `name` says where the bytes came from ("session run1.fbs").
  // `wall` paces the release (the machine's clock unless a test gives one).
  ReplaySource(std::vector<std::uint8_t> bytes, double speed, std::string name, WallClock wall = {});

  Result<ReadOutcome> read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) override;
  std::string description() const override;

  std::size_t totalBytes() const { return bytes_.size(); }
  std::size_t bytesRead() const { return position_; }

 private:
  // Finds the next chunk and the stream time of its last complete frame.
  void prepareChunk();

  std::vector<std::uint8_t> bytes_;
  PacedClock clock_;
  std::string name_;
  std::size_t position_ = 0;
  std::size_t chunkEnd_ = 0;   // > position_ while a chunk is waiting to be released
  double chunkTimeS_ = 0.0;    // stream time at which it is due
  // A private decoder tells the stream time of each chunk.
  protocol::Decoder timing_;
  std::vector<protocol::DecodedFrame> frames_;
  bool haveFirst_ = false;
  std::int64_t firstTicks_ = 0;
  double counterHz_ = 10e6;
};

}  // namespace fog::acquisition

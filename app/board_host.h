#pragma once
// The host-to-board direction in the board emulator (docs/protocol.md, "Host
// to board"): applies the host's commands to the simulator's clean stream
// before faults are injected.
//  - set pulse equivalent: echoed in every STATUS frame from then on;
//  - stop / start streaming: table and IMU frames are left out while stopped
//    (their sequence numbers do not advance: nothing is "lost"); STATUS
//    frames go on;
//  - mark test point: the STATUS frames carry the host's test point, axis,
//    phase, nominal values and flags from then on, and one is sent at once.
// Until the first command the stream passes through byte for byte, so a host
// that never sends one gets exactly what it got before. Input must be whole
// frames (the simulator's output). Not thread-safe.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/protocol/decoder.h"
#include "core/protocol/frame.h"
#include "core/protocol/host_command.h"

namespace fog::app {

class BoardHostControl {
 public:
  // Applies a command; returns a line describing it for the emulator's stdout.
  std::string apply(const protocol::HostCommand& command);
  // Appends the stream as the host has configured it.
  void process(std::span<const std::uint8_t> clean, std::vector<std::uint8_t>& out);
  bool streaming() const { return streaming_; }

 private:
  void rewrite(const protocol::Frame& frame, std::vector<std::uint8_t>& out);

  protocol::Decoder decoder_;
  std::vector<protocol::DecodedFrame> frames_;
  protocol::FrameWriter writer_;
  bool engaged_ = false;  // a command has arrived: frames are re-encoded
  bool streaming_ = true;
  bool statusDue_ = false;
  std::optional<double> pulseEquivalentDeg_;
  std::optional<protocol::HostCommand> marker_;
  std::uint32_t lastCounter_ = 0;
  protocol::StatusPayload lastStatus_;
};

}  // namespace fog::app

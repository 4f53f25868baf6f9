#pragma once
// Host-to-board commands (optional; docs/protocol.md, "Host to board"): the
// host may tell the sampling board the gyro's pulse equivalent, stop and
// start the table/IMU stream, and mark test points, which the board then
// echoes in its STATUS frames. A board that only streams ignores these bytes
// and keeps working; the host never depends on an answer (the STATUS frames
// show what the board did).
//
// Same framing as the board's frames: sync A5 5A | type 4 | length 16 |
// sequence u16 | counter u32 (0: the host has no board counter) | payload |
// CRC-16/CCITT-FALSE over type .. payload; little-endian. Payload: opcode u8,
// then the opcode's arguments, zero-padded to 16 bytes.
// Plain values and a streaming decoder; no I/O; nothing throws.

#include <cstdint>
#include <span>
#include <vector>

#include "core/protocol/frame.h"

namespace fog::protocol {

inline constexpr std::uint8_t kCommandFrameType = 4;
inline constexpr std::size_t kCommandPayloadBytes = 16;
inline constexpr std::size_t kCommandFrameBytes = kHeaderBytes + kCommandPayloadBytes + kCrcBytes;  // 28

enum class HostOpcode : std::uint8_t {
  kSetPulseEquivalent = 1,  // f64 at payload offset 1: degrees per gyro pulse (> 0)
  kStartStreaming = 2,      // table and IMU frames resume (STATUS frames never stop)
  kStopStreaming = 3,       // no table or IMU frames until started again
  kMarkTestPoint = 4,       // u16 testPoint @1, u8 axis @3, u8 phase @4, u32 µHz @5, u32 µdeg @9, u8 flags @13
};

struct HostCommand {
  HostOpcode opcode = HostOpcode::kStartStreaming;
  double pulseEquivalentDeg = 0.0;  // kSetPulseEquivalent
  // kMarkTestPoint: what the board's STATUS frames say from now on.
  std::uint16_t testPoint = kNoTestPoint;
  std::uint8_t axis = 0;
  TestPhase phase = TestPhase::kIdle;
  std::uint32_t nominalFrequencyMicroHz = 0;
  std::uint32_t nominalAmplitudeMicroDeg = 0;
  std::uint8_t flags = 0;
};

void appendHostCommand(const HostCommand& command, std::uint16_t sequence, std::vector<std::uint8_t>& out);

// Finds command frames in whatever the host sends (split anywhere); bytes
// that are not a valid command frame (bad CRC, unknown opcode, other types)
// are skipped and counted. Buffers at most one frame.
class HostCommandDecoder {
 public:
  void push(std::span<const std::uint8_t> bytes, std::vector<HostCommand>& out);
  std::uint64_t bytesSkipped() const { return skipped_; }

 private:
  std::vector<std::uint8_t> buffer_;
  std::uint64_t skipped_ = 0;
};

}  // namespace fog::protocol

#pragma once
// Sampling-board frames: the byte format the board sends over the serial line
// (docs/protocol.md has the byte tables and examples).
//
// Every frame is
//   sync 0xA5 0x5A | type u8 | payload length u8 | sequence u16 | counter u32 |
//   payload | CRC-16/CCITT-FALSE u16
// all little-endian; the CRC covers type through the end of the payload.
// `counter` is the board's common time counter when it stamped the frame (raw,
// it wraps at 2^counterBits); `sequence` is a separate 16-bit counter per frame
// type. Everything here is a plain value type, thread-compatible, no I/O.

#include <array>
#include <cstddef>
#include <cstdint>
#include <variant>
#include <vector>

namespace fog::protocol {

enum class FrameType : std::uint8_t { kImu = 1, kTable = 2, kStatus = 3 };
enum class TestPhase : std::uint8_t { kIdle = 0, kSettling = 1, kRecording = 2, kDone = 3 };

// IMU frame, 15 payload bytes.
struct ImuPayload {
  std::array<std::int32_t, 3> pulses{};  // gyro pulses since the previous IMU frame, x, y, z
  std::int16_t temperatureCentiC = 0;    // 0.01 degC
  std::uint8_t flags = 0;                // IMU status flags, passed through
};

// Turntable encoder reading, 13 payload bytes.
struct TablePayload {
  std::array<std::int32_t, 3> angleMicroDeg{};  // 1e-6 deg, x, y, z
  std::uint8_t flags = 0;                       // table flags, passed through
};

// Board and test state, 26 payload bytes. The board sends one at least every
// 100 ms and whenever testPoint or phase changes, so a raw stream describes
// itself (counter frequency and width, pulse equivalent, current test point).
struct StatusPayload {
  std::uint32_t counterHz = 10000000;      // common counter frequency
  std::uint8_t counterBits = 32;           // counter width, 8..32
  double pulseEquivalentDeg = 0;           // degrees per gyro pulse (host-configured, echoed); 0 = unknown
  std::uint16_t testPoint = 0xFFFF;        // index in the plan; kNoTestPoint = none
  std::uint8_t axis = 0;                   // swinging axis 0 = x, 1 = y, 2 = z
  TestPhase phase = TestPhase::kIdle;
  std::uint32_t nominalFrequencyMicroHz = 0;
  std::uint32_t nominalAmplitudeMicroDeg = 0;
  std::uint8_t flags = 0;                  // bit 0: kStatusFlagStatic
};

inline constexpr std::uint16_t kNoTestPoint = 0xFFFF;
// STATUS flags bit 0: the current test point is a static segment (table at
// rest; nominal frequency and amplitude 0). Streams without it are swings.
inline constexpr std::uint8_t kStatusFlagStatic = 0x01;

struct Frame {
  FrameType type = FrameType::kStatus;
  std::uint16_t sequence = 0;
  std::uint32_t counter = 0;
  std::variant<ImuPayload, TablePayload, StatusPayload> payload;
};

inline constexpr std::uint8_t kSync0 = 0xA5;
inline constexpr std::uint8_t kSync1 = 0x5A;
inline constexpr std::size_t kHeaderBytes = 10;
inline constexpr std::size_t kCrcBytes = 2;
inline constexpr std::size_t kImuPayloadBytes = 15;
inline constexpr std::size_t kTablePayloadBytes = 13;
inline constexpr std::size_t kStatusPayloadBytes = 26;
inline constexpr std::size_t kMaxFrameBytes = kHeaderBytes + kStatusPayloadBytes + kCrcBytes;  // 38

// Payload length of a frame type; 0 for a value outside the enum.
std::size_t payloadSize(FrameType type);
// Whole frame in bytes (header + payload + CRC); 0 for a value outside the enum.
std::size_t frameSize(FrameType type);
// The frame type whose payload the variant holds.
FrameType payloadType(const Frame& frame);

// Encodes one frame and appends it to `out`. The payload alternative decides
// the type byte; `frame.type` must agree with it (asserted in debug builds).
// Values are written as they are (no range checks): an encoder can produce
// deliberately odd frames for tests.
void appendFrame(const Frame& frame, std::vector<std::uint8_t>& out);

// Decodes the payload bytes of a frame whose type and length are already
// known to match (`payload.size() == payloadSize(type)`); used by Decoder.
// Returns false for an unknown type or a wrong length.
bool decodePayload(FrameType type, const std::uint8_t* payload, std::size_t size,
                   std::variant<ImuPayload, TablePayload, StatusPayload>& out);

// Keeps the per-type sequence numbers (each starts at 0 and wraps at 65536)
// and appends encoded frames. One writer per stream; not thread-safe.
class FrameWriter {
 public:
  void imu(std::uint32_t counter, const ImuPayload& payload, std::vector<std::uint8_t>& out);
  void table(std::uint32_t counter, const TablePayload& payload, std::vector<std::uint8_t>& out);
  void status(std::uint32_t counter, const StatusPayload& payload, std::vector<std::uint8_t>& out);
  // The next frame of the payload's type, numbered but not encoded: the same
  // frame the byte-writing calls above encode (a simulator's replay hands it
  // to the decoder without the byte round trip). Uses up the sequence
  // number, as a frame lost on the link does.
  Frame numbered(std::uint32_t counter, const ImuPayload& payload);
  Frame numbered(std::uint32_t counter, const TablePayload& payload);
  Frame numbered(std::uint32_t counter, const StatusPayload& payload);

  // Sequence number the next frame of this type will carry.
  std::uint16_t nextSequence(FrameType type) const;

 private:
  std::array<std::uint16_t, 3> next_{};
};

}  // namespace fog::protocol

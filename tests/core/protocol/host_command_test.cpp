#include "core/protocol/host_command.h"

#include <gtest/gtest.h>

namespace fog::protocol {
namespace {

TEST(HostCommand, EveryOpcodeRoundTripsWhateverTheSplit) {
  std::vector<std::uint8_t> bytes;
  HostCommand pe{HostOpcode::kSetPulseEquivalent, 1e-4};
  HostCommand mark;
  mark.opcode = HostOpcode::kMarkTestPoint;
  mark.testPoint = 7;
  mark.axis = 2;
  mark.phase = TestPhase::kRecording;
  mark.nominalFrequencyMicroHz = 2000000;
  mark.nominalAmplitudeMicroDeg = 1500000;
  mark.flags = 0;
  appendHostCommand(pe, 0, bytes);
  appendHostCommand(HostCommand{HostOpcode::kStopStreaming}, 1, bytes);
  appendHostCommand(mark, 2, bytes);
  appendHostCommand(HostCommand{HostOpcode::kStartStreaming}, 3, bytes);
  ASSERT_EQ(bytes.size(), 4 * kCommandFrameBytes);
  for (std::size_t chunk : {1u, 5u, 28u, 200u}) {
    HostCommandDecoder d;
    std::vector<HostCommand> out;
    for (std::size_t i = 0; i < bytes.size(); i += chunk)
      d.push(std::span(bytes).subspan(i, std::min(chunk, bytes.size() - i)), out);
    ASSERT_EQ(out.size(), 4u) << chunk;
    EXPECT_EQ(out[0].opcode, HostOpcode::kSetPulseEquivalent);
    EXPECT_EQ(out[0].pulseEquivalentDeg, 1e-4);
    EXPECT_EQ(out[1].opcode, HostOpcode::kStopStreaming);
    EXPECT_EQ(out[2].testPoint, 7);
    EXPECT_EQ(out[2].axis, 2);
    EXPECT_EQ(out[2].phase, TestPhase::kRecording);
    EXPECT_EQ(out[2].nominalAmplitudeMicroDeg, 1500000u);
    EXPECT_EQ(out[3].opcode, HostOpcode::kStartStreaming);
    EXPECT_EQ(d.bytesSkipped(), 0u);
  }
}

TEST(HostCommand, DamagedFramesAndOtherBytesAreSkipped) {
  std::vector<std::uint8_t> bytes = {0x00, 0xA5, 0x5A, 0x04};  // garbage, a false start
  FrameWriter w;
  w.status(0, StatusPayload{}, bytes);  // a board frame is not a command
  std::vector<std::uint8_t> bad;
  appendHostCommand(HostCommand{HostOpcode::kStopStreaming}, 0, bad);
  bad[12] ^= 0x01;  // CRC no longer matches
  bytes.insert(bytes.end(), bad.begin(), bad.end());
  std::vector<std::uint8_t> zeroPe;
  appendHostCommand(HostCommand{HostOpcode::kSetPulseEquivalent, 0.0}, 1, zeroPe);  // not > 0
  bytes.insert(bytes.end(), zeroPe.begin(), zeroPe.end());
  appendHostCommand(HostCommand{HostOpcode::kStartStreaming}, 2, bytes);
  HostCommandDecoder d;
  std::vector<HostCommand> out;
  d.push(bytes, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].opcode, HostOpcode::kStartStreaming);
  EXPECT_GT(d.bytesSkipped(), 38u);
}

}  // namespace
}  // namespace fog::protocol

#include "core/protocol/crc16.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace fog::protocol {
namespace {

std::vector<std::uint8_t> bytesOf(std::string_view s) { return {s.begin(), s.end()}; }

TEST(Crc16Ccitt, CheckValueOf123456789Is0x29B1) {
  EXPECT_EQ(crc16Ccitt(bytesOf("123456789")), 0x29B1);
}

TEST(Crc16Ccitt, EmptyInputGivesTheInitialValue) {
  EXPECT_EQ(crc16Ccitt({}), 0xFFFF);
}

TEST(Crc16Ccitt, SingleBytesMatchTheBitwiseDefinition) {
  // Reference: bit-at-a-time CRC, MSB first, poly 0x1021, init 0xFFFF.
  for (unsigned v = 0; v < 256; ++v) {
    std::uint16_t crc = 0xFFFF ^ static_cast<std::uint16_t>(v << 8);
    for (int bit = 0; bit < 8; ++bit)
      crc = static_cast<std::uint16_t>((crc & 0x8000u) ? (crc << 1) ^ 0x1021u : crc << 1);
    const std::uint8_t b = static_cast<std::uint8_t>(v);
    EXPECT_EQ(crc16Ccitt({&b, 1}), crc) << "byte " << v;
  }
}

}  // namespace
}  // namespace fog::protocol

#pragma once
// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection,
// no final xor. Check value: crc16Ccitt("123456789") == 0x29B1.

#include <cstdint>
#include <span>

namespace fog::protocol {

std::uint16_t crc16Ccitt(std::span<const std::uint8_t> bytes);

}  // namespace fog::protocol

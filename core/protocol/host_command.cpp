#include "core/protocol/host_command.h"

#include <cmath>
#include <cstring>

#include "core/protocol/crc16.h"

namespace fog::protocol {

namespace {

void put16(std::vector<std::uint8_t>& o, std::uint16_t v) {
  o.push_back(static_cast<std::uint8_t>(v));
  o.push_back(static_cast<std::uint8_t>(v >> 8));
}
void put32(std::vector<std::uint8_t>& o, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) o.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
std::uint16_t get16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
std::uint32_t get32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

bool decodeCommand(const std::uint8_t* p, HostCommand& c) {
  switch (p[0]) {
    case 1: {
      std::uint64_t bits = 0;
      for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(p[1 + i]) << (8 * i);
      double v = 0.0;
      std::memcpy(&v, &bits, sizeof v);
      if (!std::isfinite(v) || !(v > 0.0)) return false;
      c.opcode = HostOpcode::kSetPulseEquivalent;
      c.pulseEquivalentDeg = v;
      return true;
    }
    case 2: c.opcode = HostOpcode::kStartStreaming; return true;
    case 3: c.opcode = HostOpcode::kStopStreaming; return true;
    case 4:
      if (p[3] > 2 || p[4] > 3) return false;
      c.opcode = HostOpcode::kMarkTestPoint;
      c.testPoint = get16(p + 1);
      c.axis = p[3];
      c.phase = static_cast<TestPhase>(p[4]);
      c.nominalFrequencyMicroHz = get32(p + 5);
      c.nominalAmplitudeMicroDeg = get32(p + 9);
      c.flags = p[13];
      return true;
    default: return false;
  }
}

}  // namespace

void appendHostCommand(const HostCommand& c, std::uint16_t sequence, std::vector<std::uint8_t>& out) {
  const std::size_t start = out.size();
  out.push_back(kSync0);
  out.push_back(kSync1);
  out.push_back(kCommandFrameType);
  out.push_back(static_cast<std::uint8_t>(kCommandPayloadBytes));
  put16(out, sequence);
  put32(out, 0);
  const std::size_t payload = out.size();
  out.push_back(static_cast<std::uint8_t>(c.opcode));
  if (c.opcode == HostOpcode::kSetPulseEquivalent) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &c.pulseEquivalentDeg, sizeof bits);
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  } else if (c.opcode == HostOpcode::kMarkTestPoint) {
    put16(out, c.testPoint);
    out.push_back(c.axis);
    out.push_back(static_cast<std::uint8_t>(c.phase));
    put32(out, c.nominalFrequencyMicroHz);
    put32(out, c.nominalAmplitudeMicroDeg);
    out.push_back(c.flags);
  }
  out.resize(payload + kCommandPayloadBytes, 0);
  put16(out, crc16Ccitt(std::span(out).subspan(start + 2)));
}

void HostCommandDecoder::push(std::span<const std::uint8_t> bytes, std::vector<HostCommand>& out) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  std::size_t i = 0;
  while (buffer_.size() - i >= 2) {
    if (buffer_[i] != kSync0 || buffer_[i + 1] != kSync1) {
      ++i;
      ++skipped_;
      continue;
    }
    if (buffer_.size() - i < 4) break;
    if (buffer_[i + 2] != kCommandFrameType || buffer_[i + 3] != kCommandPayloadBytes) {
      ++i;
      ++skipped_;
      continue;
    }
    if (buffer_.size() - i < kCommandFrameBytes) break;
    const std::uint8_t* f = buffer_.data() + i;
    const std::uint16_t crc = get16(f + kHeaderBytes + kCommandPayloadBytes);
    HostCommand c;
    if (crc16Ccitt(std::span(f + 2, kHeaderBytes - 2 + kCommandPayloadBytes)) == crc &&
        decodeCommand(f + kHeaderBytes, c)) {
      out.push_back(c);
      i += kCommandFrameBytes;
    } else {
      ++i;
      ++skipped_;
    }
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(i));
}

}  // namespace fog::protocol

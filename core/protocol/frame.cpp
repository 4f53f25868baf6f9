#include "core/protocol/frame.h"

#include <bit>
#include <cassert>
#include <span>

#include "core/protocol/crc16.h"

namespace fog::protocol {
namespace {

// Little-endian writers and readers, independent of the host byte order.
void put8(std::vector<std::uint8_t>& out, std::uint8_t v) { out.push_back(v); }
void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void put64(std::vector<std::uint8_t>& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint16_t get16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
std::uint32_t get32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
std::uint64_t get64(const std::uint8_t* p) {
  return static_cast<std::uint64_t>(get32(p)) | (static_cast<std::uint64_t>(get32(p + 4)) << 32);
}

void putPayload(std::vector<std::uint8_t>& out, const ImuPayload& p) {
  for (const auto v : p.pulses) put32(out, static_cast<std::uint32_t>(v));
  put16(out, static_cast<std::uint16_t>(p.temperatureCentiC));
  put8(out, p.flags);
}
void putPayload(std::vector<std::uint8_t>& out, const TablePayload& p) {
  for (const auto v : p.angleMicroDeg) put32(out, static_cast<std::uint32_t>(v));
  put8(out, p.flags);
}
void putPayload(std::vector<std::uint8_t>& out, const StatusPayload& p) {
  put32(out, p.counterHz);
  put8(out, p.counterBits);
  put64(out, std::bit_cast<std::uint64_t>(p.pulseEquivalentDeg));
  put16(out, p.testPoint);
  put8(out, p.axis);
  put8(out, static_cast<std::uint8_t>(p.phase));
  put32(out, p.nominalFrequencyMicroHz);
  put32(out, p.nominalAmplitudeMicroDeg);
  put8(out, p.flags);
}

}  // namespace

std::size_t payloadSize(FrameType type) {
  switch (type) {
    case FrameType::kImu: return kImuPayloadBytes;
    case FrameType::kTable: return kTablePayloadBytes;
    case FrameType::kStatus: return kStatusPayloadBytes;
  }
  return 0;
}

std::size_t frameSize(FrameType type) {
  const std::size_t n = payloadSize(type);
  return n == 0 ? 0 : kHeaderBytes + n + kCrcBytes;
}

FrameType payloadType(const Frame& frame) {
  switch (frame.payload.index()) {
    case 0: return FrameType::kImu;
    case 1: return FrameType::kTable;
    default: return FrameType::kStatus;
  }
}

void appendFrame(const Frame& frame, std::vector<std::uint8_t>& out) {
  const FrameType type = payloadType(frame);
  assert(type == frame.type && "Frame::type disagrees with its payload");
  const std::size_t start = out.size();
  put8(out, kSync0);
  put8(out, kSync1);
  put8(out, static_cast<std::uint8_t>(type));
  put8(out, static_cast<std::uint8_t>(payloadSize(type)));
  put16(out, frame.sequence);
  put32(out, frame.counter);
  std::visit([&out](const auto& p) { putPayload(out, p); }, frame.payload);
  const std::uint16_t crc = crc16Ccitt(std::span(out).subspan(start + 2));
  put16(out, crc);
}

bool decodePayload(FrameType type, const std::uint8_t* p, std::size_t size,
                   std::variant<ImuPayload, TablePayload, StatusPayload>& out) {
  if (size != payloadSize(type) || size == 0) return false;
  switch (type) {
    case FrameType::kImu: {
      ImuPayload v;
      for (int i = 0; i < 3; ++i) v.pulses[i] = static_cast<std::int32_t>(get32(p + 4 * i));
      v.temperatureCentiC = static_cast<std::int16_t>(get16(p + 12));
      v.flags = p[14];
      out = v;
      return true;
    }
    case FrameType::kTable: {
      TablePayload v;
      for (int i = 0; i < 3; ++i) v.angleMicroDeg[i] = static_cast<std::int32_t>(get32(p + 4 * i));
      v.flags = p[12];
      out = v;
      return true;
    }
    case FrameType::kStatus: {
      StatusPayload v;
      v.counterHz = get32(p);
      v.counterBits = p[4];
      v.pulseEquivalentDeg = std::bit_cast<double>(get64(p + 5));
      v.testPoint = get16(p + 13);
      v.axis = p[15];
      v.phase = static_cast<TestPhase>(p[16]);
      v.nominalFrequencyMicroHz = get32(p + 17);
      v.nominalAmplitudeMicroDeg = get32(p + 21);
      v.flags = p[25];
      out = v;
      return true;
    }
  }
  return false;
}

void FrameWriter::imu(std::uint32_t counter, const ImuPayload& payload, std::vector<std::uint8_t>& out) {
  appendFrame(numbered(counter, payload), out);
}

void FrameWriter::table(std::uint32_t counter, const TablePayload& payload, std::vector<std::uint8_t>& out) {
  appendFrame(numbered(counter, payload), out);
}

void FrameWriter::status(std::uint32_t counter, const StatusPayload& payload, std::vector<std::uint8_t>& out) {
  appendFrame(numbered(counter, payload), out);
}

Frame FrameWriter::numbered(std::uint32_t counter, const ImuPayload& payload) {
  return Frame{FrameType::kImu, next_[0]++, counter, payload};
}

Frame FrameWriter::numbered(std::uint32_t counter, const TablePayload& payload) {
  return Frame{FrameType::kTable, next_[1]++, counter, payload};
}

Frame FrameWriter::numbered(std::uint32_t counter, const StatusPayload& payload) {
  return Frame{FrameType::kStatus, next_[2]++, counter, payload};
}

std::uint16_t FrameWriter::nextSequence(FrameType type) const {
  switch (type) {
    case FrameType::kImu: return next_[0];
    case FrameType::kTable: return next_[1];
    case FrameType::kStatus: return next_[2];
  }
  return 0;
}

}  // namespace fog::protocol

#pragma once
// Small helpers to build sampling-board byte streams in tests.

#include <cstdint>
#include <vector>

#include "core/protocol/decoder.h"
#include "core/protocol/frame.h"

namespace fog::protocol::testing {

inline TablePayload tableAt(std::int32_t x, std::int32_t y = 0, std::int32_t z = 0) {
  TablePayload t;
  t.angleMicroDeg = {x, y, z};
  return t;
}

inline ImuPayload imuWith(std::int32_t x, std::int32_t y = 0, std::int32_t z = 0) {
  ImuPayload m;
  m.pulses = {x, y, z};
  m.temperatureCentiC = 2512;
  return m;
}

inline Frame tableFrame(std::uint16_t seq, std::uint32_t counter, const TablePayload& p = tableAt(0)) {
  return Frame{FrameType::kTable, seq, counter, p};
}
inline Frame imuFrame(std::uint16_t seq, std::uint32_t counter, const ImuPayload& p = imuWith(0)) {
  return Frame{FrameType::kImu, seq, counter, p};
}
inline Frame statusFrame(std::uint16_t seq, std::uint32_t counter, const StatusPayload& p = {}) {
  return Frame{FrameType::kStatus, seq, counter, p};
}

inline std::vector<std::uint8_t> encode(const std::vector<Frame>& frames) {
  std::vector<std::uint8_t> out;
  for (const auto& f : frames) appendFrame(f, out);
  return out;
}

inline std::vector<DecodedFrame> decodeAll(const std::vector<std::uint8_t>& bytes, Decoder* decoder = nullptr) {
  Decoder local;
  Decoder& d = decoder ? *decoder : local;
  std::vector<DecodedFrame> out;
  d.push(bytes, out);
  return out;
}

inline bool samePayload(const Frame& a, const Frame& b) {
  if (a.payload.index() != b.payload.index()) return false;
  if (const auto* x = std::get_if<ImuPayload>(&a.payload)) {
    const auto& y = std::get<ImuPayload>(b.payload);
    return x->pulses == y.pulses && x->temperatureCentiC == y.temperatureCentiC && x->flags == y.flags;
  }
  if (const auto* x = std::get_if<TablePayload>(&a.payload)) {
    const auto& y = std::get<TablePayload>(b.payload);
    return x->angleMicroDeg == y.angleMicroDeg && x->flags == y.flags;
  }
  const auto& x = std::get<StatusPayload>(a.payload);
  const auto& y = std::get<StatusPayload>(b.payload);
  return x.counterHz == y.counterHz && x.counterBits == y.counterBits &&
         x.pulseEquivalentDeg == y.pulseEquivalentDeg && x.testPoint == y.testPoint && x.axis == y.axis &&
         x.phase == y.phase && x.nominalFrequencyMicroHz == y.nominalFrequencyMicroHz &&
         x.nominalAmplitudeMicroDeg == y.nominalAmplitudeMicroDeg && x.flags == y.flags;
}

inline bool sameFrame(const Frame& a, const Frame& b) {
  return a.type == b.type && a.sequence == b.sequence && a.counter == b.counter && samePayload(a, b);
}

}  // namespace fog::protocol::testing

#include "app/board_faults.h"

#include <cmath>

#include "core/protocol/frame.h"

namespace fog::app {

BoardFaults::BoardFaults(const FaultOptions& options) : options_(options), rng_(options.seed) {}

void BoardFaults::apply(std::span<const std::uint8_t> clean, double nowS, std::vector<std::uint8_t>& out) {
  pending_.insert(pending_.end(), clean.begin(), clean.end());
  const std::size_t start = out.size();
  if (!garbageDone_ && options_.garbageAtS >= 0.0 && nowS >= options_.garbageAtS) {
    garbageDone_ = true;
    for (std::size_t i = 0; i < options_.garbageBytes; ++i) out.push_back(static_cast<std::uint8_t>(rng_()));
    counts_.garbageBytes += options_.garbageBytes;
  }
  const bool inGap = options_.gapS > 0.0 && nowS >= options_.gapAtS && nowS < options_.gapAtS + options_.gapS;
  std::size_t p = 0;
  // The simulator's stream is clean: every frame starts at p and states its length.
  while (pending_.size() - p >= protocol::kHeaderBytes) {
    const std::size_t n = protocol::kHeaderBytes + pending_[p + 3] + protocol::kCrcBytes;
    if (pending_.size() - p < n) break;
    const auto frame = std::span(pending_).subspan(p, n);
    p += n;
    ++counts_.frames;
    if (inGap) {
      ++counts_.gapFrames;
      continue;
    }
    const bool data = frame[2] != static_cast<std::uint8_t>(protocol::FrameType::kStatus);
    if (data && chance(options_.dropRate)) {
      ++counts_.droppedFrames;
      continue;
    }
    out.insert(out.end(), frame.begin(), frame.end());
    if (data && chance(options_.duplicateRate)) {
      ++counts_.duplicatedFrames;
      out.insert(out.end(), frame.begin(), frame.end());
    }
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(p));
  if (options_.corruptRate > 0.0)
    for (std::size_t i = start; i < out.size(); ++i)
      if (chance(options_.corruptRate)) {
        out[i] ^= static_cast<std::uint8_t>(1u << (rng_() % 8));
        ++counts_.corruptedBytes;
      }
}

std::vector<std::uint8_t> uartReceive(std::span<const std::uint8_t> bytes, double boardBaud, double hostBaud,
                                      int hostDataBits, int hostParity) {
  if (boardBaud == hostBaud && hostDataBits == 8 && hostParity == 0)
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
  // The line, one entry per board bit: start 0, 8 data bits LSB first, stop 1.
  std::vector<std::uint8_t> line;
  line.reserve(bytes.size() * 10);
  for (const std::uint8_t b : bytes) {
    line.push_back(0);
    for (int i = 0; i < 8; ++i) line.push_back((b >> i) & 1u);
    line.push_back(1);
  }
  const double r = boardBaud / hostBaud;  // one host bit in board bits
  auto level = [&](double t) {
    const auto i = static_cast<std::size_t>(t);
    return i < line.size() ? line[i] : std::uint8_t{1};  // idle high after the chunk
  };
  std::vector<std::uint8_t> out;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] != 0) {
      ++i;
      continue;
    }
    const double t0 = static_cast<double>(i);
    if (level(t0 + 0.5 * r) != 0) {  // a glitch, not a start bit
      ++i;
      continue;
    }
    unsigned value = 0, ones = 0;
    for (int b = 0; b < hostDataBits; ++b)
      if (level(t0 + (1.5 + b) * r)) {
        value |= 1u << b;
        ++ones;
      }
    double at = t0 + (1.5 + hostDataBits) * r;
    bool good = true;
    if (hostParity != 0) {
      ones += level(at);
      good = hostParity == 1 ? ones % 2 == 0 : ones % 2 == 1;
      at += r;
    }
    good = good && level(at) == 1;  // the stop bit
    out.push_back(good ? static_cast<std::uint8_t>(value) : std::uint8_t{0});
    i = static_cast<std::size_t>(std::ceil(at));
  }
  return out;
}

}  // namespace fog::app

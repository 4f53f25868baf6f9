#pragma once
// Fault injection for the board emulator (fogbench-board-emu): damages a
// clean sampling-board stream the way a real link does, and counts what it
// did so that tests can compare with what the bench reports.
//
// Input is the simulator's stream in whole frames, chunk by chunk, each with
// the stream time it was produced up to. Faults, each off by default:
//  - corruptRate: each output byte has one bit flipped with this probability
//    (the decoder sees a checksum failure or a broken sync);
//  - dropRate / duplicateRate: each table or IMU frame is left out / sent
//    twice with this probability (STATUS frames are never touched, so test
//    points keep their boundaries);
//  - a gap: every frame stamped in [gapAtS, gapAtS + gapS) is left out;
//  - garbage: garbageBytes random bytes between two frames at garbageAtS.
// Deterministic for a given seed. Not thread-safe.

#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace fog::app {

struct FaultOptions {
  double corruptRate = 0.0;    // per byte
  double dropRate = 0.0;       // per table/IMU frame
  double duplicateRate = 0.0;  // per table/IMU frame
  double gapAtS = -1.0, gapS = 0.0;
  double garbageAtS = -1.0;
  std::size_t garbageBytes = 0;
  std::uint64_t seed = 1;
};

struct FaultCounts {
  std::uint64_t frames = 0;            // clean frames seen
  std::uint64_t corruptedBytes = 0;
  std::uint64_t droppedFrames = 0;     // by dropRate
  std::uint64_t gapFrames = 0;         // left out in the gap
  std::uint64_t duplicatedFrames = 0;
  std::uint64_t garbageBytes = 0;
};

class BoardFaults {
 public:
  explicit BoardFaults(const FaultOptions& options);

  // Appends the (damaged) bytes of `clean`, produced up to stream time nowS,
  // to `out`. A partial frame at the end of `clean` waits for the next call.
  void apply(std::span<const std::uint8_t> clean, double nowS, std::vector<std::uint8_t>& out);
  const FaultCounts& counts() const { return counts_; }

 private:
  bool chance(double p) { return p > 0.0 && uniform_(rng_) < p; }

  FaultOptions options_;
  FaultCounts counts_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::vector<std::uint8_t> pending_;
  bool garbageDone_ = false;
};

// What a UART receiver at hostBaud (hostDataBits, hostParity: 0 none, 1 even,
// 2 odd) makes of `bytes` sent back to back as 8N1 at boardBaud: with equal
// settings the bytes themselves, otherwise the garbage a mismatched serial
// line delivers (framing and parity errors read as 0, as Linux does without
// IGNPAR/PARMRK).
std::vector<std::uint8_t> uartReceive(std::span<const std::uint8_t> bytes, double boardBaud, double hostBaud,
                                      int hostDataBits, int hostParity);

}  // namespace fog::app

// Decoder throughput on a realistic sampling-board stream: per second 1000
// table frames (1 ms), 500 IMU frames (2 ms) and 10 status frames (100 ms),
// interleaved in counter order at 10 MHz. Reported as bytes/s of raw stream.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/protocol/decoder.h"
#include "core/protocol/frame.h"
#include "core/protocol/recording_builder.h"

namespace {

using namespace fog::protocol;

std::vector<std::uint8_t> simulatedStream(int seconds) {
  std::vector<std::uint8_t> bytes;
  FrameWriter writer;
  constexpr std::uint32_t kTicksPerMs = 10000;  // 10 MHz counter
  StatusPayload status;
  status.pulseEquivalentDeg = 5e-5;
  status.testPoint = 0;
  status.phase = TestPhase::kRecording;
  status.nominalFrequencyMicroHz = 1000000;
  status.nominalAmplitudeMicroDeg = 3000000;
  std::int64_t lastPulses = 0;
  for (int ms = 0; ms < seconds * 1000; ++ms) {
    // The counter wraps every ~7 minutes at 10 MHz; uint32 arithmetic wraps too.
    const auto counter = static_cast<std::uint32_t>(static_cast<std::uint64_t>(ms) * kTicksPerMs + 37);
    const double angleDeg = 3.0 * std::sin(2.0 * 3.141592653589793 * ms * 1e-3);
    if (ms % 100 == 0) writer.status(counter, status, bytes);
    TablePayload table;
    table.angleMicroDeg[0] = static_cast<std::int32_t>(std::lround(angleDeg * 1e6));
    writer.table(counter + 1, table, bytes);
    if (ms % 2 == 0) {
      const auto pulses = static_cast<std::int64_t>(std::floor(angleDeg / 5e-5));
      ImuPayload imu;
      imu.pulses[0] = static_cast<std::int32_t>(pulses - lastPulses);
      imu.pulses[1] = ms % 7 - 3;
      imu.temperatureCentiC = 2500;
      lastPulses = pulses;
      writer.imu(counter + 2800, imu, bytes);
    }
  }
  return bytes;
}

const std::vector<std::uint8_t>& stream() {
  static const std::vector<std::uint8_t> bytes = simulatedStream(60);
  return bytes;
}

// Serial-port style: the stream arrives in chunks of range(0) bytes.
void BM_DecoderChunked(benchmark::State& state) {
  const auto& bytes = stream();
  const auto chunk = static_cast<std::size_t>(state.range(0));
  std::vector<DecodedFrame> out;
  out.reserve(4096);
  for (auto _ : state) {
    Decoder decoder;
    std::size_t frames = 0;
    for (std::size_t at = 0; at < bytes.size(); at += chunk) {
      out.clear();
      decoder.push(std::span(bytes).subspan(at, std::min(chunk, bytes.size() - at)), out);
      frames += out.size();
    }
    benchmark::DoNotOptimize(frames);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_DecoderChunked)->Arg(64)->Arg(4096)->Arg(65536)->Unit(benchmark::kMillisecond);

// Decoder plus recording builder: a whole file as `fogbench-cli analyze` reads it.
void BM_DecodeRecording(benchmark::State& state) {
  const auto& bytes = stream();
  for (auto _ : state) {
    auto rec = decodeRecording(bytes);
    benchmark::DoNotOptimize(rec);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes.size()));
}
BENCHMARK(BM_DecodeRecording)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

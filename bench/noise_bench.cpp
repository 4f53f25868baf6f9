// Gyro noise: overlapping Allan deviation and noise-term identification of a
// 10-hour static record at 500 Hz (18 M samples). Target: under 2 s.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/model/random.h"
#include "core/noise/noise_terms.h"

namespace {

// Angle increments of a gyro at rest: white rate (ARW 0.004 deg/sqrt(h)) and
// white angle noise (Q 0.05"), 2 ms frames.
const std::vector<double>& tenHours() {
  static const std::vector<double> increments = [] {
    constexpr std::size_t n = 18'000'000;
    std::vector<double> d(n);
    fog::model::Random rng(42);
    const double arw = 0.004 / 60.0 * std::sqrt(2e-3), q = 5e-5 / std::sqrt(12.0);
    double last = 0.0;
    for (auto& v : d) {
      const double white = q * rng.normal();
      v = 1e-6 + arw * rng.normal() + white - last;
      last = white;
    }
    return d;
  }();
  return increments;
}

// Cumulative angle and the Allan curve (2 taus per octave, jackknife blocks):
// the data-size-dependent part.
void BM_AllanCurve10h500Hz(benchmark::State& state) {
  const auto& d = tenHours();
  for (auto _ : state) {
    double mean = 0.0;
    for (double v : d) mean += v;
    mean /= static_cast<double>(d.size());
    const auto phase = fog::noise::cumulativeSum(d, mean);
    auto curve = fog::noise::overlappingAllanCurve(phase, 2e-3);
    benchmark::DoNotOptimize(curve);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(d.size()));
}
BENCHMARK(BM_AllanCurve10h500Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

// The whole characterisation: the curve plus the noise-term fit and its
// jackknife replicates.
void BM_NoiseCharacterisation10h500Hz(benchmark::State& state) {
  const auto& d = tenHours();
  for (auto _ : state) {
    double mean = 0.0;
    for (double v : d) mean += v;
    mean /= static_cast<double>(d.size());
    const auto phase = fog::noise::cumulativeSum(d, mean);
    auto curve = fog::noise::overlappingAllanCurve(phase, 2e-3);
    auto model = fog::noise::identifyNoise(*curve);
    benchmark::DoNotOptimize(model);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(d.size()));
}
BENCHMARK(BM_NoiseCharacterisation10h500Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();

// Benchmarks of the simulator and the delay analysis on the paper's
// conditions. Results and machine in docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include "analysis/delay_analysis.h"
#include "model/simulator.h"
#include "protocol/recording_builder.h"

namespace {

fog::Recording decoded(const fog::TestPlan& plan) {
  auto run = fog::model::simulate(fog::model::SimConfig{}, plan);
  return *fog::protocol::decodeRecording(run->bytes);
}

// Full analysis (3- and 4-parameter fits, joint fit, bound, per-period track)
// of a 4.9-min, 0.1 Hz / 10 deg session: 294k table and 147k IMU samples.
void BM_AnalyzeSlowSession(benchmark::State& state) {
  const fog::Recording rec = decoded(fog::TestPlan::paperSlow());
  for (auto _ : state) {
    auto report = fog::analysis::analyzeRecording(rec, fog::analysis::BenchConstants{});
    benchmark::DoNotOptimize(report);
  }
  state.counters["table_samples"] = static_cast<double>(rec.testPoints[0].table.size());
  state.counters["imu_samples"] = static_cast<double>(rec.testPoints[0].imu.size());
}
BENCHMARK(BM_AnalyzeSlowSession)->Unit(benchmark::kMillisecond)->MinTime(3.0);

void BM_AnalyzeFastSession(benchmark::State& state) {
  const fog::Recording rec = decoded(fog::TestPlan::paperFast());
  for (auto _ : state) {
    auto report = fog::analysis::analyzeRecording(rec, fog::analysis::BenchConstants{});
    benchmark::DoNotOptimize(report);
  }
}
BENCHMARK(BM_AnalyzeFastSession)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Simulator speed: seconds of simulated session per second of wall time.
void BM_SimulateSlowSession(benchmark::State& state) {
  const fog::TestPlan plan = fog::TestPlan::paperSlow();
  double simulatedS = 0.0;
  for (auto _ : state) {
    auto run = fog::model::simulate(fog::model::SimConfig{}, plan);
    benchmark::DoNotOptimize(run);
    simulatedS += plan.totalDurationS() + plan.restBetweenS;
  }
  state.counters["x_real_time"] = benchmark::Counter(simulatedS, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulateSlowSession)->Unit(benchmark::kMillisecond)->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();

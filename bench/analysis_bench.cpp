// Benchmarks of the simulator and the delay analysis on the paper's
// conditions. Results and machine in docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "core/analysis/channels.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/frequency_response.h"
#include "core/analysis/joint_fit.h"
#include "core/analysis/sine_fit.h"
#include "core/analysis/validity.h"
#include "core/common/units.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

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
    auto report = fog::analysis::analyzeRecording(rec, fog::BenchConstants{});
    benchmark::DoNotOptimize(report);
  }
  state.counters["table_samples"] = static_cast<double>(rec.testPoints[0].table.size());
  state.counters["imu_samples"] = static_cast<double>(rec.testPoints[0].imu.size());
}
// CPU is the process's (both threads of the analysis): on a shared machine
// it is steadier than the wall time, which is what a quiet machine shows.
BENCHMARK(BM_AnalyzeSlowSession)->Unit(benchmark::kMillisecond)->MinTime(3.0)->MeasureProcessCPUTime();

// The user's path for a frequency response of one axis (issue 32): the
// delay analysis of the 20-point `--preset response` session (0.05 .. 11 Hz,
// 670 s: 670k table and 335k IMU samples), then the per-point gains and the
// three models. Aim: <= 1 s.
void BM_AnalyzeResponseSession(benchmark::State& state) {
  const fog::Recording rec = decoded(*fog::presetPlan("response"));
  std::size_t models = 0;
  for (auto _ : state) {
    auto report = fog::analysis::analyzeRecording(rec, fog::BenchConstants{});
    auto responses = fog::analysis::analyzeResponses(*report, 5.0);
    models = responses.empty() ? 0 : responses.front().models.size();
    benchmark::DoNotOptimize(responses);
  }
  state.counters["points"] = static_cast<double>(rec.testPoints.size());
  state.counters["models"] = static_cast<double>(models);
}
BENCHMARK(BM_AnalyzeResponseSession)->Unit(benchmark::kMillisecond)->MinTime(3.0);

// The models alone, from the 20 points (what `response` adds to `analyze`).
void BM_FitResponseModels(benchmark::State& state) {
  const fog::Recording rec = decoded(*fog::presetPlan("response"));
  const auto report = fog::analysis::analyzeRecording(rec, fog::BenchConstants{});
  const auto points = fog::analysis::responsePoints(*report, fog::Axis::kX);
  for (auto _ : state) benchmark::DoNotOptimize(fog::analysis::analyzeResponse(points, fog::Axis::kX, 5.0));
}
BENCHMARK(BM_FitResponseModels)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_AnalyzeFastSession(benchmark::State& state) {
  const fog::Recording rec = decoded(fog::TestPlan::paperFast());
  for (auto _ : state) {
    auto report = fog::analysis::analyzeRecording(rec, fog::BenchConstants{});
    benchmark::DoNotOptimize(report);
  }
}
BENCHMARK(BM_AnalyzeFastSession)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The stages of the slow session's analysis, one at a time, each from the
// inputs analyzeTestPoint gives it (some of them run concurrently there).
struct SlowStages {
  fog::TestPointData data;
  double w0 = 0.0;
  fog::analysis::Channels ch;
  fog::analysis::SineFit tableLinear, table4, gyroStart, gyro4;
  SlowStages() {
    const fog::Recording rec = decoded(fog::TestPlan::paperSlow());
    data = rec.testPoints[0];
    w0 = fog::kTwoPi * data.nominalFrequencyHz;
    ch = *fog::analysis::makeChannels(data, 1.0);  // in degrees, gyro sign +1
    tableLinear = fog::analysis::fitTableLinear(ch.table, w0, ch.referenceS);
    ch.table.noiseDeg = tableLinear.residualRmsDeg;
    table4 = *fog::analysis::fitTableNonlinear(ch.table, tableLinear);
    ch.table.noiseDeg = table4.residualRmsDeg;
    gyroStart = fog::analysis::fitGyroLinear(ch.gyro, table4.omegaRadPerS, ch.referenceS, false);
    fog::analysis::estimateGyroNoise(ch.gyro, fog::analysis::gyroIncrementResiduals(ch.gyro, gyroStart),
                                     std::clamp(0.05 / data.nominalFrequencyHz, 0.05, 1.0));
    gyro4 = *fog::analysis::fitGyroNonlinear(ch.gyro, gyroStart);
  }
};
const SlowStages& slowStages() {
  static const SlowStages s;
  return s;
}

void BM_StageChannels(benchmark::State& state) {
  const auto& s = slowStages();
  for (auto _ : state) benchmark::DoNotOptimize(fog::analysis::makeChannels(s.data, 1.0));
}
BENCHMARK(BM_StageChannels)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageLinearFits(benchmark::State& state) {  // table, gyro unweighted, gyro weighted
  const auto& s = slowStages();
  for (auto _ : state) {
    benchmark::DoNotOptimize(fog::analysis::fitTableLinear(s.ch.table, s.w0, s.ch.referenceS));
    benchmark::DoNotOptimize(fog::analysis::fitGyroLinear(s.ch.gyro, s.w0, s.ch.referenceS, false));
    benchmark::DoNotOptimize(fog::analysis::fitGyroLinear(s.ch.gyro, s.w0, s.ch.referenceS, true));
  }
}
BENCHMARK(BM_StageLinearFits)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageGyroNoise(benchmark::State& state) {
  const auto& s = slowStages();
  for (auto _ : state) {
    fog::analysis::GyroChannel gyro = s.ch.gyro;
    fog::analysis::estimateGyroNoise(gyro, fog::analysis::gyroIncrementResiduals(gyro, s.gyroStart), 0.5);
    benchmark::DoNotOptimize(gyro);
  }
}
BENCHMARK(BM_StageGyroNoise)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageTableNonlinear(benchmark::State& state) {
  const auto& s = slowStages();
  fog::analysis::TableChannel table = s.ch.table;
  table.noiseDeg = s.tableLinear.residualRmsDeg;
  for (auto _ : state) benchmark::DoNotOptimize(fog::analysis::fitTableNonlinear(table, s.tableLinear));
}
BENCHMARK(BM_StageTableNonlinear)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageGyroNonlinear(benchmark::State& state) {
  const auto& s = slowStages();
  for (auto _ : state) benchmark::DoNotOptimize(fog::analysis::fitGyroNonlinear(s.ch.gyro, s.gyroStart));
}
BENCHMARK(BM_StageGyroNonlinear)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageJoint(benchmark::State& state) {
  const auto& s = slowStages();
  for (auto _ : state) benchmark::DoNotOptimize(fog::analysis::fitJoint(s.ch, s.table4, s.gyro4));
}
BENCHMARK(BM_StageJoint)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The checks' passes over the 4-parameter fits' table residual: the
// repeating errors' covariance (every period lag, folded by phase), and the
// harmonics 2..5 (a 9-column fit).
void BM_StagePeriodicInflation(benchmark::State& state) {
  const auto& s = slowStages();
  const auto residual = fog::analysis::tableResiduals(s.ch.table, s.table4);
  for (auto _ : state)
    benchmark::DoNotOptimize(fog::analysis::periodicErrorCovariance(s.ch.table.timeS, residual, s.table4.omegaRadPerS,
                                                                    s.table4.a, s.table4.b,
                                                                    fog::analysis::SampleStream::kTable));
}
BENCHMARK(BM_StagePeriodicInflation)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_StageHarmonics(benchmark::State& state) {
  const auto& s = slowStages();
  const auto residual = fog::analysis::tableResiduals(s.ch.table, s.table4);
  for (auto _ : state)
    benchmark::DoNotOptimize(fog::analysis::harmonicAmplitude(s.ch.table.timeS, residual, s.table4.omegaRadPerS,
                                                              fog::analysis::SampleStream::kTable));
}
BENCHMARK(BM_StageHarmonics)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

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

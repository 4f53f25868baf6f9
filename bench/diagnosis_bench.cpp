// Sim-to-real gap diagnosis (docs/diagnosis.md): a whole diagnose() of a
// 4.9-min session (0.1 Hz / 10 deg on X, the paper's slow point) and of one
// blind-check session (three points, 129 s), clean, and of the 4.9-min
// session with a first-order lag (the slowest case). Target: a 5-min session in
// under 5 s. Each diagnosis runs 30 replays of the session on the simulator
// (4 for the Monte Carlo spread, 26 for the effect signatures) plus the
// exact evaluation of the best three effects.

#include <benchmark/benchmark.h>

#include "core/common/memory.h"

#include "core/common/test_plan.h"
#include "core/diagnosis/blind_check.h"
#include "core/diagnosis/diagnosis.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace {

fog::Recording sessionOf(const fog::TestPlan& plan, double lagMs) {
  fog::model::SimConfig config;
  config.seed = 7;
  std::vector<std::unique_ptr<fog::model::Effect>> effects;
  if (lagMs > 0.0) effects.push_back(fog::diagnosis::makeEffect(fog::diagnosis::EffectId::kFirstOrderLag, {lagMs}));
  auto run = fog::model::simulate(config, plan, std::move(effects));
  return *fog::protocol::decodeRecording(run->bytes);
}

void diagnoseSession(benchmark::State& state, const fog::TestPlan& plan, double lagMs = 0.0) {
  const fog::Recording recording = sessionOf(plan, lagMs);
  fog::SessionInfo info;
  info.plan = plan;
  fog::diagnosis::DiagnosisOptions options;
  options.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto d = fog::diagnosis::diagnose(recording, &info, {}, options);
    if (!d) state.SkipWithError(d.status().toString().c_str());
    benchmark::DoNotOptimize(d);
  }
}

void BM_Diagnose4_9MinSession(benchmark::State& state) { diagnoseSession(state, fog::TestPlan::paperSlow()); }
BENCHMARK(BM_Diagnose4_9MinSession)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// The slowest case: a first-order lag (20 ms) among the best three is
// refined with Ceres on the forward model (a replay per evaluation).
void BM_Diagnose4_9MinSessionWith20msLag(benchmark::State& state) {
  diagnoseSession(state, fog::TestPlan::paperSlow(), 20.0);
}
BENCHMARK(BM_Diagnose4_9MinSessionWith20msLag)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_DiagnoseBlindCheckSession(benchmark::State& state) {
  diagnoseSession(state, fog::diagnosis::blindCheckPlan());
}
BENCHMARK(BM_DiagnoseBlindCheckSession)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

int main(int argc, char** argv) {
  fog::keepFreedMemoryForReuse();  // as the CLI and the GUI do
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

#include "ui/bench_presets.h"

namespace fog::ui {

namespace {

TestPlan paperPlan() {
  TestPlan plan = TestPlan::paperSlow();
  plan.points.push_back(TestPlan::paperFast().points.front());
  return plan;
}

TestPlan quickPlan() {
  TestPlan plan = TestPlan::paperFast();
  plan.points.front().durationS = 20.0;
  return plan;
}

}  // namespace

const std::vector<BenchPreset>& benchPresets() {
  static const std::vector<BenchPreset> presets = {
      {"paper", "Paper: 0.1 Hz / 10° 294 s + 1 Hz / 3° 60 s", paperPlan()},
      {"paper-slow", "Paper slow: 0.1 Hz / 10°, 294 s", TestPlan::paperSlow()},
      {"paper-fast", "Paper fast: 1 Hz / 3°, 60 s", TestPlan::paperFast()},
      {"quick", "Quick: 1 Hz / 3°, 20 s", quickPlan()},
  };
  return presets;
}

std::optional<BenchPreset> findBenchPreset(const QString& name) {
  for (const auto& p : benchPresets())
    if (p.name == name) return p;
  return std::nullopt;
}

}  // namespace fog::ui

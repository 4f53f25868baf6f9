#include "ui/bench_presets.h"

#include <QCoreApplication>

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
      {"paper", QT_TRANSLATE_NOOP("BenchPreset", "Paper: 0.1 Hz / 10° 294 s + 1 Hz / 3° 60 s"), paperPlan()},
      {"paper-slow", QT_TRANSLATE_NOOP("BenchPreset", "Paper slow: 0.1 Hz / 10°, 294 s"), TestPlan::paperSlow()},
      {"paper-fast", QT_TRANSLATE_NOOP("BenchPreset", "Paper fast: 1 Hz / 3°, 60 s"), TestPlan::paperFast()},
      {"quick", QT_TRANSLATE_NOOP("BenchPreset", "Quick: 1 Hz / 3°, 20 s"), quickPlan()},
  };
  return presets;
}

QString BenchPreset::displayLabel() const {
  // lupdate files the labels under "BenchPreset"; the translation scripts
  // qualify every context with the namespace.
  return QCoreApplication::translate("fog::ui::BenchPreset", label.toUtf8().constData());
}

std::optional<BenchPreset> findBenchPreset(const QString& name) {
  for (const auto& p : benchPresets())
    if (p.name == name) return p;
  return std::nullopt;
}

}  // namespace fog::ui

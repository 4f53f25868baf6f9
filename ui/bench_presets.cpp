#include "ui/bench_presets.h"

#include <QCoreApplication>

namespace fog::ui {

const std::vector<BenchPreset>& benchPresets() {
  // The plans are core's (the command line offers the same names); the
  // labels are the GUI's.
  static const std::vector<BenchPreset> presets = [] {
    const std::pair<const char*, const char*> labels[] = {
        {"paper", QT_TRANSLATE_NOOP("BenchPreset", "Paper: 0.1 Hz / 10° 294 s + 1 Hz / 3° 60 s")},
        {"paper-slow", QT_TRANSLATE_NOOP("BenchPreset", "Paper slow: 0.1 Hz / 10°, 294 s")},
        {"paper-fast", QT_TRANSLATE_NOOP("BenchPreset", "Paper fast: 1 Hz / 3°, 60 s")},
        {"quick", QT_TRANSLATE_NOOP("BenchPreset", "Quick: 1 Hz / 3°, 20 s")},
        {"noise", QT_TRANSLATE_NOOP("BenchPreset", "Gyro noise: 10 min at rest on X, then 1 Hz / 3°, 60 s")},
        {"response", QT_TRANSLATE_NOOP("BenchPreset", "Frequency response: X, 20 frequencies 0.05 – 11 Hz, 11 min")},
        {"response-third-octave",
         QT_TRANSLATE_NOOP("BenchPreset", "Frequency response, standard: X, 21 one-third octaves 0.1 – 10 Hz, 7.6 min")}};
    std::vector<BenchPreset> all;
    for (const auto& name : presetPlanNames()) {
      QString label = QString::fromStdString(name);
      for (const auto& [key, text] : labels)
        if (name == key) label = text;
      all.push_back({QString::fromStdString(name), label, *presetPlan(name)});
    }
    return all;
  }();
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

#pragma once
// The test plans offered in the bench's preset selector.

#include <QString>
#include <optional>
#include <vector>

#include "core/common/test_plan.h"

namespace fog::ui {

struct BenchPreset {
  QString name;   // as given on the command line: "paper", "quick", ...
  QString label;  // English, as in the source; see displayLabel()
  TestPlan plan;
  // The label in the GUI's language.
  QString displayLabel() const;
};

// fog::presetPlanNames() in their order (the first is the default), each
// with its plan (fog::presetPlan) and a label for the selector.
const std::vector<BenchPreset>& benchPresets();

// The preset called `name`, or nothing.
std::optional<BenchPreset> findBenchPreset(const QString& name);

}  // namespace fog::ui

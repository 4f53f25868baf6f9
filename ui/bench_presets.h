#pragma once
// The test plans offered in the bench's preset selector.

#include <QString>
#include <optional>
#include <vector>

#include "common/test_plan.h"

namespace fog::ui {

struct BenchPreset {
  QString name;   // as given on the command line: "paper", "quick", ...
  QString label;  // English, as in the source; see displayLabel()
  TestPlan plan;
  // The label in the GUI's language.
  QString displayLabel() const;
};

// In display order; the first is the default.
//   paper       the paper's two conditions: 0.1 Hz / 10 deg 294 s, then 1 Hz / 3 deg 60 s
//   paper-slow  0.1 Hz / 10 deg, 294 s
//   paper-fast  1 Hz / 3 deg, 60 s
//   quick       1 Hz / 3 deg, 20 s: a result in seconds
const std::vector<BenchPreset>& benchPresets();

// The preset called `name`, or nothing.
std::optional<BenchPreset> findBenchPreset(const QString& name);

}  // namespace fog::ui

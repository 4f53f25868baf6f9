#pragma once
// The bench constants dialog: table read delay, processing-board delay (each
// with its standard uncertainty), latitude, pulse equivalent and the sampling
// board's counter frequency. What the operator sets is remembered between
// runs (QSettings, group "bench").

#include <QDialog>

#include "core/common/session_info.h"

class QDoubleSpinBox;
class QSpinBox;
class QLabel;

namespace fog::ui {

// The remembered constants (defaults: the paper's) and storing new ones.
BenchSettings loadBenchSettings();
void saveBenchSettings(const BenchSettings& settings);

class BenchSettingsDialog : public QDialog {
  Q_OBJECT

 public:
  explicit BenchSettingsDialog(const BenchSettings& settings, QWidget* parent = nullptr);
  BenchSettings settings() const;

 private:
  QDoubleSpinBox* readDelay_ = nullptr;
  QDoubleSpinBox* readDelayStd_ = nullptr;
  QDoubleSpinBox* boardDelay_ = nullptr;
  QDoubleSpinBox* boardDelayStd_ = nullptr;
  QDoubleSpinBox* latitude_ = nullptr;
  QDoubleSpinBox* pulseEquivalent_ = nullptr;
  QDoubleSpinBox* counterMHz_ = nullptr;
  QSpinBox* counterBits_ = nullptr;
};

}  // namespace fog::ui

#pragma once
// The bench constants dialog: table read delay, processing-board delay (each
// with its standard uncertainty), latitude, pulse equivalent, the sampling
// board's counter frequency and the gyro's scale tolerance (the gain check); and the analysis settings the CLI takes as
// --gyro-sign, --limit-ms and --coverage-k (the sense of each gyro axis, the
// acceptance limit and the decision rule's k). What the operator sets is remembered between runs (QSettings,
// groups "bench" and "analysis"); every run and re-analysis stores them with
// its result (session::analysisSettingsJson).

#include <QDialog>
#include <array>

#include "core/common/session_info.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QLabel;

namespace fog::ui {

// The remembered constants (defaults: the paper's) and storing new ones.
BenchConstants loadBenchConstants();
void saveBenchConstants(const BenchConstants& settings);

// What the analysis is told besides the bench constants (the CLI's
// --gyro-sign, --limit-ms and --coverage-k). Defaults: every gyro axis +1,
// 0.8 ms, k = 2.
struct AnalysisChoices {
  std::array<int, kAxisCount> gyroSign{1, 1, 1};
  double imuDelayLimitMs = 0.8;
  // The decision rule's coverage factor: PASS when IMU delay + k sigma < the
  // limit (analysis/decision_rule.h), stored with every result.
  double coverageK = 2.0;
};
AnalysisChoices loadAnalysisChoices();
void saveAnalysisChoices(const AnalysisChoices& choices);

class BenchSettingsDialog : public QDialog {
  Q_OBJECT

 public:
  BenchSettingsDialog(const BenchConstants& settings, const AnalysisChoices& choices, QWidget* parent = nullptr);
  BenchConstants settings() const;
  AnalysisChoices analysisChoices() const;
  // OK: accepted only when checkBenchConstants passes; otherwise its message
  // is shown in the dialog (objectName "benchConstantsProblem") and it stays open.
  void accept() override;

 private:
  QDoubleSpinBox* readDelay_ = nullptr;
  QDoubleSpinBox* readDelayStd_ = nullptr;
  QDoubleSpinBox* boardDelay_ = nullptr;
  QDoubleSpinBox* boardDelayStd_ = nullptr;
  QDoubleSpinBox* latitude_ = nullptr;
  QDoubleSpinBox* pulseEquivalent_ = nullptr;
  QDoubleSpinBox* counterMHz_ = nullptr;
  QSpinBox* counterBits_ = nullptr;
  QDoubleSpinBox* gainTolerance_ = nullptr;  // percent: BenchConstants::gainToleranceFraction x 100
  std::array<QComboBox*, kAxisCount> gyroSign_{};
  QComboBox* imuFrame_ = nullptr;            // convention, or not stated
  QDoubleSpinBox* forwardHeading_ = nullptr;  // FRD / RFU; its minimum reads "not stated"
  QDoubleSpinBox* limit_ = nullptr;
  QDoubleSpinBox* coverageK_ = nullptr;
  QLabel* coverageRisk_ = nullptr;  // the rule's maximum false-accept risk at the k set
  QLabel* problem_ = nullptr;  // what checkBenchConstants refused, when OK was pressed
};

}  // namespace fog::ui

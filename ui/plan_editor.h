#pragma once
// The test plan editor: one row per test point (a swing, or a static segment
// with the table at rest for the gyro's noise; axis, swing frequency,
// amplitude, duration in seconds or whole periods, settle time), rows added,
// removed and reordered, the paper's conditions as presets. Every row is
// checked against the turntable's limits as it is edited; a bad value is
// explained in the row itself (and in the tooltip of the field), and the plan
// is only valid when every row is.

#include <QString>
#include <QWidget>
#include <vector>

#include "core/common/test_plan.h"
#include "core/table/table_controller.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace fog::ui {

class PlanEditor : public QWidget {
  Q_OBJECT

 public:
  // Columns of the table.
  enum Column { kKind = 0, kAxis, kFrequency, kAmplitude, kDuration, kPeriods, kSettle, kCheck, kColumnCount };

  explicit PlanEditor(QWidget* parent = nullptr);

  // One thing wrong with a test point and the field it is about (kCheck:
  // none in particular).
  struct PointProblem {
    Column column;
    QString text;
  };
  // Every problem of one test point, not only the first
  // (TestPoint::problems), each by its column, in the GUI's language and
  // units (coreText). Empty exactly when TestPoint::validate is ok.
  static std::vector<PointProblem> pointProblems(const TestPoint& p, const TurntableLimits& limits);

  void setPlan(const TestPlan& plan);
  // The plan as edited (also when invalid).
  TestPlan plan() const;
  bool isValid() const { return problem_.isEmpty(); }
  // Empty when valid; otherwise every problem, one a line ("test point 2: ...").
  QString problem() const { return problem_; }
  // Loads the preset called `name` (see benchPresets()); false if unknown.
  bool loadPreset(const QString& name);
  // The limits each point is checked against, its axis's (the simulator's
  // turntable until the Configure view says otherwise).
  void setLimits(const table::TableLimits& limits);
  void setReadOnly(bool readOnly);

  QTableWidget* table() const { return table_; }
  // The editor of a cell (a QComboBox for kKind and kAxis, QDoubleSpinBox otherwise).
  QWidget* cellEditor(int row, Column column) const;

 signals:
  void planChanged();
  void validityChanged(bool valid, const QString& problem);

 private:
  void addRow(const TestPoint& point);
  void removeSelectedRow();
  void moveSelectedRow(int by);
  void syncPeriods(int row, Column edited);
  void validate();
  // Selects the preset the plan is, or "custom plan" when it is none.
  void showPresetOfPlan();
  TestPoint rowPoint(int row) const;
  QDoubleSpinBox* spin(int row, Column column) const;

  table::TableLimits limits_;
  QTableWidget* table_ = nullptr;
  QComboBox* presetCombo_ = nullptr;
  QDoubleSpinBox* restSpin_ = nullptr;
  QLabel* summary_ = nullptr;
  QPushButton* addButton_ = nullptr;
  QPushButton* removeButton_ = nullptr;
  QPushButton* upButton_ = nullptr;
  QPushButton* downButton_ = nullptr;
  QString problem_;
  QString shownPreset_;  // the preset the plan is; empty: a custom plan
  bool syncing_ = false;
};

}  // namespace fog::ui

#pragma once
// What the table is asked to do, point by point (issue 17): the angle range
// (position ± amplitude), the peak rate 2πfA and the peak acceleration
// (2πf)²A of the swing axis, each beside its axis's limit and flagged (red,
// with a tooltip saying which limit) when beyond it. Whose limits they are is
// set by the Configure view (ConfigureView::setConnectedTable): the
// connected controller's as it reported them, else the simulator's turntable
// (TurntableLimits defaults, positions within ±kMaxPositionDeg); the label
// above the table names them.

#include <QWidget>

#include "core/common/test_plan.h"
#include "core/table/table_controller.h"

class QLabel;
class QTableWidget;

namespace fog::ui {

// The simulator's turntable: TurntableLimits' defaults on every axis,
// positions within ±kMaxPositionDeg.
table::TableLimits simulatorLimits();

class CommandedMotionTable : public QWidget {
  Q_OBJECT

 public:
  enum Column { kPoint = 0, kAxis, kFrequency, kAngle, kRate, kAccel, kColumnCount };

  explicit CommandedMotionTable(QWidget* parent = nullptr);

  void setPlan(const TestPlan& plan);
  // `source` says whose limits they are ("the simulator's turntable").
  void setLimits(const table::TableLimits& limits, const QString& source);
  QString limitsText() const;

  QTableWidget* table() const { return table_; }
  // Cells beyond a limit, over the whole plan.
  int flaggedCells() const { return flagged_; }

 private:
  void rebuild();

  TestPlan plan_;
  table::TableLimits limits_ = simulatorLimits();
  QString source_;
  QLabel* limitsLabel_ = nullptr;
  QTableWidget* table_ = nullptr;
  int flagged_ = 0;
};

}  // namespace fog::ui

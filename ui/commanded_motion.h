#pragma once
// What the table is asked to do, point by point (issue 17): the angle range
// (position ± amplitude), the peak rate 2πfA and the peak acceleration
// (2πf)²A of the swing axis, each beside the table's limit and flagged (red,
// with a tooltip saying which limit) when beyond it. The limits are the
// table controller's when one is connected, else the simulator's turntable
// (TurntableLimits defaults, positions within ±kMaxPositionDeg).

#include <QWidget>

#include "core/common/test_plan.h"

class QLabel;
class QTableWidget;

namespace fog::ui {

class CommandedMotionTable : public QWidget {
  Q_OBJECT

 public:
  enum Column { kPoint = 0, kAxis, kFrequency, kAngle, kRate, kAccel, kColumnCount };

  explicit CommandedMotionTable(QWidget* parent = nullptr);

  void setPlan(const TestPlan& plan);
  // `source` says whose limits they are ("the simulator's turntable").
  void setLimits(const TurntableLimits& limits, double maxPositionDeg, const QString& source);

  QTableWidget* table() const { return table_; }
  // Cells beyond a limit, over the whole plan.
  int flaggedCells() const { return flagged_; }

 private:
  void rebuild();

  TestPlan plan_;
  TurntableLimits limits_;
  double maxPositionDeg_ = kMaxPositionDeg;
  QString source_;
  QLabel* limitsLabel_ = nullptr;
  QTableWidget* table_ = nullptr;
  int flagged_ = 0;
};

}  // namespace fog::ui

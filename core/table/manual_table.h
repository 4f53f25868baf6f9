#pragma once
// The manual driver: a table the bench cannot command. Each command becomes
// an instruction to the operator ("On the table controller: set X to swing
// at 1 Hz, 3 deg amplitude about 0 deg, and start it"); the state is
// unknown (TableState::known = false), so the plan runner relies on the
// board's table-angle stream instead: StreamPointRecorder checks that the
// motion is what the plan says before a point is recorded, and that the axis
// is at rest after "stop". Limits are the ones given (the table's data sheet;
// TurntableLimits defaults otherwise).
//
// Never fails except where the operator sink does; not thread-safe.

#include <functional>
#include <string>

#include "core/table/table_controller.h"

namespace fog::table {

class ManualTable : public TableController {
 public:
  // `tell` shows one instruction to the operator (the terminal, a dialog).
  explicit ManualTable(std::function<void(const std::string&)> tell, TableLimits limits = {})
      : tell_(std::move(tell)), limits_(limits) {}

  std::string description() const override { return "manual (the operator sets the table controller)"; }
  Result<std::string> identify() override { return std::string("manual table (operator)"); }
  Result<TableLimits> limits() override { return limits_; }
  Result<TableState> state() override {
    TableState s;
    s.known = false;
    return s;
  }
  Status configureSwing(Axis axis, const SwingSpec& swing) override;
  Status moveTo(Axis axis, double positionDeg) override;
  Status startSwing(Axis axis) override;
  Status stop(Axis axis) override;
  Status stopAll() override;
  Status emergencyStop() override;
  Status keepAlive() override { return Status::ok(); }

 private:
  std::function<void(const std::string&)> tell_;
  TableLimits limits_;
  SwingSpec pending_;
};

}  // namespace fog::table

#include "core/table/manual_table.h"

#include "core/table/scpi.h"

namespace fog::table {

Status ManualTable::configureSwing(Axis, const SwingSpec& swing) {
  pending_ = swing;
  return Status::ok();
}

Status ManualTable::moveTo(Axis axis, double positionDeg) {
  tell_(std::string("On the table controller: bring the ") + axisLabel(axis) + " axis to " +
        scpi::formatNumber(positionDeg) + " deg and hold it at rest.");
  return Status::ok();
}

Status ManualTable::startSwing(Axis axis) {
  tell_(std::string("On the table controller: set the ") + axisLabel(axis) + " axis to swing sinusoidally at " +
        scpi::formatNumber(pending_.frequencyHz) + " Hz, amplitude " + scpi::formatNumber(pending_.amplitudeDeg) +
        " deg about " + scpi::formatNumber(pending_.centreDeg) + " deg" +
        (pending_.startPhaseDeg != 0.0
             ? ", starting at phase " + scpi::formatNumber(pending_.startPhaseDeg) +
                   " deg (angle = centre + amplitude * sin(2 pi f t + phase))"
             : std::string()) +
        ", and start it. The bench records once the table-angle stream shows that swing.");
  return Status::ok();
}

Status ManualTable::stop(Axis axis) {
  tell_(std::string("On the table controller: stop the ") + axisLabel(axis) + " axis and let it come to rest.");
  return Status::ok();
}

Status ManualTable::stopAll() {
  tell_("On the table controller: stop every axis and let the table come to rest.");
  return Status::ok();
}

Status ManualTable::emergencyStop() {
  tell_("EMERGENCY: stop the table now (emergency stop button).");
  return Status::ok();
}

}  // namespace fog::table

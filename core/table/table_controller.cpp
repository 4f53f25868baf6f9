#include "core/table/table_controller.h"

#include <cmath>
#include <cstdio>

#include "core/common/units.h"

namespace fog::table {

namespace {
std::string num(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
}  // namespace

const char* axisModeName(AxisMode mode) {
  switch (mode) {
    case AxisMode::kRest: return "rest";
    case AxisMode::kPositioning: return "positioning";
    case AxisMode::kSwinging: return "swinging";
    case AxisMode::kStopping: return "stopping";
    case AxisMode::kEmergencyStop: return "emergency-stop";
    case AxisMode::kUnknown: return "unknown";
  }
  return "unknown";
}

std::string TableState::blockingReason() const {
  std::string r;
  auto add = [&](const std::string& s) { r += (r.empty() ? "" : ", ") + s; };
  if (emergencyStopped) add("emergency stop engaged");
  if (interlockOpen) add("interlock open");
  if (heartbeatLost) add("heartbeat lost (the controller stopped the table)");
  for (const auto& f : faults) add("fault " + f);
  return r;
}

Status checkPositionAgainstLimits(Axis axis, double positionDeg, const TableLimits& limits) {
  if (!std::isfinite(positionDeg))
    return invalidArgument(std::string(axisLabel(axis)) + " position is not a number; the table was not moved");
  if (std::abs(positionDeg) > limits.maxPositionDeg)
    return outOfRange(std::string(axisLabel(axis)) + " position " + num(positionDeg) + " deg is beyond the table's +-" +
                      num(limits.maxPositionDeg) + " deg; the table was not moved");
  return Status::ok();
}

Status checkPlanAgainstLimits(const TestPlan& plan, const TableLimits& limits) {
  if (plan.points.empty()) return invalidArgument("the plan has no test points");
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const TestPoint& p = plan.points[i];
    const auto& l = limits.axes[static_cast<std::size_t>(p.axis)];
    const std::string head = "test point " + std::to_string(i + 1) + " (" + axisLabel(p.axis) + " " +
                             num(p.frequencyHz) + " Hz / " + num(p.amplitudeDeg) + " deg): ";
    const std::string tail = std::string(" on ") + axisLabel(p.axis) + "; the plan was refused before any motion";
    for (int a = 0; a < kAxisCount; ++a)
      if (!std::isfinite(p.positionDeg[static_cast<std::size_t>(a)]) ||
          std::abs(p.positionDeg[static_cast<std::size_t>(a)]) > limits.maxPositionDeg)
        return outOfRange(head + "table position " + num(p.positionDeg[static_cast<std::size_t>(a)]) + " deg of " +
                          axisLabel(static_cast<Axis>(a)) + " is beyond the table's +-" + num(limits.maxPositionDeg) +
                          " deg; the plan was refused before any motion");
    if (p.isStatic()) continue;
    if (!(p.frequencyHz > 0.0) || !(p.amplitudeDeg > 0.0) || !std::isfinite(p.frequencyHz) ||
        !std::isfinite(p.amplitudeDeg))
      return invalidArgument(head + "frequency and amplitude must be > 0");
    const double w = kTwoPi * p.frequencyHz;
    const double rate = w * p.amplitudeDeg, accel = w * w * p.amplitudeDeg;
    if (p.amplitudeDeg > l.maxAmplitudeDeg)
      return outOfRange(head + "amplitude is beyond the table's " + num(l.maxAmplitudeDeg) + " deg" + tail);
    if (std::abs(p.positionDeg[static_cast<std::size_t>(p.axis)]) + p.amplitudeDeg > limits.maxPositionDeg)
      return outOfRange(head + "the swing leaves the table's +-" + num(limits.maxPositionDeg) + " deg" + tail);
    if (p.frequencyHz > l.maxFrequencyHz)
      return outOfRange(head + "frequency is beyond the table's " + num(l.maxFrequencyHz) + " Hz" + tail);
    if (rate > l.maxRateDegPerS)
      return outOfRange(head + "peak rate " + num(rate) + " deg/s is beyond the table's " + num(l.maxRateDegPerS) +
                        " deg/s" + tail);
    if (accel > l.maxAccelDegPerS2)
      return outOfRange(head + "peak acceleration " + num(accel) + " deg/s^2 is beyond the table's " +
                        num(l.maxAccelDegPerS2) + " deg/s^2" + tail);
  }
  return Status::ok();
}

}  // namespace fog::table

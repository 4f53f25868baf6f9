#pragma once
// The turntable as the bench drives it: one interface for every way a table
// can be commanded (a controller on a serial line or TCP speaking the remote
// protocol of docs/table-control.md, an operator told what to set, a fake in
// tests). Qt-free; units are in the names (Hz, deg, deg/s, s).
//
// Contracts for implementations:
//  - No exception crosses this interface: every call returns a Status or a
//    Result. A call that cannot reach the controller (link lost, no reply
//    within the implementation's bounded timeout, a malformed reply) returns
//    kIoError / kCorruptData with a message that names the controller; a
//    command the controller refuses returns kInvalidArgument / kOutOfRange
//    with the controller's own reason.
//  - Every call returns within a bounded time (the implementation's reply
//    timeout); none waits for motion to finish: moveTo(), startSwing() and
//    stop() start a motion and return; state() says where it stands.
//  - stop() brings the axis to rest with bounded deceleration (the
//    controller's acceleration limit); emergencyStop() stops every axis at
//    once and latches until the controller is reset by hand.
//  - Not thread-safe: one thread drives a controller (the plan runner).
//  - keepAlive() tells the controller the host is still there; a controller
//    with a heartbeat timeout brings the table to rest when the host is
//    quiet longer than that (docs/table-control.md, "Heartbeat").

#include <array>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/test_plan.h"

namespace fog::table {

enum class AxisMode {
  kRest = 0,         // not moving, holding its position
  kPositioning = 1,  // moving to a commanded position
  kSwinging = 2,     // running its sinusoidal swing
  kStopping = 3,     // decelerating to rest
  kEmergencyStop = 4,  // stopped by an emergency stop (latched)
  kUnknown = 5,      // the driver cannot tell (an operator-set table)
};
const char* axisModeName(AxisMode mode);  // "rest", "positioning", ...

// angle = centreDeg + amplitudeDeg * sin(2*pi*frequencyHz*(t - t_start) + startPhaseDeg)
// once the amplitude has ramped up (the axis starts from rest at its centre).
struct SwingSpec {
  double frequencyHz = 1.0;
  double amplitudeDeg = 3.0;
  double centreDeg = 0.0;
  double startPhaseDeg = 0.0;  // the plan's TestPoint::startPhaseDeg
};

struct AxisState {
  AxisMode mode = AxisMode::kUnknown;
  double positionDeg = 0.0;
  double rateDegPerS = 0.0;
};

struct TableState {
  std::array<AxisState, kAxisCount> axes{};
  bool interlockOpen = false;    // a door, a guard: no motion while open
  bool emergencyStopped = false; // latched until reset by hand
  bool heartbeatLost = false;    // the controller stopped the table: host was quiet too long
  std::vector<std::string> faults;  // the controller's own fault names, empty when none
  bool known = true;             // false: the driver cannot read the table (operator-set)

  const AxisState& axis(Axis a) const { return axes[static_cast<std::size_t>(a)]; }
  // Interlock, emergency stop, heartbeat or a named fault: "interlock open", ...
  // Empty when the table may move.
  std::string blockingReason() const;
};

// Per-axis limits as the controller reports them (the plan is checked
// against these before anything moves).
struct TableLimits {
  std::array<TurntableLimits, kAxisCount> axes{};
  double maxPositionDeg = 180.0;  // |centre| and |centre| + amplitude must stay within
};

class TableController {
 public:
  virtual ~TableController() = default;
  // "remote tcp:127.0.0.1:5025 (fogbench,table-emu,0,0.1.0)", "manual (operator)".
  virtual std::string description() const = 0;
  virtual Result<std::string> identify() = 0;
  virtual Result<TableLimits> limits() = 0;
  virtual Result<TableState> state() = 0;
  virtual Status configureSwing(Axis axis, const SwingSpec& swing) = 0;
  virtual Status moveTo(Axis axis, double positionDeg) = 0;
  virtual Status startSwing(Axis axis) = 0;
  virtual Status stop(Axis axis) = 0;
  virtual Status stopAll() = 0;
  virtual Status emergencyStop() = 0;
  virtual Status keepAlive() = 0;
  // The host is done and has seen the table at rest: the controller may stop
  // watching for heartbeats (a remote controller's timeout is set to 0). Not
  // called after a failure, so a host that lost track of the table leaves
  // the watchdog armed.
  virtual Status release() { return Status::ok(); }
  // Seconds from startSwing() until the swing runs at its full amplitude
  // (the controller's ramp). The runner starts a point's settle time after
  // it, so the plan's settleS is steady swing as in the simulator. 0 when
  // the driver cannot tell (an operator-set table: the stream check decides).
  virtual double swingRampS(const SwingSpec& swing) const {
    (void)swing;
    return 0.0;
  }
};

// Checks every point of a plan against the limits (amplitude, frequency, peak
// rate, peak acceleration per axis, position range). Ok, or the first point
// beyond them: "test point 2 (Y 5 Hz / 10 deg): peak rate 314.2 deg/s is
// beyond the table's 200 deg/s on Y".
Status checkPlanAgainstLimits(const TestPlan& plan, const TableLimits& limits);

// Checks a position an axis is to be moved to (a jog, a go-to, home) against
// the table's position range before any motion: kOutOfRange "X position
// 200 deg is beyond the table's +-180 deg; the table was not moved", or
// kInvalidArgument for a position that is not a number.
Status checkPositionAgainstLimits(Axis axis, double positionDeg, const TableLimits& limits);

}  // namespace fog::table

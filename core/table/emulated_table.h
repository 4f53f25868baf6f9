#pragma once
// A simulated three-axis turntable and its controller's side of the remote
// protocol (docs/table-control.md), for fogbench-table-emu and for tests.
//
// Motion, per axis, in table seconds (the emulator's clock, which may run
// faster than real time): a commanded reference built from analytic pieces —
// hold, a trapezoidal move (positioning rate and acceleration), a swing whose
// amplitude ramps up over whole periods with a smooth envelope 3x^2 - 2x^3
// (continuous rate whatever the start phase, bounded acceleration), then
// runs centre + A sin(w (t - t0) + startPhase), a stop at the stop
// deceleration — and the actual angle,
// which follows the reference with a pure servo lag:
//   actual(t) = reference(t - servoLagS).
// angleDeg(axis, t) is a pure function of t for every t up to the last
// command's time, so a board simulator may sample it at any instant it has
// reached (the IMU and the encoder look slightly into the past).
//
// TableServer interprets protocol lines (handleLine) and keeps the error
// queue, the heartbeat watchdog, the interlock and the emergency stop, with
// faults injected on request. Not thread-safe: one thread (the emulator's
// loop) owns both.

#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/test_plan.h"
#include "core/table/scpi.h"
#include "core/table/table_controller.h"

namespace fog::table {

struct EmulatedTableParams {
  TableLimits limits;
  double servoLagS = 0.002;
  double positionRateDegPerS = 20.0;
  double positionAccelDegPerS2 = 100.0;
  double stopAccelDegPerS2 = 100.0;        // stop(): bounded deceleration
  double emergencyAccelDegPerS2 = 2000.0;  // emergency stop, interlock trip
  double rampPeriods = 1.0;                // swing amplitude ramp, whole periods (>= 1)
};

class EmulatedTable {
 public:
  explicit EmulatedTable(EmulatedTableParams params = {});

  const EmulatedTableParams& params() const { return params_; }
  // Actual angle and rate (the servo's output) at table time t.
  double angleDeg(Axis axis, double t) const;
  double rateDegPerS(Axis axis, double t) const;
  // Mode at table time t, of the commanded reference (no servo lag): a swing is
  // "swinging" from the instant it is started, a stop "stopping" from its command.
  AxisMode mode(Axis axis, double t) const;

  // Commands at table time t (t never decreases between calls). Ok, or why not
  // (the axis is moving, beyond the limits).
  Status moveTo(Axis axis, double positionDeg, double t);
  Status startSwing(Axis axis, const SwingSpec& swing, double t);
  void stop(Axis axis, double t, double accelDegPerS2);
  void markEmergency(Axis axis, bool on) { emergency_[static_cast<std::size_t>(axis)] = on; }

 private:
  struct Piece {
    enum Kind { kHold, kMove, kSwing, kStop } kind = kHold;
    double t0 = 0.0;
    double p0 = 0.0;       // start position (hold: the position)
    double p1 = 0.0;       // move: target
    double v = 0.0;        // move: cruise rate; stop: start rate
    double a = 0.0;        // move / stop: acceleration magnitude
    double amp = 0.0, w = 0.0, ramp = 0.0, phase = 0.0;  // swing (centre = p0; phase rad)
    double duration() const;  // move / stop: time to rest; swing/hold: infinite
    double ref(double t) const;
    double refRate(double t) const;
  };
  const Piece& pieceAt(Axis axis, double t) const;
  void push(Axis axis, Piece p);

  EmulatedTableParams params_;
  std::array<std::deque<Piece>, kAxisCount> pieces_;
  std::array<bool, kAxisCount> emergency_{};
};

struct ServerFaults {
  std::string refuseHeader;      // the first command whose header is this (case-insensitive) is refused
  int refuseCount = 1;
  double interlockAfterStartS = -1.0;  // trip the interlock this long after the first swing starts
  double interlockForS = 1e9;          // ... and close it again after this long
};

class TableServer {
 public:
  TableServer(EmulatedTable& table, ServerFaults faults = {}, std::string identity = "fogbench,table-emu,0,0.1.0");

  // One protocol line at table time tableS, wall time wallS (the heartbeat
  // watchdog runs on wall time). Returns the reply line for a query.
  std::optional<std::string> handleLine(const std::string& line, double tableS, double wallS);
  // Runs the watchdog and injected faults; call often. Events (heartbeat lost,
  // interlock) go to `events`.
  void tick(double tableS, double wallS);
  // The host's link went away (TCP closed, pty closed): the watchdog decides.
  void setEventSink(std::function<void(const std::string&)> sink) { events_ = std::move(sink); }

  bool interlockOpen() const { return interlockOpen_; }
  bool emergencyStopped() const { return estop_; }
  bool heartbeatLost() const { return heartbeatLost_; }
  double firstSwingStartS() const { return firstSwingS_; }
  int swingsStarted() const { return swingsStarted_; }

 private:
  void pushError(int code, const std::string& text = {});
  // One parsed line: a query's answer, or nothing for a command (errors go
  // to the queue). Queries, the system commands and the axis commands are
  // handled each by their own function; false: not one of theirs.
  std::optional<std::string> execute(const scpi::Command& c, double t);
  std::string query(const scpi::Command& c, double t);
  bool systemCommand(const scpi::Command& c, double t);
  bool axisCommand(const scpi::Command& c, double t);
  // The argument checks of every command: they queue the SCPI error.
  bool wantArgs(const scpi::Command& c, std::size_t n);
  bool numbers(const scpi::Command& c, std::vector<double>& out);
  std::string blocked() const;  // error text when motion is not allowed, else empty
  void stopAll(double t, double accel);
  void event(const std::string& e) {
    if (events_) events_(e);
  }

  EmulatedTable& table_;
  ServerFaults faults_;
  std::string identity_;
  std::deque<std::pair<int, std::string>> errors_;
  std::array<std::optional<SwingSpec>, kAxisCount> swings_{};
  double heartbeatTimeoutS_ = 0.0;
  double lastLineWallS_ = 0.0;
  bool heartbeatLost_ = false;
  bool interlockOpen_ = false;
  bool interlockDone_ = false;
  bool estop_ = false;
  double firstSwingS_ = -1.0;
  int swingsStarted_ = 0;
  int refusedSoFar_ = 0;
  std::function<void(const std::string&)> events_;
};

}  // namespace fog::table

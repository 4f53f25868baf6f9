#pragma once
// Runs a test plan on a table controller, point by point:
//
//   check the whole plan against the controller's limits (nothing moves if
//   any point is beyond them)
//   for each point:
//     move the table to the point's position (TestPoint::positionDeg: the
//     swing axis to its swing centre, the others to where they hold) and
//     wait until it is there at rest
//     configure the swing, start it, wait the controller's amplitude ramp
//     (TableController::swingRampS) and then the point's settle time
//     record: the PointRecorder watches the board's table-angle stream, checks
//       the swing is the one planned and records the point's duration
//     stop (bounded deceleration), wait until at rest, rest restBetweenS
//
// A static point (gyro noise) skips the swing: the axis is held at rest.
// The swing is configured with the point's TestPoint::startPhaseDeg: it
// starts from rest at its centre and, once its amplitude has ramped up, runs
// centre + amplitude * sin(2 pi f (t - start) + startPhaseDeg).
//
// Safety: whatever ends the run early — the stop flag (Ctrl+C), a refused
// command, a lost link, a fault, an interlock, an emergency stop, the
// recorder failing (the board's link lost), a timeout — the runner brings
// the table to rest (stopAll(); if that fails, emergencyStop()) before it
// returns the reason. It never starts motion while the controller reports
// an interlock, an emergency stop or a fault.
//
// While it waits, the runner polls the controller's state every
// pollIntervalS and sends keepAlive() at least every heartbeatIntervalS, so a
// controller with a heartbeat timeout keeps the table moving only while the
// host is alive.
//
// Time comes from a RunnerClock (plan seconds): the machine's steady clock,
// optionally sped up for emulators, or a fake in tests, so tests need no
// sleeps. Not thread-safe; runs in the calling thread until done.

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/common/test_plan.h"
#include "core/table/table_controller.h"

namespace fog::table {

// Plan seconds: nowS() is monotonic; sleepS() waits that many plan seconds.
class RunnerClock {
 public:
  virtual ~RunnerClock() = default;
  virtual double nowS() = 0;
  virtual void sleepS(double s) = 0;
};
// The steady clock, `speed` plan seconds per wall second (1 = real time;
// emulators run faster).
std::unique_ptr<RunnerClock> steadyClock(double speed = 1.0);

// The stream side of a test point: what the board's data say. Implemented
// by the command line over the acquisition (thread-safe there); by scripts
// in tests.
struct RecorderProgress {
  bool done = false;  // the point's duration is recorded
  Status failure;     // not ok: the point cannot be recorded (why)
  std::string note;   // progress for the log ("steady swing verified at 12.3 s")
};
class PointRecorder {
 public:
  virtual ~PointRecorder() = default;
  // The table is (to the controller's knowledge) swinging `point` (or at rest
  // for a static point) and has settled: verify and record it.
  virtual Status begin(int index, const TestPoint& point) = 0;
  virtual RecorderProgress poll() = 0;
  // The point is over (recorded, or abandoned): stop recording it.
  virtual void end(int index) = 0;
  // Not ok once the stream can no longer be recorded (the board's link is
  // lost): the runner stops the table at its next step.
  virtual Status health() { return Status::ok(); }
  // For a table whose state the driver cannot read (manual): whether the
  // stream shows `axis` at rest now. Others need not answer.
  virtual bool streamShowsRest(Axis axis) {
    (void)axis;
    return true;
  }
};

struct RunnerOptions {
  double positionToleranceDeg = 0.01;  // "in position"
  double restRateDegPerS = 0.01;       // "at rest"
  double pollIntervalS = 0.05;
  double heartbeatIntervalS = 0.5;
  double moveTimeoutS = 60.0;           // to reach a position
  double stopTimeoutS = 30.0;           // to come to rest after stop()
  // A point's recording must be done within settle + duration + this.
  double recordMarginS = 30.0;
};

struct RunnerResult {
  int pointsDone = 0;        // recorded completely
  Status status;             // ok: the whole plan ran; otherwise why it stopped
  bool tableAtRest = false;  // the runner saw the table at rest at the end (or stopped it)
};

class PlanRunner {
 public:
  // `log` receives one line per step ("point 1: X swing 1 Hz / 3 deg started"),
  // for the session's table log and the terminal. May be empty.
  PlanRunner(TableController& controller, RunnerClock& clock, PointRecorder& recorder,
             RunnerOptions options = {}, std::function<void(const std::string&)> log = {});
  // Runs `plan`; `stop` (may be null) ends it early as "stopped by the operator".
  RunnerResult run(const TestPlan& plan, const std::atomic<bool>* stop);
  // An emergency stop asked from another thread (the GUI's tool bar while a
  // run holds the controller): once set, the runner's next step (within a
  // poll interval, or the end of the controller call under way) ends the
  // run as "emergency stop by the operator" and sends emergencyStop() — not
  // the bounded-deceleration stop — before it waits for rest. Set before run().
  void setEmergencyFlag(const std::atomic<bool>* emergency) { emergency_ = emergency; }

 private:
  Status runPoint(int index, const TestPoint& point);
  // Polls state (and sends heartbeats) until `done(state)` or timeoutS.
  Status waitUntil(const std::function<bool(const TableState&)>& done, double timeoutS, const std::string& what);
  Status tick();  // heartbeat when due, stop and emergency flags
  Result<TableState> checkedState();
  // The swing axis was seen in `mode` while `during` ("settling", "recording"):
  // the controller's reason when it gives one, else "the table stopped swinging".
  Status notSwinging(const std::string& label, const char* during, AxisMode mode);
  // stopAll() (emergencyStop() when it fails, or at once when `emergency`),
  // then waits (bounded) for every axis at rest.
  Status bringToRest(bool& atRest, bool emergency);
  void say(const std::string& line);

  TableController& controller_;
  RunnerClock& clock_;
  PointRecorder& recorder_;
  RunnerOptions options_;
  std::function<void(const std::string&)> log_;
  const std::atomic<bool>* stop_ = nullptr;
  const std::atomic<bool>* emergency_ = nullptr;
  double lastHeartbeatS_ = -1e300;
  Axis activeAxis_ = Axis::kX;
  std::array<double, kAxisCount> lastTargetDeg_{};  // where the runner last put each axis
};

}  // namespace fog::table

#include "core/table/plan_runner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace fog::table {

namespace {

std::string num(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

class SteadyClock : public RunnerClock {
 public:
  explicit SteadyClock(double speed) : speed_(speed > 0.0 && std::isfinite(speed) ? speed : 1.0) {}
  double nowS() override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() * speed_;
  }
  void sleepS(double s) override {
    if (s > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(s / speed_));
  }

 private:
  double speed_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string pointLabel(int index, const TestPoint& p) {
  if (p.isStatic()) return "point " + std::to_string(index + 1) + " (" + axisLabel(p.axis) + " at rest)";
  return "point " + std::to_string(index + 1) + " (" + axisLabel(p.axis) + " " + num(p.frequencyHz) + " Hz / " +
         num(p.amplitudeDeg) + " deg)";
}

}  // namespace

std::unique_ptr<RunnerClock> steadyClock(double speed) { return std::make_unique<SteadyClock>(speed); }

PlanRunner::PlanRunner(TableController& controller, RunnerClock& clock, PointRecorder& recorder,
                       RunnerOptions options, std::function<void(const std::string&)> log)
    : controller_(controller), clock_(clock), recorder_(recorder), options_(options), log_(std::move(log)) {}

void PlanRunner::say(const std::string& line) {
  if (log_) log_(line);
}

Status PlanRunner::tick() {
  if (emergency_ && emergency_->load()) return Status(StatusCode::kInvalidArgument, "emergency stop by the operator");
  if (stop_ && stop_->load()) return Status(StatusCode::kInvalidArgument, "stopped by the operator");
  FOG_RETURN_IF_ERROR(recorder_.health());
  const double now = clock_.nowS();
  if (now - lastHeartbeatS_ >= options_.heartbeatIntervalS) {
    lastHeartbeatS_ = now;
    FOG_RETURN_IF_ERROR(controller_.keepAlive());
  }
  return Status::ok();
}

Result<TableState> PlanRunner::checkedState() {
  FOG_ASSIGN_OR_RETURN(auto state, controller_.state());
  if (const auto why = state.blockingReason(); !why.empty())
    return Status(StatusCode::kIoError, "the table controller reports " + why);
  return state;
}

Status PlanRunner::waitUntil(const std::function<bool(const TableState&)>& done, double timeoutS,
                             const std::string& what) {
  const double giveUp = clock_.nowS() + timeoutS;
  for (;;) {
    FOG_RETURN_IF_ERROR(tick());
    FOG_ASSIGN_OR_RETURN(auto state, checkedState());
    if (done(state)) return Status::ok();
    if (clock_.nowS() >= giveUp)
      return Status(StatusCode::kIoError, what + " did not happen within " + num(timeoutS) + " s");
    clock_.sleepS(options_.pollIntervalS);
  }
}

Status PlanRunner::notSwinging(const std::string& label, const char* during, AxisMode mode) {
  // A controller that stopped the axis for an interlock, an emergency stop or
  // its heartbeat says so; but the flags of the state read that saw the axis
  // stopped may predate the stop (the remote driver reads them first), so
  // read once more for the reason.
  if (auto again = checkedState(); !again.isOk()) return again.status();
  return Status(StatusCode::kIoError, label + ": the table stopped swinging while " + during + " (axis " +
                                          axisModeName(mode) + ")");
}

Status PlanRunner::runPoint(int index, const TestPoint& p) {
  const std::string label = pointLabel(index, p);
  const Axis axis = p.axis;
  activeAxis_ = axis;
  // The plan's table position for this point: the swing axis swings about
  // its entry, the others hold theirs.
  const auto& target = p.positionDeg;
  const double centre = target[static_cast<std::size_t>(axis)];
  auto allInPlace = [&](const TableState& s) {
    if (!s.known) return true;
    for (int a = 0; a < kAxisCount; ++a) {
      const auto& ax = s.axes[static_cast<std::size_t>(a)];
      if (ax.mode != AxisMode::kRest || std::abs(ax.positionDeg - target[static_cast<std::size_t>(a)]) >
                                            options_.positionToleranceDeg ||
          std::abs(ax.rateDegPerS) > options_.restRateDegPerS)
        return false;
    }
    return true;
  };
  // Position and settle: every axis whose position differs (all of them
  // when the driver cannot read the table).
  FOG_RETURN_IF_ERROR(tick());
  FOG_ASSIGN_OR_RETURN(auto before, checkedState());
  std::string where;
  for (int a = 0; a < kAxisCount; ++a) {
    const auto ax = static_cast<Axis>(a);
    const double want = target[static_cast<std::size_t>(a)];
    const auto& now = before.axes[static_cast<std::size_t>(a)];
    // A table the driver cannot read (manual) is where the plan last put it.
    const bool there = before.known ? now.mode == AxisMode::kRest &&
                                          std::abs(now.positionDeg - want) <= options_.positionToleranceDeg
                                    : lastTargetDeg_[static_cast<std::size_t>(a)] == want;
    if (there && ax != axis) continue;
    FOG_RETURN_IF_ERROR(controller_.moveTo(ax, want));
    lastTargetDeg_[static_cast<std::size_t>(a)] = want;
    where += std::string(where.empty() ? "" : ", ") + axisLabel(ax) + " to " + num(want) + " deg";
  }
  say(label + ": move " + where);
  FOG_RETURN_IF_ERROR(waitUntil(allInPlace, options_.moveTimeoutS, label + ": reaching the table position"));
  // Swing.
  // The settle time is steady swing, as in the simulator: it starts once the
  // controller's amplitude ramp is over.
  double rampS = 0.0;
  if (!p.isStatic()) {
    const SwingSpec swing{p.frequencyHz, p.amplitudeDeg, centre, std::remainder(p.startPhaseDeg, 360.0) + 0.0};
    FOG_RETURN_IF_ERROR(controller_.configureSwing(axis, swing));
    FOG_RETURN_IF_ERROR(controller_.startSwing(axis));
    const double ramp = controller_.swingRampS(swing);
    rampS = std::isfinite(ramp) && ramp > 0.0 ? ramp : 0.0;
    say(label + ": swing started" +
        (rampS > 0.0 ? "; ramp " + num(rampS) + " s, then settle " + num(p.settleS) + " s" : std::string()));
  }
  const double settleUntil = clock_.nowS() + rampS + p.settleS;
  auto swinging = [&](const TableState& s) {
    return !s.known || p.isStatic() || s.axis(axis).mode == AxisMode::kSwinging;
  };
  while (clock_.nowS() < settleUntil) {
    FOG_RETURN_IF_ERROR(tick());
    FOG_ASSIGN_OR_RETURN(auto state, checkedState());
    if (!swinging(state)) return notSwinging(label, "settling", state.axis(axis).mode);
    clock_.sleepS(std::min(options_.pollIntervalS, settleUntil - clock_.nowS()));
  }
  // Record.
  say(label + ": recording " + num(p.durationS) + " s");
  FOG_RETURN_IF_ERROR(recorder_.begin(index, p));
  const double recordBy = clock_.nowS() + p.durationS + options_.recordMarginS;
  std::string lastNote;
  for (;;) {
    auto progress = recorder_.poll();
    if (!progress.note.empty() && progress.note != lastNote) {
      lastNote = progress.note;
      say(label + ": " + progress.note);
    }
    if (!progress.failure.isOk()) {
      recorder_.end(index);
      return Status(progress.failure.code(), label + ": " + progress.failure.message());
    }
    if (progress.done) break;
    if (auto s = tick(); !s.isOk()) {
      recorder_.end(index);
      return s;
    }
    auto state = checkedState();
    if (!state.isOk() || !swinging(*state)) {
      recorder_.end(index);
      if (!state.isOk()) return state.status();
      return notSwinging(label, "recording", state->axis(axis).mode);
    }
    if (clock_.nowS() >= recordBy) {
      recorder_.end(index);
      return Status(StatusCode::kIoError,
                    label + ": not recorded within " + num(p.durationS + options_.recordMarginS) + " s" +
                        (lastNote.empty() ? std::string(" (is the board streaming the table angle?)")
                                          : "; last check: " + lastNote));
    }
    clock_.sleepS(options_.pollIntervalS);
  }
  recorder_.end(index);
  say(label + ": recorded");
  // Stop and rest.
  if (!p.isStatic()) {
    FOG_RETURN_IF_ERROR(controller_.stop(axis));
    auto atRest = [&](const TableState& s) {
      if (!s.known) return recorder_.streamShowsRest(axis);
      const auto& a = s.axis(axis);
      return a.mode == AxisMode::kRest && std::abs(a.rateDegPerS) <= options_.restRateDegPerS;
    };
    FOG_RETURN_IF_ERROR(waitUntil(atRest, options_.stopTimeoutS, label + ": coming to rest"));
    say(label + ": at rest");
  }
  return Status::ok();
}

Status PlanRunner::bringToRest(bool& atRest, bool emergency) {
  atRest = false;
  Status stopped = emergency ? Status(StatusCode::kInvalidArgument, "the operator asked for it") : controller_.stopAll();
  if (!stopped.isOk()) {
    say((emergency ? "emergency stop (" : "stop failed (") + stopped.message() + ")" +
        (emergency ? std::string() : std::string("; emergency stop")));
    Status e = controller_.emergencyStop();
    if (!e.isOk()) {
      say("emergency stop failed too (" + e.message() + "): the table controller is unreachable; its heartbeat "
          "timeout must stop the table");
      return e;
    }
  }
  // Wait (bounded) until every axis is at rest, ignoring the reason the run
  // ended (an interlock still reports its state).
  const double giveUp = clock_.nowS() + options_.stopTimeoutS;
  for (;;) {
    auto state = controller_.state();
    if (!state.isOk()) return state.status();
    bool rest = true;
    if (state->known)
      for (const auto& a : state->axes)
        rest = rest && (a.mode == AxisMode::kRest || a.mode == AxisMode::kEmergencyStop) &&
               std::abs(a.rateDegPerS) <= options_.restRateDegPerS;
    if (rest) {
      atRest = true;
      return Status::ok();
    }
    if (clock_.nowS() >= giveUp) return Status(StatusCode::kIoError, "the table did not come to rest");
    (void)controller_.keepAlive();
    clock_.sleepS(options_.pollIntervalS);
  }
}

RunnerResult PlanRunner::run(const TestPlan& plan, const std::atomic<bool>* stop) {
  stop_ = stop;
  lastTargetDeg_ = {};
  RunnerResult result;
  lastHeartbeatS_ = -1e300;
  auto fail = [&](Status why) {
    // The operator's emergency stop is the cause even when something it set
    // off (the recording ending) was seen first.
    const bool emergency = emergency_ && emergency_->load();
    if (emergency && why.message().rfind("emergency stop by the operator", 0) != 0)
      why = Status(why.code(), "emergency stop by the operator (then: " + why.message() + ")");
    result.status = std::move(why);
    say("run stopped: " + result.status.message() + "; bringing the table to rest");
    bool atRest = false;
    Status rested = bringToRest(atRest, emergency);
    result.tableAtRest = atRest;
    say(atRest ? "table at rest" : "the table was NOT seen at rest: " + rested.message());
    return result;
  };
  // Nothing moves before the whole plan is known to fit the table.
  auto id = controller_.identify();
  if (!id) {
    result.status = id.status();
    return result;
  }
  say("controller: " + *id);
  auto limits = controller_.limits();
  if (!limits) {
    result.status = limits.status();
    return result;
  }
  if (auto s = checkPlanAgainstLimits(plan, *limits); !s.isOk()) {
    result.status = s;
    say("plan refused: " + s.message());
    return result;
  }
  if (auto s = tick(); !s.isOk()) return fail(s);
  if (auto st = checkedState(); !st.isOk()) {
    result.status = st.status();
    say("not starting: " + st.status().message());
    return result;
  }
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    if (auto s = runPoint(static_cast<int>(i), plan.points[i]); !s.isOk()) {
      // Every reason names the point it stopped at.
      const std::string label = pointLabel(static_cast<int>(i), plan.points[i]);
      if (s.message().rfind(label, 0) != 0 && s.message() != "stopped by the operator" &&
          s.message() != "emergency stop by the operator")
        s = Status(s.code(), label + ": " + s.message());
      return fail(s);
    }
    ++result.pointsDone;
    if (i + 1 < plan.points.size()) {
      const double restUntil = clock_.nowS() + plan.restBetweenS;
      while (clock_.nowS() < restUntil) {
        if (auto s = tick(); !s.isOk()) return fail(s);
        clock_.sleepS(std::min(options_.pollIntervalS, restUntil - clock_.nowS()));
      }
    }
  }
  result.tableAtRest = true;
  say("plan done: " + std::to_string(result.pointsDone) + " points");
  if (auto s = controller_.release(); !s.isOk()) say("could not release the controller's heartbeat: " + s.message());
  return result;
}

}  // namespace fog::table

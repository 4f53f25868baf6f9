#include "ui/table_drive.h"

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "core/table/manual_table.h"
#include "core/table/remote_table.h"

namespace fog::ui {

// The controller as the runner uses it; every state it reads is copied into
// the snapshot, so the Live view needs no link traffic of its own.
class TableDrive::Observed : public table::TableController {
 public:
  Observed(table::TableController& inner, TableDrive& drive) : inner_(inner), drive_(drive) {}
  std::string description() const override { return inner_.description(); }
  Result<std::string> identify() override { return inner_.identify(); }
  Result<table::TableLimits> limits() override { return inner_.limits(); }
  Result<table::TableState> state() override {
    auto s = inner_.state();
    if (s) {
      drive_.setSnapshot([&](TableSnapshot& snap) {
        snap.stateRead = true;
        snap.state = *s;
      });
    }
    return s;
  }
  Status configureSwing(Axis axis, const table::SwingSpec& swing) override { return inner_.configureSwing(axis, swing); }
  Status moveTo(Axis axis, double positionDeg) override { return inner_.moveTo(axis, positionDeg); }
  Status startSwing(Axis axis) override { return inner_.startSwing(axis); }
  Status stop(Axis axis) override { return inner_.stop(axis); }
  Status stopAll() override { return inner_.stopAll(); }
  Status emergencyStop() override { return inner_.emergencyStop(); }
  Status keepAlive() override { return inner_.keepAlive(); }
  Status release() override { return inner_.release(); }
  double swingRampS(const table::SwingSpec& swing) const override { return inner_.swingRampS(swing); }

 private:
  table::TableController& inner_;
  TableDrive& drive_;
};

// The stream recorder, with the phase of the point for the snapshot and the
// board (settling while the swing is checked, recording once it is verified,
// idle when the point is over), as fogbench-cli's.
class TableDrive::Marking : public table::PointRecorder {
 public:
  Marking(TableDrive& drive) : drive_(drive) {}
  Status begin(int index, const TestPoint& point) override {
    index_ = index;
    point_ = point;
    windowsAtBegin_ = drive_.recorder_.windows().size();
    marked_ = false;
    phase(protocol::TestPhase::kSettling);
    return drive_.recorder_.begin(index, point);
  }
  table::RecorderProgress poll() override {
    auto progress = drive_.recorder_.poll();
    if (!marked_ && drive_.recorder_.windows().size() > windowsAtBegin_) {
      marked_ = true;
      phase(protocol::TestPhase::kRecording);
    }
    return progress;
  }
  void end(int index) override {
    drive_.recorder_.end(index);
    phase(protocol::TestPhase::kIdle);
  }
  Status health() override { return drive_.recorder_.health(); }
  bool streamShowsRest(Axis axis) override { return drive_.recorder_.streamShowsRest(axis); }

 private:
  void phase(protocol::TestPhase p) {
    drive_.board_->markPoint(index_, point_, p);
    drive_.setSnapshot([&](TableSnapshot& s) {
      s.point = index_;
      s.phase = p;
    });
  }
  TableDrive& drive_;
  int index_ = -1;
  TestPoint point_;
  std::size_t windowsAtBegin_ = 0;
  bool marked_ = false;
};

TableDrive::TableDrive(TableDriveSettings settings, TestPlan plan)
    : settings_(std::move(settings)), plan_(std::move(plan)) {
  board_ = std::make_unique<acquisition::BoardCommander>(nullptr);
  marking_ = std::make_unique<Marking>(*this);
}

TableDrive::~TableDrive() {
  if (runner_.joinable()) finish("the bench is closing");
}

std::string TableDrive::driverName() const {
  return settings_.manual ? std::string("manual") : "remote " + settings_.address;
}

void TableDrive::log(const std::string& kind, const std::string& text) {
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::lock_guard lock(mutex_);
  log_.push_back({t, kind, text});
  if (kind == "step") {
    snapshot_.step = text;
    // "point 2 (Y 2 Hz / 1.5 deg): move …": where the runner is.
    if (text.rfind("point ", 0) == 0) {
      const int n = std::atoi(text.c_str() + 6);
      if (n >= 1 && n - 1 != snapshot_.point) {
        snapshot_.point = n - 1;
        snapshot_.phase = protocol::TestPhase::kIdle;
      }
    }
  } else if (kind == "operator") {
    snapshot_.instruction = text;
  }
}

void TableDrive::setSnapshot(const std::function<void(TableSnapshot&)>& change) {
  std::lock_guard lock(mutex_);
  change(snapshot_);
}

TableSnapshot TableDrive::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

std::vector<session::TableLogEntry> TableDrive::drainLog() {
  std::lock_guard lock(mutex_);
  std::vector<session::TableLogEntry> out;
  out.swap(log_);
  return out;
}

std::string TableDrive::description() const {
  return controller_ ? controller_->description() : driverName();
}

Status TableDrive::connect() {
  if (settings_.manual) {
    controller_ = std::make_unique<table::ManualTable>([this](const std::string& text) { log("operator", text); });
  } else {
    auto link = table::openTransport(settings_.address, settings_.baud);
    if (!link) return link.status();
    table::RemoteOptions ro;
    ro.replyTimeout = std::chrono::milliseconds(std::llround(settings_.replyTimeoutS * 1e3));
    ro.heartbeatTimeoutS = settings_.heartbeatS;
    auto remote = table::RemoteTable::connect(std::move(*link), ro,
                                              [this](const std::string& k, const std::string& t) { log(k, t); });
    if (!remote) return remote.status();
    controller_ = std::move(*remote);
  }
  observed_ = std::make_unique<Observed>(*controller_, *this);
  auto limits = controller_->limits();
  if (!limits) return limits.status();
  if (auto s = table::checkPlanAgainstLimits(plan_, *limits); !s.isOk()) {
    log("step", "plan refused: " + s.message());
    return s;
  }
  // Nothing is moving yet: what the controller says of the table.
  (void)observed_->state();
  setSnapshot([&](TableSnapshot& s) {
    s.connected = true;
    s.description = controller_->description();
  });
  return Status::ok();
}

void TableDrive::configure(acquisition::AcquisitionOptions& options) {
  options.shouldEnd = [this]() -> std::optional<std::string> {
    if (!runnerDone_) return std::nullopt;
    if (result_.status.isOk()) return std::string();
    return "table: " + result_.status.message();
  };
  options.drainTableLog = [this] { return drainLog(); };
  options.segment = [this](const Recording& whole) { return table::segmentByWindows(whole, recorder_.windows()); };
}

void TableDrive::start(acquisition::ByteSource* source, const std::atomic<bool>* stop) {
  board_ = std::make_unique<acquisition::BoardCommander>(settings_.boardCommands ? source : nullptr,
                                                         [this](const std::string& what) { log("board", what); });
  if (settings_.pulseEquivalentDeg) board_->setPulseEquivalent(*settings_.pulseEquivalentDeg);
  board_->startStreaming();
  clock_ = table::steadyClock(settings_.speed);
  recorder_.setHostClock(clock_.get());
  table::RunnerOptions options;
  options.pollIntervalS = 0.1 * settings_.speed;
  options.heartbeatIntervalS = std::min(0.5, settings_.heartbeatS / 4.0) * settings_.speed;
  if (settings_.manual) options.recordMarginS = settings_.operatorTimeoutS;
  // `stop` (the Stop button, closing the window) ends the run; so does the
  // recording ending (finish()).
  runnerStarted_ = true;
  runner_ = std::thread([this, stop, options] {
    table::PlanRunner r(*observed_, *clock_, *marking_, options,
                        [this](const std::string& line) { log("step", line); });
    r.setEmergencyFlag(&emergency_);
    result_ = r.run(plan_, stop);
    if (result_.status.isOk()) board_->markDone();
    setSnapshot([&](TableSnapshot& s) {
      s.finished = true;
      s.atRest = result_.tableAtRest;
      s.failure = result_.status.isOk() ? std::string() : result_.status.message();
      if (result_.status.isOk()) s.phase = protocol::TestPhase::kDone;
    });
    runnerDone_ = true;
  });
}

bool TableDrive::requestEmergencyStop() {
  if (!runnerStarted_ || runnerDone_) return false;
  emergency_ = true;
  log("step", "emergency stop asked by the operator");
  return true;
}

void TableDrive::observe(const acquisition::AcquisitionBatch& batch) { recorder_.addFrames(batch.frames); }

void TableDrive::finish(const std::string& why) {
  // The board's recording has ended: a runner still going stops the table.
  if (!runnerDone_) recorder_.failLink(why.empty() ? std::string("the recording ended") : why);
  if (runner_.joinable()) runner_.join();
  board_->stopStreaming();
}

}  // namespace fog::ui

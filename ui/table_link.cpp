#include "ui/table_link.h"

#include <QTimer>
#include <chrono>
#include <cstdlib>

#include "core/table/transport.h"

namespace fog::ui {

namespace {

using Clock = std::chrono::steady_clock;

// The remote link as the worker uses it: a read waits at most kSliceMs at a
// time (RemoteTable's reply wait loops until its own timeout), so a cancel
// flag set by the GUI thread ends a hung call within kSliceMs.
class CancellableTransport : public table::ByteTransport {
 public:
  CancellableTransport(std::unique_ptr<table::ByteTransport> inner, std::shared_ptr<const std::atomic<bool>> cancel)
      : inner_(std::move(inner)), cancel_(std::move(cancel)) {}
  std::string description() const override { return inner_->description(); }
  Status write(std::string_view bytes) override {
    if (*cancel_) return cancelled();
    return inner_->write(bytes);
  }
  Result<std::size_t> read(std::string& out, std::chrono::milliseconds timeout) override {
    if (*cancel_) return cancelled();
    return inner_->read(out, std::min(timeout, std::chrono::milliseconds(TableLink::kSliceMs)));
  }

 private:
  Status cancelled() const { return ioError("table link " + inner_->description() + " closed by the bench"); }
  std::unique_ptr<table::ByteTransport> inner_;
  std::shared_ptr<const std::atomic<bool>> cancel_;
};

// A refusal's number and reply from RemoteTable's message
// ("the table controller refused 'LINE': CODE,\"TEXT\"[; then …]").
TableCommandResult resultOf(const Status& s) {
  TableCommandResult r;
  if (s.isOk()) return r;
  r.message = s.message();
  const bool refused = s.code() == StatusCode::kInvalidArgument || s.code() == StatusCode::kOutOfRange;
  r.outcome = refused ? TableCommandResult::kRefused : TableCommandResult::kLinkFailed;
  if (const auto at = r.message.find("': "); refused && at != std::string::npos) {
    r.reply = r.message.substr(at + 3);
    r.scpiCode = static_cast<int>(std::strtol(r.reply.c_str(), nullptr, 10));
  }
  return r;
}

bool linkFailure(const Status& s) {
  return s.code() == StatusCode::kIoError || s.code() == StatusCode::kCorruptData;
}

}  // namespace

// Lives on the link's thread: owns the controller, does every call to it.
class TableLinkWorker : public QObject {
  Q_OBJECT

 public:
  explicit TableLinkWorker(std::shared_ptr<TableLink::Flags> flags) : flags_(std::move(flags)) {
    timer_ = new QTimer(this);  // moves to the link's thread with its parent
    timer_->setInterval(TableLink::kPollMs);
    connect(timer_, &QTimer::timeout, this, &TableLinkWorker::poll);
  }

  void open(const std::string& address, const TableLinkOptions& options) {
    address_ = address;
    options_ = options;
    timer_->start();
    if (!tryOpen(false)) {
      address_.clear();  // a first attempt that fails is not retried
      timer_->stop();
    }
  }

  void adopt(std::unique_ptr<table::TableController> controller) {
    controller_ = std::move(controller);
    if (!controller_) return;
    auto limits = controller_->limits();
    emit opened(QString::fromStdString(controller_->description()), limits ? *limits : table::TableLimits{});
    timer_->start();
    poll();
  }

  void poll() {
    sendPendingEmergency();
    if (!controller_) {
      if (!address_.empty() && Clock::now() - lastAttempt_ >= std::chrono::milliseconds(TableLink::kReconnectMs))
        tryOpen(true);
      return;
    }
    auto state = controller_->state();
    if (state) {
      emit stateRead(*state);
      (void)controller_->keepAlive();  // a failed heartbeat shows in the next state read
      return;
    }
    if (address_.empty()) emit readFailed(QString::fromStdString(state.status().message()));
    else dropLink(state.status());
  }

  void move(const TableCommand& command, unsigned epoch) {
    sendPendingEmergency();
    if (epoch != flags_->stopEpoch.load()) {
      TableCommandResult dropped;
      dropped.outcome = TableCommandResult::kDropped;
      emit commandDone(command, dropped);
      return;
    }
    run(command, [&] { return controller_->moveTo(command.axis, command.positionDeg); });
  }

  void stop() {
    sendPendingEmergency();
    run(TableCommand{TableCommand::kStop}, [&] { return controller_->stopAll(); });
  }

  void emergency() {
    if (sendPendingEmergency()) poll();  // the state shows it at once
  }

  // retire(): the controller let go (heartbeat off when the link works),
  // the thread ended. shutdown(): the same without a word to the controller.
  void finish(bool release) {
    timer_->stop();
    if (release && controller_) (void)controller_->release();
    controller_.reset();
    thread()->quit();
  }

 signals:
  void opening(const QString& address, bool again);
  void opened(const QString& description, const fog::table::TableLimits& limits);
  void lost(const QString& why, bool reconnecting);
  void stateRead(const fog::table::TableState& state);
  void readFailed(const QString& why);
  void commandDone(const fog::ui::TableCommand& command, const fog::ui::TableCommandResult& result);

 private:
  // Connect, identify, set the heartbeat, read the limits. False when any
  // failed; the next attempt is kReconnectMs after this one ended (each one
  // to a hung controller leaves a connection in its queue to accept).
  bool tryOpen(bool again) {
    const QString address = QString::fromStdString(address_);
    emit opening(address, again);
    const auto failed = [&](const Status& why) {
      lastAttempt_ = Clock::now();
      emit lost(QString::fromStdString(why.message()), again);
      return false;
    };
    const auto timeout = options_.remote.replyTimeout;
    auto link = table::openTransport(address_, options_.baud, timeout, timeout);
    if (!link) return failed(link.status());
    auto cancellable = std::make_unique<CancellableTransport>(std::move(*link), cancelFlag());
    auto remote = table::RemoteTable::connect(std::move(cancellable), options_.remote);
    if (!remote) return failed(remote.status());
    auto limits = (*remote)->limits();
    if (!limits) return failed(limits.status());
    controller_ = std::move(*remote);
    emit opened(QString::fromStdString(controller_->description()), *limits);
    poll();
    return true;
  }

  std::shared_ptr<const std::atomic<bool>> cancelFlag() const {
    return std::shared_ptr<const std::atomic<bool>>(flags_, &flags_->cancel);
  }

  // A remote link that failed is dropped: reopening it is the way back in
  // step (poll() tries every kReconnectMs).
  void dropLink(const Status& why) {
    controller_.reset();
    lastAttempt_ = Clock::now();
    emit lost(QString::fromStdString(why.message()), true);
  }

  template <typename Call>
  void run(const TableCommand& command, Call call) {
    if (!controller_) {
      TableCommandResult r;
      r.outcome = TableCommandResult::kLinkFailed;
      r.message = "the table controller is not connected (the panel is reconnecting)";
      emit commandDone(command, r);
      return;
    }
    const Status s = call();
    emit commandDone(command, resultOf(s));
    if (linkFailure(s) && !address_.empty()) {
      dropLink(s);
      return;
    }
    poll();  // the motion (or the stop) shows at once
  }

  // The emergency stop asked for by the GUI thread, before anything else.
  bool sendPendingEmergency() {
    if (!flags_->emergency.exchange(false)) return false;
    const TableCommand command{TableCommand::kEmergencyStop};
    if (!controller_) {
      TableCommandResult r;
      r.outcome = TableCommandResult::kLinkFailed;
      r.message = "the table controller is not connected (the panel is reconnecting)";
      emit commandDone(command, r);
      return true;
    }
    const Status s = controller_->emergencyStop();
    emit commandDone(command, resultOf(s));
    if (linkFailure(s) && !address_.empty()) dropLink(s);
    return true;
  }

  std::shared_ptr<TableLink::Flags> flags_;
  std::unique_ptr<table::TableController> controller_;
  std::string address_;  // empty: an adopted controller (never reopened)
  TableLinkOptions options_;
  Clock::time_point lastAttempt_{};
  QTimer* timer_ = nullptr;
};

TableLink::TableLink(QObject* parent) : QObject(parent) {
  static const bool registered = [] {
    qRegisterMetaType<fog::table::TableState>();
    qRegisterMetaType<fog::table::TableLimits>();
    qRegisterMetaType<fog::ui::TableCommand>();
    qRegisterMetaType<fog::ui::TableCommandResult>();
    return true;
  }();
  (void)registered;
  worker_ = new TableLinkWorker(flags_);
  worker_->moveToThread(&thread_);
  // Queued (the worker is on another thread); nothing is passed on once retired.
  connect(worker_, &TableLinkWorker::opening, this, [this](const QString& a, bool again) {
    if (!retired_) emit opening(a, again);
  });
  connect(worker_, &TableLinkWorker::opened, this, [this](const QString& d, const table::TableLimits& l) {
    if (!retired_) emit opened(d, l);
  });
  connect(worker_, &TableLinkWorker::lost, this, [this](const QString& why, bool again) {
    if (!retired_) emit lost(why, again);
  });
  connect(worker_, &TableLinkWorker::stateRead, this, [this](const table::TableState& s) {
    if (!retired_) emit stateRead(s);
  });
  connect(worker_, &TableLinkWorker::readFailed, this, [this](const QString& why) {
    if (!retired_) emit readFailed(why);
  });
  connect(worker_, &TableLinkWorker::commandDone, this, [this](const TableCommand& c, const TableCommandResult& r) {
    if (!retired_) emit commandDone(c, r);
  });
  thread_.setObjectName("table link");
  thread_.start();
}

TableLink::~TableLink() {
  flags_->cancel = true;  // the call under way gives up within kSliceMs
  if (thread_.isRunning()) {
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->finish(false); }, Qt::QueuedConnection);
    thread_.wait();
  }
  delete worker_;  // its thread has ended (its timer was stopped there)
}

void TableLink::open(const QString& address, const TableLinkOptions& options) {
  QMetaObject::invokeMethod(worker_, [w = worker_, a = address.toStdString(), options] { w->open(a, options); },
                            Qt::QueuedConnection);
}

void TableLink::adopt(std::unique_ptr<table::TableController> controller) {
  // (A queued functor must be copyable: the controller travels in a shared holder.)
  auto holder = std::make_shared<std::unique_ptr<table::TableController>>(std::move(controller));
  QMetaObject::invokeMethod(worker_, [w = worker_, holder] { w->adopt(std::move(*holder)); }, Qt::QueuedConnection);
}

void TableLink::pollNow() {
  QMetaObject::invokeMethod(worker_, [w = worker_] { w->poll(); }, Qt::QueuedConnection);
}

void TableLink::moveTo(Axis axis, double positionDeg) {
  const TableCommand command{TableCommand::kMove, axis, positionDeg};
  const unsigned epoch = flags_->stopEpoch.load();
  QMetaObject::invokeMethod(worker_, [w = worker_, command, epoch] { w->move(command, epoch); },
                            Qt::QueuedConnection);
}

void TableLink::stopAll() {
  ++flags_->stopEpoch;
  QMetaObject::invokeMethod(worker_, [w = worker_] { w->stop(); }, Qt::QueuedConnection);
}

void TableLink::emergencyStop() {
  ++flags_->stopEpoch;
  flags_->emergency = true;  // whatever the worker does next starts with it
  QMetaObject::invokeMethod(worker_, [w = worker_] { w->emergency(); }, Qt::QueuedConnection);
}

void TableLink::retire() {
  if (retired_) return;
  retired_ = true;
  connect(&thread_, &QThread::finished, this, &QObject::deleteLater);
  QMetaObject::invokeMethod(worker_, [w = worker_] { w->finish(true); }, Qt::QueuedConnection);
}

}  // namespace fog::ui

#include "table_link.moc"

#include "ui/acquisition_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>

#include "core/session/session_api.h"
#include "ui/table_drive.h"

namespace fog::ui {

AcquisitionRunner::AcquisitionRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<std::shared_ptr<const fog::ui::RunOutcome>>();
}

AcquisitionRunner::~AcquisitionRunner() {
  stop_.store(true);
  future_.waitForFinished();
}

bool AcquisitionRunner::start(RunRequest request) {
  if (running_ || (!request.source && !request.openSource)) return false;
  running_ = true;
  stop_.store(false);
  dropped_.store(0);
  {
    std::lock_guard lock(mutex_);
    buffer_.clear();
    bufferedFrames_ = 0;
  }
  future_ = QtConcurrent::run([this, request = std::move(request)]() mutable {
    Result<acquisition::AcquisitionResult> result = Status(StatusCode::kInternal, "no source");
    const auto table = request.table;
    // The table first: nothing is recorded for a table that cannot run the plan.
    bool refused = false;
    if (table)
      if (auto s = table->connect(); !s.isOk()) {
        result = s;
        refused = true;
      }
    if (!refused && !request.source) {
      auto opened = request.openSource();
      if (opened) request.source = std::shared_ptr<acquisition::ByteSource>(std::move(*opened));
      else result = opened.status();
    }
    if (!refused && request.source) {
      if (table) {
        table->configure(request.options);
        table->start(request.source.get(), &stop_);
      }
      result = acquisition::acquire(*request.source, request.options, &stop_,
                                    [this, &table](acquisition::AcquisitionBatch&& b) {
                                      if (table) table->observe(b);
                                      push(std::move(b));
                                    });
      if (table) {
        // The recording is over: a runner still going brings the table to
        // rest now; the run finishes only once it has.
        table->finish(result ? (result->incompleteReason.empty() ? std::string("the recording ended")
                                                                 : result->incompleteReason)
                             : result.status().message());
        request.source->flushToDevice(std::chrono::milliseconds(200));
        if (result && !result->sessionPath.empty()) (void)session::appendTableLog(result->sessionPath, table->drainLog());
      }
    }
    // A serial port is closed in the thread that read it.
    request.source.reset();
    std::shared_ptr<RunOutcome> outcome;
    if (result) {
      outcome = std::make_shared<RunOutcome>();
      outcome->info = request.options.info;
      outcome->sessionPath = result->sessionPath;
      outcome->complete = result->complete;
      outcome->incompleteReason = result->incompleteReason;
      outcome->recording = std::move(result->recording);
      outcome->report = std::move(result->report);
      outcome->truth = request.truth;
      outcome->imuDelayLimitMs = request.options.reportContext.imuDelayLimitMs;
      outcome->coverageK = request.options.reportContext.coverageK;
      // The result the run stored is the session's first: shown as such.
      if (!outcome->sessionPath.empty() && outcome->report)
        if (auto opened = session::openSessionOrStream(outcome->sessionPath, session::OpenOptions::sessionRecords())) {
          outcome->results = std::move(opened->results);
          if (const auto* newest = newestUsable(outcome->results)) outcome->shownResultId = newest->id;
        }
      completeOutcome(*outcome, request.options.reportContext.source);
    }
    const QString error = result ? QString() : QString::fromStdString(result.status().message());
    QMetaObject::invokeMethod(
        this,
        [this, outcome, error] {
          running_ = false;
          if (outcome) emit finished(outcome);
          else emit failed(error);
        },
        Qt::QueuedConnection);
  });
  return true;
}

void AcquisitionRunner::stop() { stop_.store(true); }

void AcquisitionRunner::push(acquisition::AcquisitionBatch&& batch) {
  std::lock_guard lock(mutex_);
  bufferedFrames_ += batch.frames.size();
  buffer_.push_back(std::move(batch));
  // Drop the oldest frames for display, keeping the newest batch's counters.
  while (bufferedFrames_ > kMaxBufferedFrames && buffer_.size() > 1) {
    bufferedFrames_ -= buffer_.front().frames.size();
    dropped_ += buffer_.front().frames.size();
    buffer_.erase(buffer_.begin());
  }
}

std::vector<acquisition::AcquisitionBatch> AcquisitionRunner::takeBatches() {
  std::lock_guard lock(mutex_);
  std::vector<acquisition::AcquisitionBatch> out;
  out.swap(buffer_);
  bufferedFrames_ = 0;
  return out;
}

}  // namespace fog::ui

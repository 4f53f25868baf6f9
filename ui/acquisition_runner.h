#pragma once
// The bridge between the Qt-free acquisition run and the widgets: runs
// acquisition::acquire() on a worker thread and hands its decoded frames to
// the GUI through a bounded buffer that the GUI drains on its own timer
// (about 30 times a second; never a signal per frame).
//
//   AcquisitionRunner runner;
//   connect(&runner, &AcquisitionRunner::finished, view, &View::show);
//   runner.start(request);          // returns at once
//   ... every 33 ms: for (auto& b : runner.takeBatches()) live.add(b.frames);
//   runner.stop();                  // any time; the run ends incomplete, data kept
//
// One run at a time. Exactly one of finished / failed ends every started run
// (a stopped run finishes, marked incomplete, with what it recorded), and
// isRunning() is true until it is emitted. The worker never waits on the GUI
// and never touches a widget; it shares with the GUI thread only the atomic
// stop flag and the mutex-guarded buffer. If the GUI falls behind, the oldest
// batches are dropped from the buffer (droppedFrames() counts them): the
// display thins, the recording never does. Destroying the runner stops a run
// and waits for its worker.

#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/acquisition/acquisition.h"
#include "ui/run_outcome.h"

namespace fog::ui {

class TableDrive;

struct RunRequest {
  std::shared_ptr<acquisition::ByteSource> source;
  // Instead of `source`: opens the source in the worker thread, for sources
  // that must be opened and read in one thread (a serial port).
  std::function<Result<std::unique_ptr<acquisition::ByteSource>>()> openSource;
  acquisition::AcquisitionOptions options;
  std::vector<model::TestPointTruth> truth;  // when the simulator is the source
  // A table-driven run (docs/table-control.md): the worker connects it and
  // checks the plan before it opens the source (a refused plan records
  // nothing), drives the table while it records, and brings the table to
  // rest before the run finishes (Stop, the window closing, any fault).
  std::shared_ptr<TableDrive> table;
};

class AcquisitionRunner : public QObject {
  Q_OBJECT

 public:
  // At 1.5 kHz of frames, about three minutes of display backlog.
  static constexpr std::size_t kMaxBufferedFrames = 300000;

  explicit AcquisitionRunner(QObject* parent = nullptr);
  ~AcquisitionRunner() override;

  // Starts a run; false (and nothing emitted) while another run is active.
  bool start(RunRequest request);
  // Asks the worker to end the run at its next read; harmless when idle.
  void stop();
  bool isRunning() const { return running_; }

  // The batches decoded since the previous call, oldest first (GUI thread).
  std::vector<acquisition::AcquisitionBatch> takeBatches();
  std::uint64_t droppedFrames() const { return dropped_.load(); }

 signals:
  void finished(std::shared_ptr<const fog::ui::RunOutcome> outcome);
  // Nothing could be recorded (the session file could not be created or
  // written); the message says what to do.
  void failed(const QString& message);

 private:
  void push(acquisition::AcquisitionBatch&& batch);

  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::vector<acquisition::AcquisitionBatch> buffer_;  // guarded by mutex_
  std::size_t bufferedFrames_ = 0;                      // guarded by mutex_
  std::atomic<std::uint64_t> dropped_{0};
  QFuture<void> future_;
  bool running_ = false;
};

}  // namespace fog::ui

Q_DECLARE_METATYPE(std::shared_ptr<const fog::ui::RunOutcome>)

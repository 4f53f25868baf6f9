#pragma once
// The bridge between the Qt-free core and the widgets: runs a test plan on
// the simulator, decodes its byte stream and analyses it, all off the GUI
// thread, and reports back with signals emitted in the runner's own (GUI)
// thread, so receivers never see a worker thread.
//
//   BenchRunner runner;
//   connect(&runner, &BenchRunner::finished, window, &Window::show...);
//   runner.start(job);      // returns at once
//   runner.cancel();        // any time; `cancelled` follows
//
// One run at a time. Exactly one of finished / failed / cancelled ends every
// started run, and isRunning() is true until it is emitted. The worker never
// waits on the GUI and never touches a widget; the only state it shares with
// the GUI thread is the atomic cancel flag. Destroying the runner cancels a
// run and waits for its worker.

#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "analysis/delay_analysis.h"
#include "common/recording.h"
#include "model/sim_config.h"
#include "model/simulator.h"
#include "ui/test_point_traces.h"

namespace fog::ui {

struct BenchJob {
  TestPlan plan;
  model::SimConfig config;
  analysis::BenchConstants constants;
  double chunkS = 0.5;  // simulated time per streaming step (progress granularity)
};

struct BenchProgress {
  double simulatedS = 0.0, totalS = 0.0;  // simulated session time so far / in all
  double remainingS = 0.0;                // wall-clock estimate for the simulation
  bool analysing = false;                 // simulation done, decoding finished, fitting
  StreamHealth health;                    // decoder counters so far
};

struct BenchOutcome {
  Recording recording;
  analysis::DelayReport report;
  std::vector<model::TestPointTruth> truth;
  std::vector<TestPointTraces> traces;  // one per report point, same order
  std::string reportText;               // formatReportText with the simulator's truth
};

class BenchRunner : public QObject {
  Q_OBJECT

 public:
  explicit BenchRunner(QObject* parent = nullptr);
  ~BenchRunner() override;

  // Starts a run; false (and nothing emitted) while another run is active.
  bool start(const BenchJob& job);
  // Asks the worker to stop at its next step; harmless when idle.
  void cancel();
  bool isRunning() const { return running_; }

 signals:
  // At most ~25 per second.
  void progressed(const fog::ui::BenchProgress& progress);
  void finished(std::shared_ptr<const fog::ui::BenchOutcome> outcome);
  void failed(const QString& message);
  void cancelled();

 private:
  void post(std::function<void()> inGuiThread);

  std::atomic<bool> cancel_{false};  // the only state shared with the worker
  QFuture<void> future_;
  bool running_ = false;
};

}  // namespace fog::ui

Q_DECLARE_METATYPE(fog::ui::BenchProgress)
Q_DECLARE_METATYPE(std::shared_ptr<const fog::ui::BenchOutcome>)

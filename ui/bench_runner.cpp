#include "ui/bench_runner.h"

#include <QMetaObject>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <chrono>
#include <functional>

#include "analysis/report_writer.h"
#include "common/version.h"
#include "protocol/decoder.h"
#include "protocol/recording_builder.h"

namespace fog::ui {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kProgressInterval = std::chrono::milliseconds(40);

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

analysis::ReportContext reportContext(const BenchJob& job, const analysis::DelayReport& report,
                                      const std::vector<model::TestPointTruth>& truth) {
  analysis::ReportContext context;
  context.source = "simulator, seed " + std::to_string(job.config.seed) + ", fogbench " + FOG_VERSION;
  // The report pairs trueLagMs with its points by position; a test point that
  // gave no delay is missing from report.points, so match by index.
  for (const auto& point : report.points) {
    const auto t = std::find_if(truth.begin(), truth.end(),
                                [&](const model::TestPointTruth& x) { return x.index == point.index; });
    if (t == truth.end()) break;
    context.trueLagMs.push_back(t->lagS * 1e3);
  }
  return context;
}

// The whole run, on a worker thread. A null outcome means cancelled.
Result<std::shared_ptr<BenchOutcome>> runJob(const BenchJob& job, const std::atomic<bool>& cancel,
                                             const std::function<void(const BenchProgress&)>& onProgress) {
  auto simulator = model::Simulator::create(job.config, job.plan);
  if (!simulator) return simulator.status();
  model::Simulator& sim = **simulator;

  // Decoded as it is produced, like a live board: the byte stream is never
  // held whole, and the frame counters are live.
  protocol::Decoder decoder;
  protocol::RecordingBuilder builder;
  std::vector<std::uint8_t> bytes;
  std::vector<protocol::DecodedFrame> frames;
  const auto started = Clock::now();
  auto lastProgress = started - kProgressInterval;
  const double totalS = sim.endS();
  const double chunkS = job.chunkS > 0.0 ? job.chunkS : 0.5;
  bool more = true;
  for (double untilS = chunkS; more; untilS += chunkS) {
    if (cancel.load()) return std::shared_ptr<BenchOutcome>();
    more = sim.advance(untilS, bytes);
    decoder.push(bytes, frames);
    builder.add(frames);
    bytes.clear();
    frames.clear();
    if (Clock::now() - lastProgress >= kProgressInterval) {
      lastProgress = Clock::now();
      BenchProgress p;
      p.totalS = totalS;
      p.simulatedS = std::min(untilS, totalS);
      const double fraction = totalS > 0.0 ? p.simulatedS / totalS : 1.0;
      p.remainingS = fraction > 0.0 ? secondsSince(started) * (1.0 - fraction) / fraction : 0.0;
      p.health = decoder.health();
      onProgress(p);
    }
  }
  if (builder.framesAdded() == 0)
    return corruptData("the simulator produced no decodable sampling-board frames");

  auto outcome = std::make_shared<BenchOutcome>();
  outcome->recording = builder.finish(decoder.health());
  outcome->truth = sim.truth();
  BenchProgress analysing;
  analysing.simulatedS = analysing.totalS = totalS;
  analysing.analysing = true;
  analysing.health = outcome->recording.health;
  onProgress(analysing);

  auto report = analysis::analyzeRecording(outcome->recording, job.constants);
  if (!report) return report.status();
  if (cancel.load()) return std::shared_ptr<BenchOutcome>();
  outcome->report = std::move(*report);

  const double scale = outcome->recording.pulseEquivalentDeg > 0.0 ? 1.0 : job.constants.pulseEquivalentDeg;
  for (const auto& point : outcome->report.points) {
    const auto& points = outcome->recording.testPoints;
    const auto data = std::find_if(points.begin(), points.end(),
                                   [&](const TestPointData& d) { return d.index == point.index; });
    Result<TestPointTraces> traces =
        data == points.end() ? Result<TestPointTraces>(insufficientData("no data")) : makeTestPointTraces(*data, point, scale);
    if (traces) {
      outcome->traces.push_back(std::move(*traces));
    } else {
      TestPointTraces empty;  // keeps traces aligned with report.points
      empty.index = point.index;
      outcome->traces.push_back(std::move(empty));
    }
  }
  outcome->reportText =
      analysis::formatReportText(outcome->report, reportContext(job, outcome->report, outcome->truth));
  return outcome;
}

}  // namespace

BenchRunner::BenchRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<fog::ui::BenchProgress>();
  qRegisterMetaType<std::shared_ptr<const fog::ui::BenchOutcome>>();
}

BenchRunner::~BenchRunner() {
  cancel_.store(true);
  future_.waitForFinished();
}

bool BenchRunner::start(const BenchJob& job) {
  if (running_) return false;
  running_ = true;
  cancel_.store(false);
  future_ = QtConcurrent::run([this, job] {
    auto result = runJob(job, cancel_, [this](const BenchProgress& p) { post([this, p] { emit progressed(p); }); });
    post([this, result = std::move(result)] {
      running_ = false;
      if (!result) emit failed(QString::fromStdString(result.status().toString()));
      else if (!*result) emit cancelled();
      else emit finished(std::shared_ptr<const BenchOutcome>(*result));
    });
  });
  return true;
}

void BenchRunner::cancel() { cancel_.store(true); }

void BenchRunner::post(std::function<void()> inGuiThread) {
  QMetaObject::invokeMethod(this, std::move(inGuiThread), Qt::QueuedConnection);
}

}  // namespace fog::ui

// fog_bench_live: the live pipeline of the desktop bench, measured in the
// real window (offscreen platform unless a display is set): frames per
// second from the source through the decoder to the live plots, plot
// refreshes per second, and how late the GUI event loop answers (a 5 ms
// probe timer: its lateness is the longest time any event was blocked).
//
//   fog_bench_live [--seconds S]
//
// Scenarios: the simulator at real time with a three-axis plan (X, Y, Z test
// points, 1 Hz / 3 deg), and the replay of a recorded session at 20x.
// Not a test: it prints figures (docs/benchmarks.md) and asserts nothing.

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/acquisition/acquisition.h"
#include "core/acquisition/simulator_source.h"
#include "ui/live_view.h"
#include "ui/main_window.h"
#include "ui/plan_editor.h"

namespace {

struct Figures {
  double seconds = 0;
  std::uint64_t frames = 0;
  int refreshes = 0;
  std::vector<double> latenessMs;
};

// Runs the window's current source for `seconds` (or to its end) and measures.
Figures measure(fog::ui::MainWindow& window, double seconds) {
  Figures f;
  QElapsedTimer clock;
  QTimer probe;
  probe.setTimerType(Qt::PreciseTimer);
  probe.setInterval(5);
  qint64 last = 0;
  QObject::connect(&probe, &QTimer::timeout, [&] {
    const qint64 now = clock.nsecsElapsed();
    if (last > 0) f.latenessMs.push_back(std::max(0.0, static_cast<double>(now - last) / 1e6 - 5.0));
    last = now;
  });
  // Count plot refreshes by watching the live table plot repaint requests.
  QTimer counter;
  std::uint64_t lastShown = 0;
  counter.setInterval(1);
  QObject::connect(&counter, &QTimer::timeout, [&] {
    const auto shown = window.liveView()->traces().framesSeen();
    if (shown != lastShown) {
      ++f.refreshes;
      lastShown = shown;
    }
  });
  window.startRun();
  clock.start();
  probe.start();
  counter.start();
  while (window.isRunning() && static_cast<double>(clock.elapsed()) < seconds * 1000.0) QApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
  f.seconds = static_cast<double>(clock.elapsed()) / 1e3;
  f.frames = window.liveView()->traces().framesSeen();
  probe.stop();
  counter.stop();
  if (window.isRunning()) {
    window.stopRun();
    while (window.isRunning()) QApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
  }
  return f;
}

void print(const char* name, Figures f) {
  std::sort(f.latenessMs.begin(), f.latenessMs.end());
  auto pct = [&](double p) {
    return f.latenessMs.empty() ? 0.0 : f.latenessMs[static_cast<std::size_t>(p * static_cast<double>(f.latenessMs.size() - 1))];
  };
  std::printf("%-40s %6.1f s  %9.0f frames/s  %5.1f plot updates/s  event lateness: median %.2f ms, p99 %.2f ms, max %.2f ms\n",
              name, f.seconds, static_cast<double>(f.frames) / f.seconds, static_cast<double>(f.refreshes) / f.seconds, pct(0.5), pct(0.99),
              f.latenessMs.empty() ? 0.0 : f.latenessMs.back());
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("fogbench-bench");
  double seconds = 20.0;
  const auto args = QApplication::arguments();
  const int i = static_cast<int>(args.indexOf("--seconds"));
  if (i > 0 && i + 1 < args.size()) seconds = args[i + 1].toDouble();

  QTemporaryDir dir;
  fog::ui::MainWindow window;
  window.setSessionFolder(dir.path());
  window.resize(1500, 950);
  window.show();

  // Three axes at real time, recorded into a session.
  fog::TestPlan plan;
  for (auto axis : {fog::Axis::kX, fog::Axis::kY, fog::Axis::kZ}) {
    fog::TestPoint p;
    p.axis = axis;
    p.frequencyHz = 1.0;
    p.amplitudeDeg = 3.0;
    p.durationS = seconds / 3.0;
    p.settleS = 1.0;
    plan.points.push_back(p);
  }
  window.planEditor()->setPlan(plan);
  window.useSimulator(1.0, 1);
  print("simulator, 3 axes, real time", measure(window, seconds));

  // The paper's fast condition recorded as fast as possible, then replayed at 20x.
  window.planEditor()->loadPreset("paper-fast");
  window.useSimulator(0.0, 2);
  measure(window, 600.0);
  const auto* outcome = window.lastOutcome();
  if (!outcome || outcome->sessionPath.empty()) {
    std::fprintf(stderr, "fog_bench_live: the recording for the replay failed\n");
    return 1;
  }
  window.useReplay(QString::fromStdString(outcome->sessionPath), 20.0);
  print("replay of a 63-s session at 20x", measure(window, seconds));
  window.useSimulator(0.0, 3);
  window.planEditor()->loadPreset("paper-fast");
  print("simulator, as fast as possible", measure(window, seconds));
  return 0;
}

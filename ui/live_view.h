#pragma once
// The live view of a run: the turntable angle and the integrated gyro angle
// (bias and Earth-rate trend removed on the fly) of the swinging axis,
// scrolling over the last few seconds, with progress for the test point and
// the whole plan. It paints only what the GUI timer hands it (about 30 times
// a second); it never talks to the worker.
//
// Mouse (as on every plot, ui/plots/plot_interaction.h): wheel zooms the time
// axis, drag pans it, clicks set cursors A and B (Δt and the values read
// out), right-click removes them; the tracker lists both angles at the
// mouse's time. The two plots' time axes are linked. Zooming or panning
// stops the scrolling; "Follow live" or a double-click resumes it.

#include <QElapsedTimer>
#include <QWidget>
#include <optional>
#include <span>

#include "core/acquisition/live_traces.h"
#include "core/common/test_plan.h"
#include "ui/table_drive.h"

class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QDoubleSpinBox;
class QwtPlot;
class QwtPlotCurve;

namespace fog::ui {
class TimeAxisLink;
}

namespace fog::ui {

class LiveView : public QWidget {
  Q_OBJECT

 public:
  explicit LiveView(QWidget* parent = nullptr);

  // A new run of `plan` (empty plan: unknown, e.g. a serial board's own).
  // benchPulseEquivalentDeg: acquisition::LiveTraces::setBenchPulseEquivalent.
  void startRun(const TestPlan& plan, double speed, double benchPulseEquivalentDeg = 0.0);
  void addFrames(std::span<const protocol::DecodedFrame> frames);
  // Redraws with everything added since the last call.
  void refresh();
  void endRun();
  // The table driver in use for the run ("simulator", a controller's
  // description); empty: the bench does not drive the table (a serial
  // board's own plan, a replay) and the table status is hidden. Call before
  // startRun().
  void setTableDriver(const QString& driver);
  // A driven table's status (remote, manual; ui/table_drive.h), about 30
  // times a second while it runs; nullopt for the simulator's table, whose
  // status comes from the stream alone. The point and phase the runner is
  // at also place the plots and progress (a board that sends no test-point
  // markers).
  void setTableSnapshot(const std::optional<TableSnapshot>& snapshot);

  // The table status (issue 17): the driver, the mode, the commanded swing of
  // the current point and the one measured from the table-angle stream
  // (fitted over the last max(2 periods, 1 s)), faults and interlocks.
  QString tableMode() const;
  double measuredAmplitudeDeg() const { return measuredAmplitudeDeg_; }  // NaN until measured
  double measuredFrequencyHz() const { return measuredFrequencyHz_; }
  QGroupBox* tableStatusBox() const { return tableBox_; }

  const acquisition::LiveTraces& traces() const { return traces_; }
  // Points currently drawn in the table / gyro curve (after thinning).
  std::size_t shownTablePoints() const;
  std::size_t shownGyroPoints() const;
  QwtPlot* tablePlot() const { return tablePlot_; }
  QwtPlot* gyroPlot() const { return gyroPlot_; }
  // Progress of the current test point and of the plan, 0..1.
  double pointProgress() const;
  double planProgress() const;
  QString remainingText() const;

 private:
  QwtPlot* makePlot(const QString& title, const QString& yTitle, QwtPlotCurve** curve, const QColor& colour,
                    const QString& unit);
  void setFollowing(bool following);
  void updateProgress();
  void updateTableStatus();
  void showDrivenMode();  // mode, faults and step of a driven table (snapshot_)

  acquisition::LiveTraces traces_{120.0};
  TestPlan plan_;
  double speed_ = 1.0;
  bool following_ = true;
  bool dirty_ = false;
  TimeAxisLink* timeLink_ = nullptr;  // the two plots' time axes
  QElapsedTimer wall_;

  QwtPlot* tablePlot_ = nullptr;
  QwtPlot* gyroPlot_ = nullptr;
  QwtPlotCurve* tableCurve_ = nullptr;
  QwtPlotCurve* gyroCurve_ = nullptr;
  QLabel* stateLabel_ = nullptr;
  QProgressBar* pointBar_ = nullptr;
  QProgressBar* planBar_ = nullptr;
  QLabel* remainingLabel_ = nullptr;
  QDoubleSpinBox* windowSpin_ = nullptr;
  QPushButton* followButton_ = nullptr;

  QString tableDriver_;
  bool running_ = false;
  double measuredAmplitudeDeg_ = 0.0, measuredFrequencyHz_ = 0.0;
  QGroupBox* tableBox_ = nullptr;
  QLabel* tableDriverLabel_ = nullptr;
  QLabel* tableModeLabel_ = nullptr;
  QLabel* tableCommandedLabel_ = nullptr;
  QLabel* tableMeasuredLabel_ = nullptr;
  QLabel* tableFaultsLabel_ = nullptr;
  QLabel* tableStepLabel_ = nullptr;
  QLabel* tableStepTitle_ = nullptr;
  std::optional<TableSnapshot> snapshot_;
};

}  // namespace fog::ui

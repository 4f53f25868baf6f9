#pragma once
// The bench window: choose a plan preset and a seed, Run (or Stop), watch
// progress, then inspect each test point: normalised table and gyro angles
// with their fitted sinusoids, the fit residuals, and the delay report.
//
// The window owns a BenchRunner and only reacts to its signals; it never
// waits for the worker. Failures are shown in the status bar and the report
// panel.

#include <QElapsedTimer>
#include <QMainWindow>
#include <memory>

#include "analysis/delay_analysis.h"
#include "ui/bench_runner.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace fog::ui {

class SeriesPlot;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Selects a preset by name (see benchPresets()); false for an unknown name.
  bool selectPreset(const QString& name);
  void setSeed(int seed);
  bool isRunning() const;

  // The report of the last finished run, null before one finished.
  const analysis::DelayReport* lastReport() const;
  QString reportText() const;
  SeriesPlot* anglePlot() const { return anglePlot_; }
  SeriesPlot* residualPlot() const { return residualPlot_; }

 public slots:
  void startRun();
  void stopRun();

 signals:
  // Every started run ends with this, once its results (or error) are shown.
  void runEnded(bool succeeded);

 private:
  void buildControls();
  void buildResults();
  void setRunning(bool running);
  void showProgress(const BenchProgress& progress);
  void showOutcome(std::shared_ptr<const BenchOutcome> outcome);
  void showFailure(const QString& message);
  void showCancelled();
  void showTestPoint(int position);
  void showHealth(const StreamHealth& health);

  BenchRunner runner_;
  std::shared_ptr<const BenchOutcome> outcome_;
  QElapsedTimer runClock_;

  QComboBox* presetCombo_ = nullptr;
  QSpinBox* seedSpin_ = nullptr;
  QPushButton* runButton_ = nullptr;
  QPushButton* stopButton_ = nullptr;
  QProgressBar* progressBar_ = nullptr;
  QLabel* remainingLabel_ = nullptr;
  QLabel* framesLabel_ = nullptr;
  QComboBox* testPointCombo_ = nullptr;
  QLabel* lagLabel_ = nullptr;
  SeriesPlot* anglePlot_ = nullptr;
  SeriesPlot* residualPlot_ = nullptr;
  QPlainTextEdit* reportView_ = nullptr;
};

}  // namespace fog::ui

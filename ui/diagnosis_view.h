#pragma once
// The sim-to-real diagnosis of the shown result (core/diagnosis): the verdict
// and the gap per channel; the real and the simulated (replayed) gyro
// residual curves overlaid; the gap map as a heat map (z-scores of every
// residual feature against the simulator's spread, per test point and time
// segment); the residual spectrum (harmonics of the gyro and the table, real
// beside simulated); and the held-out shrink of every candidate effect.
//
// While a diagnosis runs (12-20 s) the view shows a progress bar with the
// stage and a Cancel button, and no plots until the result is there; a
// cancelled diagnosis leaves the view saying so, with no result.

#include <QWidget>
#include <memory>

#include "core/diagnosis/diagnosis.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QStackedWidget;
class QwtPlot;
class QwtPlotSpectrogram;

namespace fog::ui {

class PlotInteraction;

class DiagnosisView : public QWidget {
  Q_OBJECT

 public:
  enum class State { kIdle, kRunning, kShown, kCancelled, kFailed };

  explicit DiagnosisView(QWidget* parent = nullptr);

  // A diagnosis of `title` has started: progress bar and Cancel, no plots.
  void startDiagnosis(const QString& title);
  // Progress reported by the diagnosis (fraction in [0, 1], the core's
  // stage name); ignored unless running.
  void setProgress(double fraction, const std::string& stage);
  void showDiagnosis(std::shared_ptr<const diagnosis::Diagnosis> diagnosis, const QString& title);
  // The diagnosis was cancelled: no result, the view says so.
  void showCancelled(const QString& title);
  // Why there is no diagnosis (a failure), or what to do to get one.
  void showMessage(const QString& message);
  const diagnosis::Diagnosis* diagnosis() const { return diagnosis_.get(); }
  State state() const { return state_; }
  // The core's stage names ("replays", ...) in the GUI's language.
  static QString stageText(const std::string& stage);

  QProgressBar* progressBar() const { return progress_; }
  QPushButton* cancelButton() const { return cancel_; }
  // The IMU's bias instability as the operator stated it (its static noise
  // test) into the options of the next diagnosis; unstated, the options keep
  // the simulator's default. Remembered between runs (QSettings, group
  // "diagnosis").
  void applyStatedNoise(diagnosis::DiagnosisOptions& options) const;
  QCheckBox* noiseStatedBox() const { return noiseStated_; }
  QDoubleSpinBox* instabilitySpin() const { return instability_; }
  QDoubleSpinBox* correlationSpin() const { return correlation_; }
  QString stageShown() const;
  // The plots are shown (only with a result).
  bool plotsShown() const;

  QwtPlot* curvePlot() const { return curvePlot_; }
  QwtPlot* gapMapPlot() const { return gapMapPlot_; }
  QwtPlot* spectrumPlot() const { return spectrumPlot_; }
  QwtPlot* shrinkPlot() const { return shrinkPlot_; }
  PlotInteraction* curveInteraction() const { return curveInteraction_; }
  QString verdictText() const;
  // Rows and columns of the heat map shown now.
  int gapMapRows() const { return static_cast<int>(rowNames_.size()); }
  int gapMapColumns() const { return static_cast<int>(columnNames_.size()); }

 signals:
  // The operator pressed Cancel while a diagnosis runs.
  void cancelRequested();

 private:
  // The constructor's sections, top to bottom.
  QHBoxLayout* buildVerdictRow();
  QHBoxLayout* buildNoiseRow();
  QWidget* buildProgressRow();
  QWidget* buildPlots();
  QStackedWidget* buildResultStack(QWidget* plots);

  void showPoint(int position);
  void showGapMap();
  void showShrink();

  void showPlaceholder(const QString& text);
  void setVerdict(const QString& text);  // and the label's height for its lines
  void fitVerdictHeight();
  void fitGapMapColumns();

  std::shared_ptr<const diagnosis::Diagnosis> diagnosis_;
  State state_ = State::kIdle;
  QWidget* progressRow_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* stage_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QStackedWidget* stack_ = nullptr;
  QLabel* placeholder_ = nullptr;
  QStringList rowNames_, columnNames_;
  QLabel* verdict_ = nullptr;
  QLabel* pointLabel_ = nullptr;
  QComboBox* pointCombo_ = nullptr;
  QCheckBox* noiseStated_ = nullptr;
  QDoubleSpinBox* instability_ = nullptr;
  QDoubleSpinBox* correlation_ = nullptr;
  QwtPlot* curvePlot_ = nullptr;
  QwtPlot* gapMapPlot_ = nullptr;
  QwtPlot* spectrumPlot_ = nullptr;
  QwtPlot* shrinkPlot_ = nullptr;
  QwtPlotSpectrogram* gapMap_ = nullptr;
  PlotInteraction* curveInteraction_ = nullptr;
  PlotInteraction* gapMapInteraction_ = nullptr;
  PlotInteraction* spectrumInteraction_ = nullptr;
  PlotInteraction* shrinkInteraction_ = nullptr;
  QPlainTextEdit* text_ = nullptr;
};

}  // namespace fog::ui

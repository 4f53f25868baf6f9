#pragma once
// The sim-to-real diagnosis of the shown result (core/diagnosis): the verdict
// and the gap per channel; the real and the simulated (replayed) gyro
// residual curves overlaid; the gap map as a heat map (z-scores of every
// residual feature against the simulator's spread, per test point and time
// segment); the residual spectrum (harmonics of the gyro and the table, real
// beside simulated); and the held-out shrink of every candidate effect.

#include <QWidget>
#include <memory>

#include "diagnosis/diagnosis.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QwtPlot;
class QwtPlotSpectrogram;

namespace fog::ui {

class DiagnosisView : public QWidget {
  Q_OBJECT

 public:
  explicit DiagnosisView(QWidget* parent = nullptr);

  void showDiagnosis(std::shared_ptr<const diagnosis::Diagnosis> diagnosis, const QString& title);
  void showMessage(const QString& message);
  const diagnosis::Diagnosis* diagnosis() const { return diagnosis_.get(); }

  QwtPlot* curvePlot() const { return curvePlot_; }
  QwtPlot* gapMapPlot() const { return gapMapPlot_; }
  QwtPlot* spectrumPlot() const { return spectrumPlot_; }
  QwtPlot* shrinkPlot() const { return shrinkPlot_; }
  QString verdictText() const;
  // Rows and columns of the heat map shown now.
  int gapMapRows() const { return static_cast<int>(rowNames_.size()); }
  int gapMapColumns() const { return static_cast<int>(columnNames_.size()); }

 private:
  void showPoint(int position);
  void showGapMap();
  void showShrink();

  std::shared_ptr<const diagnosis::Diagnosis> diagnosis_;
  QStringList rowNames_, columnNames_;
  QLabel* verdict_ = nullptr;
  QComboBox* pointCombo_ = nullptr;
  QwtPlot* curvePlot_ = nullptr;
  QwtPlot* gapMapPlot_ = nullptr;
  QwtPlot* spectrumPlot_ = nullptr;
  QwtPlot* shrinkPlot_ = nullptr;
  QwtPlotSpectrogram* gapMap_ = nullptr;
  QPlainTextEdit* text_ = nullptr;
};

}  // namespace fog::ui

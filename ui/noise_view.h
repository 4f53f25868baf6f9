#pragma once
// Gyro noise of the shown result's static segments (core/noise): the
// overlapping Allan deviation on log-log axes with its confidence band, the
// identified IEEE 952 noise terms as lines and their sum, and the table of
// terms with uncertainties and the tau range each came from; the bias and
// its Earth-rate-corrected value. A result without a static segment says how
// to get one.

#include <QWidget>
#include <memory>
#include <vector>

#include "core/noise/gyro_noise.h"

class QComboBox;
class QLabel;
class QTableWidget;
class QwtPlot;

namespace fog::ui {

class PlotInteraction;

class NoiseView : public QWidget {
  Q_OBJECT

 public:
  explicit NoiseView(QWidget* parent = nullptr);

  void showReports(std::vector<noise::GyroNoiseReport> reports);
  void showMessage(const QString& message);
  const std::vector<noise::GyroNoiseReport>& reports() const { return reports_; }
  QwtPlot* allanPlot() const { return plot_; }
  QTableWidget* termTable() const { return table_; }
  QString summaryText() const;
  // False while the view has no analysis to draw: it shows only why (an
  // empty 0..1000 plot would look like a result).
  bool plotShown() const;

 private:
  void showSegment(int position);

  std::vector<noise::GyroNoiseReport> reports_;
  QLabel* summary_ = nullptr;
  QComboBox* segmentCombo_ = nullptr;
  QLabel* segmentLabel_ = nullptr;
  QWidget* content_ = nullptr;  // the plot and the term table
  QwtPlot* plot_ = nullptr;
  PlotInteraction* interaction_ = nullptr;
  QTableWidget* table_ = nullptr;
};

}  // namespace fog::ui

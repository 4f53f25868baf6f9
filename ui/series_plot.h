#pragma once
// A Qwt plot of dense time series that stays fast: every curve keeps its full
// data (shared, never copied) and is shown thinned to min/max per pixel column
// over the visible range, re-thinned after each zoom, pan or resize. Fitted
// functions are evaluated over the visible range at two points per pixel, so
// they stay smooth at any zoom. Antialiasing is off for data curves.
//
// Zoom: drag with the left button (right button: back one step); pan: middle
// button; magnify: wheel. The picker reads out (time, value) at the cursor.

#include <QPen>
#include <QString>
#include <QTimer>
#include <functional>
#include <memory>
#include <qwt_plot.h>
#include <vector>

#include "ui/test_point_traces.h"

class QwtPlotCurve;
class QwtPlotMagnifier;
class QwtPlotPanner;
class QwtPlotPicker;
class QwtPlotZoomer;

namespace fog::ui {

class SeriesPlot : public QwtPlot {
  Q_OBJECT

 public:
  SeriesPlot(const QString& title, const QString& yTitle, QWidget* parent = nullptr);
  ~SeriesPlot() override;

  void clearCurves();
  void addData(const QString& title, const QPen& pen, std::shared_ptr<const Trace> trace);
  void addFunction(const QString& title, const QPen& pen, std::function<double(double)> function);
  // Scales to the data's full extent and makes it the zoom base; call after adding curves.
  void showAll();

  int curveCount() const { return static_cast<int>(curves_.size()); }
  // Points of curve `i` in the full data (0 for a function) and as drawn now.
  std::size_t dataPoints(int i) const;
  std::size_t shownPoints(int i) const;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Curve {
    QwtPlotCurve* item = nullptr;  // owned by the plot
    std::shared_ptr<const Trace> data;
    std::function<double(double)> function;
  };
  void scheduleThinning();
  void thin();

  std::vector<Curve> curves_;
  QwtPlotZoomer* zoomer_ = nullptr;
  QwtPlotPanner* panner_ = nullptr;
  QwtPlotMagnifier* magnifier_ = nullptr;
  QwtPlotPicker* picker_ = nullptr;
  QTimer thinTimer_;
};

}  // namespace fog::ui

#pragma once
// A Qwt plot of dense time series that stays fast: every curve keeps its full
// data (shared, never copied) and is shown thinned to min/max per pixel column
// over the visible range, re-thinned after each zoom, pan or resize. Fitted
// functions are evaluated over the visible range at two points per pixel, so
// they stay smooth at any zoom. Antialiasing is off for data curves.
//
// Interaction (ui/plots/plot_interaction.h, as on every plot): wheel zoom, drag
// pan (both along time only; Ctrl for both axes), double-click for the whole
// data, click for measuring cursors A and B (Δt and every curve's value at
// both, from the full data). The tracker lists the time and every curve's
// value at the mouse (and those of plots linked with interaction()'s
// TimeAxisLink).

#include <QPen>
#include <QString>
#include <QTimer>
#include <functional>
#include <memory>
#include <qwt_plot.h>
#include <vector>

#include "ui/plot_data/test_point_traces.h"

class QwtPlotCurve;
class QwtPlotTextLabel;

namespace fog::ui {

class PlotInteraction;

class SeriesPlot : public QwtPlot {
  Q_OBJECT

 public:
  // valueUnit: appended to values in the cursor readout ("″"; "" for none).
  SeriesPlot(const QString& title, const QString& yTitle, const QString& valueUnit = QString(),
             QWidget* parent = nullptr);
  ~SeriesPlot() override;

  void clearCurves();
  // samples: each data point also drawn as a dot (for a few points).
  void addData(const QString& title, const QPen& pen, std::shared_ptr<const Trace> trace, bool samples = false);
  void addFunction(const QString& title, const QPen& pen, std::function<double(double)> function);
  // Scales to the data's full extent and makes it the zoom base; call after adding curves.
  void showAll();

  // A line shown in the middle of the plot while it has no curve (what to
  // do to fill it); "" for none.
  void setEmptyText(const QString& text);
  bool showsEmptyText() const;

  int curveCount() const { return static_cast<int>(curves_.size()); }
  // Points of curve `i` in the full data (0 for a function) and as drawn now.
  std::size_t dataPoints(int i) const;
  std::size_t shownPoints(int i) const;
  // Curve `i`'s value at time t: its data interpolated linearly (NaN outside
  // it), or its function.
  double valueAt(int i, double t) const;
  PlotInteraction* interaction() const { return interaction_; }
  // The time axis's title and unit (default "time (s)", 1 s).
  void setTimeAxis(const QString& title, double secondsPerUnit);

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
  void updateEmptyLabel();

  std::vector<Curve> curves_;
  PlotInteraction* interaction_ = nullptr;
  QTimer thinTimer_;
  QwtPlotTextLabel* emptyLabel_ = nullptr;  // owned by the plot
};

}  // namespace fog::ui

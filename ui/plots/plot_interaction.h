#pragma once
// One way to handle every plot of the bench (Results, Diagnosis, Noise):
//   wheel          zoom about the cursor (a time plot, Options::xOnlyZoom:
//                  the time axis only; Ctrl+wheel zooms both axes)
//   drag (left)    pan (a time plot: along time only; Ctrl+drag both ways)
//   double-click   back to the whole view ("home")
//   click          a measuring cursor: A, then B, then A again ...; the
//                  readout gives x at each, Δx (Δt as a duration on time
//                  axes) and every curve's value at A and B with its Δ
//   right-click    removes the cursors
// A hint in the canvas's corner says so; it is a widget over the canvas, so
// plot exports (QwtPlotRenderer) leave it out. The cursors are plot markers
// and do appear in exports; they stay attached to the plot (which owns them),
// so a view must not detach all of its plot's items (detach by type).
// The tracker (Options::tracker) follows the mouse and lists the time and
// every curve's value at that time, those of the plots linked to it too.
// A view's time plots share one time axis through a TimeAxisLink.

#include <QObject>
#include <QPointer>
#include <QPoint>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QLabel;
class QWidget;
class QwtPlot;
class QwtPlotMagnifier;
class QwtPlotMarker;
class QwtPlotPanner;

namespace fog::ui {

// The bench's plots on screen: the title in the widget's font, bold; axis
// titles in the widget's font, not bold (they wrap less on a small plot);
// the title label sized for the font it draws (no clipped descenders); the
// value axis' title kept whole on a short plot (a smaller font, down to
// 7 pt, then cut at its start so that its unit stays).
void useCompactTitles(QwtPlot* plot);

class PlotInteraction : public QObject {
  Q_OBJECT

 public:
  struct Options {
    bool cursors = false;     // measuring cursors (x-axis positions)
    bool timeAxis = true;     // x is a time: Δt reads as a duration
    double secondsPerX = 1.0; // a time axis's unit in seconds (1e-3: x in ms)
    QString xUnit;            // unit of x when it is not a time ("Hz")
    QString xName = QStringLiteral("x");  // its symbol in the readout when it is not a time ("f")
    QString yUnit;            // unit appended to the curves' values ("″", "")
    bool zoomX = true, zoomY = true;  // which axes the wheel zooms and a drag pans
    // A time plot: the wheel and a drag act on x only unless Ctrl is held
    // (then on both axes, where zoomY allows).
    bool xOnlyZoom = false;
    // A tracker at the mouse listing x and every curve's value there.
    bool tracker = false;
  };
  // A curve's name and its value at some x (the readout's lines).
  using Values = std::vector<std::pair<QString, double>>;

  PlotInteraction(QwtPlot* plot, Options options);

  // What the plot shows now becomes its home view (call after the view has
  // set its scales and replotted); or a function that brings the home view
  // back (a plot that rescales to its data).
  void setHome();
  void setHomeFunction(std::function<void()> home);
  // The curves' values at x for the cursor readout (default: none).
  void setValuesAt(std::function<Values(double x)> valuesAt);
  // A time axis's unit: 1 for seconds, 1e-3 for milliseconds.
  void setSecondsPerX(double secondsPerX);

  // Back to the home view (what a double-click does).
  void resetView();
  // Places the next cursor (A, then B, then A ...) at x; removes them.
  void placeCursor(double x);
  void clearCursors();
  int cursorCount() const;
  std::optional<double> cursor(int i) const;  // 0: A, 1: B
  // The readout's text (empty without cursors): the cursors' positions and
  // Δt, then a line per curve ("gyro: A 0.01 °, B 0.02 °, Δ 0.01 °"); what
  // the canvas shows of it (the first lines, as many as leave room); the
  // hint's text.
  QString readout() const;
  QString shownReadout() const;
  QString hint() const;
  // Call when the data changed: cursors go, values are read anew.
  void dataChanged();

  QwtPlot* plot() const { return plot_; }
  const Options& options() const { return options_; }
  // This plot's curves at x (setValuesAt's function; empty without one).
  Values valuesAt(double x) const;
  // The tracker's text at x: "t = 1.2345 s", then a line per curve with its
  // value ("gyro: 0.4521 °"), this plot's curves first, then those of every
  // plot linked to it (each with its own unit).
  QString trackerText(double x) const;
  class TimeAxisLink* timeAxisLink() const { return link_; }

 signals:
  // The operator zoomed or panned (not emitted for resetView()).
  void viewChangedByUser();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  friend class TimeAxisLink;
  void updateReadout();
  void placeOverlays();
  QString xText(double x) const;
  QStringList valueLines(double x) const;  // "name: value unit" per curve of this plot

  QwtPlot* plot_;
  // The plot's canvas, kept: events reach the filter while the plot is being
  // destroyed (its children go after ~QwtPlot), when plot_->canvas() is no
  // longer a call on a QwtPlot.
  QWidget* canvas_;
  Options options_;
  QwtPlotPanner* panner_ = nullptr;
  QwtPlotMagnifier* magnifier_ = nullptr;
  QPointer<TimeAxisLink> link_;
  QLabel* hint_ = nullptr;
  QLabel* readout_ = nullptr;
  QStringList readoutLines_;
  QwtPlotMarker* markers_[2] = {nullptr, nullptr};
  std::optional<double> cursors_[2];
  int nextCursor_ = 0;
  std::function<void()> homeFunction_;
  std::vector<std::pair<int, std::pair<double, double>>> home_;  // axis, interval
  std::function<Values(double)> valuesAt_;
  // A click places a cursor once it is clear it is not a double-click.
  QTimer clickTimer_;
  QPoint pressPos_;
  double pendingX_ = 0.0;
};

// The time plots of one view move together: when one's time axis changes
// (wheel, drag, double-click, or setAxisScale + replot from code) every other
// member takes its range. The members' trackers list the curves of all.
// A plot belongs to at most one link; the link must outlive none of its
// members' use (parent it to the view).
class TimeAxisLink : public QObject {
  Q_OBJECT

 public:
  explicit TimeAxisLink(QObject* parent = nullptr);
  void add(PlotInteraction* member);
  std::vector<PlotInteraction*> members() const;
  // While paused, ranges are not passed on (a view that sets every member's
  // range itself, as Live while it follows the stream).
  void setPaused(bool paused) { paused_ = paused; }

 signals:
  // A member's time range changed and the others took it.
  void rangeChanged(double lower, double upper);

 private:
  void follow(PlotInteraction* from);

  std::vector<QPointer<PlotInteraction>> members_;
  bool paused_ = false;
  bool passing_ = false;  // while setting the others: their own changes are not passed back
};

}  // namespace fog::ui

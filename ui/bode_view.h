#pragma once
// The gyro's frequency response as a Bode plot (docs/method.md "Frequency
// response"): magnitude (dB) and phase (degrees) of gyro angle / table angle
// against a log frequency axis, each test point with its ±1σ error bar and
// the model chosen by AIC drawn through them; below, every fitted model with
// χ², AIC, BIC, its parameters ± 1σ, the −3 dB bandwidth, the group delay
// and what the points cannot separate (strongly correlated parameters, a
// bandwidth beyond the highest point). Both plots share one frequency axis
// and have measuring cursors (ui/plots/plot_interaction.h).
//
// Beside the model table, a points table lists every point shown: its
// magnitude and phase with ±1σ, and the phase a certificate states —
// against the table's motion, with its expanded uncertainty U (k = 2) in
// degrees and in ms, the table read delay's uncertainty in its budget
// (analysis::certifiedPhase).
//
// Results shows one recording's responses (RunOutcome::responses, one per
// axis, chosen in the axis box); Compare shows two sessions' of the same axis
// and their difference B − A at the frequencies both have
// (analysis::responseDifference). Nothing is fitted here: the view draws the
// core's analysis.

#include <QWidget>
#include <optional>
#include <vector>

#include "core/analysis/frequency_response.h"
#include "ui/plot_data/bode_curves.h"

class QComboBox;
class QLabel;
class QTableWidget;
class QTabWidget;
class QwtPlot;

namespace fog::ui {

class PlotInteraction;

class BodeView : public QWidget {
  Q_OBJECT

 public:
  explicit BodeView(QWidget* parent = nullptr);
  // Stops hearing the model table before the widgets go: their teardown
  // resizes its sections, and fitNotesColumn must not run on a half-destroyed view.
  ~BodeView() override;

  // One recording's responses; `emptyReason` is shown when there are none.
  // Each model's row states its χ² p-value (marked when rejected) and why it
  // is not admissible; an axis with no chosen model (chosen = -1) shows its
  // points alone and "no model fits" with the response's noModelReason.
  void showResponses(std::vector<analysis::ResponseAnalysis> responses, const QString& emptyReason);
  // Two sessions' responses, named aName and bName (their letters in
  // Compare): per axis that both have, A, B and B − A.
  void showComparison(std::vector<analysis::ResponseAnalysis> a, std::vector<analysis::ResponseAnalysis> b,
                      const QString& aName, const QString& bName, const QString& emptyReason);
  // Nothing to draw: only why.
  void showMessage(const QString& message);

  bool plotShown() const;  // false while only a message is shown
  QComboBox* axisCombo() const { return axisCombo_; }
  QwtPlot* magnitudePlot() const { return magnitudePlot_; }
  QwtPlot* phasePlot() const { return phasePlot_; }
  PlotInteraction* magnitudeInteraction() const { return magnitudeInteraction_; }
  PlotInteraction* phaseInteraction() const { return phaseInteraction_; }
  QTableWidget* modelTable() const { return modelTable_; }
  // One row per point of the series shown (A's and B's in Compare, not the
  // difference): series, test point, f, |H| dB ± 1σ, phase ± 1σ, phase
  // against the table's motion, U (k = 2) in ° and in ms, lag ± 1σ.
  QTableWidget* pointTable() const { return pointTable_; }
  // The models' and the points' tables, one tab each.
  QTabWidget* tableTabs() const { return tableTabs_; }
  // The axis shown (its response's axis), or nothing while only a message is shown.
  std::optional<Axis> shownAxis() const;
  QString summaryText() const;
  // What the points cannot separate, per model (the table's last column).
  QString notesText() const;
  // The series drawn now (points and models), for tests.
  const std::vector<BodeSeries>& series() const { return series_; }

 private:
  // The content shown with these axes (Axis values) in the box, the first drawn.
  void showAxes(const std::vector<int>& axes);
  void showAxis(int position);
  void addModelRow(const QString& series, const analysis::ResponseModelFit& m, bool chosen, double atHz);
  void addPointRows(const QString& series, const analysis::ResponseAnalysis& r);
  // The notes column takes what the other columns leave of the table's
  // width, at least its header's (the other columns fit their contents).
  void fitNotesColumn();
  bool eventFilter(QObject* watched, QEvent* event) override;

  // Both inputs are kept: the series point at their models.
  std::vector<analysis::ResponseAnalysis> a_, b_;
  bool comparison_ = false;
  QString aName_, bName_;
  std::vector<BodeSeries> series_;
  QLabel* message_ = nullptr;
  QWidget* content_ = nullptr;
  QComboBox* axisCombo_ = nullptr;
  QLabel* summary_ = nullptr;
  QwtPlot* magnitudePlot_ = nullptr;
  QwtPlot* phasePlot_ = nullptr;
  PlotInteraction* magnitudeInteraction_ = nullptr;
  PlotInteraction* phaseInteraction_ = nullptr;
  QTableWidget* modelTable_ = nullptr;
  QTableWidget* pointTable_ = nullptr;
  QTabWidget* tableTabs_ = nullptr;
};

// Why a report has no frequency response: how many passed test points each
// axis has, and how to record one.
QString responseMissingText(const analysis::DelayReport& report);

}  // namespace fog::ui

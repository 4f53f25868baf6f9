#pragma once
// The result of a run or of a reviewed session: per test point the measured
// curves with their fitted sinusoids (normalised as in the paper) and the
// residuals, the fit table (period and phase in ms, amplitude), the delay
// breakdown (measured lag, + table read delay = IMU delay, − board delay =
// gyro's own delay) with uncertainties beside the paper's theory budget; the
// delay against frequency across test points; the frequency response as a
// Bode plot (ui/bode_view.h, a tab beside the fits); and the text report. Every plot
// can be exported (PNG/SVG/PDF), and the calibration report written as PDF.

#include <QWidget>
#include <limits>
#include <memory>
#include <vector>

#include "ui/report/calibration_report.h"
#include "ui/run_outcome.h"

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTabWidget;
class QVBoxLayout;
class QTableWidget;
class QToolButton;
class QwtPlot;
class QwtPlotMarker;

namespace fog::ui {

class BodeView;
class PlotInteraction;
class SeriesPlot;

class ResultView : public QWidget {
  Q_OBJECT

 public:
  explicit ResultView(QWidget* parent = nullptr);

  void showOutcome(std::shared_ptr<const RunOutcome> outcome);
  void clear();
  // The session's stored results, one per entry (newest last), the shown
  // one current; choosing another emits resultChosen with its id.
  QComboBox* resultCombo() const { return resultCombo_; }
  // The shown result in words: which of the session's results, when it was
  // stored, by which version, with which constants.
  QString resultDescription() const;
  // While another result is being loaded: the chooser says so and waits.
  void setChoosing(bool choosing);
  const RunOutcome* outcome() const { return outcome_.get(); }
  // Shared ownership of what is shown (for exporting off the widget).
  std::shared_ptr<const RunOutcome> sharedOutcome() const { return outcome_; }
  void showTestPoint(int position);
  // The verdict line of a test point: the shown stored result's verdict,
  // reasons and limit as stored (a record is never re-judged), or, for a
  // result not stored, the run's own judgement; an incomplete run's verdict
  // is INCOMPLETE. Says when this version's analysis differs from the record.
  QString verdictHtml(const analysis::TestPointResult& point) const;
  QString headlineHtml(const analysis::TestPointResult& point) const;
  QString decisionRuleHtml(const session::ShownVerdict& shown, const session::ShownPoint* point) const;

  SeriesPlot* anglePlot() const { return anglePlot_; }
  SeriesPlot* residualPlot() const { return residualPlot_; }
  QwtPlot* frequencyPlot() const { return frequencyPlot_; }
  // The frequency response of the shown result (RunOutcome::responses), in
  // the left tabs beside the fits; shown first for a recording with a
  // response of 5 or more frequencies.
  BodeView* bodeView() const { return bodeView_; }
  QTabWidget* leftTabs() const { return leftTabs_; }
  // Table and gyro angle (each minus its offset, in degrees) around a rising
  // zero crossing of the table's fit near the middle of the test point, with
  // both fits; x is milliseconds from the table fit's crossing; markers at 0
  // and at the fitted lag. The gap between the curves can be measured with
  // the cursors.
  SeriesPlot* zeroCrossingPlot() const { return zeroCrossingPlot_; }
  // The session time (s) of the table fit's zero crossing shown; the fitted
  // lag (ms) marked; NaN when there is none.
  double zeroCrossingTimeS() const { return zeroCrossingS_; }
  double zeroCrossingLagMs() const { return zeroCrossingLagMs_; }
  QTableWidget* fitTable() const { return fitTable_; }
  QTableWidget* delayTable() const { return delayTable_; }
  QString reportText() const;

  // What the calibration report of the shown result is drawn from: the
  // shown stored result's verdict and limit, as stored; for a result not
  // stored, the run's limit (and INCOMPLETE for a run stopped early).
  Result<report::ReportInput> reportInput() const;
  // Writes the calibration report of what is shown (see ui/report).
  Status writeReportPdf(const QString& path) const;
  // The export menu's work without its file dialogs: writes and, when it
  // worked, emits exported().
  Status exportPlotTo(QwtPlot* plot, const QString& path);
  Status exportReportTo(const QString& path);
  // The delay rows of every test point of the shown result as one CSV
  // (ui/data_export.h); empty, or why not (the file is then as it was).
  QString exportDelayRowsTo(const QString& path);
  // The frequency response shown in the Bode tab (every axis): its points
  // to `path` (ui/data_export.h responsePointsCsv) and its models beside it
  // (responseModelsCsv, to responseModelsPath(path)). `path` was named in the
  // save dialog and may be replaced; the models' file was not, so an export
  // that would replace one is refused before anything is written. Empty, or
  // why not (nothing was written then).
  QString exportResponseTo(const QString& path);
  // The Bode plot shown (magnitude over phase of the axis shown) as one
  // PNG, SVG or PDF file (ui/plots/plot_export.h exportPlots). Empty, or
  // why not in the GUI's language.
  QString exportBodePlotTo(const QString& path);

  // The session's data with the shown result's fits, residuals and report,
  // as `fogbench-cli export --csv` writes them, into a new or empty folder.
  Status exportDataTo(const QString& dir);

  // Where an export goes unless the operator picks another place: the
  // folder of the shown session (else the fallback folder), named with what
  // it is, the IMU serial and the recording date, e.g.
  // calibration-report-SN-77-20240102-103000.pdf (no suffix: a folder's name).
  QString defaultExportPath(const QString& what, const QString& suffix) const;
  // The folder for results that were not recorded into a session.
  void setExportFolder(const QString& folder) { exportFolder_ = folder; }

 signals:
  // The operator asked for the sim-to-real diagnosis of what is shown.
  void diagnoseRequested();
  // The operator chose another stored result of the shown session.
  void resultChosen(qint64 resultId);
  // An export wrote `path`.
  void exported(const QString& path);
  // An export failed; `why` says what to do.
  void exportFailed(const QString& title, const QString& why);
  // The export menu's "Open the export folder".
  void openExportFolderRequested();

 protected:
  // The delay table keeps every row in view as its width (and so its
  // wrapped rows' heights) changes.
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void fitDelayTableHeight();
  void buildHeader(QVBoxLayout* layout);
  QWidget* buildPlotsAndTables();
  QWidget* buildReportView();
  void buildExportMenu();
  void buildFrequencyPlot();
  void showFrequencyPlot();
  void fillTables(std::size_t i);
  void fillResultCombo();
  void showZeroCrossing(std::size_t i);

  std::shared_ptr<const RunOutcome> outcome_;
  QString exportFolder_;
  QComboBox* testPointCombo_ = nullptr;
  QComboBox* resultCombo_ = nullptr;
  QLabel* lagLabel_ = nullptr;
  QLabel* verdictLabel_ = nullptr;
  QLabel* decisionRuleLabel_ = nullptr;  // the shown result's decision rule and the point's risk
  QToolButton* exportButton_ = nullptr;
  QPushButton* diagnoseButton_ = nullptr;
  SeriesPlot* anglePlot_ = nullptr;
  SeriesPlot* residualPlot_ = nullptr;
  QwtPlot* frequencyPlot_ = nullptr;
  SeriesPlot* zeroCrossingPlot_ = nullptr;
  std::vector<QwtPlotMarker*> zeroMarkers_;  // owned by zeroCrossingPlot_ while attached
  double zeroCrossingS_ = std::numeric_limits<double>::quiet_NaN();
  double zeroCrossingLagMs_ = std::numeric_limits<double>::quiet_NaN();
  QTabWidget* plotTabs_ = nullptr;
  QTabWidget* leftTabs_ = nullptr;
  BodeView* bodeView_ = nullptr;
  PlotInteraction* frequencyInteraction_ = nullptr;
  QTableWidget* fitTable_ = nullptr;
  QTableWidget* delayTable_ = nullptr;
  QPlainTextEdit* reportView_ = nullptr;
};

}  // namespace fog::ui

#include "ui/result_view.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QFileDialog>
#include <QFontDatabase>
#include <QFontInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_text.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_plot_marker.h>
#include <qwt_scale_div.h>
#include <qwt_symbol.h>

#include "core/common/gyro_signs.h"
#include "core/analysis/decision_rule.h"
#include "core/analysis/theory.h"
#include "ui/data_export.h"
#include "core/session/shown_csv.h"
#include "core/analysis/uncertainty_bound.h"
#include "core/analysis/verdict.h"
#include "core/common/version.h"
#include "core/session/session_api.h"
#include "ui/bode_view.h"
#include "ui/core_text.h"
#include "ui/verdict_text.h"
#include "ui/language/language.h"
#include "ui/plots/plot_export.h"
#include "ui/plots/plot_interaction.h"
#include "ui/report/calibration_report.h"
#include "ui/plots/series_plot.h"

namespace fog::ui {

namespace {

const QColor kTableData(31, 119, 180);
const QColor kGyroData(255, 127, 14);
const QColor kTableFit(8, 48, 107);
const QColor kGyroFit(165, 15, 21);
const QColor kAxisColour[kAxisCount] = {QColor(31, 119, 180), QColor(44, 160, 44), QColor(214, 39, 40)};

QString num(double value, int decimals) { return localNumber(value, 'f', decimals); }

QString pointLabel(const analysis::TestPointResult& p) {
  return QObject::tr("%1: %2 axis, %3 Hz / %4°")
      .arg(p.index + 1)
      .arg(QString(axisName(p.axis)).toUpper())
      .arg(p.nominalFrequencyHz)
      .arg(num(p.tableFit.amplitudeDeg, 2));
}

// A result's constants in a few words.
QString constantsText(const BenchConstants& c) {
  return QObject::tr("table read %1 ms, board %2 ms").arg(num(c.tableReadDelayMs, 4), num(c.boardDelayMs, 4));
}

// What an import applied, in words ("" for a recorded session).
QString importText(const ImportSettings& imported) {
  QStringList parts;
  if (imported.gyroRateConvention == "frame_average")
    parts << QObject::tr("rates as frame averages (%1 ms frames)").arg(num(imported.gyroFramePeriodMs, 4));
  else if (imported.gyroRateConvention == "sample_at_stamp")
    parts << QObject::tr("rates sampled at their stamps");
  if (!imported.segmentation.empty())
    parts << QObject::tr("cut at the swing windows %1").arg(QString::fromStdString(imported.segmentation));
  return parts.isEmpty() ? QString() : QObject::tr(", imported with %1").arg(parts.join(QObject::tr("; ")));
}

// A stored result's settings in a few words: its constants, the gyro signs,
// the session's IMU frame, its limit and what the import applied.
// Constants with the conventions their numbers depend on: the gyro signs
// always (a +1 is a statement too) and the session's IMU frame.
QString constantsAndConventionsText(const BenchConstants& constants, const ImuFrame& sessionFrame) {
  return constantsText(constants) + QObject::tr(", gyro signs %1, IMU frame %2")
                                        .arg(QString::fromStdString(describeGyroSigns(constants.gyroSign)),
                                             coreText(describeImuFrame(sessionFrame)));
}

QString settingsText(const ResultRecord& r, const ImuFrame& sessionFrame) {
  return constantsAndConventionsText(r.constants, sessionFrame) +
         QObject::tr(", limit %1 ms").arg(num(r.imuDelayLimitMs, 3)) +
         (r.coverageKStated ? QObject::tr(", k = %1").arg(QString::fromStdString(analysis::coverageFactorText(r.coverageK)))
                            : QObject::tr(", k = 2 (not stored: the rule of that version)")) +
         importText(r.imported);
}

QString versionText(const ResultRecord& r) {
  return r.softwareVersion.empty() ? QObject::tr("version not stated")
                                   : QObject::tr("fogbench %1").arg(QString::fromStdString(r.softwareVersion));
}

QString storedText(const ResultRecord& r) {
  const QDateTime when = QDateTime::fromString(QString::fromStdString(r.createdUtc), Qt::ISODate);
  return when.isValid() ? when.toUTC().toString("yyyy-MM-dd HH:mm:ss") + " UTC" : QString::fromStdString(r.createdUtc);
}

QTableWidget* makeTable(const QStringList& headers) {
  auto* t = new QTableWidget(0, static_cast<int>(headers.size()));
  t->setHorizontalHeaderLabels(headers);
  t->verticalHeader()->setVisible(false);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  t->horizontalHeader()->setStretchLastSection(true);
  t->setSelectionMode(QAbstractItemView::ContiguousSelection);
  return t;
}

void setRow(QTableWidget* t, int row, const QStringList& cells, bool bold = false) {
  for (int c = 0; c < cells.size(); ++c) {
    auto* item = new QTableWidgetItem(cells[c]);
    item->setToolTip(cells[c]);  // whole, when a narrow column cuts it
    // Numbers (and ranges of them) right-aligned, words left.
    bool number = false;
    cells[c].section(' ', 0, 0).toDouble(&number);
    item->setTextAlignment((number ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter);
    if (bold) {
      QFont f = item->font();
      f.setBold(true);
      item->setFont(f);
    }
    t->setItem(row, c, item);
  }
}

}  // namespace

ResultView::ResultView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  buildHeader(layout);
  // The text report is a tab beside the fits (buildPlotsAndTables), not a
  // pane below them: on a laptop's 700 px a pane there squeezed every plot.
  layout->addWidget(buildPlotsAndTables(), 1);
  buildExportMenu();
  clear();
}

// The test point and result choosers, the buttons, the headline and the
// verdict line.
void ResultView::buildHeader(QVBoxLayout* layout) {
  auto* row = new QHBoxLayout();
  row->addWidget(new QLabel(tr("Test point")));
  testPointCombo_ = new QComboBox();
  testPointCombo_->setObjectName("testPointCombo");
  testPointCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  testPointCombo_->setMinimumContentsLength(8);
  // Grows to show the whole label when there is room, shrinks in Compare.
  testPointCombo_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  testPointCombo_->setMaximumWidth(320);
  row->addWidget(testPointCombo_, 1);
  lagLabel_ = new QLabel();
  lagLabel_->setObjectName("lagLabel");
  lagLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // Wraps on a narrow window (a laptop, the Compare window) instead of
  // widening it.
  lagLabel_->setWordWrap(true);
  lagLabel_->setMinimumWidth(120);  // (Qt 5 asks a wrapping label for much more)
  row->addStretch(1);
  diagnoseButton_ = new QPushButton(tr("Diagnose"));
  diagnoseButton_->setObjectName("diagnoseButton");
  diagnoseButton_->setToolTip(tr("Compare with the simulator replaying this session: where the gap lies and which "
                                 "unmodelled effect explains it"));
  row->addWidget(diagnoseButton_);
  connect(diagnoseButton_, &QPushButton::clicked, this, &ResultView::diagnoseRequested);
  exportButton_ = new QToolButton();
  exportButton_->setObjectName("exportButton");
  exportButton_->setText(tr("Export"));
  exportButton_->setPopupMode(QToolButton::InstantPopup);
  row->addWidget(exportButton_);
  layout->addLayout(row);
  // Which of the session's stored results is shown (and reported, exported).
  auto* resultRow = new QHBoxLayout();
  resultRow->addWidget(new QLabel(tr("Result")));
  resultCombo_ = new QComboBox();
  resultCombo_->setObjectName("resultCombo");
  resultCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  resultCombo_->setMinimumContentsLength(12);
  resultCombo_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  resultCombo_->setToolTip(tr("The session keeps every analysis of it (the recording's, each re-analysis) with the "
                              "constants and software version that made it; the chosen one is shown, reported and "
                              "exported"));
  resultRow->addWidget(resultCombo_, 1);
  layout->addLayout(resultRow);
  connect(resultCombo_, qOverload<int>(&QComboBox::activated), this, [this](int index) {
    const QVariant id = resultCombo_->itemData(index);
    if (outcome_ && id.isValid() && id.toLongLong() != outcome_->shownResultId) emit resultChosen(id.toLongLong());
  });
  // The lag on a line of its own: the row above stays narrow enough for the
  // Compare window's two columns.
  layout->addWidget(lagLabel_);
  // The core's verdict on the shown test point (analysis/verdict.h), with
  // its reasons in full: an invalid delay is never shown without them.
  verdictLabel_ = new QLabel();
  verdictLabel_->setObjectName("verdictLabel");
  verdictLabel_->setWordWrap(true);
  verdictLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(verdictLabel_);
  // Under it, the rule the verdict applied with its k and risk (ISO/IEC
  // 17025 §7.8.6): the shown result's, never today's setting. A label of its
  // own, so the verdict's words stay the verdict's.
  decisionRuleLabel_ = new QLabel();
  decisionRuleLabel_->setObjectName("decisionRuleLabel");
  decisionRuleLabel_->setWordWrap(true);
  decisionRuleLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(decisionRuleLabel_);
  connect(testPointCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ResultView::showTestPoint);
}

// The fits (left, with the Bode plot in a second tab) beside the tables and
// the zero-crossing and frequency plots (right).
QWidget* ResultView::buildPlotsAndTables() {
  anglePlot_ = new SeriesPlot(tr("Normalised angles and fits"), tr("(angle − offset) / amplitude"));
  anglePlot_->setObjectName("anglePlot");
  residualPlot_ = new SeriesPlot(tr("Residuals (data − fit)"), tr("residual (arcsec)"), tr("″"));
  residualPlot_->setObjectName("residualPlot");
  // Empty (a first start): say how to fill the view rather than show bare axes.
  anglePlot_->setEmptyText(tr("No result yet.\nRun a test plan (Run), or open a session (Sessions)."));
  residualPlot_->setEmptyText(tr("The fits' residuals appear here."));
  // Explicit minimum sizes below the plots' own hints: the view fits a
  // laptop screen and the Compare window's two columns fit side by side.
  for (QwtPlot* plot : {static_cast<QwtPlot*>(anglePlot_), static_cast<QwtPlot*>(residualPlot_)})
    plot->setMinimumSize(200, 130);
  // One time axis for both: zoom or pan one, the other follows.
  auto* timeLink = new TimeAxisLink(this);
  timeLink->add(anglePlot_->interaction());
  timeLink->add(residualPlot_->interaction());
  auto* left = new QSplitter(Qt::Vertical);
  left->setObjectName("resultFitsSplitter");
  left->setChildrenCollapsible(false);
  left->addWidget(anglePlot_);
  left->addWidget(residualPlot_);

  fitTable_ = makeTable({tr("fit"), tr("period (ms)"), tr("σ (µs)"), tr("phase t₀ (ms)"), tr("σ (µs)"),
                         tr("amplitude (°)"), tr("χ²/dof")});
  fitTable_->setObjectName("fitTable");
  delayTable_ = makeTable({tr("delay"), tr("value (ms)"), tr("1σ (ms)"), tr("theory (ms)"), tr("basis")});
  delayTable_->setObjectName("delayTable");
  // One line a row (a cut text is whole in its tooltip): all five rows fit
  // a laptop's height whatever the width and the fonts.
  delayTable_->setWordWrap(false);
  // The basis column takes the width that is left and elides; where too
  // little is left it is hidden and each row's tooltip carries it: the table
  // never scrolls sideways (fitDelayTableHeight).
  delayTable_->horizontalHeader()->setSectionResizeMode(4, QHeaderView::Stretch);
  delayTable_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  delayTable_->setTextElideMode(Qt::ElideRight);
  delayTable_->installEventFilter(this);
  for (QTableWidget* t : {fitTable_, delayTable_}) t->setMinimumSize(150, 60);
  buildFrequencyPlot();
  // The lag itself, measurable: table and gyro around one zero crossing.
  zeroCrossingPlot_ = new SeriesPlot(tr("Zero crossing: the gyro behind the table"), tr("angle − offset (°)"), tr("°"));
  zeroCrossingPlot_->setObjectName("zeroCrossingPlot");
  zeroCrossingPlot_->setTimeAxis(tr("time from the table fit's zero crossing (ms)"), 1e-3);
  // A canvas of 120 px at least (the ticks of both axes readable) besides
  // its title, time axis (ticks and title) and legend: some six lines of
  // text (measured: 93-96 px of 17-px lines on Qt 6; the desk tests check
  // the canvas).
  zeroCrossingPlot_->setMinimumSize(200, 120 + 6 * fontMetrics().lineSpacing() + 4);
  plotTabs_ = new QTabWidget();
  plotTabs_->setObjectName("resultPlotTabs");
  plotTabs_->addTab(zeroCrossingPlot_, tr("Zero crossing"));
  plotTabs_->addTab(frequencyPlot_, tr("Lag vs frequency"));
  // The fits' numbers in a tab of their own: above the delay table they
  // took the height the zero-crossing plot needs on a laptop.
  plotTabs_->addTab(fitTable_, tr("Fit table"));
  plotTabs_->setTabToolTip(2, tr("The 3- and 4-parameter fits of table and gyro and the joint fit: period, phase, "
                                 "amplitude, χ²/dof"));
  plotTabs_->setTabToolTip(0, tr("Table and gyro angle around a zero crossing with the fitted lag marked: click twice "
                                 "to set cursors A and B and read Δt"));
  plotTabs_->setTabToolTip(1, tr("The lag of every test point against its swing frequency"));
  // A divider (remembered from a larger screen, or dragged) never squeezes
  // the plots below their minimum: the view scrolls instead.
  plotTabs_->setMinimumHeight(zeroCrossingPlot_->minimumHeight() + plotTabs_->tabBar()->sizeHint().height() + 8);
  auto* right = new QSplitter(Qt::Vertical);
  right->setObjectName("resultRightSplitter");
  right->setChildrenCollapsible(false);
  right->addWidget(delayTable_);
  right->addWidget(plotTabs_);
  // The delay table keeps what its rows need; the plots take the rest.
  right->setStretchFactor(0, 0);
  right->setStretchFactor(1, 1);

  bodeView_ = new BodeView();
  bodeView_->setObjectName("resultBodeView");
  leftTabs_ = new QTabWidget();
  leftTabs_->setObjectName("resultLeftTabs");
  leftTabs_->addTab(left, tr("Fits"));
  leftTabs_->addTab(bodeView_, tr("Frequency response"));
  leftTabs_->addTab(buildReportView(), tr("Report"));
  leftTabs_->setTabToolTip(0, tr("The chosen test point's angles with their fitted sinusoids, and the residuals"));
  leftTabs_->setTabToolTip(1, tr("Magnitude and phase of gyro angle / table angle at every test frequency of an axis, "
                                 "with the delay models fitted to them (Bode plot)"));
  leftTabs_->setTabToolTip(2, tr("The delay report as text, as the command line prints it"));

  auto* top = new QSplitter(Qt::Horizontal);
  top->setObjectName("resultTopSplitter");
  top->setChildrenCollapsible(false);
  top->addWidget(leftTabs_);
  top->addWidget(right);
  top->setStretchFactor(0, 1);
  top->setStretchFactor(1, 1);
  return top;
}

QWidget* ResultView::buildReportView() {
  reportView_ = new QPlainTextEdit();
  reportView_->setObjectName("reportView");
  reportView_->setReadOnly(true);
  reportView_->setLineWrapMode(QPlainTextEdit::NoWrap);
  // Some platforms (offscreen) answer the fixed-font query with a
  // proportional font; ask fontconfig's alias then.
  QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  if (!QFontInfo(mono).fixedPitch()) {
    mono.setFamily("monospace");
    mono.setStyleHint(QFont::TypeWriter);
  }
  reportView_->setFont(mono);
  reportView_->setPlaceholderText(tr("The delay report appears here after a run."));

  return reportView_;
}

void ResultView::buildExportMenu() {
  auto* menu = new QMenu(exportButton_);
  auto addPlotExport = [this, menu](const QString& label, QwtPlot* plot) {
    menu->addAction(label, this, [this, plot] {
      const QString path = QFileDialog::getSaveFileName(this, tr("Export plot"),
                                                        defaultExportPath(plot->objectName(), "png"), plotExportFilter());
      if (path.isEmpty()) return;
      if (auto s = exportPlotTo(plot, path); !s.isOk())
        emit exportFailed(tr("Export plot"), coreText(s.message()));
    });
  };
  addPlotExport(tr("Angles plot…"), anglePlot_);
  addPlotExport(tr("Residuals plot…"), residualPlot_);
  addPlotExport(tr("Zero crossing plot…"), zeroCrossingPlot_);
  addPlotExport(tr("Delay vs frequency plot…"), frequencyPlot_);
  menu->addAction(tr("Bode plot (frequency response)…"), this, [this] {
    if (!outcome_) return;
    const auto axis = bodeView_->shownAxis();
    const QString what = axis ? QStringLiteral("bode-") + QString(axisName(*axis)) : QStringLiteral("bode");
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the Bode plot"),
                                                      defaultExportPath(what, "png"), plotExportFilter());
    if (path.isEmpty()) return;
    if (const QString why = exportBodePlotTo(path); !why.isEmpty()) emit exportFailed(tr("Export the Bode plot"), why);
  });
  menu->addSeparator();
  menu->addAction(tr("Calibration report (PDF)…"), this, [this] {
    if (!outcome_ || !outcome_->report) return;
    // No limit is asked for: the report prints the stored result's verdict
    // and limit (another limit is a re-analysis, stored as a new result).
    const QString path = QFileDialog::getSaveFileName(this, tr("Calibration report"),
                                                      defaultExportPath("calibration-report", "pdf"),
                                                      tr("PDF document (*.pdf)"));
    if (path.isEmpty()) return;
    if (auto s = exportReportTo(path); !s.isOk())
      emit exportFailed(tr("Calibration report"), coreText(s.message()));
  });
  menu->addSeparator();
  // Data: the delay rows as one CSV, or the session's data with the shown
  // result's fits as `fogbench-cli export --csv` writes them.
  menu->addAction(tr("Delay table (CSV)…"), this, [this] {
    if (!outcome_ || !outcome_->report) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Delay table (CSV)"),
                                                      defaultExportPath("delays", "csv"), tr("CSV file (*.csv)"));
    if (path.isEmpty()) return;
    if (const QString why = exportDelayRowsTo(path); !why.isEmpty()) emit exportFailed(tr("Delay table (CSV)"), why);
  });
  menu->addAction(tr("Frequency response: points and models (CSV)…"), this, [this] {
    if (!outcome_) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Frequency response (CSV): the points; the models go beside them"),
                                                      defaultExportPath("response", "csv"), tr("CSV file (*.csv)"));
    if (path.isEmpty()) return;
    if (const QString why = exportResponseTo(path); !why.isEmpty())
      emit exportFailed(tr("Frequency response (CSV)"), why);
  });
  menu->addAction(tr("Session data and fits (CSV folder)…"), this, [this] {
    if (!outcome_) return;
    // A new folder's name: the export never writes into a folder that
    // holds anything (the core refuses, saying so).
    const QString dir = QFileDialog::getSaveFileName(this, tr("Session data: name a new folder"),
                                                     defaultExportPath("data", QString()), QString(), nullptr,
                                                     QFileDialog::DontConfirmOverwrite);
    if (dir.isEmpty()) return;
    if (auto s = exportDataTo(dir); !s.isOk())
      emit exportFailed(tr("Session data (CSV)"),
                        tr("%1\nThe session itself is unchanged.").arg(coreText(s.message())));
  });
  menu->addAction(tr("Session data and result (HDF5 file)…"), this, [this] {
    if (!outcome_) return;
    // The dialog asks before replacing a file; a session is never replaced.
    const QString path = QFileDialog::getSaveFileName(this, tr("Session data (HDF5)"),
                                                      defaultExportPath("data", "h5"), tr("HDF5 file (*.h5)"));
    if (path.isEmpty()) return;
    if (auto s = exportSessionHdf5(*outcome_, path); !s.isOk())
      emit exportFailed(tr("Session data (HDF5)"),
                        tr("%1\nThe session itself is unchanged.").arg(coreText(s.message())));
    else
      emit exported(path);
  });
  menu->addSeparator();
  menu->addAction(tr("Open the export folder"), this, &ResultView::openExportFolderRequested);
  exportButton_->setMenu(menu);
}

void ResultView::buildFrequencyPlot() {
  frequencyPlot_ = new QwtPlot();
  frequencyPlot_->setObjectName("frequencyPlot");
  frequencyPlot_->setTitle(tr("Lag against swing frequency"));
  frequencyPlot_->setAxisTitle(QwtPlot::xBottom, tr("swing frequency (Hz)"));
  frequencyPlot_->setAxisTitle(QwtPlot::yLeft, tr("lag (ms), ±1σ"));
  frequencyPlot_->setCanvasBackground(Qt::white);
  frequencyPlot_->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  frequencyPlot_->setMinimumSize(200, 120);
  useCompactTitles(frequencyPlot_);
  PlotInteraction::Options options;
  options.timeAxis = false;
  frequencyInteraction_ = new PlotInteraction(frequencyPlot_, options);
}

void ResultView::clear() {
  outcome_.reset();
  {
    const QSignalBlocker block(testPointCombo_);
    testPointCombo_->clear();
  }
  lagLabel_->setText(tr("No result yet: run a test plan (Run) or open a session (Sessions)."));
  verdictLabel_->clear();
  decisionRuleLabel_->clear();
  resultCombo_->clear();
  resultCombo_->setEnabled(false);
  anglePlot_->clearCurves();
  anglePlot_->showAll();
  residualPlot_->clearCurves();
  residualPlot_->showAll();
  showZeroCrossing(static_cast<std::size_t>(-1));
  fitTable_->setRowCount(0);
  delayTable_->setRowCount(0);
  frequencyPlot_->detachItems();
  frequencyPlot_->replot();
  bodeView_->showMessage(tr("No frequency response yet."));
  reportView_->clear();
  exportButton_->setEnabled(false);
  diagnoseButton_->setEnabled(false);
}

QString ResultView::reportText() const { return reportView_->toPlainText(); }

void ResultView::showOutcome(std::shared_ptr<const RunOutcome> outcome) {
  clear();
  outcome_ = std::move(outcome);
  if (!outcome_) return;
  fillResultCombo();
  reportView_->setPlainText(tr("Result shown: %1").arg(resultDescription()) + "\n\n" +
                            coreText(outcome_->reportText));
  exportButton_->setEnabled(true);
  diagnoseButton_->setEnabled(outcome_->report.isOk());
  if (!outcome_->report) {
    lagLabel_->setText(tr("<b>No delay:</b> %1").arg(coreText(outcome_->report.status().message())));
    return;
  }
  {
    const QSignalBlocker block(testPointCombo_);
    for (const auto& p : outcome_->report->points) testPointCombo_->addItem(pointLabel(p));
  }
  showFrequencyPlot();
  bodeView_->showResponses(outcome_->responses, responseMissingText(*outcome_->report));
  // A response plan's result is its Bode plot; any other opens on the fits.
  std::size_t mostPoints = 0;
  for (const auto& r : outcome_->responses) mostPoints = std::max(mostPoints, r.points.size());
  leftTabs_->setCurrentIndex(mostPoints >= 5 ? 1 : 0);
  testPointCombo_->setCurrentIndex(0);
  showTestPoint(0);
}

QString ResultView::resultDescription() const {
  if (!outcome_) return QString();
  const ResultRecord* r = outcome_->shownResult();
  if (!r) {
    const QString constants =
        (outcome_->report ? constantsAndConventionsText(outcome_->report->constants, outcome_->info.bench.imuFrame)
                          : QString()) +
        importText(outcome_->info.imported);
    if (outcome_->sessionPath.empty())
      return tr("this run's, not recorded in a session; computed by fogbench %1 with %2")
          .arg(QStringLiteral(FOG_VERSION), constants);
    return tr("none stored in the session; computed by fogbench %1 with the session's constants (%2)")
        .arg(QStringLiteral(FOG_VERSION), constants);
  }
  return tr("result %1 of %2: %7, stored %3 by %4 (%5), %6")
      .arg(outcome_->shownResultNumber())
      .arg(outcome_->results.size())
      .arg(storedText(*r), versionText(*r),
           r->analysedBy.empty() ? tr("analysis") : QString::fromStdString(r->analysedBy),
           settingsText(*r, outcome_->info.bench.imuFrame),
           verdictWord(r->verdict));
}

void ResultView::fillResultCombo() {
  const QSignalBlocker block(resultCombo_);
  resultCombo_->clear();
  const int count = static_cast<int>(outcome_->results.size());
  for (int i = 0; i < count; ++i) {
    const auto& r = outcome_->results[static_cast<std::size_t>(i)];
    QString text = r.usable ? tr("%1 of %2 · %6 · %3 · %4 · %5")
                                  .arg(i + 1)
                                  .arg(count)
                                  .arg(storedText(r), versionText(r), settingsText(r, outcome_->info.bench.imuFrame),
                                       verdictWord(r.verdict))
                            : tr("%1 of %2 · %3 · %4 · %5")
                                  .arg(i + 1)
                                  .arg(count)
                                  .arg(storedText(r), versionText(r), constantsText(r.constants));
    if (!r.usable) text += tr(" · damaged, cannot be shown");
    resultCombo_->addItem(text, QVariant::fromValue<qint64>(r.id));
    resultCombo_->setItemData(i, text, Qt::ToolTipRole);
    // A damaged result cannot be chosen.
    if (!r.usable)
      if (auto* model = qobject_cast<QStandardItemModel*>(resultCombo_->model()))
        if (auto* item = model->item(i)) item->setEnabled(false);
    if (r.id == outcome_->shownResultId) resultCombo_->setCurrentIndex(i);
  }
  if (!outcome_->shownResult()) {
    resultCombo_->addItem(resultDescription());
    resultCombo_->setCurrentIndex(resultCombo_->count() - 1);
  }
  resultCombo_->setToolTip(resultCombo_->currentText());
  resultCombo_->setEnabled(count > 1 || (count == 1 && !outcome_->shownResult()));
}

void ResultView::setChoosing(bool choosing) {
  if (choosing) {
    const QSignalBlocker block(resultCombo_);
    resultCombo_->setEnabled(false);
    lagLabel_->setText(tr("Loading the chosen result …"));
  } else if (outcome_) {
    fillResultCombo();
  }
}

void ResultView::fillTables(std::size_t i) {
  const auto& p = outcome_->report->points[i];
  fitTable_->setRowCount(5);
  auto fitRow = [&](int row, const QString& name, const analysis::SineFit& f, bool nominal) {
    setRow(fitTable_, row,
           {name, num(f.periodMs, 4), nominal ? tr("nominal") : num(f.periodStdMs * 1e3, 3), num(f.phaseMs, 4),
            num(f.phaseStdMs * 1e3, 3), num(f.amplitudeDeg, 5), num(f.chiSquarePerDof, 2)});
  };
  fitRow(0, tr("table, 3-parameter"), p.tableNominal, true);
  fitRow(1, tr("gyro, 3-parameter"), p.gyroNominal, true);
  fitRow(2, tr("table, 4-parameter"), p.tableFit, false);
  fitRow(3, tr("gyro, 4-parameter"), p.gyroFit, false);
  const double periodMs = 1e3 / p.joint.frequencyHz;
  const double periodStdUs = 1e6 * p.joint.frequencyStdHz / (p.joint.frequencyHz * p.joint.frequencyHz);
  setRow(fitTable_, 4,
         {tr("joint: lag as t₀"), num(periodMs, 4), num(periodStdUs, 3), num(p.joint.lagS * 1e3, 5),
          num(p.joint.lagStdS * 1e6, 3), tr("gain %1").arg(num(p.joint.gain, 6)), num(p.joint.chiSquarePerDof, 2)},
         true);

  const auto& c = outcome_->report->constants;
  const auto budget = analysis::delayBudget(analysis::TheoryInputs{});
  // A refused point's delays keep their mark in the table too.
  const session::ShownVerdict shown = outcome_->shownVerdict();
  session::ShownPoint refusedOrNot;
  if (const auto* sp = shown.point(p.index)) refusedOrNot = *sp;
  auto delay = [&](double v) { return shownNumber(refusedOrNot, v, 5); };
  auto range = [](double lo, double hi) { return QString("%1 – %2").arg(num(lo, 4), num(hi, 4)); };
  delayTable_->setRowCount(5);
  setRow(delayTable_, 0,
         {tr("measured lag (gyro behind table)"), delay(p.lagMs),
          // A σ below its bound is marked on the number itself, not only in
          // the basis column a narrow window may cut.
          num(p.lagStdMs, 5) + (analysis::sigmaBelowBound(p) ? QStringLiteral(" ⚠") : QString()), QString(),
          tr("joint fit; CRLB %1 ms, σ/CRLB %2").arg(num(p.crlbMs, 5), num(p.stdOverCrlb, 2)) +
              (analysis::sigmaBelowBound(p) ? tr(" — σ below the bound: understated (check uncertainty_below_bound)")
                                            : QString())},
         true);
  setRow(delayTable_, 1,
         {tr("+ table read delay"), num(c.tableReadDelayMs, 5), num(c.tableReadDelayStdMs, 5), QString(),
          tr("bench constant")});
  setRow(delayTable_, 2,
         {tr("= IMU delay"), delay(p.imuDelayMs), num(p.imuDelayStdMs, 5),
          range(budget.totalMinMs, budget.totalMaxMs), tr("the paper: < 0.8 ms")},
         true);
  setRow(delayTable_, 3,
         {tr("− processing-board delay"), num(c.boardDelayMs, 5), num(c.boardDelayStdMs, 5),
          num(budget.boardMaxMs, 4), tr("bench constant; theory: sampling, compensation, serial frame")});
  setRow(delayTable_, 4,
         {tr("= gyro's own delay"), delay(p.gyroDelayMs), num(p.gyroDelayStdMs, 5),
          range(std::max(0.0, budget.totalMinMs - budget.boardMaxMs), budget.totalMaxMs - budget.boardMaxMs),
          tr("sensing, loop and pulse update")},
         true);
  // Every cell's tooltip also gives the row's basis (hidden on a narrow table).
  for (int r = 0; r < delayTable_->rowCount(); ++r)
    if (const auto* basis = delayTable_->item(r, 4); basis && !basis->text().isEmpty())
      for (int col = 0; col < 4; ++col)
        if (auto* item = delayTable_->item(r, col))
          item->setToolTip(item->text().isEmpty() ? basis->text() : item->text() + "\n" + basis->text());
  fitDelayTableHeight();
}

// Every delay row stays in view (the gyro's own delay is the last): the
// table is at least as tall as its rows; the plots below give way down to
// their minimum.
void ResultView::fitDelayTableHeight() {
  // The basis column only where it has room to be read.
  int fixed = 0;
  for (int c = 0; c < 4; ++c) fixed += delayTable_->horizontalHeader()->sectionSize(c);
  const int basisMin = delayTable_->fontMetrics().horizontalAdvance(QStringLiteral("bench constant"));
  delayTable_->setColumnHidden(4, fixed + basisMin > delayTable_->viewport()->width());
  delayTable_->resizeRowsToContents();
  int height = delayTable_->horizontalHeader()->height() + 2 * delayTable_->frameWidth();
  for (int r = 0; r < delayTable_->rowCount(); ++r) height += delayTable_->rowHeight(r);
  if (delayTable_->horizontalScrollBar()->isVisible()) height += delayTable_->horizontalScrollBar()->height();
  delayTable_->setMinimumHeight(height);
}

bool ResultView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == delayTable_ && event->type() == QEvent::Resize && delayTable_->rowCount() > 0)
    QMetaObject::invokeMethod(this, &ResultView::fitDelayTableHeight, Qt::QueuedConnection);
  return QWidget::eventFilter(watched, event);
}

// One line: the decision rule with the shown result's k, its maximum
// false-accept risk, and the point's own risk when its delay is vouched for.
QString ResultView::decisionRuleHtml(const session::ShownVerdict& v, const session::ShownPoint* sp) const {
  const QString k = QString::fromStdString(analysis::coverageFactorText(v.coverageK));
  // Short enough for one line on a laptop (Qt 5's fonts too); the standard
  // it follows in the tooltip.
  QString line = tr("Decision rule: PASS when IMU delay + k·σ < limit (k = %1, guarded acceptance); false-accept "
                    "risk ≤ 1 − Φ(k) = %2")
                     .arg(k, QString::fromStdString(
                                 analysis::probabilityText(analysis::maxFalseAcceptProbability(v.coverageK))));
  if (!v.ruleProvenance.empty()) line += tr(" (k %1)").arg(coreText(v.ruleProvenance));
  if (sp && sp->vouched() && std::isfinite(sp->falseAcceptProbability)) {
    // "= 2.3 %", or "< 1e-6 %" as it stands (never "= < 1e-6 %").
    const QString risk = QString::fromStdString(analysis::probabilityText(sp->falseAcceptProbability));
    line += tr("; this point: guard band %1 ms, P(true delay ≥ limit) %2")
                .arg(num(sp->guardBandMs, 4), risk.startsWith('<') ? risk : "= " + risk);
  } else {
    line += tr("; this point: no risk stated, its delay is refused");
  }
  decisionRuleLabel_->setToolTip(
      tr("ISO/IEC 17025:2017 §7.8.6 asks a statement of conformity to state its decision rule and risk; this one is "
         "ILAC-G8:09/2019's guarded acceptance: the guard band is k·σ, and 1 − Φ(k) is the largest probability that "
         "a delay accepted at the boundary truly reaches the limit (a Gaussian error with the stated σ)"));
  return "<span style='color:#555555'>" + line.toHtmlEscaped() + "</span>";
}

QString ResultView::verdictHtml(const analysis::TestPointResult& p) const {
  // Core's one rule (session::judgeShown): the record's verdict, reasons and
  // limit, never re-judged here; a result not stored is judged there once.
  using K = session::ShownVerdictKind;
  const session::ShownVerdict v = outcome_->shownVerdict();
  const session::ShownPoint* sp = v.point(p.index);
  QStringList reasons;
  if (sp)
    for (const auto& why : sp->reasons) reasons << coreText(why).toHtmlEscaped();
  const QString whose = v.stored ? tr("stored verdict") : tr("verdict, not stored");
  QString html = tr("Result: <span style='color:%1'><b>%2</b></span>")
                     .arg(verdictColour(v.verdict), verdictWord(v.verdict));
  if (v.verdict == K::kIncomplete) {
    html += tr(" (incomplete run: %1; the data recorded give %2)")
                .arg(coreText(v.incompleteReason).toHtmlEscaped(), verdictWord(v.dataVerdict));
  }
  html += tr("  ·  %1 (limit %2 ms)").arg(whose, num(v.limitMs, 3));
  const K pointVerdict = sp ? sp->verdict : K::kNone;
  if (pointVerdict == K::kIncomplete)  // no point of an incomplete run passes
    html += tr("<br>Test point: <span style='color:%1'><b>%2</b></span> (its data give %3): %4")
                .arg(verdictColour(pointVerdict), verdictWord(pointVerdict), verdictWord(sp->dataVerdict),
                     reasons.join("<br>"));
  else
    html += tr("<br>Test point: <span style='color:%1'><b>%2</b></span>: %3")
                .arg(verdictColour(pointVerdict), verdictWord(pointVerdict), reasons.join("<br>"));
  if (!outcome_->differences.empty()) {
    QStringList diffs;
    for (const auto& d : outcome_->differences) diffs << coreText(d).toHtmlEscaped();
    html += tr("<br><span style='color:#a05000'>This version's analysis of the same data with the stored settings "
               "differs from the stored result (%1); the verdict shown is the stored one. Re-analyse the session "
               "(Sessions) to store this version's result.</span>")
                .arg(diffs.join("; "));
  }
  return html;
}

// The headline: the shown point's delays with their σ when they are vouched
// for; a refused delay is marked as refused, its number only in brackets.
QString ResultView::headlineHtml(const analysis::TestPointResult& p) const {
  const session::ShownVerdict v = outcome_->shownVerdict();
  const session::ShownPoint* sp = v.point(p.index);
  QString lag;
  if (sp && sp->vouched()) {
    lag = tr("<b>lag %1 ± %2 ms</b>  ·  IMU delay %3 ms  ·  gyro's own delay %4 ms")
              .arg(num(p.lagMs, 4), num(p.lagStdMs, 4), num(p.imuDelayMs, 4), num(p.gyroDelayMs, 4));
  } else {
    const QString word = verdictWord(sp ? sp->verdict : session::ShownVerdictKind::kNone);
    lag = tr("<span style='color:%1'><b>delay refused (%2)</b></span>  ·  not vouched for: lag (%3 ms), IMU delay "
             "(%4 ms)")
              .arg(verdictColour(sp ? sp->verdict : session::ShownVerdictKind::kNone), word, num(p.lagMs, 4),
                   num(p.imuDelayMs, 4));
  }
  for (const auto& t : outcome_->truth)
    if (t.index == p.index) lag += tr("  ·  simulator truth: lag %1 ms").arg(num(t.lagS * 1e3, 4));
  if (!outcome_->complete) lag += tr("  ·  <span style='color:#b00000'>incomplete run</span>");
  return lag;
}

void ResultView::showTestPoint(int position) {
  anglePlot_->clearCurves();
  residualPlot_->clearCurves();
  if (!outcome_ || !outcome_->report || position < 0 ||
      position >= static_cast<int>(outcome_->traces.size())) {
    anglePlot_->showAll();
    residualPlot_->showAll();
    showZeroCrossing(static_cast<std::size_t>(-1));
    return;
  }
  const auto i = static_cast<std::size_t>(position);
  const auto& p = outcome_->report->points[i];
  lagLabel_->setText(headlineHtml(p));
  verdictLabel_->setText(verdictHtml(p));
  {
    const session::ShownVerdict v = outcome_->shownVerdict();
    decisionRuleLabel_->setText(decisionRuleHtml(v, v.point(p.index)));
  }
  fillTables(i);

  // Aliasing pointers: the plots share the outcome, nothing is copied.
  const std::shared_ptr<const TestPointTraces> traces(outcome_, &outcome_->traces[i]);
  auto part = [&](const Trace& t) { return std::shared_ptr<const Trace>(outcome_, &t); };
  anglePlot_->addData(tr("table"), QPen(kTableData), part(traces->tableNormalised));
  anglePlot_->addData(tr("gyro (integrated, trend removed)"), QPen(kGyroData), part(traces->gyroNormalised));
  anglePlot_->addFunction(tr("table fit"), QPen(kTableFit, 1.5),
                          [traces](double t) { return traces->tableFitNormalised(t); });
  anglePlot_->addFunction(tr("gyro fit"), QPen(kGyroFit, 1.5, Qt::DashLine),
                          [traces](double t) { return traces->gyroFitNormalised(t); });
  anglePlot_->showAll();
  residualPlot_->addData(tr("gyro"), QPen(kGyroData), part(traces->gyroResidualArcsec));
  residualPlot_->addData(tr("table"), QPen(kTableData), part(traces->tableResidualArcsec));
  residualPlot_->showAll();
  showZeroCrossing(i);
}

void ResultView::showZeroCrossing(std::size_t i) {
  zeroCrossingPlot_->clearCurves();
  for (QwtPlotMarker* m : zeroMarkers_) {
    m->detach();
    delete m;
  }
  zeroMarkers_.clear();
  zeroCrossingS_ = zeroCrossingLagMs_ = std::numeric_limits<double>::quiet_NaN();
  if (!outcome_ || !outcome_->report || i >= outcome_->traces.size() || i >= outcome_->report->points.size()) {
    zeroCrossingPlot_->showAll();
    return;
  }
  const auto& p = outcome_->report->points[i];
  const std::shared_ptr<const TestPointTraces> traces(outcome_, &outcome_->traces[i]);
  const analysis::SineFit& tf = traces->tableFit;
  const auto& tx = traces->tableNormalised.x;
  if (!(tf.omegaRadPerS > 0.0) || tx.size() < 2 || !std::isfinite(p.lagMs)) {
    zeroCrossingPlot_->showAll();
    return;
  }
  // The table fit's rising zero crossing nearest the middle of the data.
  const double tc = risingZeroCrossingS(tf, 0.5 * (tx.front() + tx.back()));
  const double lagMs = p.lagMs;
  // Wide enough for a few gyro samples on either side and the lag many times.
  const double halfMs = std::max(5.0, 8.0 * std::abs(lagMs));
  const double tableAmp = std::hypot(tf.a, tf.b) > 0.0 ? std::hypot(tf.a, tf.b) : 1.0;
  const analysis::SineFit& gf = traces->gyroFit;
  const double gyroAmp = std::hypot(gf.a, gf.b) > 0.0 ? std::hypot(gf.a, gf.b) : 1.0;
  // Around tc, in ms from it, in degrees (each normalised trace times its
  // amplitude).
  auto window = [&](const Trace& t, double amplitude) {
    auto out = std::make_shared<Trace>();
    const auto lo = std::lower_bound(t.x.begin(), t.x.end(), tc - halfMs * 1e-3);
    const auto hi = std::upper_bound(t.x.begin(), t.x.end(), tc + halfMs * 1e-3);
    for (auto it = lo; it != hi; ++it) {
      const auto n = static_cast<std::size_t>(it - t.x.begin());
      out->x.push_back((*it - tc) * 1e3);
      out->y.push_back(t.y[n] * amplitude);
    }
    return std::shared_ptr<const Trace>(std::move(out));
  };
  zeroCrossingS_ = tc;
  zeroCrossingLagMs_ = lagMs;
  zeroCrossingPlot_->addData(tr("table"), QPen(kTableData), window(traces->tableNormalised, tableAmp), true);
  zeroCrossingPlot_->addData(tr("gyro (integrated, trend removed)"), QPen(kGyroData),
                             window(traces->gyroNormalised, gyroAmp), true);
  zeroCrossingPlot_->addFunction(tr("table fit"), QPen(kTableFit, 1.5), [traces, tc, tableAmp](double ms) {
    return traces->tableFitNormalised(tc + ms * 1e-3) * tableAmp;
  });
  zeroCrossingPlot_->addFunction(tr("gyro fit"), QPen(kGyroFit, 1.5, Qt::DashLine),
                                 [traces, tc, gyroAmp](double ms) {
                                   return traces->gyroFitNormalised(tc + ms * 1e-3) * gyroAmp;
                                 });
  auto marker = [this](double x, const QString& text, Qt::Alignment align, Qt::PenStyle style) {
    auto* m = new QwtPlotMarker();
    m->setLineStyle(QwtPlotMarker::VLine);
    m->setLinePen(QPen(QColor(60, 60, 60), 1, style));
    m->setXValue(x);
    QwtText label(text);
    label.setColor(QColor(60, 60, 60));
    label.setBackgroundBrush(QColor(255, 255, 255, 200));
    m->setLabel(label);
    m->setLabelAlignment(align);
    m->setItemAttribute(QwtPlotItem::AutoScale, false);
    m->attach(zeroCrossingPlot_);
    zeroMarkers_.push_back(m);
  };
  marker(0.0, tr("table crosses zero"), Qt::AlignLeft | Qt::AlignTop, Qt::DotLine);
  // A refused lag is marked refused on the plot too.
  const session::ShownVerdict shown = outcome_->shownVerdict();
  const session::ShownPoint* sp = shown.point(p.index);
  marker(lagMs,
         sp && sp->vouched() ? tr("+ fitted lag %1 ms").arg(num(lagMs, 4))
                             : tr("+ fitted lag %1 ms, refused (%2)")
                                   .arg(num(lagMs, 4), verdictWord(sp ? sp->verdict : session::ShownVerdictKind::kNone)),
         Qt::AlignRight | Qt::AlignTop, Qt::SolidLine);
  auto* zero = new QwtPlotMarker();
  zero->setLineStyle(QwtPlotMarker::HLine);
  zero->setLinePen(QPen(QColor(160, 160, 160), 1, Qt::DotLine));
  zero->setYValue(0.0);
  zero->setItemAttribute(QwtPlotItem::AutoScale, false);
  zero->attach(zeroCrossingPlot_);
  zeroMarkers_.push_back(zero);
  zeroCrossingPlot_->showAll();
}

void ResultView::showFrequencyPlot() {
  frequencyPlot_->detachItems();
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
  grid->attach(frequencyPlot_);
  const auto& report = *outcome_->report;
  double fMin = 1e300, fMax = 0.0;
  double yMin = 1e300, yMax = -1e300;
  for (int a = 0; a < kAxisCount; ++a) {
    QVector<QPointF> points;
    QVector<QwtIntervalSample> bars;
    for (const auto& p : report.points) {
      if (static_cast<int>(p.axis) != a) continue;
      const double f = p.joint.frequencyHz > 0.0 ? p.joint.frequencyHz : p.nominalFrequencyHz;
      points.push_back({f, p.lagMs});
      bars.push_back(QwtIntervalSample(f, p.lagMs - p.lagStdMs, p.lagMs + p.lagStdMs));
      fMin = std::min(fMin, f);
      fMax = std::max(fMax, f);
      yMin = std::min(yMin, p.lagMs - p.lagStdMs);
      yMax = std::max(yMax, p.lagMs + p.lagStdMs);
    }
    if (points.isEmpty()) continue;
    const QColor colour = kAxisColour[a];
    auto* curve = new QwtPlotCurve(tr("%1 axis").arg(QString(axisName(static_cast<Axis>(a))).toUpper()));
    curve->setStyle(QwtPlotCurve::NoCurve);
    curve->setSymbol(new QwtSymbol(QwtSymbol::Ellipse, QBrush(colour), QPen(colour), QSize(8, 8)));
    curve->setSamples(points);
    curve->attach(frequencyPlot_);
    auto* errors = new QwtPlotIntervalCurve();
    errors->setStyle(QwtPlotIntervalCurve::NoCurve);
    errors->setSymbol(new QwtIntervalSymbol(QwtIntervalSymbol::Bar));
    errors->setPen(QPen(colour, 1.5));
    errors->setSamples(bars);
    errors->setItemAttribute(QwtPlotItem::Legend, false);
    errors->attach(frequencyPlot_);
  }
  for (const auto& c : report.consistency) {
    auto* mean = new QwtPlotMarker();
    mean->setLineStyle(QwtPlotMarker::HLine);
    mean->setLinePen(QPen(kAxisColour[static_cast<int>(c.axis)], 1, Qt::DashLine));
    mean->setYValue(c.weightedLagMs);
    QString label = tr("%1: weighted %2 ms, %3 with a pure delay (p = %4)")
                        .arg(QString(axisName(c.axis)).toUpper())
                        .arg(num(c.weightedLagMs, 4))
                        .arg(c.consistentWithPureDelay ? tr("consistent") : tr("NOT consistent"))
                        .arg(num(c.pValue, 3));
    if (c.leftOutPoints > 0) label += tr("; %1 refused test point(s) left out").arg(c.leftOutPoints);
    mean->setLabel(QwtText(label));
    mean->setLabelAlignment(Qt::AlignLeft | Qt::AlignTop);
    mean->attach(frequencyPlot_);
  }
  if (fMax > 0.0) {
    // Margins so that points at the ends are not on the frame.
    const double span = std::max(fMax - fMin, 0.2 * fMax);
    frequencyPlot_->setAxisScale(QwtPlot::xBottom, std::max(0.0, fMin - 0.15 * span), fMax + 0.15 * span);
  }
  for (const auto& c : report.consistency) {
    yMin = std::min(yMin, c.weightedLagMs);
    yMax = std::max(yMax, c.weightedLagMs);
  }
  if (yMax >= yMin && std::isfinite(yMax - yMin)) {
    // Every point with its whole error bar, clear of the frame (and of the
    // mean's label above it).
    const double span = std::max(yMax - yMin, 1e-3);
    frequencyPlot_->setAxisScale(QwtPlot::yLeft, yMin - 0.15 * span, yMax + 0.3 * span);
  } else {
    frequencyPlot_->setAxisAutoScale(QwtPlot::yLeft, true);
  }
  frequencyPlot_->replot();
  frequencyInteraction_->setHome();
}

Status ResultView::exportPlotTo(QwtPlot* plot, const QString& path) {
  FOG_RETURN_IF_ERROR(exportPlot(plot, path));
  emit exported(path);
  return Status::ok();
}

Status ResultView::exportReportTo(const QString& path) {
  FOG_RETURN_IF_ERROR(writeReportPdf(path));
  emit exported(path);
  return Status::ok();
}

QString ResultView::exportDelayRowsTo(const QString& path) {
  if (!outcome_ || !outcome_->report) return tr("There is no delay result to export.");
  const QString source = outcome_->sessionPath.empty() ? QString::fromStdString(outcome_->info.source)
                                                       : QString::fromStdString(outcome_->sessionPath);
  const QString why = writeTextFile(path, session::delayBreakdownCsv(*outcome_->report, outcome_->shownVerdict(), source.toStdString()));
  if (why.isEmpty()) emit exported(path);
  return why;
}

QString ResultView::exportResponseTo(const QString& path) {
  if (!outcome_ || !outcome_->report) return tr("There is no result to export.");
  if (outcome_->responses.empty())
    return tr("There is no frequency response to export: %1").arg(responseMissingText(*outcome_->report));
  const QString models = responseModelsPath(path);
  // The dialog asked before replacing `path`; nobody asked about the models'
  // file, so one already there is never replaced.
  if (QFileInfo(models).absoluteFilePath() == QFileInfo(path).absoluteFilePath())
    return tr("%1 cannot hold both the points and the models; choose another name.")
        .arg(QDir::toNativeSeparators(path));
  if (QFileInfo::exists(models))
    return tr("Nothing was exported: the models go beside the points as %1, and that file already exists. It was "
              "not named in the dialog and is not replaced: move or delete it, or choose another name for the points.")
        .arg(QDir::toNativeSeparators(models));
  const std::string source = outcome_->sessionPath.empty() ? outcome_->info.source : outcome_->sessionPath;
  if (QString why = writeTextFile(path, responsePointsCsv(outcome_->responses, source)); !why.isEmpty()) return why;
  if (QString why = writeTextFile(models, responseModelsCsv(outcome_->responses, source)); !why.isEmpty())
    return tr("%1\nThe points were written to %2; the models were not.").arg(why, QDir::toNativeSeparators(path));
  emit exported(path);
  emit exported(models);
  return QString();
}

QString ResultView::exportBodePlotTo(const QString& path) {
  if (!outcome_ || !outcome_->report) return tr("There is no result to export.");
  if (!bodeView_->plotShown())
    return tr("There is no Bode plot to export: %1").arg(responseMissingText(*outcome_->report));
  if (auto s = exportPlots({bodeView_->magnitudePlot(), bodeView_->phasePlot()}, path); !s.isOk())
    return coreText(s.message());
  emit exported(path);
  return QString();
}

Status ResultView::exportDataTo(const QString& dir) {
  if (!outcome_) return insufficientData("there is no session to export");
  FOG_RETURN_IF_ERROR(exportSessionData(*outcome_, dir));
  emit exported(dir);
  return Status::ok();
}

QString ResultView::defaultExportPath(const QString& what, const QString& suffix) const {
  QString folder = exportFolder_;
  QString name = what;
  QDateTime when = QDateTime::currentDateTimeUtc();
  if (outcome_) {
    if (!outcome_->sessionPath.empty())
      folder = QFileInfo(QString::fromStdString(outcome_->sessionPath)).absolutePath();
    QString serial = QString::fromStdString(outcome_->info.imuSerial).trimmed();
    // Only characters every file system takes.
    serial.replace(QRegularExpression("[^A-Za-z0-9._-]+"), "_");
    if (!serial.isEmpty()) name += "-" + serial;
    const QDateTime recorded = QDateTime::fromString(QString::fromStdString(outcome_->info.createdUtc), Qt::ISODate);
    if (recorded.isValid()) when = recorded.toUTC();
  }
  if (folder.isEmpty()) folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  name += "-" + when.toString("yyyyMMdd-HHmmss") + (suffix.isEmpty() ? QString() : "." + suffix);
  return QDir(folder).filePath(name);
}

Result<report::ReportInput> ResultView::reportInput() const {
  if (!outcome_ || !outcome_->report) return insufficientData("there is no delay result to report");
  // The report carries the hash of the raw stream the result came from.
  std::vector<std::uint8_t> rawBytes;
  std::vector<session::StoredResultRecord> analyses;
  if (!outcome_->sessionPath.empty()) {
    FOG_ASSIGN_OR_RETURN(auto opened,
                         session::openSessionOrStream(outcome_->sessionPath, session::OpenOptions::sessionStream()));
    rawBytes = std::move(opened.rawBytes);
    // The file's trail as it is now: every analysis stored so far.
    analyses = opened.results;
  }
  auto in = report::makeReportInput(outcome_->info, outcome_->recording, *outcome_->report, std::move(rawBytes),
                                    outcome_->shownResult(), outcome_->imuDelayLimitMs,
                                    outcome_->complete ? std::string() : outcome_->incompleteReason,
                                    resultDescription(), outcome_->coverageK);
  in.analyses = std::move(analyses);
  return in;
}

Status ResultView::writeReportPdf(const QString& path) const {
  FOG_ASSIGN_OR_RETURN(auto in, reportInput());
  return report::writeCalibrationPdf(in, path);
}

}  // namespace fog::ui

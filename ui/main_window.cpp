#include "ui/main_window.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QFontInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/bench_presets.h"
#include "ui/series_plot.h"

namespace fog::ui {

namespace {

const QColor kTableData(31, 119, 180);
const QColor kGyroData(255, 127, 14);
const QColor kTableFit(8, 48, 107);
const QColor kGyroFit(165, 15, 21);

QString number(double value, int decimals) { return QString::number(value, 'f', decimals); }

QString pointLabel(const analysis::TestPointResult& p) {
  return QObject::tr("%1: %2 axis, %3 Hz / %4°")
      .arg(p.index + 1)
      .arg(QString(axisName(p.axis)).toUpper())
      .arg(p.nominalFrequencyHz)
      .arg(number(p.tableFit.amplitudeDeg, 2));
}

QString durationText(double seconds) {
  const auto s = static_cast<long long>(std::ceil(std::max(seconds, 0.0)));
  return s >= 60 ? QObject::tr("%1 min %2 s").arg(s / 60).arg(s % 60, 2, 10, QChar('0')) : QObject::tr("%1 s").arg(s);
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("fogbench — FOG IMU delay bench"));
  buildControls();
  buildResults();
  connect(&runner_, &BenchRunner::progressed, this, &MainWindow::showProgress);
  connect(&runner_, &BenchRunner::finished, this, &MainWindow::showOutcome);
  connect(&runner_, &BenchRunner::failed, this, &MainWindow::showFailure);
  connect(&runner_, &BenchRunner::cancelled, this, &MainWindow::showCancelled);
  setRunning(false);
  statusBar()->showMessage(tr("Choose a plan and press Run."));
}

MainWindow::~MainWindow() = default;

void MainWindow::buildControls() {
  auto* bar = addToolBar(tr("Run"));
  bar->setObjectName("runToolBar");
  bar->setMovable(false);

  bar->addWidget(new QLabel(tr(" Plan ")));
  presetCombo_ = new QComboBox();
  presetCombo_->setObjectName("presetCombo");
  for (const auto& preset : benchPresets()) presetCombo_->addItem(preset.label, preset.name);
  bar->addWidget(presetCombo_);

  bar->addWidget(new QLabel(tr("  Seed ")));
  seedSpin_ = new QSpinBox();
  seedSpin_->setObjectName("seedSpin");
  seedSpin_->setRange(0, std::numeric_limits<int>::max());
  seedSpin_->setValue(1);
  seedSpin_->setToolTip(tr("Simulator seed: the same seed gives the same data"));
  bar->addWidget(seedSpin_);
  bar->addSeparator();

  runButton_ = new QPushButton(tr("Run"));
  runButton_->setObjectName("runButton");
  stopButton_ = new QPushButton(tr("Stop"));
  stopButton_->setObjectName("stopButton");
  bar->addWidget(runButton_);
  bar->addWidget(stopButton_);
  connect(runButton_, &QPushButton::clicked, this, &MainWindow::startRun);
  connect(stopButton_, &QPushButton::clicked, this, &MainWindow::stopRun);

  framesLabel_ = new QLabel();
  framesLabel_->setObjectName("framesLabel");
  progressBar_ = new QProgressBar();
  progressBar_->setObjectName("progressBar");
  progressBar_->setRange(0, 1000);
  progressBar_->setMaximumWidth(220);
  remainingLabel_ = new QLabel();
  statusBar()->addPermanentWidget(framesLabel_);
  statusBar()->addPermanentWidget(progressBar_);
  statusBar()->addPermanentWidget(remainingLabel_);
  showHealth({});
}

void MainWindow::buildResults() {
  auto* top = new QWidget();
  auto* topLayout = new QVBoxLayout(top);
  topLayout->setContentsMargins(6, 6, 6, 0);

  auto* selectorRow = new QHBoxLayout();
  selectorRow->addWidget(new QLabel(tr("Test point")));
  testPointCombo_ = new QComboBox();
  testPointCombo_->setObjectName("testPointCombo");
  testPointCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  selectorRow->addWidget(testPointCombo_);
  lagLabel_ = new QLabel();
  lagLabel_->setObjectName("lagLabel");
  lagLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  selectorRow->addSpacing(12);
  selectorRow->addWidget(lagLabel_, 1);
  topLayout->addLayout(selectorRow);
  connect(testPointCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &MainWindow::showTestPoint);

  anglePlot_ = new SeriesPlot(tr("Normalised angles and fits"), tr("(angle − offset) / amplitude"));
  anglePlot_->setObjectName("anglePlot");
  residualPlot_ = new SeriesPlot(tr("Residuals (data − fit)"), tr("residual (arcsec)"));
  residualPlot_->setObjectName("residualPlot");
  auto* plots = new QSplitter(Qt::Horizontal);
  plots->addWidget(anglePlot_);
  plots->addWidget(residualPlot_);
  topLayout->addWidget(plots, 1);

  reportView_ = new QPlainTextEdit();
  reportView_->setObjectName("reportView");
  reportView_->setReadOnly(true);
  reportView_->setLineWrapMode(QPlainTextEdit::NoWrap);
  // The report is laid out in columns. Some platforms (offscreen) answer the
  // fixed-font query with a proportional font; ask fontconfig's alias then.
  QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  if (!QFontInfo(mono).fixedPitch()) {
    mono.setFamily("monospace");
    mono.setStyleHint(QFont::TypeWriter);
  }
  reportView_->setFont(mono);
  reportView_->setPlaceholderText(tr("The delay report appears here after a run."));

  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(top);
  split->addWidget(reportView_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  setCentralWidget(split);
}

bool MainWindow::selectPreset(const QString& name) {
  const int i = presetCombo_->findData(name);
  if (i < 0) return false;
  presetCombo_->setCurrentIndex(i);
  return true;
}

void MainWindow::setSeed(int seed) { seedSpin_->setValue(seed); }

bool MainWindow::isRunning() const { return runner_.isRunning(); }

const analysis::DelayReport* MainWindow::lastReport() const { return outcome_ ? &outcome_->report : nullptr; }

QString MainWindow::reportText() const { return reportView_->toPlainText(); }

void MainWindow::startRun() {
  if (runner_.isRunning()) return;
  const auto preset = findBenchPreset(presetCombo_->currentData().toString());
  if (!preset) {
    showFailure(tr("no plan is selected"));
    return;
  }
  BenchJob job;
  job.plan = preset->plan;
  job.config.seed = static_cast<std::uint64_t>(seedSpin_->value());
  std::string why;
  if (!job.plan.isValid(job.config.turntable.limits, &why)) {
    showFailure(tr("the plan cannot run: %1").arg(QString::fromStdString(why)));
    return;
  }

  outcome_.reset();
  testPointCombo_->clear();
  lagLabel_->clear();
  anglePlot_->clearCurves();
  anglePlot_->showAll();
  residualPlot_->clearCurves();
  residualPlot_->showAll();
  reportView_->clear();
  showHealth({});
  progressBar_->setValue(0);
  remainingLabel_->clear();
  runClock_.start();
  if (!runner_.start(job)) return;
  setRunning(true);
  statusBar()->showMessage(tr("Running %1, seed %2 …").arg(preset->label).arg(seedSpin_->value()));
}

void MainWindow::stopRun() {
  if (!runner_.isRunning()) return;
  runner_.cancel();
  stopButton_->setEnabled(false);
  statusBar()->showMessage(tr("Stopping …"));
}

void MainWindow::setRunning(bool running) {
  runButton_->setEnabled(!running);
  stopButton_->setEnabled(running);
  presetCombo_->setEnabled(!running);
  seedSpin_->setEnabled(!running);
  progressBar_->setVisible(running);
  remainingLabel_->setVisible(running);
}

void MainWindow::showProgress(const BenchProgress& progress) {
  const double fraction = progress.totalS > 0.0 ? progress.simulatedS / progress.totalS : 1.0;
  progressBar_->setValue(static_cast<int>(std::lround(1000.0 * std::clamp(fraction, 0.0, 1.0))));
  remainingLabel_->setText(progress.analysing ? tr("analysing …")
                                              : tr("%1 left").arg(durationText(progress.remainingS)));
  showHealth(progress.health);
}

void MainWindow::showHealth(const StreamHealth& h) {
  framesLabel_->setText(tr("Frames decoded: %1 table, %2 IMU, %3 status  ·  checksum failures: %4 ")
                            .arg(h.tableFrames)
                            .arg(h.imuFrames)
                            .arg(h.statusFrames)
                            .arg(h.checksumFailures));
}

void MainWindow::showOutcome(std::shared_ptr<const BenchOutcome> outcome) {
  outcome_ = std::move(outcome);
  setRunning(false);
  showHealth(outcome_->recording.health);
  reportView_->setPlainText(QString::fromStdString(outcome_->reportText));
  {
    const QSignalBlocker block(testPointCombo_);
    testPointCombo_->clear();
    for (const auto& p : outcome_->report.points) testPointCombo_->addItem(pointLabel(p));
  }
  testPointCombo_->setCurrentIndex(0);
  showTestPoint(0);
  statusBar()->showMessage(tr("Done in %1: %2 test point(s) analysed, %3 without a delay")
                               .arg(durationText(static_cast<double>(runClock_.elapsed()) / 1e3))
                               .arg(outcome_->report.points.size())
                               .arg(outcome_->report.failedPoints.size()));
  emit runEnded(true);
}

void MainWindow::showFailure(const QString& message) {
  setRunning(false);
  statusBar()->showMessage(tr("Run failed: %1").arg(message));
  reportView_->setPlainText(tr("The run gave no result.\n\n%1\n").arg(message));
  emit runEnded(false);
}

void MainWindow::showCancelled() {
  setRunning(false);
  statusBar()->showMessage(tr("Run stopped; nothing was analysed."));
  emit runEnded(false);
}

void MainWindow::showTestPoint(int position) {
  anglePlot_->clearCurves();
  residualPlot_->clearCurves();
  if (!outcome_ || position < 0 || position >= static_cast<int>(outcome_->traces.size())) {
    lagLabel_->clear();
    anglePlot_->showAll();
    residualPlot_->showAll();
    return;
  }
  const auto i = static_cast<std::size_t>(position);
  const auto& p = outcome_->report.points[i];
  QString lag = tr("<b>lag %1 ± %2 ms</b>  ·  IMU delay %3 ms  ·  gyro's own delay %4 ms")
                    .arg(number(p.lagMs, 4), number(p.lagStdMs, 4), number(p.imuDelayMs, 4), number(p.gyroDelayMs, 4));
  for (const auto& t : outcome_->truth)
    if (t.index == p.index) lag += tr("  ·  simulator truth: lag %1 ms").arg(number(t.lagS * 1e3, 4));
  lagLabel_->setText(lag);

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
}

}  // namespace fog::ui

#include "ui/main_window.h"

#include <QActionGroup>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QApplication>
#include <QScreen>
#include <QScrollArea>
#include <QUrl>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>
#include <QDockWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <qwt_global.h>
#include <sstream>

#include "core/acquisition/replay_source.h"
#include "core/acquisition/simulator_source.h"
#include "core/analysis/report_writer.h"
#include "core/common/version.h"
#include "core/io/csv_import.h"
#include "core/io/imported_session.h"
#include "core/serial/serial_source.h"
#include "core/session/session_api.h"
#include "ui/bench_settings_dialog.h"
#include "ui/compare_view.h"
#include "ui/table_panel.h"
#include "ui/core_text.h"
#include "ui/verdict_text.h"
#include "ui/import_dialog.h"
#include "ui/diagnosis_view.h"
#include "ui/language/language.h"
#include "ui/live_view.h"
#include "ui/messages.h"
#include "ui/noise_view.h"
#include "ui/plan_editor.h"
#include "ui/result_view.h"
#include "ui/session_browser.h"
#include "ui/table_drive.h"
#include "ui/units_view.h"

namespace fog::ui {

namespace {

QString durationText(double seconds) {
  const auto s = static_cast<long long>(std::ceil(std::max(seconds, 0.0)));
  return s >= 60 ? QObject::tr("%1 min %2 s").arg(s / 60).arg(s % 60, 2, 10, QChar('0')) : QObject::tr("%1 s").arg(s);
}

// The simulated chain follows the bench's constants, so that the simulator
// behaves like the bench the operator described.
model::SimConfig simConfigOf(const BenchConstants& b, int seed) {
  model::SimConfig c;
  c.seed = static_cast<std::uint64_t>(seed);
  c.encoder.readDelayS = b.tableReadDelayMs * 1e-3;
  c.imuBoard.processingS = b.boardDelayMs * 1e-3 - c.imuBoard.serialS();
  c.earth.latitudeDeg = b.latitudeDeg;
  model::applyImuFrame(b.imuFrame, c.earth);
  if (b.pulseEquivalentDeg > 0.0) c.fog.pulseEquivalentDeg = b.pulseEquivalentDeg;  // else the simulator's own
  c.samplingBoard.counterHz = b.counterHz;
  c.samplingBoard.counterBits = b.counterBits;
  return c;
}

// Holds a view at the size of the scroll area's viewport, down to the view's
// minimum size. (A view whose layout has height-for-width, from a wrapping
// label, would otherwise be given its preferred height by the scroll area
// and scroll even when it could fit.)
class Fitted : public QWidget {
 public:
  explicit Fitted(QWidget* view) : view_(view) {
    setObjectName(view->objectName() + "Frame");
    view->setParent(this);
    view->installEventFilter(this);
  }
  QSize minimumSizeHint() const override { return view_->minimumSizeHint().expandedTo(view_->minimumSize()); }
  QSize sizeHint() const override { return view_->sizeHint(); }

 protected:
  void resizeEvent(QResizeEvent*) override { view_->setGeometry(rect()); }
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched == view_ && event->type() == QEvent::LayoutRequest) updateGeometry();
    return false;
  }

 private:
  QWidget* view_;
};

// A view in a scroll area: on a small screen the view keeps its minimum size
// and scrolls instead of pushing the window off the screen.
QWidget* scrollable(QWidget* view) {
  auto* area = new QScrollArea();
  area->setObjectName(view->objectName() + "Scroll");
  area->setWidget(new Fitted(view));
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  return area;
}

constexpr int kMaxRecentSessions = 8;

// Runs `work` on the thread pool and hands its result to `done` on the GUI
// thread, as long as `owner` lives. The result type must be
// default-constructible (QFuture's rule): an outcome or the reason why not.
template <typename Work, typename Done>
QFuture<std::invoke_result_t<Work>> inBackground(QObject* owner, Work work, Done done) {
  using Result = std::invoke_result_t<Work>;
  auto* watcher = new QFutureWatcher<Result>(owner);
  QObject::connect(watcher, &QFutureWatcherBase::finished, owner, [watcher, done = std::move(done)]() mutable {
    Result result = watcher->result();
    watcher->deleteLater();
    done(std::move(result));
  });
  auto future = QtConcurrent::run(std::move(work));
  watcher->setFuture(future);
  return future;
}

QString defaultSessionFolder() {
  return QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)).filePath("fogbench-sessions");
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("fogbench %1 — FOG IMU delay bench").arg(FOG_VERSION));

  tabs_ = new QTabWidget();
  tabs_->setObjectName("viewTabs");
  tabs_->setDocumentMode(true);
  configureView_ = new ConfigureView();
  configureView_->setObjectName("configureView");
  planEditor_ = configureView_->planEditor();
  tabs_->addTab(scrollable(configureView_), tr("Configure"));
  liveView_ = new LiveView();
  liveView_->setObjectName("liveView");
  tabs_->addTab(scrollable(liveView_), tr("Live"));
  resultView_ = new ResultView();
  resultView_->setObjectName("resultView");
  tabs_->addTab(scrollable(resultView_), tr("Results"));
  sessionBrowser_ = new SessionBrowser();
  sessionBrowser_->setObjectName("sessionBrowser");
  tabs_->addTab(scrollable(sessionBrowser_), tr("Sessions"));
  unitsView_ = new UnitsView();
  unitsView_->setObjectName("unitsView");
  tabs_->addTab(scrollable(unitsView_), tr("Units"));
  diagnosisView_ = new DiagnosisView();
  diagnosisView_->setObjectName("diagnosisView");
  tabs_->addTab(scrollable(diagnosisView_), tr("Diagnosis"));
  noiseView_ = new NoiseView();
  noiseView_->setObjectName("noiseView");
  tabs_->addTab(scrollable(noiseView_), tr("Noise"));
  setCentralWidget(tabs_);
  // The turntable between runs (ui/table_panel.h): a dock, hidden until
  // View ▸ Table controls; its emergency stop is also in the tool bar.
  tablePanel_ = new TablePanel();
  tablePanel_->setAddressSource([this] {
    return configureView_->tableDriver() == ConfigureView::TableDriver::kRemote ? configureView_->tableAddress()
                                                                                : QString();
  });
  tableDock_ = new QDockWidget(tr("Table"));
  tableDock_->setObjectName("tableDock");
  tableDock_->setWidget(scrollable(tablePanel_));
  addDockWidget(Qt::RightDockWidgetArea, tableDock_);
  tableDock_->hide();
  buildToolBar();
  buildMenus();
  analysis_ = loadAnalysisChoices();
  setBenchConstants(loadBenchConstants());

  framesLabel_ = new QLabel();
  framesLabel_->setObjectName("framesLabel");
  statusBar()->addPermanentWidget(framesLabel_);
  showHealth({}, 0);

  connect(&runner_, &AcquisitionRunner::finished, this, &MainWindow::showOutcome);
  connect(&runner_, &AcquisitionRunner::failed, this, &MainWindow::showFailure);
  liveTimer_.setInterval(33);
  connect(&liveTimer_, &QTimer::timeout, this, &MainWindow::drainLive);
  connect(planEditor_, &PlanEditor::validityChanged, this, &MainWindow::updateRunButton);
  connect(sessionBrowser_, &SessionBrowser::openRequested, this, &MainWindow::openSession);
  connect(sessionBrowser_, &SessionBrowser::reanalyseRequested, this, &MainWindow::reanalyseSession);
  connect(resultView_, &ResultView::resultChosen, this, &MainWindow::chooseResult);
  connect(sessionBrowser_, &SessionBrowser::compareRequested, this, &MainWindow::compareSessions);
  connect(sessionBrowser_, &SessionBrowser::importRequested, this, &MainWindow::chooseImportOptions);
  // Units shows the catalog of the folder Sessions shows, and opens a
  // result's session the way Sessions does.
  connect(sessionBrowser_, &SessionBrowser::folderChanged, unitsView_, &UnitsView::setSessionFolder);
  connect(unitsView_, &UnitsView::openSessionRequested, this, &MainWindow::openSession);
  connect(unitsView_, &UnitsView::statusMessage, this, &MainWindow::tell);
  connect(resultView_, &ResultView::diagnoseRequested, this, &MainWindow::diagnoseShown);
  connect(diagnosisView_, &DiagnosisView::cancelRequested, this, &MainWindow::cancelDiagnosis);
  connect(resultView_, &ResultView::exported, this, &MainWindow::exported);
  connect(resultView_, &ResultView::exportFailed, this, [this](const QString& title, const QString& why) {
    reportError(title, title, why);
  });
  connect(resultView_, &ResultView::openExportFolderRequested, this, &MainWindow::openExportFolder);

  QSettings settings;
  setSessionFolder(settings.value("sessions/folder", defaultSessionFolder()).toString());
  restoreState();
  // The operator's choices are remembered as they are made.
  connect(planEditor_, &PlanEditor::planChanged, this, &MainWindow::rememberState);
  connect(configureView_, &ConfigureView::paceChanged, this, &MainWindow::rememberState);
  // A driven table needs a pace (not "as fast as possible").
  connect(configureView_, &ConfigureView::paceChanged, this, &MainWindow::updateRunButton);
  connect(configureView_, &ConfigureView::identityChanged, this, &MainWindow::rememberState);
  connect(configureView_, &ConfigureView::sourceChanged, this, &MainWindow::rememberState);
  connect(configureView_, &ConfigureView::runnabilityChanged, this, &MainWindow::rememberState);
  connect(configureView_, &ConfigureView::sourceChanged, this, [this] { setRunning(runner_.isRunning()); });
  connect(configureView_, &ConfigureView::runnabilityChanged, this, &MainWindow::updateRunButton);
  connect(configureView_, &ConfigureView::folderChosen, this, [this](const QString& folder) { setSessionFolder(folder); });
  connect(configureView_, &ConfigureView::editBenchSettingsRequested, this, &MainWindow::editBenchConstants);
  setRunning(false);
  tell(tr("Configure a plan and press Run."));
}

MainWindow::~MainWindow() {
  // A running diagnosis posts its progress to this window: it ends first
  // (a cancel stops it within about a second).
  cancelDiagnosis();
  diagnosisFuture_.waitForFinished();
}

void MainWindow::editBenchConstants() {
  BenchSettingsDialog dialog(bench_, analysis_, this);
  if (dialog.exec() == QDialog::Accepted) {
    setAnalysisChoices(dialog.analysisChoices());
    setBenchConstants(dialog.settings());
    saveBenchConstants(bench_);
    saveAnalysisChoices(analysis_);
  }
}

QString MainWindow::aboutText() const {
  return tr("<h3>fogbench %1</h3><p>Fiber-optic gyro IMU delay test bench: swing the IMU on a turntable, "
            "stamp table angle and gyro increments with one counter, fit sinusoids to both and turn their "
            "phase difference into the IMU's delay, with its uncertainty.</p>"
            "<p>Built with Qt %2 (running on %3) and Qwt %4.</p>")
      .arg(FOG_VERSION, QT_VERSION_STR, qVersion(), QWT_VERSION_STR);
}

void MainWindow::buildToolBar() {
  auto* bar = addToolBar(tr("Run"));
  bar->setObjectName("runToolBar");
  bar->setMovable(false);
  runButton_ = new QPushButton(tr("Run"));
  runButton_->setObjectName("runButton");
  stopButton_ = new QPushButton(tr("Stop"));
  stopButton_->setObjectName("stopButton");
  stopButton_->setToolTip(tr("End the run now; everything received so far is kept and analysed"));
  bar->addWidget(runButton_);
  bar->addWidget(stopButton_);
  connect(runButton_, &QPushButton::clicked, this, &MainWindow::startRun);
  connect(stopButton_, &QPushButton::clicked, this, &MainWindow::stopRun);

  // The emergency stop, always in view: every axis of the connected table
  // stops at once (and a run is stopped too).
  bar->addSeparator();
  emergencyStopAction_ = new QAction(tr("EMERGENCY STOP"), this);
  emergencyStopAction_->setObjectName("emergencyStopAction");
  connect(emergencyStopAction_, &QAction::triggered, this, &MainWindow::emergencyStop);
  bar->addAction(emergencyStopAction_);
  if (auto* button = bar->widgetForAction(emergencyStopAction_)) {
    button->setObjectName("emergencyStopButton");
    button->setStyleSheet("QToolButton { background: #c00000; color: white; font-weight: bold; padding: 3px 10px; }"
                          "QToolButton:disabled { background: #d8b0b0; color: #f4f4f4; }");
  }
  connect(tablePanel_, &TablePanel::availabilityChanged, this, &MainWindow::updateEmergencyStop);
  connect(tablePanel_, &TablePanel::controllerLimits, this,
          [this](const QString& description, const std::optional<table::TableLimits>& limits) {
            if (limits)
              configureView_->setConnectedTable(description, *limits);
            else
              configureView_->clearConnectedTable();
          });
  // The emergency stop's outcome comes later (it never waits): a failure is
  // for the operator to read whole.
  connect(tablePanel_, &TablePanel::emergencyStopReport, this, [this](const QString& text, bool failed) {
    if (failed) reportError(tr("Emergency stop"), tr("The emergency stop failed"), text);
  });
  updateEmergencyStop();
}

void MainWindow::updateEmergencyStop() {
  const bool runDrivesTable = table_ && runner_.isRunning();
  const bool available = tablePanel_->emergencyStopAvailable() || runDrivesTable;
  emergencyStopAction_->setEnabled(available);
  emergencyStopAction_->setToolTip(available ? tr("Stop every axis of the table at once (latched at the controller)")
                                             : tablePanel_->disabledReason() + tr(" (View ▸ Table controls)"));
}

void MainWindow::emergencyStop() {
  // The run's own connection first: it is the one moving the table.
  const bool throughRun = table_ && runner_.isRunning() && table_->requestEmergencyStop();
  // ... and, as the runner may be waiting on its controller, on the
  // emergency line too: a connection of its own that nothing holds up.
  const bool runManual = throughRun && table_->settings().manual;
  if (throughRun && !runManual)
    tablePanel_->emergencyStopAt(QString::fromStdString(table_->settings().address));
  QString why;
  bool throughPanel = false;
  if (tablePanel_->emergencyStopAvailable()) {
    why = tablePanel_->emergencyStop();
    throughPanel = why.isEmpty();
  }
  if (runner_.isRunning()) stopRun();
  if (tablePanel_->emergencyStopAvailable()) tableDock_->show();  // where the axes' state and the message are
  if (!throughRun && !throughPanel)
    reportError(tr("Emergency stop"), tr("The emergency stop failed"),
                why.isEmpty() ? tr("No table connection is open: neither a run drives the table nor is the table "
                                   "panel connected. Use the controller's own emergency stop.")
                              : why);
  else if (throughRun)
    tell((runManual
              ? tr("Emergency stop: the run's table driver sends it at its next step; the run stops.")
              : tr("Emergency stop: sent on a connection of its own, and by the run's table driver at its next "
                   "step; the run stops.")) +
         (why.isEmpty() ? QString() : tr(" The table panel's connection failed: %1").arg(why)));
  else
    tell(tr("Emergency stop sent to the table; the table panel says what came of it."));
}

void MainWindow::buildMenus() {
  auto* file = menuBar()->addMenu(tr("&File"));
  auto* open = file->addAction(tr("&Open session…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), sessionBrowser_->folder(),
                                                      tr("fogbench sessions (*.fbs);;All files (*)"));
    if (!path.isEmpty()) openSession(path);
  });
  open->setObjectName("openSessionAction");
  open->setShortcut(QKeySequence::Open);
  recentMenu_ = file->addMenu(tr("Open &recent"));
  recentMenu_->setObjectName("recentMenu");
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
  fillRecentMenu();
  file->addSeparator();
  auto* loadPlan = file->addAction(tr("&Load test plan…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load test plan"), sessionFolder(),
                                                      tr("Test plans (*.json);;All files (*)"));
    if (path.isEmpty()) return;
    if (auto s = loadPlanFile(path); !s.isOk())
      reportError(tr("Load test plan"), tr("Cannot load the test plan %1").arg(QFileInfo(path).fileName()),
                  coreText(s.message()));
  });
  loadPlan->setObjectName("loadPlanAction");
  loadPlan->setShortcut(QKeySequence(QStringLiteral("Ctrl+L")));
  auto* savePlan = file->addAction(tr("&Save test plan…"), this, [this] {
    QString path = QFileDialog::getSaveFileName(this, tr("Save test plan"), QDir(sessionFolder()).filePath("plan.json"),
                                                tr("Test plans (*.json)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += ".json";
    if (auto s = savePlanFile(path); !s.isOk())
      reportError(tr("Save test plan"), tr("Cannot save the test plan as %1").arg(path),
                  coreText(s.message()));
  });
  savePlan->setObjectName("savePlanAction");
  savePlan->setShortcut(QKeySequence::Save);
  file->addSeparator();
  auto* import = file->addAction(tr("&Import CSV data…"), this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder with metadata.json, table.csv, gyro.csv"));
    if (!dir.isEmpty()) chooseImportOptions(dir);
  });
  import->setObjectName("importAction");
  openExportFolderAction_ = file->addAction(tr("Open the &export folder"), this, &MainWindow::openExportFolder);
  openExportFolderAction_->setObjectName("openExportFolderAction");
  openExportFolderAction_->setToolTip(tr("Show the folder of the last export (plot or report)"));
  file->addSeparator();
  auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setObjectName("quitAction");
  quit->setShortcut(QKeySequence(QStringLiteral("Ctrl+Q")));
  quit->setMenuRole(QAction::QuitRole);

  auto* run = menuBar()->addMenu(tr("&Run"));
  runAction_ = run->addAction(tr("&Run"), this, &MainWindow::startRun);
  runAction_->setObjectName("runAction");
  runAction_->setShortcuts({QKeySequence(QStringLiteral("F5")), QKeySequence(QStringLiteral("Ctrl+R"))});
  stopAction_ = run->addAction(tr("&Stop"), this, &MainWindow::stopRun);
  stopAction_->setObjectName("stopAction");
  stopAction_->setShortcuts({QKeySequence(QStringLiteral("Shift+F5")), QKeySequence(QStringLiteral("Ctrl+."))});
  stopAction_->setToolTip(tr("End the run now; everything received so far is kept and analysed"));
  run->addSeparator();
  auto* diagnose = run->addAction(tr("&Diagnose the shown result"), this, &MainWindow::diagnoseShown);
  diagnose->setObjectName("diagnoseAction");
  diagnose->setShortcut(QKeySequence(QStringLiteral("Ctrl+D")));
  auto* reanalyse = run->addAction(tr("Re-&analyse the shown session"), this, [this] {
    if (const auto* o = resultView_->outcome(); o && !o->sessionPath.empty())
      reanalyseSession(QString::fromStdString(o->sessionPath));
    else
      tell(tr("Open a session first: a re-analysis is stored in the session it analyses."));
  });
  reanalyse->setObjectName("reanalyseAction");
  reanalyse->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+R")));

  auto* view = menuBar()->addMenu(tr("&View"));
  const QStringList names = {tr("&Configure"), tr("&Live"), tr("&Results"), tr("&Sessions"), tr("&Units"),
                             tr("&Diagnosis"), tr("&Noise")};
  for (int i = 0; i < names.size(); ++i) {
    auto* action = view->addAction(names[i], this, [this, i] { showView(static_cast<View>(i)); });
    action->setObjectName(QString("viewAction%1").arg(i));
    action->setShortcut(QKeySequence(QString("Ctrl+%1").arg(i + 1)));
  }

  view->addSeparator();
  QAction* tableAction = tableDock_->toggleViewAction();
  tableAction->setText(tr("&Table controls"));
  tableAction->setObjectName("tableControlsAction");
  tableAction->setShortcut(QKeySequence(QStringLiteral("Ctrl+T")));
  view->addAction(tableAction);

  auto* tools = menuBar()->addMenu(tr("&Tools"));
  auto* constants = tools->addAction(tr("&Bench constants…"), this, &MainWindow::editBenchConstants);
  constants->setObjectName("benchConstantsAction");
  auto* languages = tools->addMenu(tr("&Language"));
  auto* group = new QActionGroup(languages);
  const QString current = languageSetting();
  QStringList codes = {"system"};
  codes << availableLanguages();
  for (const QString& code : codes) {
    auto* action = languages->addAction(code == "system" ? tr("System default") : languageName(code));
    action->setObjectName("language_" + code);
    action->setCheckable(true);
    action->setChecked(code == current);
    group->addAction(action);
    connect(action, &QAction::triggered, this, [this, code, action] {
      if (isRunning() || isDiagnosing()) {
        // The window is made again in the new language: not under a run.
        action->setChecked(false);
        if (auto* same = findChild<QAction*>("language_" + languageSetting())) same->setChecked(true);
        tell(tr("The language can be changed once the run or the diagnosis has ended."));
        return;
      }
      setLanguageSetting(code);
      emit languageChosen(code);
    });
  }

  auto* help = menuBar()->addMenu(tr("&Help"));
  auto* guide = help->addAction(tr("&Shortcuts"), this, [this] {
    showMessage(this, MessageKind::kInformation, tr("Shortcuts"), tr("Keyboard shortcuts"),
                tr("Run: F5 or Ctrl+R\nStop: Shift+F5 or Ctrl+.\nDiagnose the shown result: Ctrl+D\n"
                   "Re-analyse the shown session: Ctrl+Shift+R\nOpen a session: Ctrl+O\nLoad a test plan: Ctrl+L\n"
                   "Save the test plan: Ctrl+S\nViews: Ctrl+1 … Ctrl+7\nQuit: Ctrl+Q\n"
                   "Plots: wheel zooms, drag pans, double-click shows all, click sets cursors A/B"));
  });
  guide->setObjectName("shortcutsAction");
  auto* about = help->addAction(tr("&About fogbench"));
  about->setObjectName("aboutAction");
  about->setMenuRole(QAction::AboutRole);
  connect(about, &QAction::triggered, this, [this] { QMessageBox::about(this, tr("About fogbench"), aboutText()); });
}

void MainWindow::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = recentSessions();
  for (const QString& path : recent) {
    auto* action = recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] { openSession(path); });
    action->setToolTip(path);
    action->setStatusTip(path);
  }
  if (recent.isEmpty()) recentMenu_->addAction(tr("(none yet)"))->setEnabled(false);
  recentMenu_->setEnabled(true);
}

QStringList MainWindow::recentSessions() const { return QSettings().value("sessions/recent").toStringList(); }

void MainWindow::addRecentSession(const QString& path) {
  if (path.isEmpty()) return;
  QStringList recent = recentSessions();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recent.removeAll(absolute);
  recent.prepend(absolute);
  while (recent.size() > kMaxRecentSessions) recent.removeLast();
  QSettings().setValue("sessions/recent", recent);
}

Status MainWindow::loadPlanFile(const QString& path) {
  auto plan = loadTestPlanFile(path.toStdString());
  if (!plan) return plan.status();
  planEditor_->setPlan(*plan);
  tell(tr("Test plan loaded from %1").arg(QDir::toNativeSeparators(path)));
  return Status::ok();
}

Status MainWindow::savePlanFile(const QString& path) {
  std::ofstream out(path.toStdString(), std::ios::binary | std::ios::trunc);
  if (!out) return ioError("cannot write '" + path.toStdString() + "'; choose a folder you can write to");
  out << testPlanToJson(planEditor_->plan()) << '\n';
  out.close();
  if (!out) return ioError("writing '" + path.toStdString() + "' failed; check the free space");
  tell(tr("Test plan saved as %1").arg(QDir::toNativeSeparators(path)));
  return Status::ok();
}

void MainWindow::rememberState() {
  if (!remembering_ || restoring_) return;
  QSettings s;
  s.beginGroup("state");
  s.setValue("plan", QString::fromStdString(testPlanToJson(planEditor_->plan())));
  s.setValue("pace", configureView_->pace());
  s.setValue("operator", configureView_->operatorName());
  s.setValue("imuModel", configureView_->imuModel());
  s.setValue("imuSerial", configureView_->imuSerial());
  s.setValue("lot", configureView_->lot());
  // The station is set up once, like the serial port below.
  s.setValue("benchId", configureView_->benchId());
  // Where the data come from and who drives the table: a lab bench is set up
  // once, not at every start.
  s.setValue("source", static_cast<int>(configureView_->sourceKind()));
  s.setValue("serialPort", configureView_->serialPort());
  s.setValue("tableDriver", static_cast<int>(configureView_->tableDriver()));
  s.setValue("tableAddress", configureView_->tableAddress());
}

void MainWindow::restoreState() {
  restoring_ = true;
  QSettings s;
  s.beginGroup("state");
  if (s.contains("plan"))
    if (auto plan = testPlanFromJson(s.value("plan").toString().toStdString()); plan) planEditor_->setPlan(*plan);
  if (s.contains("pace") && s.value("pace").toDouble() >= 0.0) configureView_->setPace(s.value("pace").toDouble());
  configureView_->setIdentity(s.value("operator").toString(), s.value("imuModel").toString(),
                              s.value("imuSerial").toString());
  configureView_->setLotAndBench(s.value("lot").toString(), s.value("benchId").toString());
  if (const int source = s.value("source", -1).toInt(); source >= 0 && source <= 2)
    configureView_->setSourceKind(static_cast<ConfigureView::SourceKind>(source));
  if (s.contains("serialPort")) configureView_->setSerialPort(s.value("serialPort").toString());
  if (const int driver = s.value("tableDriver", -1).toInt(); driver >= 0 && driver <= 2)
    configureView_->setTableDriver(static_cast<ConfigureView::TableDriver>(driver),
                                   s.value("tableAddress").toString());
  restoring_ = false;
}

namespace {
// Splitters are named by their place among the window's splitters (created
// in the same order at every start), unless they have a name of their own.
QString splitterKey(const QSplitter* splitter, int index) {
  return "splitter/" + (splitter->objectName().isEmpty() ? QString::number(index) : splitter->objectName());
}
}  // namespace

void MainWindow::saveLayout() {
  if (!remembering_) return;
  QSettings s;
  s.beginGroup("layout");
  s.setValue("geometry", saveGeometry());
  s.setValue("view", static_cast<int>(currentView()));
  const auto splitters = findChildren<QSplitter*>();
  for (int i = 0; i < splitters.size(); ++i) s.setValue(splitterKey(splitters[i], i), splitters[i]->saveState());
}

namespace {
// Restores a splitter's divider once it is on screen at its real size: a
// splitter in a view not shown yet has no size, and its divider would be
// rescaled when the view first appears.
class SplitterRestorer : public QObject {
 public:
  SplitterRestorer(QSplitter* splitter, QByteArray state) : QObject(splitter), state_(std::move(state)) {
    splitter->installEventFilter(this);
    if (splitter->isVisible()) restoreLater(splitter);
  }
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Show) restoreLater(static_cast<QSplitter*>(watched));
    return false;
  }

 private:
  void restoreLater(QSplitter* splitter) {
    splitter->removeEventFilter(this);
    QTimer::singleShot(0, this, [this, splitter] {
      splitter->restoreState(state_);
      deleteLater();
    });
  }
  QByteArray state_;
};
}  // namespace

bool MainWindow::restoreLayout() {
  QSettings s;
  s.beginGroup("layout");
  const auto splitters = findChildren<QSplitter*>();
  for (int i = 0; i < splitters.size(); ++i)
    if (const QVariant state = s.value(splitterKey(splitters[i], i)); state.isValid())
      new SplitterRestorer(splitters[i], state.toByteArray());
  const int view = s.value("view", -1).toInt();
  if (view >= kConfigure && view <= kNoise) showView(static_cast<View>(view));
  // Qt moves a remembered window back onto a screen that has changed.
  return s.contains("geometry") && restoreGeometry(s.value("geometry").toByteArray());
}

void MainWindow::showOnScreen() {
  if (restoreLayout()) {
    show();
    return;
  }
  const QScreen* screen = QApplication::primaryScreen();
  const QRect free = screen ? screen->availableGeometry() : QRect(0, 0, 1500, 950);
  if (free.width() >= 1500 + 60 && free.height() >= 950 + 80) {
    resize(1500, 950);
    move(free.center() - QPoint(750, 475));
    show();
    return;
  }
  resize(free.width() - 16, free.height() - 48);
  move(free.topLeft());
  showMaximized();
}

void MainWindow::reportError(const QString& title, const QString& headline, const QString& details) {
  tell(headline);
  showMessage(this, MessageKind::kError, title, headline, details);
}

void MainWindow::exported(const QString& path) {
  lastExport_ = path;
  openExportFolderAction_->setEnabled(true);
  tell(tr("Saved %1 — File ▸ Open the export folder shows it").arg(QDir::toNativeSeparators(path)));
}

void MainWindow::openExportFolder() {
  const QString folder = lastExport_.isEmpty() ? sessionFolder() : QFileInfo(lastExport_).absolutePath();
  if (folder.isEmpty()) return;
  if (!QDesktopServices::openUrl(QUrl::fromLocalFile(folder)))
    reportError(tr("Open the export folder"), tr("Cannot open the folder %1").arg(QDir::toNativeSeparators(folder)),
                tr("No file manager answered; open the folder by hand: %1").arg(QDir::toNativeSeparators(folder)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!runner_.isRunning()) {
    saveLayout();
    event->accept();
    return;
  }
  event->ignore();
  // Non-modal: the run goes on while the operator decides.
  auto* box = findChild<QMessageBox*>("closeConfirmDialog", Qt::FindDirectChildrenOnly);
  if (!box) {
    box = new QMessageBox(QMessageBox::Question, tr("A run is under way"),
                          tr("A run is under way. Stop it and close fogbench?"), QMessageBox::NoButton, this);
    box->setObjectName("closeConfirmDialog");  // kept when closed, reused
    box->setWindowModality(Qt::NonModal);
    auto* stop = box->addButton(tr("Stop the run and close"), QMessageBox::AcceptRole);
    stop->setObjectName("stopAndCloseButton");
    auto* keep = box->addButton(tr("Keep running"), QMessageBox::RejectRole);
    keep->setObjectName("keepRunningButton");
    box->setDefaultButton(keep);
    connect(stop, &QPushButton::clicked, this, [this] {
      closeAfterRun_ = true;
      stopRun();
    });
  }
  box->setInformativeText(table_ ? tr("Stopping brings the table to rest and keeps everything received so far in "
                                      "the session file, marked incomplete; fogbench closes once the table is at rest.")
                                 : tr("Stopping keeps everything received so far in the session file, marked incomplete."));
  box->show();
  box->raise();
}

void MainWindow::showView(View view) { tabs_->setCurrentIndex(view); }

QString MainWindow::shownSessionPath() const { return shown_ ? QString::fromStdString(shown_->sessionPath) : QString(); }

MainWindow::View MainWindow::currentView() const { return static_cast<View>(tabs_->currentIndex()); }

void MainWindow::useSimulator(double speed, int seed) {
  setSourceKind(SourceKind::kSimulator);
  configureView_->setPace(speed);
  configureView_->setSeed(seed);
}

void MainWindow::useReplay(const QString& sessionPath, double speed) {
  useSimulator(speed, configureView_->seed());
  setSourceKind(SourceKind::kReplay);
  configureView_->setReplayPath(sessionPath);
}

void MainWindow::useSerialBoard(const QString& port, ConfigureView::TableDriver table, const QString& tableAddress) {
  setSourceKind(SourceKind::kSerial);
  configureView_->setSerialPort(port);
  configureView_->setTableDriver(table, tableAddress.isEmpty() ? QString() : tableAddress);
}

void MainWindow::setSessionFolder(const QString& folder) {
  configureView_->setSessionFolder(folder);
  resultView_->setExportFolder(folder);
  if (!folder.isEmpty()) {
    // A one-off folder (fogbench --session-folder) is not remembered.
    if (remembering_) QSettings().setValue("sessions/folder", folder);
    if (sessionBrowser_->folder() != folder) sessionBrowser_->setFolder(folder);
  }
}

QString MainWindow::sessionFolder() const { return configureView_->sessionFolder(); }

void MainWindow::setBenchConstants(const BenchConstants& s) {
  bench_ = s;
  configureView_->showBenchConstants(bench_, analysis_.gyroSign);
}

void MainWindow::setAnalysisChoices(const AnalysisChoices& choices) {
  analysis_ = choices;
  configureView_->showBenchConstants(bench_, analysis_.gyroSign);
}

const RunOutcome* MainWindow::lastOutcome() const { return shown_.get(); }

void MainWindow::tell(const QString& message) {
  lastMessage_ = message;
  statusBar()->showMessage(message);
}

SessionInfo MainWindow::sessionInfo() const {
  SessionInfo info;
  info.operatorName = configureView_->operatorName().toStdString();
  info.imuModel = configureView_->imuModel().toStdString();
  info.imuSerial = configureView_->imuSerial().toStdString();
  info.lot = configureView_->lot().toStdString();
  info.benchId = configureView_->benchId().toStdString();
  info.notes = configureView_->notes().toStdString();
  info.softwareVersion = FOG_VERSION;
  info.createdUtc = session::utcNow();
  info.bench = bench_;
  return info;
}

void MainWindow::updateRunButton() {
  QString why;
  if (runner_.isRunning()) why = tr("a run is under way");
  else if (sourceKind() == SourceKind::kSimulator && !planEditor_->isValid()) why = planEditor_->problem();
  else if (sourceKind() == SourceKind::kReplay && configureView_->replayPath().isEmpty())
    why = tr("choose the session file to replay");
  else if (sourceKind() == SourceKind::kSerial && configureView_->serialPort().isEmpty())
    why = tr("choose the sampling board's serial port");
  else if (drivesTable() && !planEditor_->isValid()) why = planEditor_->problem();
  else if (drivesTable() && configureView_->tableDriver() == ConfigureView::TableDriver::kRemote &&
           configureView_->tableAddress().isEmpty())
    why = tr("give the turntable controller's address (tcp:HOST:PORT or its serial device)");
  else if (drivesTable() && !(configureView_->pace() > 0.0))
    why = tr("a driven table swings in real time: choose a pace (real time for a real table)");
  runButton_->setEnabled(why.isEmpty());
  runAction_->setEnabled(why.isEmpty());
  runButton_->setToolTip(why.isEmpty() ? tr("Start the run") : tr("Cannot run: %1").arg(why));
  if (!runner_.isRunning()) {
    configureView_->setMessage(why.isEmpty() ? QString()
                                             : tr("<span style='color:#b00000'>Cannot run: %1</span>")
                                                   .arg(why.toHtmlEscaped().replace("\n", "<br>")));
  }
}

Result<RunRequest> MainWindow::buildRunRequest() const {
  const double speed = configureView_->pace();
  const SourceKind kind = sourceKind();
  RunRequest request;
  request.options.info = sessionInfo();
  request.options.auditCommand = "fogbench GUI Configure: Run";
  // The gyro signs are chosen with the analysis settings and stored with the
  // session's bench constants, so that the session reads with them later.
  request.options.info.bench.gyroSign = analysis_.gyroSign;
  request.options.constants = request.options.info.bench;
  request.options.reportContext.imuDelayLimitMs = analysis_.imuDelayLimitMs;
  request.options.reportContext.coverageK = analysis_.coverageK;
  TestPlan plan;
  if (kind == SourceKind::kSimulator) {
    plan = planEditor_->plan();
    const auto config = simConfigOf(bench_, configureView_->seed());
    auto source = acquisition::SimulatorSource::create(config, plan, speed);
    if (!source) return source.status();
    request.truth = (*source)->truth();
    request.options.info.source = (*source)->description();
    request.source = std::shared_ptr<acquisition::ByteSource>(std::move(*source));
  } else if (kind == SourceKind::kSerial) {
    serial::SerialSettings settings;
    settings.port = configureView_->serialPort().toStdString();
    const bool ok = configureView_->baudRate(&settings.baudRate);
    const Status validity = settings.validate();
    if (!ok) return invalidArgument(tr("the baud rate must be a whole number").toStdString());
    if (!validity.isOk()) return validity;
    // Without a driven table the board runs its own plan; the one in the
    // editor is stored as the plan the operator intended, and drives the
    // progress bars. With one, the plan is what the table swings
    // (docs/table-control.md): the run ends when the plan runner does.
    plan = planEditor_->plan();
    request.options.info.source = "serial " + settings.port + " at " + settings.summary();
    request.options.stallWarning = std::chrono::milliseconds(2000);
    request.options.stallLimit = std::chrono::milliseconds(10000);
    request.options.endWhenBoardDone = !drivesTable();
    if (drivesTable()) {
      TableDriveSettings table;
      table.manual = configureView_->tableDriver() == ConfigureView::TableDriver::kManual;
      table.address = configureView_->tableAddress().toStdString();
      table.speed = speed;
      request.table = std::make_shared<TableDrive>(table, plan);
      request.options.info.source += "; table " + request.table->driverName();
    }
    request.openSource = [settings]() -> Result<std::unique_ptr<acquisition::ByteSource>> {
      auto source = serial::SerialSource::open(settings);
      if (!source) return source.status();
      return std::unique_ptr<acquisition::ByteSource>(std::move(*source));
    };
  } else {
    const QString path = configureView_->replayPath();
    auto opened = session::openSessionOrStream(path.toStdString(), session::OpenOptions::sessionStream());
    if (!opened) return opened.status();
    auto bytes = std::move(opened->rawBytes);
    plan = opened->info.plan;
    // A replay records into a new session like a live run, and keeps the
    // original's identity and constants.
    const SessionInfo original = opened->info;
    request.options.info = original;
    request.options.info.createdUtc = session::utcNow();
    request.options.info.softwareVersion = FOG_VERSION;
    request.options.constants = original.bench;
    auto source = std::make_shared<acquisition::ReplaySource>(std::move(bytes), speed,
                                                              "session " + QFileInfo(path).fileName().toStdString());
    // The original's source stays named (a replay of a simulated session is
    // still simulated data: the report says so).
    request.options.info.source =
        source->description() + (original.source.empty() ? std::string() : " (" + original.source + ")");
    request.source = source;
  }
  request.options.info.plan = plan;
  request.options.reportContext.source = request.options.info.source + ", fogbench " + FOG_VERSION;
  const QString folder = sessionFolder();
  if (!folder.isEmpty()) {
    if (!QDir().mkpath(folder))
      return ioError(tr("cannot create the session folder '%1'; choose another one").arg(folder).toStdString());
    // The serial as far as every file system takes it ("SN 7/a" -> "SN_7_a").
    QString serial = configureView_->imuSerial().trimmed();
    serial.replace(QRegularExpression("[^A-Za-z0-9._-]+"), "_");
    const QString name = QDateTime::currentDateTimeUtc().toString("yyyyMMdd-HHmmss-zzz") +
                         (serial.isEmpty() ? QString() : "-" + serial) + ".fbs";
    request.options.sessionPath = QDir(folder).filePath(name).toStdString();
  }
  return request;
}

void MainWindow::startRun() {
  if (runner_.isRunning()) return;
  updateRunButton();
  if (!runButton_->isEnabled()) {
    showFailure(runButton_->toolTip());
    return;
  }
  auto built = buildRunRequest();
  if (!built) {
    showFailure(coreText(built.status().message()));
    return;
  }
  RunRequest request = std::move(*built);
  const TestPlan plan = request.options.info.plan;
  const double speed = configureView_->pace();
  resultView_->clear();
  shown_.reset();
  // The simulator described in the GUI's language; other sources by the core (port, file).
  const QString sourceText =
      sourceKind() == SourceKind::kSimulator
          ? tr("simulator, seed %1, %2")
                .arg(configureView_->seed())
                .arg(speed <= 0.0   ? tr("as fast as possible")
                     : speed == 1.0 ? tr("real time")
                                    : tr("%1× real time").arg(speed))
          : coreText(request.options.info.source);
  // The table status: the simulator drives its simulated turntable through
  // the plan; a serial board runs its own plan and a replay drives nothing.
  // A driven table (remote, manual) shows what its controller reports.
  table_ = request.table;
  if (table_)
    liveView_->setTableDriver(configureView_->tableDriver() == ConfigureView::TableDriver::kManual
                                  ? tr("manual (the operator sets the controller)")
                                  : tr("remote controller %1").arg(configureView_->tableAddress()));
  else
    liveView_->setTableDriver(sourceKind() == SourceKind::kSimulator ? tr("simulator (simulated turntable)") : QString());
  liveView_->setTableSnapshot(table_ ? std::optional<TableSnapshot>(table_->snapshot()) : std::nullopt);
  // A serial board runs at its own (real-time) pace; a driven table at the pace chosen.
  liveView_->startRun(plan, request.openSource && !table_ ? 1.0 : speed,
                      request.options.constants.pulseEquivalentDeg);
  showHealth({}, 0);
  runClock_.start();
  if (!runner_.start(std::move(request))) {
    table_.reset();
    return;
  }
  stopRequested_ = false;
  setRunning(true);
  updateEmergencyStop();
  liveTimer_.start();
  showView(kLive);
  tell(tr("Running: %1 …").arg(sourceText));
}

MainWindow::SourceKind MainWindow::sourceKind() const { return configureView_->sourceKind(); }
void MainWindow::setSourceKind(SourceKind kind) { configureView_->setSourceKind(kind); }

void MainWindow::stopRun() {
  if (!runner_.isRunning()) return;
  stopRequested_ = true;
  runner_.stop();
  stopButton_->setEnabled(false);
  stopAction_->setEnabled(false);
  tell(table_ ? tr("Stopping: bringing the table to rest; everything received so far is kept …")
              : tr("Stopping: everything received so far is kept …"));
}

void MainWindow::setRunning(bool running) {
  tablePanel_->setRunActive(running && drivesTable());
  stopButton_->setEnabled(running);
  stopAction_->setEnabled(running);
  configureView_->setRunning(running);
  updateRunButton();
}

void MainWindow::drainLive() {
  auto batches = runner_.takeBatches();
  for (const auto& b : batches) liveView_->addFrames(b.frames);
  if (table_) liveView_->setTableSnapshot(table_->snapshot());
  if (!batches.empty()) {
    const auto& last = batches.back();
    showHealth(last.health, runner_.droppedFrames());
    if (last.silentForS > 0.0)
      tell(tr("No data from the source for %1 s — check the connection").arg(last.silentForS, 0, 'f', 1));
  }
  liveView_->refresh();
}

void MainWindow::showHealth(const StreamHealth& h, std::uint64_t dropped) {
  // Short, so that the status bar keeps room for messages; the breakdown is
  // in the tooltip.
  QString text = tr("frames: %1 · checksum failures: %2 · lost: %3 · duplicates: %4")
                     .arg(h.tableFrames + h.imuFrames + h.statusFrames)
                     .arg(h.checksumFailures)
                     .arg(h.lostFrames)
                     .arg(h.duplicateFrames);
  QString tip = tr("frames: %1 table · %2 IMU · %3 status  ·  checksum failures: %4  ·  lost: %5  ·  duplicates: %6")
                    .arg(h.tableFrames)
                    .arg(h.imuFrames)
                    .arg(h.statusFrames)
                    .arg(h.checksumFailures)
                    .arg(h.lostFrames)
                    .arg(h.duplicateFrames);
  if (dropped > 0) {
    text += tr(" · display skipped %1").arg(dropped);
    tip += tr("  ·  display skipped %1 frames (all recorded)").arg(dropped);
  }
  framesLabel_->setText(text + " ");
  framesLabel_->setToolTip(tip);
}

void MainWindow::showOutcome(std::shared_ptr<const RunOutcome> outcome) {
  liveTimer_.stop();
  drainLive();
  liveView_->endRun();
  setRunning(false);
  shown_ = outcome;
  showHealth(outcome->recording.health, runner_.droppedFrames());
  resultView_->showOutcome(outcome);
  nameShownInTitle();
  analyseNoise(outcome);
  const bool delay = outcome->report.isOk();
  QString message;
  if (!outcome->complete)
    message = tr("Run incomplete (%1); ").arg(coreText(outcome->incompleteReason));
  else
    message = tr("Run done in %1; ").arg(durationText(static_cast<double>(runClock_.elapsed()) / 1e3));
  message += delay ? tr("%1 test point(s) analysed, %2 without a delay")
                         .arg(outcome->report->points.size())
                         .arg(outcome->report->failedPoints.size())
                   : tr("no delay: %1").arg(coreText(outcome->report.status().message()));
  if (!outcome->sessionPath.empty())
    message += tr(". Saved as %1").arg(QFileInfo(QString::fromStdString(outcome->sessionPath)).fileName());
  // A driven table the bench did not see at rest (the controller was
  // unreachable: its heartbeat is what stops the table) must be looked at.
  const bool tableNotAtRest = table_ && !table_->snapshot().atRest;
  if (tableNotAtRest)
    message += tr(". WARNING: the table was not seen at rest at the end; check it");
  table_.reset();
  updateEmergencyStop();
  tell(message);
  configureView_->setMessage(message.toHtmlEscaped());
  // A run the operator did not stop that ended early, or gave no delay, is
  // explained whole (the status bar line is cut and soon overwritten).
  // (Not when the operator stopped it: they know.)
  if (tableNotAtRest)
    showMessage(this, MessageKind::kError, tr("Check the turntable"),
                tr("The table was not seen at rest at the end of the run; check it before you go near it."),
                message);
  else if (!stopRequested_ && !outcome->complete)
    showMessage(this, MessageKind::kError, tr("Run incomplete"),
                tr("The run ended early; everything received is kept and analysed."), message);
  else if (!stopRequested_ && !delay)
    showMessage(this, MessageKind::kError, tr("No delay"), tr("The run gave no delay."), message);
  sessionBrowser_->refresh();
  if (!outcome->sessionPath.empty()) {
    sessionBrowser_->selectPath(QString::fromStdString(outcome->sessionPath));
    addRecentSession(QString::fromStdString(outcome->sessionPath));
  }
  showView(kResults);
  emit runEnded(delay);
  // (A table not seen at rest keeps the window open with its warning.)
  if (closeAfterRun_ && !tableNotAtRest) QTimer::singleShot(0, this, &QWidget::close);
  closeAfterRun_ = closeAfterRun_ && !tableNotAtRest;
}

void MainWindow::showFailure(const QString& message) {
  liveTimer_.stop();
  // A run that failed before it recorded never moved the table (a refused
  // plan, an unreachable controller or board).
  table_.reset();
  updateEmergencyStop();
  liveView_->endRun();
  setRunning(false);
  reportError(tr("Run failed"), tr("Run failed"), message);
  tell(tr("Run failed: %1").arg(message));
  configureView_->setMessage(tr("<span style='color:#b00000'>Run failed: %1</span>").arg(message.toHtmlEscaped()));
  emit runEnded(false);
  if (closeAfterRun_) QTimer::singleShot(0, this, &QWidget::close);
}

void MainWindow::loadSession(const QString& path, bool reanalyse, std::int64_t resultId,
                             std::function<void(std::shared_ptr<const RunOutcome>)> done, bool announce) {
  const QString name = QFileInfo(path).fileName();
  if (announce) tell(reanalyse ? tr("Re-analysing %1 …").arg(name) : tr("Opening %1 …").arg(name));
  const BenchConstants bench = bench_;
  const AnalysisChoices choices = analysis_;
  // Who re-analyses (the audit trail): the operator in the Configure view,
  // else the login name.
  const std::string analyst = configureView_->operatorName().trimmed().toStdString();
  // QFuture needs a default-constructible value: the outcome, or why not.
  struct Loaded {
    std::shared_ptr<RunOutcome> outcome;
    Status status;
  };
  // Reading and fitting a long session takes a while: off the GUI thread.
  inBackground(
      this, [path, reanalyse, resultId, bench, choices, analyst]() -> Loaded {
        // The session's own pulse equivalent first; a session that states
        // none (nor its stream) takes the bench constants' (as the CLI's
        // --pulse-equivalent-deg), else the refusal says what to set.
        auto options = session::OpenOptions::session();
        options.fallbackPulseEquivalentDeg = bench.pulseEquivalentDeg;
        auto opened = session::openSessionOrStream(path.toStdString(), options);
        if (!opened) return {nullptr, opened.status()};
        auto outcome = std::make_shared<RunOutcome>();
        outcome->info = opened->info;
        outcome->sessionPath = path.toStdString();
        outcome->complete = opened->complete;
        outcome->incompleteReason = opened->incompleteReason;
        outcome->results = opened->results;
        // A re-analysis uses the bench's constants, gyro signs and limit, and
        // stores them with its result; the new result is the newest, the one
        // shown. Review re-analyses with exactly the chosen stored result's
        // settings (the newest unless one is asked for), only to draw its
        // plots and fits: the verdict shown is the stored one. With none
        // stored: the session's own constants.
        BenchConstants constants = opened->info.bench;
        std::string source = opened->sourceLine();
        if (reanalyse) {
          session::AnalysisSettings settings;
          settings.constants = bench;
          // The session's stored signs (an import's bench.gyro_sign is applied
          // by the analysis, not to the data); an axis the bench constants
          // mark reversed is analysed reversed, as the CLI's --gyro-sign.
          settings.constants.gyroSign = opened->info.bench.gyroSign;
          for (std::size_t a = 0; a < settings.constants.gyroSign.size(); ++a)
            if (choices.gyroSign[a] < 0) settings.constants.gyroSign[a] = -1;
          settings.imuDelayLimitMs = choices.imuDelayLimitMs;
          settings.coverageK = choices.coverageK;
          settings.producedBy = "fogbench GUI";
          settings.tool = "fogbench GUI Results";
          settings.command = "Results view: re-analyse with the bench constants";
          settings.operatorName = analyst;
          auto result = session::analyseAndStore(*opened, settings);
          if (!result.storeStatus.isOk()) return {nullptr, result.storeStatus};
          // A session being recorded is not written to: a re-analysis that
          // cannot be stored is refused, not shown as if it were.
          if (!result.notStored.empty())
            return {nullptr, Status(StatusCode::kIoError, "the result was not stored: " + result.notStored)};
          constants = settings.constants;
          outcome->report = std::move(result.report);
          outcome->results = std::move(result.results);
          if (result.stored)
            if (const auto* newest = newestUsable(outcome->results)) outcome->shownResultId = newest->id;
          if (const ResultRecord* shown = outcome->shownResult(); shown && outcome->report)
            outcome->differences = session::differencesFromRecord(*shown, *outcome->report);
        } else {
          auto shown = session::showResult(*opened, resultId, constants, choices.imuDelayLimitMs, choices.coverageK);
          constants = shown.constants;
          if (shown.record) outcome->shownResultId = shown.record->id;
          outcome->report = std::move(shown.report);
          outcome->differences = std::move(shown.differences);
        }
        outcome->recording = std::move(opened->recording);
        // What the shown result was computed with, everywhere (report pages, Diagnose).
        outcome->info.bench.tableReadDelayMs = constants.tableReadDelayMs;
        outcome->info.bench.tableReadDelayStdMs = constants.tableReadDelayStdMs;
        outcome->info.bench.boardDelayMs = constants.boardDelayMs;
        outcome->info.bench.boardDelayStdMs = constants.boardDelayStdMs;
        if (constants.pulseEquivalentDeg > 0.0) outcome->info.bench.pulseEquivalentDeg = constants.pulseEquivalentDeg;
        outcome->info.bench.gyroSign = constants.gyroSign;
        outcome->info.bench.gainToleranceFraction = constants.gainToleranceFraction;
        completeOutcome(*outcome, source);
        return {outcome, Status::ok()};
      },
      [this, path, name, reanalyse, resultId, done, announce](Loaded result) {
        if (!result.outcome) {
          reportError(reanalyse ? tr("Re-analyse") : tr("Open session"),
                      reanalyse ? tr("Cannot re-analyse %1").arg(name) : tr("Cannot open %1").arg(name),
                      tr("%1\n\nFile: %2").arg(coreText(result.status.message()), QDir::toNativeSeparators(path)));
          done(nullptr);
          return;
        }
        if (!announce) {
          // Compare's: Results and the status bar go on naming their session.
        } else if (reanalyse) {
          tell(tr("%1: re-analysed with the bench constants; the result was added to the session and is shown").arg(name));
          showMessage(this, MessageKind::kInformation, tr("Re-analyse"), tr("%1 re-analysed").arg(name),
                      tr("The session was analysed with the current bench constants and the result was added to it; "
                         "its recorded data did not change. The Results view shows the new result; its Result list "
                         "holds the earlier ones.\n\nFile: %1").arg(QDir::toNativeSeparators(path)));
        } else if (resultId != 0) {
          tell(tr("%1: result %2 of %3 shown")
                   .arg(name)
                   .arg(result.outcome->shownResultNumber())
                   .arg(result.outcome->results.size()));
        } else {
          tell(tr("%1: read-only review").arg(name));
          addRecentSession(path);
        }
        done(result.outcome);
      });
}

void MainWindow::openSession(const QString& path) {
  loadSession(path, false, 0, [this](std::shared_ptr<const RunOutcome> outcome) {
    if (outcome) showLoaded(outcome);
    emit sessionOpened(outcome != nullptr);
  });
}

void MainWindow::reanalyseSession(const QString& path) {
  loadSession(path, true, 0, [this](std::shared_ptr<const RunOutcome> outcome) {
    if (outcome) {
      sessionBrowser_->refresh();
      showLoaded(outcome);
    }
    emit reanalysed(outcome != nullptr);
  });
}

void MainWindow::chooseResult(qint64 resultId) {
  const auto outcome = resultView_->sharedOutcome();
  if (!outcome || outcome->sessionPath.empty() || resultId == outcome->shownResultId) return;
  resultView_->setChoosing(true);
  loadSession(QString::fromStdString(outcome->sessionPath), false, resultId,
              [this](std::shared_ptr<const RunOutcome> o) {
                resultView_->setChoosing(false);
                if (o) showLoaded(o);
                else resultView_->showOutcome(resultView_->sharedOutcome());  // back to what is shown
                emit resultShown(o != nullptr);
              });
}

void MainWindow::showLoaded(std::shared_ptr<const RunOutcome> outcome) {
  shown_ = outcome;
  showHealth(outcome->recording.health, 0);
  resultView_->showOutcome(outcome);
  nameShownInTitle();
  analyseNoise(outcome);
  showView(kResults);
}

void MainWindow::nameShownInTitle() {
  QString what;
  if (shown_) {
    const session::ShownVerdict v = shown_->shownVerdict();
    const QString name = shown_->sessionPath.empty()
                             ? tr("run not recorded")
                             : QFileInfo(QString::fromStdString(shown_->sessionPath)).fileName();
    what = shown_->shownResult() ? tr("%1, result %2 of %3: %4")
                                       .arg(name)
                                       .arg(shown_->shownResultNumber())
                                       .arg(shown_->results.size())
                                       .arg(verdictWord(v.verdict))
                                 : tr("%1: %2 (not stored)").arg(name, verdictWord(v.verdict));
  }
  setWindowTitle(what.isEmpty() ? tr("fogbench %1 — FOG IMU delay bench").arg(FOG_VERSION)
                                : tr("%1 — fogbench %2").arg(what, QStringLiteral(FOG_VERSION)));
}

void MainWindow::chooseImportOptions(const QString& csvFolder) {
  ImportDialog dialog(csvFolder, this);
  if (dialog.exec() == QDialog::Accepted) importCsv(csvFolder, dialog.options());
}

void MainWindow::importCsv(const QString& csvFolder, const io::ImportOptions& options) {
  QString folder = sessionBrowser_->folder();
  if (folder.isEmpty()) folder = sessionFolder();
  if (folder.isEmpty() || !QDir().mkpath(folder)) {
    reportError(tr("Import CSV data"), tr("Choose a session folder to import into first."),
                tr("The imported data becomes a session file in the session folder; choose a folder you can write to "
                   "in the Sessions view."));
    emit importEnded(QString());
    return;
  }
  const QString path = QDir(folder).filePath(QDateTime::currentDateTimeUtc().toString("yyyyMMdd-HHmmss-zzz") +
                                             "-import-" + QFileInfo(csvFolder).fileName() + ".fbs");
  tell(tr("Importing %1 …").arg(csvFolder));
  inBackground(
      this, [csvFolder, path, options]() -> Status {
        auto imported = io::importCsvDirectory(csvFolder.toStdString(), options);
        if (!imported) return imported.status();
        return io::saveImportedSession(*imported, csvFolder.toStdString(), path.toStdString());
      },
      [this, path, csvFolder](Status s) {
        if (!s.isOk()) {
          reportError(tr("Import CSV data"), tr("Cannot import %1").arg(QDir::toNativeSeparators(csvFolder)),
                      coreText(s.message()));
          tell(tr("Cannot import %1: %2").arg(csvFolder, coreText(s.message())));
          emit importEnded(QString());
          return;
        }
        sessionBrowser_->refresh();
        sessionBrowser_->selectPath(path);
        tell(tr("Imported %1 as %2").arg(csvFolder, QFileInfo(path).fileName()));
        emit importEnded(path);
      });
}

void MainWindow::diagnoseShown() {
  const auto outcome = resultView_->sharedOutcome();
  if (!outcome || !outcome->report) return;
  if (diagnosisCancel_) {  // one at a time: the running one is in view
    showView(kDiagnosis);
    return;
  }
  const QString title = outcome->sessionPath.empty() ? tr("this run")
                                                    : QFileInfo(QString::fromStdString(outcome->sessionPath)).fileName();
  diagnosisView_->startDiagnosis(title);
  showView(kDiagnosis);
  tell(tr("Diagnosing %1 …").arg(title));
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  diagnosisCancel_ = cancel;
  struct Done {
    std::shared_ptr<diagnosis::Diagnosis> result;
    Status status;
  };
  diagnosis::DiagnosisOptions options;
  diagnosisView_->applyStatedNoise(options);
  // Called on the diagnosis' threads, one call at a time: posted to the GUI
  // thread, never waited for. (The window waits for a running diagnosis
  // before it goes, so `this` outlives every call.)
  options.progress = [this, cancel](double fraction, const std::string& stage) {
    QMetaObject::invokeMethod(
        this, [this, fraction, stage] { diagnosisView_->setProgress(fraction, stage); }, Qt::QueuedConnection);
    return !cancel->load();
  };
  // Several replays of the session in the simulator: off the GUI thread.
  // The frame the session states, as the CLI's diagnose, the noise view and
  // the report take it (the dialog's frame goes with new recordings).
  BenchConstants constants = outcome->report->constants;
  constants.imuFrame = outcome->info.bench.imuFrame;
  diagnosisFuture_ = inBackground(
      this, [outcome, options, constants]() -> Done {
        auto d = diagnosis::diagnose(outcome->recording, &outcome->info, constants, options);
        if (!d) return {nullptr, d.status()};
        return {std::make_shared<diagnosis::Diagnosis>(std::move(*d)), Status::ok()};
      },
      [this, title](Done done) {
        diagnosisCancel_.reset();
        if (done.status.code() == StatusCode::kCancelled) {
          diagnosisView_->showCancelled(title);
          tell(tr("Diagnosis of %1 cancelled").arg(title));
          emit diagnosisEnded(false);
          return;
        }
        if (!done.result) {
          diagnosisView_->showMessage(tr("No diagnosis: %1").arg(coreText(done.status.message())));
          reportError(tr("Diagnosis"), tr("No diagnosis of %1").arg(title), coreText(done.status.message()));
          tell(tr("No diagnosis of %1: %2").arg(title, coreText(done.status.message())));
          emit diagnosisEnded(false);
          return;
        }
        diagnosisView_->showDiagnosis(done.result, title);
        tell(tr("Diagnosis of %1: %2 (%3 s)")
                 .arg(title, coreText(done.result->verdict))
                 .arg(localNumber(done.result->elapsedS, 'f', 1)));
        emit diagnosisEnded(true);
      });
}

void MainWindow::cancelDiagnosis() {
  if (diagnosisCancel_) diagnosisCancel_->store(true);
}

void MainWindow::analyseNoise(std::shared_ptr<const RunOutcome> outcome) {
  const bool anyStatic = std::any_of(outcome->recording.testPoints.begin(), outcome->recording.testPoints.end(),
                                     [](const TestPointData& p) { return p.kind == TestPointKind::kStatic; });
  if (!anyStatic) {
    noiseView_->showMessage(tr("This result has no static segment. To measure the gyro's noise (Allan deviation, "
                               "noise terms, bias), add a test point of kind \"static\" to the plan: the table "
                               "rests while the gyro is recorded."));
    emit noiseAnalysed(false);
    return;
  }
  noiseView_->showMessage(tr("Computing the Allan deviation …"));
  struct Done {
    std::vector<noise::GyroNoiseReport> reports;
    Status status;
  };
  inBackground(
      this, [outcome]() -> Done {
        noise::GyroNoiseOptions options;
        options.earth.latitudeDeg = outcome->info.bench.latitudeDeg;
        model::applyImuFrame(outcome->info.bench.imuFrame, options.earth);
        auto reports = noise::analyzeGyroNoise(outcome->recording, options);
        if (!reports) return {{}, reports.status()};
        return {std::move(*reports), Status::ok()};
      },
      [this](Done done) {
        if (!done.status.isOk()) {
          noiseView_->showMessage(tr("No noise analysis: %1").arg(coreText(done.status.message())));
          emit noiseAnalysed(false);
          return;
        }
        noiseView_->showReports(std::move(done.reports));
        emit noiseAnalysed(true);
      });
}

QWidget* MainWindow::compareSessions(const QStringList& paths) {
  auto* dialog = new QWidget(this, Qt::Window);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setObjectName("compareWindow");
  QStringList names;
  for (const QString& path : paths) names << QFileInfo(path).fileName();
  dialog->setWindowTitle(tr("Compare %1").arg(names.join(", ")));
  auto* layout = new QVBoxLayout(dialog);
  auto* view = new CompareView(paths);
  layout->addWidget(view);
  QPointer<CompareView> guard(view);
  for (int i = 0; i < paths.size(); ++i)
    loadSession(
        paths[i], false, 0,
        [guard, i](std::shared_ptr<const RunOutcome> o) {
          if (guard) guard->setOutcome(i, o, o ? QString() : tr("the session could not be read (see the message)"));
        },
        false);
  // As large as the screen allows with the window manager's frame, up to
  // 1600 x 900, and on the screen: the frame's size is known only once the
  // window is shown, so the main window's frame stands in for it (0.95 of the
  // screen's height was 7 px too tall on a 700-px screen with a title bar).
  QSize size(1600, 900);
  if (const QScreen* screen = this->screen()) {
    const QRect free = screen->availableGeometry();
    const QSize frame(std::max(16, frameGeometry().width() - geometry().width()),
                      std::max(48, frameGeometry().height() - geometry().height()));
    size = size.boundedTo(free.size() - frame);
    dialog->resize(size);
    dialog->move(free.topLeft() + QPoint((free.width() - size.width() - frame.width()) / 2,
                                         (free.height() - size.height() - frame.height()) / 2));
  } else {
    dialog->resize(size);
  }
  dialog->show();
  return dialog;
}

}  // namespace fog::ui

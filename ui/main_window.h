#pragma once
// The bench window a lab operator works in, in four views:
//   Configure  the test plan, the source (simulator, replay of a session,
//              serial board), the session's metadata and where it is
//              recorded (ui/configure_view.h; the window builds the run
//              from it, buildRunRequest)
//   Live       the scrolling table and gyro angles, progress, counters
//   Results    curves, fits, delay breakdown, delay vs frequency, report
//   Sessions   the session browser: review, re-analyse, compare
//   Units      the lab's catalog by unit and lot (ui/units_view.h)
// Run and Stop are always at hand; Stop ends the run and keeps everything
// recorded so far. Bench constants are set in a dialog and remembered.
//
// The window owns an AcquisitionRunner and reacts to its signals; it drains
// the runner's buffer on a ~30 Hz timer and never waits for a worker.
// Failures are shown whole in a non-modal message box (ui/messages.h: the
// text selectable, never a blocking dialog, so an unattended window never
// blocks), briefly in the status bar and on the Configure view.
//
// Every view sits in a scroll area and the wide ones are split, so that the
// window fits a 1366x768 laptop screen and stays workable at 1024x700.
// The plan, pace, operator, IMU and session folder are remembered between
// starts (QSettings); plans load and save in the CLI's JSON plan format.

#include <QElapsedTimer>
#include <QFuture>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QTimer>
#include <atomic>
#include <memory>

#include "core/common/session_info.h"
#include "core/io/csv_import.h"
#include "ui/acquisition_runner.h"
#include "ui/bench_settings_dialog.h"
#include "ui/configure_view.h"

class QAction;
class QCheckBox;
class QCloseEvent;
class QDockWidget;
class QMenu;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace fog::ui {

class DiagnosisView;
class NoiseView;
class LiveView;
class PlanEditor;
class ResultView;
class SessionBrowser;
class TableDrive;
class TablePanel;
class UnitsView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  enum View { kConfigure = 0, kLive, kResults, kSessions, kUnits, kDiagnosis, kNoise };
  using SourceKind = ConfigureView::SourceKind;

  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  ConfigureView* configureView() const { return configureView_; }
  PlanEditor* planEditor() const { return planEditor_; }
  LiveView* liveView() const { return liveView_; }
  ResultView* resultView() const { return resultView_; }
  // The table's axis panel (a dock: View ▸ Table controls) and the tool
  // bar's emergency stop, enabled while the panel is connected or a run
  // drives a table.
  TablePanel* tablePanel() const { return tablePanel_; }
  QAction* emergencyStopAction() const { return emergencyStopAction_; }
  // The tool bar's emergency stop: through the run's own controller
  // connection when a run drives the table (TableDrive::requestEmergencyStop),
  // through the panel's when it is connected (both when both), and the run
  // is stopped.
  void emergencyStop();
  SessionBrowser* sessionBrowser() const { return sessionBrowser_; }
  UnitsView* unitsView() const { return unitsView_; }
  DiagnosisView* diagnosisView() const { return diagnosisView_; }
  NoiseView* noiseView() const { return noiseView_; }
  void showView(View view);
  // The session whose result is shown, or empty (a run not recorded, nothing shown).
  QString shownSessionPath() const;
  View currentView() const;

  // Source: the simulator at `speed` x real time (0: as fast as possible),
  // or the replay of a session file.
  void useSimulator(double speed, int seed);
  void useReplay(const QString& sessionPath, double speed);
  // A sampling board on `port` (a device or a pseudo-terminal); the table
  // not driven, driven through a remote controller at `tableAddress`, or set
  // by the operator (docs/table-control.md).
  void useSerialBoard(const QString& port, ConfigureView::TableDriver table = ConfigureView::TableDriver::kNone,
                      const QString& tableAddress = QString());
  SourceKind sourceKind() const;
  void setSourceKind(SourceKind kind);
  // Where sessions are recorded; empty: runs are not recorded.
  void setSessionFolder(const QString& folder);
  // Whether the operator's choices (plan, pace, operator, IMU model and
  // serial, session folder) are remembered for the next start. Off while the
  // command line applies one-off choices (--session-folder, --preset).
  void setRemembering(bool remembering) { remembering_ = remembering; }
  // The window's layout: size and position, every splitter and the view
  // shown, remembered when the window closes (QSettings group "layout") and
  // restored at the next start. restoreLayout() returns false when nothing
  // was remembered (or it no longer fits a screen): the caller then sizes
  // the window to the screen.
  void saveLayout();
  bool restoreLayout();
  // Shows the window as a start does: the remembered layout, else 1500 x 950
  // where the screen has room for it with its frame, else maximised (a bare
  // X server without a window manager: the free area less a frame's room).
  // The frame, the title bar and the status bar stay on the screen.
  void showOnScreen();
  // Test plans in the CLI's JSON format (fogbench-cli run --plan FILE).
  Status loadPlanFile(const QString& path);
  Status savePlanFile(const QString& path);
  // Sessions recently recorded or opened, newest first (remembered).
  QStringList recentSessions() const;
  // The file the last export wrote (empty before one).
  QString lastExport() const { return lastExport_; }
  QString sessionFolder() const;
  void setBenchConstants(const BenchConstants& settings);
  const BenchConstants& benchConstants() const { return bench_; }
  // The gyro signs and acceptance limit every run and re-analysis uses and
  // stores with its result (the bench-constants dialog).
  const AnalysisChoices& analysisChoices() const { return analysis_; }
  void setAnalysisChoices(const AnalysisChoices& choices);

  bool isRunning() const { return runner_.isRunning(); }
  // The last run's or opened session's result (null before one).
  const RunOutcome* lastOutcome() const;
  // The About box's text: version of fogbench, Qt and Qwt.
  QString aboutText() const;
  // What the operator was last told in the status bar.
  QString lastMessage() const { return lastMessage_; }

 public slots:
  void startRun();
  void stopRun();
  // Opens a session read-only (in the background) and shows its newest
  // stored result (the session's own constants when none is stored).
  void openSession(const QString& path);
  // Analyses a session again with the bench constants, adds the result to
  // it and shows that result.
  void reanalyseSession(const QString& path);
  // Shows another stored result of the shown session (its id).
  void chooseResult(qint64 resultId);
  // Imports a folder in the CSV layout (docs/formats.md) as a new session in
  // the browser's folder, in the background, with the options the import
  // dialog sets (rate convention, segmentation; stored with the session).
  void importCsv(const QString& csvFolder, const io::ImportOptions& options = {});
  // Asks for the import options of the folder (ImportDialog), then imports.
  void chooseImportOptions(const QString& csvFolder);
  // The sim-to-real diagnosis of the shown result, in the background; shown
  // in the Diagnosis view.
  void diagnoseShown();
  // Cancels a running diagnosis (it ends within about a second, with no result).
  void cancelDiagnosis();
  bool isDiagnosing() const { return diagnosisCancel_ != nullptr; }
  // Opens a Compare window of these sessions (A, B, C, ... in this order)
  // and returns it; its CompareView emits loaded() once all have arrived.
  QWidget* compareSessions(const QStringList& paths);
  // Opens the folder of the last export (or the session folder) in the
  // desktop's file manager.
  void openExportFolder();

 signals:
  // Every started run ends with this, once its results (or error) are shown.
  void runEnded(bool succeeded);
  // Every openSession ends with this.
  void sessionOpened(bool succeeded);
  // Every reanalyseSession ends with this.
  void reanalysed(bool succeeded);
  // Every chooseResult that loads another result ends with this.
  void resultShown(bool succeeded);
  // Every importCsv ends with this: the new session, or empty on failure.
  void importEnded(const QString& sessionPath);
  // Every diagnoseShown ends with this.
  void diagnosisEnded(bool succeeded);
  // After every shown result: whether its static segments gave a noise analysis.
  void noiseAnalysed(bool succeeded);
  // The operator picked a language ("system", "en", "zh_CN"; already remembered);
  // the WindowHost makes the window again in it. Never during a run or a diagnosis.
  void languageChosen(const QString& language);

 protected:
  // Closing during a run asks first (non-modal): stop the run and close, or
  // keep running.
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildToolBar();
  void buildMenus();
  // An error the operator must read whole: message box + status bar.
  void reportError(const QString& title, const QString& headline, const QString& details);
  void rememberState();
  void restoreState();
  void addRecentSession(const QString& path);
  void fillRecentMenu();
  void exported(const QString& path);
  void drainLive();
  void setRunning(bool running);
  void showOutcome(std::shared_ptr<const RunOutcome> outcome);
  void showFailure(const QString& message);
  void showHealth(const StreamHealth& health, std::uint64_t dropped);
  void tell(const QString& message);
  // Reads a session and analyses it in the background: with the bench's
  // constants when `reanalyse` (the result is added to the session), else
  // with the constants of its stored result `resultId` (0: the newest).
  // `announce` false (Compare's sessions): the status bar keeps naming the
  // session Results shows; errors are still reported.
  void loadSession(const QString& path, bool reanalyse, std::int64_t resultId,
                   std::function<void(std::shared_ptr<const RunOutcome>)> done, bool announce = true);
  // Shows a loaded session's outcome in Results (and its noise analysis).
  void showLoaded(std::shared_ptr<const RunOutcome> outcome);
  // The window title names the session shown, its result and verdict.
  void nameShownInTitle();
  // The Allan deviation of the outcome's static segments, in the background.
  void analyseNoise(std::shared_ptr<const RunOutcome> outcome);
  void updateRunButton();
  // The run the Configure view describes (source, session identity, bench
  // constants, plan, where it is recorded), or why it cannot run.
  Result<RunRequest> buildRunRequest() const;
  SessionInfo sessionInfo() const;
  void editBenchConstants();

  // Whether the run drives the turntable (a serial board with a remote or
  // manual table driver chosen).
  bool drivesTable() const {
    return sourceKind() == SourceKind::kSerial &&
           configureView_->tableDriver() != ConfigureView::TableDriver::kNone;
  }

  AcquisitionRunner runner_;
  // The running run's driven table (null when none): its status for Live.
  std::shared_ptr<TableDrive> table_;
  // The running diagnosis: its cancel flag (null when none runs) and future.
  std::shared_ptr<std::atomic<bool>> diagnosisCancel_;
  QFuture<void> diagnosisFuture_;
  QTimer liveTimer_;
  QElapsedTimer runClock_;
  BenchConstants bench_;
  AnalysisChoices analysis_;
  std::shared_ptr<const RunOutcome> shown_;
  QString lastMessage_;
  QString lastExport_;
  bool remembering_ = true;
  bool restoring_ = false;
  bool stopRequested_ = false;
  bool closeAfterRun_ = false;

  QTabWidget* tabs_ = nullptr;
  ConfigureView* configureView_ = nullptr;
  PlanEditor* planEditor_ = nullptr;
  LiveView* liveView_ = nullptr;
  ResultView* resultView_ = nullptr;
  TablePanel* tablePanel_ = nullptr;
  QDockWidget* tableDock_ = nullptr;
  QAction* emergencyStopAction_ = nullptr;
  void updateEmergencyStop();
  SessionBrowser* sessionBrowser_ = nullptr;
  UnitsView* unitsView_ = nullptr;
  DiagnosisView* diagnosisView_ = nullptr;
  NoiseView* noiseView_ = nullptr;

  QPushButton* runButton_ = nullptr;
  QPushButton* stopButton_ = nullptr;
  QLabel* framesLabel_ = nullptr;
  QAction* runAction_ = nullptr;
  QAction* stopAction_ = nullptr;
  QAction* openExportFolderAction_ = nullptr;
  QMenu* recentMenu_ = nullptr;
};

}  // namespace fog::ui

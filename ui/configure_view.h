#pragma once
// The Configure view: the test plan beside the source (simulator, replay of
// a session, serial sampling board with the turntable driven or not; pace
// and seed), the session's identity and where it is recorded, the bench
// constants and why a run cannot start.
// It holds the operator's choices and tells when they change; the window
// that owns it turns them into a run (MainWindow::buildRunRequest) and
// remembers them.

#include <QString>
#include <QWidget>
#include <optional>

#include "core/common/session_info.h"
#include "core/table/table_controller.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QSplitter;

namespace fog::ui {

class CommandedMotionTable;
class PlanEditor;

class ConfigureView : public QWidget {
  Q_OBJECT

 public:
  // Where a run's bytes come from.
  enum class SourceKind { kSimulator = 0, kReplay, kSerial };

  explicit ConfigureView(QWidget* parent = nullptr);

  PlanEditor* planEditor() const { return planEditor_; }
  // The commanded motion of every point against the table's limits.
  CommandedMotionTable* commandedMotion() const { return commandedMotion_; }

  SourceKind sourceKind() const;
  void setSourceKind(SourceKind kind);
  // X times real time, 0: as fast as possible. A pace not in the list is added.
  double pace() const;
  void setPace(double pace);
  int seed() const;
  void setSeed(int seed);
  QString replayPath() const;
  void setReplayPath(const QString& path);
  // A listed port's device, or the text typed (e.g. a pseudo-terminal).
  QString serialPort() const;
  void setSerialPort(const QString& port);
  // The baud rate typed or chosen; false when it is not a whole number.
  bool baudRate(int* baud) const;
  // Who swings the table while a serial board records: nobody the bench
  // commands (the board runs its own plan), a remote controller at
  // tableAddress() (tcp:HOST:PORT or a serial device), or the operator.
  enum class TableDriver { kNone = 0, kRemote, kManual };
  TableDriver tableDriver() const;
  // A null `address` leaves the address as it is.
  void setTableDriver(TableDriver driver, const QString& address = QString());
  QString tableAddress() const;

  // The folder sessions are recorded into; empty when recording is off.
  QString sessionFolder() const;
  // Shows `folder` and turns recording on (off for an empty folder).
  void setSessionFolder(const QString& folder);

  // Operator, IMU model and serial, notes; the production lot and the bench
  // (station) id stored with the session (docs/sessions.md, schema 6).
  QString operatorName() const;
  QString imuModel() const;
  QString imuSerial() const;
  QString lot() const;
  QString benchId() const;
  QString notes() const;
  void setIdentity(const QString& operatorName, const QString& imuModel, const QString& imuSerial);
  void setLotAndBench(const QString& lot, const QString& benchId);

  // The constants and the gyro signs the next analysis uses (Tools → Bench
  // constants chooses both).
  void showBenchConstants(const BenchConstants& settings, const std::array<int, kAxisCount>& gyroSign);
  // Rich text under the source and session: why a run cannot start, or how
  // the last one ended.
  void setMessage(const QString& html);
  // During a run the plan, source and folder are locked.
  void setRunning(bool running);
  // The controller the table panel is connected to, as it described itself,
  // and the limits it reported: while the source is the serial board with a
  // remote controller, the plan and the commanded motion are checked against
  // them and the limits are named as the controller's. Otherwise (and after
  // clearConnectedTable()) against the simulator's turntable, saying so.
  void setConnectedTable(const QString& description, const table::TableLimits& limits);
  void clearConnectedTable();

 signals:
  void sourceChanged();
  // The replay file or the serial port changed: whether a run can start.
  void runnabilityChanged();
  void paceChanged();
  // Operator, IMU model or serial edited.
  void identityChanged();
  // The operator chose or typed a session folder.
  void folderChosen(const QString& folder);
  void editBenchSettingsRequested();

 private:
  // The constructor's sections, in the order they are shown.
  QGroupBox* buildPlanGroup();
  QGroupBox* buildSourceGroup();
  void addSerialRows(QFormLayout* sourceForm);
  QGroupBox* buildSessionGroup();
  QGroupBox* buildConstantsGroup();
  void applyTableLimits();
  // The plan beside the rest where the room shown (the scroll area's
  // viewport) holds both with the plan's tables whole, the divider moved
  // for them if need be; above it otherwise (a laptop with the table panel
  // docked), so that nothing scrolls sideways.
  bool eventFilter(QObject* watched, QEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void fitLayoutLater();
  void fitLayout();

  struct ConnectedTable {
    QString description;
    table::TableLimits limits;
  };
  std::optional<ConnectedTable> connected_;

  QSplitter* split_ = nullptr;
  QWidget* watchedRoom_ = nullptr;
  int horizontalNeeds_ = 0;    // the room side by side needs, learnt when it was too little
  int planLengthLearnt_ = 0;   // the plan table's width then
  bool fitPending_ = false;
  PlanEditor* planEditor_ = nullptr;
  CommandedMotionTable* commandedMotion_ = nullptr;
  QComboBox* sourceCombo_ = nullptr;
  QComboBox* speedCombo_ = nullptr;
  QSpinBox* seedSpin_ = nullptr;
  QLineEdit* replayEdit_ = nullptr;
  QComboBox* portCombo_ = nullptr;
  QComboBox* baudCombo_ = nullptr;
  QComboBox* tableCombo_ = nullptr;
  QLineEdit* tableAddressEdit_ = nullptr;
  QCheckBox* recordCheck_ = nullptr;
  QLineEdit* folderEdit_ = nullptr;
  QLineEdit* operatorEdit_ = nullptr;
  QLineEdit* imuModelEdit_ = nullptr;
  QLineEdit* imuSerialEdit_ = nullptr;
  QLineEdit* lotEdit_ = nullptr;
  QLineEdit* benchIdEdit_ = nullptr;
  QLineEdit* notesEdit_ = nullptr;
  QLabel* message_ = nullptr;
  QLabel* constantsLabel_ = nullptr;
};

}  // namespace fog::ui

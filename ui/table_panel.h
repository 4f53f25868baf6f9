#pragma once
// The turntable at hand between runs (issue 31): an axis status panel as a
// table vendor's console keeps one — each axis's position and state (idle,
// moving, emergency stop, no answer, unreachable) — with jog (− / + by a
// step), home (go to 0), go to a position, an ordinary Stop (every axis
// decelerates to rest; not latched) and the emergency stop (also in the main
// window's tool bar, always in view).
//
// The GUI thread never waits for the controller (issue 41, "a safety path
// never waits"): the panel's connection is a TableLink (ui/table_link.h), a
// thread of its own that connects, polls every TableLink::kPollMs, sends
// the moves and stops, and reports back by queued signals. While the
// controller does not answer, the panel says so ("connecting…", "no answer
// for N s", "reconnecting") and the window goes on. The EMERGENCY STOP goes
// out on two paths at once: on the emergency line's connection of its own
// (core/table/emergency_line.h: opened once the controller has answered and
// kept, or opened on the click; no poll, connect or hung controller delays
// it), and through the panel's link before anything queued there. The
// ordinary Stop goes the same two ways (on the line unconfirmed; through
// the link, dropping the moves queued before it, confirmed), so a call the
// controller hangs in does not hold it up either.
//
// Every move is checked before it is sent: against the table's position
// range (table::checkPositionAgainstLimits, the limits the controller
// reported on connecting), against what blocks motion
// (TableState::blockingReason: emergency stop, interlock, faults) and
// against a state too old to trust; a refused move says why and nothing is
// sent. The controller's own refusal is said in words ("-221 Settings
// conflict" → the table is moving; wait or press Stop) and cleared when the
// table's state changes.
//
// The panel holds its own controller connection (Connect uses the Configure
// view's remote address, tcp:HOST:PORT or a serial device; tests hand it a
// controller). While a run drives the table (setRunActive), jog, home, go-to
// and Stop are disabled; the emergency stop never is while a link is held.
// Without a controller every control is disabled, its tooltip saying why.

#include <QElapsedTimer>
#include <QString>
#include <QTimer>
#include <QWidget>
#include <array>
#include <functional>
#include <memory>
#include <optional>

#include "core/common/test_plan.h"
#include "core/table/emergency_line.h"
#include "core/table/table_controller.h"
#include "ui/table_link.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace fog::ui {

class TablePanel : public QWidget {
  Q_OBJECT

 public:
  // A state older than this is not trusted for a move; the panel says "no answer for N s".
  static constexpr int kStaleMs = 1000;

  enum class Link {
    kNone,          // no controller
    kConnecting,    // the first connect under way
    kConnected,     // the controller answers
    kUnreachable,   // it stopped answering; a remote link is being reopened
  };

  explicit TablePanel(QWidget* parent = nullptr);
  ~TablePanel() override;

  // Takes the controller (null: disconnects) onto the panel's link thread,
  // which reads its limits and state. Returns at once.
  void setController(std::unique_ptr<table::TableController> controller);
  // Connect / Disconnect as the button does. Return at once.
  void connectTable();
  void disconnectTable();
  Link link() const { return link_; }
  // The controller answered since the link was opened (it may be hanging now).
  bool connected() const { return link_ == Link::kConnected || link_ == Link::kUnreachable; }
  // A link is held or being opened: the emergency stop is offered.
  bool emergencyStopAvailable() const { return tableLink_ != nullptr; }
  // Where Connect finds the address (the Configure view's remote table),
  // read when Connect is pressed.
  void setAddressSource(std::function<QString()> source) { addressSource_ = std::move(source); }
  // A run drives the table: no jog, home, go-to or Stop meanwhile.
  void setRunActive(bool active);

  // The operator's actions, checked first (see above). Empty when the
  // command was handed to the link (its outcome shows in the panel when it
  // comes), else why not (also shown in the panel).
  QString jog(Axis axis, int direction);  // ±1 × the step
  QString home(Axis axis);
  QString goTo(Axis axis, double positionDeg);
  // Every axis decelerates to rest (STOP); moves still queued are dropped.
  QString stop();
  // Every axis stops at once, latched until reset at the controller: fired
  // on the emergency line (a remote link's address) and queued first on the
  // link. Empty when it went out on at least one path; what came of it
  // shows in the panel (and emergencyStopReport()).
  QString emergencyStop();
  // The emergency line alone, at another address (a run's controller).
  void emergencyStopAt(const QString& address);
  // Asks the link for a state read now (it polls every TableLink::kPollMs).
  void poll();

  // What the panel shows, for tests: an axis's position text and state word.
  QString positionText(Axis axis) const;
  QString stateText(Axis axis) const;
  QString statusText() const;
  QString message() const;
  QPushButton* jogButton(Axis axis, int direction) const;
  QPushButton* homeButton(Axis axis) const;
  QPushButton* goButton() const { return goButton_; }
  QPushButton* stopButton() const { return stopButton_; }
  QPushButton* emergencyStopButton() const { return emergencyButton_; }
  QPushButton* connectButton() const { return connectButton_; }
  QDoubleSpinBox* stepSpin() const { return stepSpin_; }
  // Why the controls are disabled (the tooltip), empty when they are not.
  QString disabledReason() const;
  // The emergency line's last outcome of an emergency stop, and of an
  // ordinary stop (none before the first).
  std::optional<table::EmergencyOutcome> lastEmergencyLine() const { return lastLine_; }
  std::optional<table::EmergencyOutcome> lastStopLine() const { return lastStopLine_; }

 signals:
  // Connected, disconnected, or the run took or gave back the table: the
  // emergency-stop action follows.
  void availabilityChanged(bool available);
  // What came of an emergency stop, as shown in the panel; `failed`: it
  // reached the controller on no path.
  void emergencyStopReport(const QString& text, bool failed);
  // The controller answered (again) and reported its limits, or the link was
  // dropped (none): whose limits the Configure view checks the plan against.
  void controllerLimits(const QString& description, const std::optional<fog::table::TableLimits>& limits);

 private:
  struct AxisRow {
    QLabel* position = nullptr;
    QLabel* state = nullptr;
    QPushButton* minus = nullptr;
    QPushButton* plus = nullptr;
    QPushButton* home = nullptr;
  };
  void buildAxes(QVBoxLayout* layout);
  void buildMoves(QVBoxLayout* layout);
  void startLink();
  void dropLink();
  void onOpening(const QString& address, bool again);
  void onOpened(const QString& description, const table::TableLimits& limits);
  void onLost(const QString& why, bool reconnecting);
  void onStateRead(const table::TableState& state);
  void onCommandDone(const TableCommand& command, const TableCommandResult& result);
  void onEmergencyLine(const table::EmergencyOutcome& outcome);
  void reportEmergency();
  QString move(Axis axis, double positionDeg);
  bool stale() const;
  void showMessage(const QString& text, bool error);
  void updateEnabled();
  void showState();

  TableLink* tableLink_ = nullptr;  // the link held; retired links delete themselves
  Link link_ = Link::kNone;
  QString address_;      // the remote address in use (empty: an adopted controller)
  QString description_;  // the controller's, once it answered
  table::TableLimits limits_;
  std::optional<table::TableState> state_;  // as last read; none: not read yet, or unreachable
  QString unreachable_;                     // why the last read or connect failed
  QElapsedTimer sinceAnswer_;               // since the last state read (or the connect began)
  std::string refusalKey_;                  // the state when a refusal was shown: cleared once it differs
  bool refusalShown_ = false;
  bool runActive_ = false;
  std::function<QString()> addressSource_;
  QTimer clock_;  // "no answer for N s" goes on counting while the controller is silent

  // The stops' two paths (the line's own connection, the link's queue) and
  // what each said.
  std::unique_ptr<table::EmergencyLine> emergencyLine_;
  std::optional<table::EmergencyOutcome> lastLine_, lastStopLine_;
  bool lineFired_ = false, lineDone_ = false, linkEstopDone_ = false;
  bool stopLineFired_ = false, linkStopDone_ = false;
  TableCommandResult linkEstop_;

  QLabel* statusLabel_ = nullptr;
  QPushButton* connectButton_ = nullptr;
  std::array<AxisRow, kAxisCount> rows_{};
  QDoubleSpinBox* stepSpin_ = nullptr;
  QComboBox* goAxis_ = nullptr;
  QDoubleSpinBox* goPosition_ = nullptr;
  QPushButton* goButton_ = nullptr;
  QPushButton* stopButton_ = nullptr;
  QPushButton* emergencyButton_ = nullptr;
  QLabel* messageLabel_ = nullptr;
};

}  // namespace fog::ui

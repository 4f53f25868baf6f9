#pragma once
// The turntable at hand between runs (issue 31): an axis status panel as a
// table vendor's console keeps one — each axis's position and state (idle,
// moving, emergency stop, unreachable) — with jog (− / + by a step), home
// (go to 0) and go to a position, and the emergency stop (also in the main
// window's tool bar, always in view).
//
// Every move is checked before it is sent: against the table's position
// range (table::checkPositionAgainstLimits, the limits the controller
// reported on connecting) and against what blocks motion
// (TableState::blockingReason: emergency stop, interlock, faults); a
// refused move says why and nothing is sent. The controller's own refusal
// is shown as it gives it.
//
// The panel holds its own controller connection (Connect uses the Configure
// view's remote address, tcp:HOST:PORT or a serial device; tests hand it a
// controller). It polls the state every kPollMs on the GUI thread; every
// call returns within the driver's reply timeout, and a remote driver that
// lost its link fails at once after that (the axes then read
// "unreachable"). While a run drives the table (setRunActive), jog, home
// and go-to are disabled; the emergency stop never is while connected.
// Without a controller every control is disabled, its tooltip saying why.

#include <QString>
#include <QTimer>
#include <QWidget>
#include <array>
#include <functional>
#include <memory>
#include <optional>

#include "core/common/test_plan.h"
#include "core/table/table_controller.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace fog::ui {

class TablePanel : public QWidget {
  Q_OBJECT

 public:
  static constexpr int kPollMs = 250;

  explicit TablePanel(QWidget* parent = nullptr);
  ~TablePanel() override;

  // Takes the controller (null: disconnects), reads its limits and state.
  void setController(std::unique_ptr<table::TableController> controller);
  bool connected() const { return controller_ != nullptr; }
  // Where Connect finds the address (the Configure view's remote table),
  // read when Connect is pressed.
  void setAddressSource(std::function<QString()> source) { addressSource_ = std::move(source); }
  // A run drives the table: no jog, home or go-to meanwhile.
  void setRunActive(bool active);

  // The operator's actions, checked first (see above). Empty when the
  // command was sent, else why not (also shown in the panel).
  QString jog(Axis axis, int direction);  // ±1 × the step
  QString home(Axis axis);
  QString goTo(Axis axis, double positionDeg);
  // Stops every axis at once through the controller (latched until reset at
  // the controller). Empty, or why it failed.
  QString emergencyStop();
  // Reads the state now (the timer does this every kPollMs).
  void poll();

  // What the panel shows, for tests: an axis's position text and state word.
  QString positionText(Axis axis) const;
  QString stateText(Axis axis) const;
  QString message() const;
  QPushButton* jogButton(Axis axis, int direction) const;
  QPushButton* homeButton(Axis axis) const;
  QPushButton* goButton() const { return goButton_; }
  QDoubleSpinBox* stepSpin() const { return stepSpin_; }
  // Why the controls are disabled (the tooltip), empty when they are not.
  QString disabledReason() const;

 signals:
  // Connected, disconnected, or the run took or gave back the table: the
  // emergency-stop action follows.
  void availabilityChanged(bool connected);

 private:
  struct AxisRow {
    QLabel* position = nullptr;
    QLabel* state = nullptr;
    QPushButton* minus = nullptr;
    QPushButton* plus = nullptr;
    QPushButton* home = nullptr;
  };
  void connectToAddress();
  QString move(Axis axis, double positionDeg);
  void showMessage(const QString& text, bool error);
  void updateEnabled();
  void showState();

  std::unique_ptr<table::TableController> controller_;
  table::TableLimits limits_;
  std::optional<table::TableState> state_;  // as last read; none: unreachable
  QString unreachable_;                     // why the last read failed
  bool runActive_ = false;
  std::function<QString()> addressSource_;
  QTimer pollTimer_;

  QLabel* statusLabel_ = nullptr;
  QPushButton* connectButton_ = nullptr;
  std::array<AxisRow, kAxisCount> rows_{};
  QDoubleSpinBox* stepSpin_ = nullptr;
  QComboBox* goAxis_ = nullptr;
  QDoubleSpinBox* goPosition_ = nullptr;
  QPushButton* goButton_ = nullptr;
  QPushButton* stopButton_ = nullptr;
  QLabel* messageLabel_ = nullptr;
};

}  // namespace fog::ui

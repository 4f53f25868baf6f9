#include "ui/table_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "core/table/scpi.h"
#include "ui/core_text.h"
#include "ui/language/language.h"

namespace fog::ui {

namespace {

QString modeWord(table::AxisMode mode) {
  switch (mode) {
    case table::AxisMode::kRest: return TablePanel::tr("idle");
    case table::AxisMode::kPositioning:
    case table::AxisMode::kSwinging:
    case table::AxisMode::kStopping: return TablePanel::tr("moving");
    case table::AxisMode::kEmergencyStop: return TablePanel::tr("emergency stop");
    case table::AxisMode::kUnknown: return TablePanel::tr("unknown");
  }
  return TablePanel::tr("unknown");
}

// What a refusal is about to change: the modes and flags. A refusal is
// cleared once these differ from what they were when it came.
std::string stateKey(const table::TableState& s) {
  std::string key = std::to_string(s.interlockOpen) + std::to_string(s.emergencyStopped) +
                    std::to_string(s.heartbeatLost) + std::to_string(s.faults.size());
  for (const auto& a : s.axes) key += std::to_string(static_cast<int>(a.mode));
  return key;
}

QString actionText(const TableCommand& c) {
  switch (c.kind) {
    case TableCommand::kMove:
      return TablePanel::tr("moving %1 to %2°")
          .arg(QString::fromLatin1(axisLabel(c.axis)), localNumber(c.positionDeg, 'f', 4));
    case TableCommand::kStop: return TablePanel::tr("the stop");
    case TableCommand::kEmergencyStop: return TablePanel::tr("the emergency stop");
  }
  return QString();
}

// The controller's refusal in words: what it means at the panel and what to
// do, the controller's own number and text kept in brackets.
QString refusalText(const TableCommand& c, const TableCommandResult& r) {
  const QString action = actionText(c);
  const QString raw = QString::fromStdString(r.reply);
  switch (r.scpiCode) {
    case table::scpi::kSettingsConflict:
      return TablePanel::tr("The controller refuses %1: the table is moving (settings conflict); wait for the move "
                            "to end or press Stop.").arg(action);
    case table::scpi::kDataOutOfRange:
      return TablePanel::tr("The controller refuses %1: the position is beyond what it accepts (data out of range: "
                            "%2).").arg(action, raw);
    case table::scpi::kInterlockOpen:
      return TablePanel::tr("The controller refuses %1: its interlock is open (a door or a guard); close it, then "
                            "try again.").arg(action);
    case table::scpi::kEmergencyStop:
      return TablePanel::tr("The controller refuses %1: its emergency stop is engaged; reset it at the controller "
                            "first.").arg(action);
    case table::scpi::kHeartbeatLost:
      return TablePanel::tr("The controller refuses %1: it missed the bench's heartbeat and stopped the table; "
                            "disconnect and connect again.").arg(action);
    case table::scpi::kSyntaxError:
    case table::scpi::kParameterNotAllowed:
    case table::scpi::kMissingParameter:
    case table::scpi::kUndefinedHeader:
      return TablePanel::tr("The controller does not understand %1 (%2); does it speak the bench's table "
                            "protocol (docs/table-control.md)?").arg(action, raw);
    default: return TablePanel::tr("The controller refuses %1 (%2).").arg(action, raw);
  }
}

int secondsOf(const QElapsedTimer& t) { return static_cast<int>(t.elapsed() / 1000); }

}  // namespace

TablePanel::TablePanel(QWidget* parent) : QWidget(parent) {
  setObjectName("tablePanel");
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout();
  statusLabel_ = new QLabel();
  statusLabel_->setObjectName("tablePanelStatus");
  statusLabel_->setWordWrap(true);
  top->addWidget(statusLabel_, 1);
  connectButton_ = new QPushButton(tr("Connect"));
  connectButton_->setObjectName("tableConnectButton");
  connect(connectButton_, &QPushButton::clicked, this, [this] {
    if (tableLink_) disconnectTable();
    else connectTable();
  });
  top->addWidget(connectButton_);
  layout->addLayout(top);
  buildAxes(layout);
  buildMoves(layout);

  messageLabel_ = new QLabel();
  messageLabel_->setObjectName("tablePanelMessage");
  messageLabel_->setWordWrap(true);
  messageLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(messageLabel_);
  layout->addStretch(1);

  // The emergency line reports on its own thread; the panel hears it on the GUI thread.
  emergencyLine_ = std::make_unique<table::EmergencyLine>([this](const table::EmergencyOutcome& outcome) {
    QMetaObject::invokeMethod(this, [this, outcome] { onEmergencyLine(outcome); }, Qt::QueuedConnection);
  });
  // The translation layer compiles its patterns on first use (some 70 ms):
  // done here off the GUI thread, so that the first message the controller
  // causes (an emergency stop's outcome) does not stall the window.
  (void)QtConcurrent::run([] { (void)coreText(QStringLiteral("-")); });
  clock_.setInterval(TableLink::kPollMs);
  connect(&clock_, &QTimer::timeout, this, [this] {
    showState();
    updateEnabled();
  });
  clock_.start();
  showState();
  updateEnabled();
}

TablePanel::~TablePanel() {
  // The line first: a send under way ends (bounded) while the panel is whole.
  emergencyLine_.reset();
  // Links (the one held and any retired one still letting go) cancel their
  // call under way and end their threads before the panel goes.
  qDeleteAll(findChildren<TableLink*>(QString(), Qt::FindDirectChildrenOnly));
}

void TablePanel::buildAxes(QVBoxLayout* layout) {
  auto* grid = new QGridLayout();
  grid->addWidget(new QLabel(tr("axis")), 0, 0);
  grid->addWidget(new QLabel(tr("position")), 0, 1);
  grid->addWidget(new QLabel(tr("state")), 0, 2);
  for (int a = 0; a < kAxisCount; ++a) {
    const auto axis = static_cast<Axis>(a);
    auto& row = rows_[static_cast<std::size_t>(a)];
    const QString name = QString::fromLatin1(axisLabel(axis));
    grid->addWidget(new QLabel(name), a + 1, 0);
    row.position = new QLabel();
    row.position->setObjectName("tablePosition" + name);
    row.position->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    row.position->setMinimumWidth(row.position->fontMetrics().horizontalAdvance("−180.0000°") + 6);
    row.state = new QLabel();
    row.state->setObjectName("tableState" + name);
    row.minus = new QPushButton(QStringLiteral("−"));
    row.minus->setObjectName("tableJogMinus" + name);
    row.plus = new QPushButton(QStringLiteral("+"));
    row.plus->setObjectName("tableJogPlus" + name);
    row.home = new QPushButton(tr("Home"));
    row.home->setObjectName("tableHome" + name);
    for (QPushButton* b : {row.minus, row.plus}) b->setMaximumWidth(b->fontMetrics().horizontalAdvance("−") + 28);
    connect(row.minus, &QPushButton::clicked, this, [this, axis] { jog(axis, -1); });
    connect(row.plus, &QPushButton::clicked, this, [this, axis] { jog(axis, +1); });
    connect(row.home, &QPushButton::clicked, this, [this, axis] { home(axis); });
    grid->addWidget(row.position, a + 1, 1);
    grid->addWidget(row.state, a + 1, 2);
    grid->addWidget(row.minus, a + 1, 3);
    grid->addWidget(row.plus, a + 1, 4);
    grid->addWidget(row.home, a + 1, 5);
  }
  grid->setColumnStretch(2, 1);
  layout->addLayout(grid);
}

void TablePanel::buildMoves(QVBoxLayout* layout) {
  auto* step = new QHBoxLayout();
  step->addWidget(new QLabel(tr("Jog step")));
  stepSpin_ = new QDoubleSpinBox();
  stepSpin_->setObjectName("tableJogStep");
  stepSpin_->setRange(0.001, 90.0);
  stepSpin_->setDecimals(3);
  stepSpin_->setValue(1.0);
  stepSpin_->setSuffix(tr(" °"));
  step->addWidget(stepSpin_);
  step->addStretch(1);
  layout->addLayout(step);

  auto* go = new QHBoxLayout();
  go->addWidget(new QLabel(tr("Go to")));
  goAxis_ = new QComboBox();
  goAxis_->setObjectName("tableGoAxis");
  for (int a = 0; a < kAxisCount; ++a) goAxis_->addItem(QString::fromLatin1(axisLabel(static_cast<Axis>(a))), a);
  go->addWidget(goAxis_);
  goPosition_ = new QDoubleSpinBox();
  goPosition_->setObjectName("tableGoPosition");
  goPosition_->setRange(-360.0, 360.0);  // the table's own range is checked on Go
  goPosition_->setDecimals(4);
  goPosition_->setSuffix(tr(" °"));
  go->addWidget(goPosition_, 1);
  goButton_ = new QPushButton(tr("Go"));
  goButton_->setObjectName("tableGoButton");
  connect(goButton_, &QPushButton::clicked, this,
          [this] { goTo(static_cast<Axis>(goAxis_->currentData().toInt()), goPosition_->value()); });
  go->addWidget(goButton_);
  layout->addLayout(go);

  // Stop (decelerate, not latched) beside the emergency stop (at once, latched).
  auto* stops = new QHBoxLayout();
  stopButton_ = new QPushButton(tr("Stop"));
  stopButton_->setObjectName("tablePanelStop");
  stopButton_->setStyleSheet("QPushButton { font-weight: bold; padding: 6px; }");
  connect(stopButton_, &QPushButton::clicked, this, [this] { stop(); });
  stops->addWidget(stopButton_, 1);
  emergencyButton_ = new QPushButton(tr("EMERGENCY STOP"));
  emergencyButton_->setObjectName("tablePanelEmergencyStop");
  emergencyButton_->setStyleSheet("QPushButton { background: #c00000; color: white; font-weight: bold; padding: 6px; }"
                                  "QPushButton:disabled { background: #d8b0b0; color: #f4f4f4; }");
  connect(emergencyButton_, &QPushButton::clicked, this, [this] { emergencyStop(); });
  stops->addWidget(emergencyButton_, 2);
  layout->addLayout(stops);
}

void TablePanel::connectTable() {
  const QString address = addressSource_ ? addressSource_().trimmed() : QString();
  if (address.isEmpty()) {
    showMessage(tr("No table address: choose Table ▸ Remote controller in Configure and give its address "
                   "(tcp:HOST:PORT or a serial device)."),
                true);
    return;
  }
  startLink();
  address_ = address;
  tableLink_->open(address);
}

void TablePanel::disconnectTable() {
  dropLink();
  showState();
  updateEnabled();
}

void TablePanel::setController(std::unique_ptr<table::TableController> controller) {
  if (!controller) {
    disconnectTable();
    return;
  }
  startLink();
  tableLink_->adopt(std::move(controller));
}

// A new link (the one held, if any, is let go first).
void TablePanel::startLink() {
  dropLink();
  messageLabel_->clear();
  tableLink_ = new TableLink(this);
  link_ = Link::kConnecting;
  sinceAnswer_.start();
  connect(tableLink_, &TableLink::opening, this, &TablePanel::onOpening);
  connect(tableLink_, &TableLink::opened, this, &TablePanel::onOpened);
  connect(tableLink_, &TableLink::lost, this, &TablePanel::onLost);
  connect(tableLink_, &TableLink::stateRead, this, &TablePanel::onStateRead);
  connect(tableLink_, &TableLink::readFailed, this, [this](const QString& why) {
    state_.reset();
    unreachable_ = coreText(why);
    link_ = Link::kUnreachable;
    showState();
    updateEnabled();
  });
  connect(tableLink_, &TableLink::commandDone, this, &TablePanel::onCommandDone);
  connectButton_->setText(tr("Disconnect"));
  showState();
  updateEnabled();
  emit availabilityChanged(true);
}

// Lets the link go without waiting: it releases the controller and ends on
// its own thread (TableLink::retire), and is heard no more.
void TablePanel::dropLink() {
  if (!tableLink_) return;
  disconnect(tableLink_, nullptr, this, nullptr);
  tableLink_->retire();
  emergencyLine_->arm(std::string());
  tableLink_ = nullptr;
  link_ = Link::kNone;
  address_.clear();
  description_.clear();
  state_.reset();
  unreachable_.clear();
  refusalShown_ = false;
  connectButton_->setText(tr("Connect"));
  emit availabilityChanged(false);
  emit controllerLimits(QString(), std::nullopt);
}

void TablePanel::onOpening(const QString& address, bool again) {
  if (!again) link_ = Link::kConnecting;
  (void)address;
  showState();
  updateEnabled();
}

void TablePanel::onOpened(const QString& description, const table::TableLimits& limits) {
  description_ = description;
  limits_ = limits;
  link_ = Link::kConnected;
  emit controllerLimits(description, limits);
  // The emergency line's own connection, opened while the controller answers
  // (again after a reconnect): a fire then only writes.
  if (!address_.isEmpty()) emergencyLine_->arm(address_.toStdString());
  unreachable_.clear();
  sinceAnswer_.start();
  showState();
  updateEnabled();
}

void TablePanel::onLost(const QString& why, bool reconnecting) {
  if (!reconnecting) {
    // The first connect failed: nothing is held.
    const QString text = tr("Cannot connect to the table: %1").arg(coreText(why));
    dropLink();
    showMessage(text, true);
    showState();
    updateEnabled();
    return;
  }
  if (link_ != Link::kUnreachable) sinceAnswer_.start();  // the silence began before; counted from the failure
  link_ = Link::kUnreachable;
  state_.reset();
  unreachable_ = coreText(why);
  showState();
  updateEnabled();
}

void TablePanel::onStateRead(const table::TableState& state) {
  state_ = state;
  link_ = Link::kConnected;
  unreachable_.clear();
  sinceAnswer_.start();
  if (refusalShown_ && stateKey(state) != refusalKey_) {
    refusalShown_ = false;
    messageLabel_->clear();
  }
  showState();
  updateEnabled();
}

void TablePanel::onCommandDone(const TableCommand& command, const TableCommandResult& result) {
  if (command.kind == TableCommand::kEmergencyStop) {
    linkEstop_ = result;
    linkEstopDone_ = true;
    reportEmergency();
    return;
  }
  switch (result.outcome) {
    case TableCommandResult::kDone:
      if (command.kind == TableCommand::kStop) {
        linkStopDone_ = true;
        showMessage(tr("Stop sent: every axis decelerates to rest."), false);
      }
      return;
    case TableCommandResult::kDropped:  // the stop that dropped it says what happens
      return;
    case TableCommandResult::kRefused:
      showMessage(refusalText(command, result), true);
      refusalShown_ = true;
      refusalKey_ = state_ ? stateKey(*state_) : std::string();
      return;
    case TableCommandResult::kLinkFailed:
      showMessage(tr("%1 did not reach the controller: %2").arg(actionText(command), coreText(result.message)), true);
      return;
  }
}

void TablePanel::setRunActive(bool active) {
  runActive_ = active;
  updateEnabled();
}

void TablePanel::poll() {
  if (tableLink_) tableLink_->pollNow();
}

bool TablePanel::stale() const { return link_ == Link::kConnected && sinceAnswer_.elapsed() > kStaleMs; }

QString TablePanel::jog(Axis axis, int direction) {
  if (!state_) return move(axis, std::nan(""));
  const double from = state_->axis(axis).positionDeg;
  return move(axis, from + (direction < 0 ? -1.0 : 1.0) * stepSpin_->value());
}

QString TablePanel::home(Axis axis) { return move(axis, 0.0); }

QString TablePanel::goTo(Axis axis, double positionDeg) { return move(axis, positionDeg); }

QString TablePanel::move(Axis axis, double positionDeg) {
  QString why;
  if (!tableLink_) why = disabledReason();
  else if (runActive_) why = tr("A run drives the table; stop it first.");
  else if (link_ == Link::kConnecting) why = tr("The table is not connected yet; the table was not moved.");
  else if (!state_) why = tr("The table does not answer (%1); the table was not moved.").arg(unreachable_);
  else if (stale())
    why = tr("The table has not answered for %1 s; the table was not moved.").arg(secondsOf(sinceAnswer_));
  else if (const std::string blocked = state_->blockingReason(); !blocked.empty())
    why = tr("The table cannot move: %1; the table was not moved.").arg(coreText(blocked));
  else if (auto check = table::checkPositionAgainstLimits(axis, positionDeg, limits_); !check.isOk())
    why = coreText(check.message());
  if (!why.isEmpty()) {
    showMessage(why, true);
    return why;
  }
  tableLink_->moveTo(axis, positionDeg);
  refusalShown_ = false;
  showMessage(tr("%1 to %2°").arg(QString::fromLatin1(axisLabel(axis)), localNumber(positionDeg, 'f', 4)), false);
  return QString();
}

QString TablePanel::stop() {
  QString why;
  if (!tableLink_) why = disabledReason();
  else if (runActive_) why = tr("A run drives the table; stop the run (tool bar) instead.");
  if (!why.isEmpty()) {
    showMessage(why, true);
    return why;
  }
  // Both paths, as for the emergency stop: the line's own connection (a
  // call the controller hangs in does not hold it up) and the link's queue
  // (which drops the moves queued before it and confirms the stop).
  stopLineFired_ = !address_.isEmpty();
  linkStopDone_ = false;
  if (stopLineFired_) emergencyLine_->fire(address_.toStdString(), table::LineCommand::kStopAll);
  tableLink_->stopAll();
  refusalShown_ = false;
  showMessage(tr("Stopping every axis…"), false);
  return QString();
}

QString TablePanel::emergencyStop() {
  if (!tableLink_) {
    showMessage(disabledReason(), true);
    return disabledReason();
  }
  // Both paths at once: the line (its own connection: nothing holds it up)
  // and the link (first in its queue: it also confirms through the link).
  lineFired_ = !address_.isEmpty();
  lineDone_ = false;
  linkEstopDone_ = false;
  if (lineFired_) emergencyLine_->fire(address_.toStdString());
  tableLink_->emergencyStop();
  refusalShown_ = false;
  showMessage(tr("EMERGENCY STOP: sending…"), true);
  return QString();
}

void TablePanel::emergencyStopAt(const QString& address) {
  if (!address.isEmpty()) emergencyLine_->fire(address.toStdString());
}

void TablePanel::onEmergencyLine(const table::EmergencyOutcome& outcome) {
  if (outcome.command == table::LineCommand::kStopAll) {
    lastStopLine_ = outcome;
    if (!stopLineFired_ || outcome.address != address_.toStdString()) return;
    stopLineFired_ = false;
    if (linkStopDone_) return;  // the link's confirmation already said it
    if (outcome.sent)
      showMessage(tr("Stop sent %1 ms after the click on a connection of its own: every axis decelerates to rest "
                     "(the panel's connection confirms it once the controller answers).")
                      .arg(localNumber(outcome.sentAfterMs, 'f', 0)),
                  false);
    else
      showMessage(tr("The stop's own connection failed (%1); it waits in the panel's connection until the "
                     "controller answers. If the table must stop now, use the emergency stop.")
                      .arg(coreText(outcome.why)),
                  true);
    return;
  }
  lastLine_ = outcome;
  if (!lineFired_ || outcome.address != address_.toStdString()) return;  // a run's, or an older link's
  lineDone_ = true;
  reportEmergency();
}

// The panel's word on an emergency stop, from what each path said so far.
void TablePanel::reportEmergency() {
  const bool linkOk = linkEstopDone_ && linkEstop_.outcome == TableCommandResult::kDone;
  const QString reset = tr("Reset it at the controller before the table moves again.");
  QString text;
  bool failed = false;
  if (!lineFired_ || !lineDone_) {
    if (linkOk) text = tr("Emergency stop sent: every axis stops.") + ' ' + reset;
    else if (linkEstopDone_ && !lineFired_) {
      text = tr("The emergency stop did not reach the controller: %1. Use the table's own stop button.")
                 .arg(coreText(linkEstop_.message));
      failed = true;
    }
  } else if (const auto& line = *lastLine_; line.sent) {
    const QString after = localNumber(line.sentAfterMs, 'f', 0);
    if (line.confirmed || linkOk)
      text = tr("Emergency stop sent %1 ms after the click on a connection of its own; the controller reports it "
                "engaged: every axis stops.").arg(after) + ' ' + reset;
    else
      text = tr("Emergency stop sent %1 ms after the click on a connection of its own, but the controller has not "
                "confirmed it (%2). Watch the table; if it still moves, use its own stop button.")
                 .arg(after, coreText(line.why));
  } else if (linkOk) {
    text = tr("The emergency stop's own connection failed (%1), but it reached the controller through the panel's "
              "connection: every axis stops.").arg(coreText(line.why)) + ' ' + reset;
  } else {
    failed = true;
    text = linkEstopDone_
               ? tr("The emergency stop did not reach the controller: its own connection failed (%1) and so did the "
                    "panel's (%2). Use the table's own stop button.")
                     .arg(coreText(line.why), coreText(linkEstop_.message))
               : tr("The emergency stop's own connection failed (%1); it waits in the panel's connection until the "
                    "controller answers. If the table still moves, use its own stop button.")
                     .arg(coreText(line.why));
  }
  if (text.isEmpty()) return;
  showMessage(text, true);
  emit emergencyStopReport(text, failed);
}

QString TablePanel::positionText(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].position->text(); }
QString TablePanel::stateText(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].state->text(); }
QString TablePanel::statusText() const { return statusLabel_->text(); }
QString TablePanel::message() const { return messageLabel_->text(); }
QPushButton* TablePanel::jogButton(Axis axis, int direction) const {
  const auto& row = rows_[static_cast<std::size_t>(axis)];
  return direction < 0 ? row.minus : row.plus;
}
QPushButton* TablePanel::homeButton(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].home; }

QString TablePanel::disabledReason() const {
  if (!tableLink_)
    return tr("No table is connected: press Connect (the address is the Configure view's remote table).");
  if (runActive_) return tr("A run drives the table; only the emergency stop is available.");
  if (link_ == Link::kConnecting) return tr("Connecting to the table…");
  if (!state_) return tr("The table does not answer; only the emergency stop is available.");
  if (stale()) return tr("The table has not answered for %1 s; only the emergency stop is available.")
                          .arg(secondsOf(sinceAnswer_));
  return QString();
}

void TablePanel::showMessage(const QString& text, bool error) {
  messageLabel_->setText(text);
  messageLabel_->setStyleSheet(error ? "QLabel { color: #b00000; }" : QString());
}

void TablePanel::showState() {
  const QString where = address_.isEmpty() ? description_ : address_;
  switch (link_) {
    case Link::kNone: statusLabel_->setText(tr("No table connected.")); break;
    case Link::kConnecting:
      statusLabel_->setText(
          sinceAnswer_.elapsed() < kStaleMs
              ? tr("Connecting to %1…").arg(where)
              : tr("Connecting to %1: no answer for %2 s…").arg(where).arg(secondsOf(sinceAnswer_)));
      break;
    case Link::kConnected:
      statusLabel_->setText(stale() ? tr("%1: no answer for %2 s").arg(description_).arg(secondsOf(sinceAnswer_))
                                    : description_);
      break;
    case Link::kUnreachable:
      statusLabel_->setText(address_.isEmpty()
                                ? tr("Unreachable: %1").arg(unreachable_)
                                : tr("No answer for %1 s (%2); reconnecting to %3…")
                                      .arg(secondsOf(sinceAnswer_)).arg(unreachable_, address_));
      break;
  }
  for (int a = 0; a < kAxisCount; ++a) {
    auto& row = rows_[static_cast<std::size_t>(a)];
    if (link_ == Link::kNone || (link_ == Link::kConnecting && !state_)) {
      row.position->setText(QStringLiteral("—"));
      row.state->setText(QStringLiteral("—"));
    } else if (!state_) {
      row.position->setText(QStringLiteral("—"));
      row.state->setText(tr("unreachable"));
    } else {
      const auto& axis = state_->axis(static_cast<Axis>(a));
      row.position->setText(state_->known ? localNumber(axis.positionDeg, 'f', 4) + QStringLiteral("°")
                                          : QStringLiteral("—"));
      // A position the controller has not confirmed for a while is kept, marked.
      row.state->setText(stale() ? tr("no answer")
                                 : state_->emergencyStopped ? tr("emergency stop") : modeWord(axis.mode));
    }
  }
}

void TablePanel::updateEnabled() {
  const QString why = disabledReason();
  const bool movable = why.isEmpty() && state_.has_value();
  for (auto& row : rows_)
    for (QPushButton* b : {row.minus, row.plus, row.home}) {
      b->setEnabled(movable);
      b->setToolTip(why);
    }
  goButton_->setEnabled(movable);
  goButton_->setToolTip(why);
  // Stop goes on the line's own connection and in the link's queue: offered whenever a link is held.
  const bool stoppable = tableLink_ != nullptr && !runActive_;
  stopButton_->setEnabled(stoppable);
  stopButton_->setToolTip(stoppable ? tr("Every axis decelerates to rest (not latched); a move still queued is "
                                         "dropped")
                                    : disabledReason());
  emergencyButton_->setEnabled(emergencyStopAvailable());
  emergencyButton_->setToolTip(emergencyStopAvailable()
                                   ? tr("Stop every axis at once, on a connection of its own and through the "
                                        "panel's (latched at the controller)")
                                   : disabledReason());
}

}  // namespace fog::ui

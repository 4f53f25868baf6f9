#include "ui/table_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

#include "core/table/remote_table.h"
#include "core/table/transport.h"
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
    if (controller_) setController(nullptr);
    else connectToAddress();
  });
  top->addWidget(connectButton_);
  layout->addLayout(top);

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

  stopButton_ = new QPushButton(tr("EMERGENCY STOP"));
  stopButton_->setObjectName("tablePanelEmergencyStop");
  stopButton_->setStyleSheet("QPushButton { background: #c00000; color: white; font-weight: bold; padding: 6px; }"
                             "QPushButton:disabled { background: #d8b0b0; color: #f4f4f4; }");
  connect(stopButton_, &QPushButton::clicked, this, [this] { emergencyStop(); });
  layout->addWidget(stopButton_);

  messageLabel_ = new QLabel();
  messageLabel_->setObjectName("tablePanelMessage");
  messageLabel_->setWordWrap(true);
  messageLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(messageLabel_);
  layout->addStretch(1);

  pollTimer_.setInterval(kPollMs);
  connect(&pollTimer_, &QTimer::timeout, this, &TablePanel::poll);
  showState();
  updateEnabled();
}

TablePanel::~TablePanel() = default;

void TablePanel::connectToAddress() {
  const QString address = addressSource_ ? addressSource_().trimmed() : QString();
  if (address.isEmpty()) {
    showMessage(tr("No table address: choose Table ▸ Remote controller in Configure and give its address "
                   "(tcp:HOST:PORT or a serial device)."),
                true);
    return;
  }
  auto link = table::openTransport(address.toStdString());
  if (!link) {
    showMessage(coreText(link.status().message()), true);
    return;
  }
  auto remote = table::RemoteTable::connect(std::move(*link));
  if (!remote) {
    showMessage(coreText(remote.status().message()), true);
    return;
  }
  setController(std::move(*remote));
}

void TablePanel::setController(std::unique_ptr<table::TableController> controller) {
  // A remote controller watches for our heartbeat: tell it we are done.
  // (Its failure changes nothing here: the link is being dropped.)
  if (controller_) (void)controller_->release();
  controller_ = std::move(controller);
  state_.reset();
  unreachable_.clear();
  messageLabel_->clear();
  if (controller_) {
    if (auto limits = controller_->limits()) limits_ = *limits;
    else limits_ = table::TableLimits{};  // the conservative defaults until it answers
    poll();
    pollTimer_.start();
  } else {
    pollTimer_.stop();
  }
  connectButton_->setText(controller_ ? tr("Disconnect") : tr("Connect"));
  showState();
  updateEnabled();
  emit availabilityChanged(connected());
}

void TablePanel::setRunActive(bool active) {
  runActive_ = active;
  updateEnabled();
}

void TablePanel::poll() {
  if (!controller_) return;
  auto state = controller_->state();
  if (state) {
    state_ = *state;
    unreachable_.clear();
    // A failed heartbeat shows in the next state read.
    (void)controller_->keepAlive();
  } else {
    state_.reset();
    unreachable_ = coreText(state.status().message());
  }
  showState();
  updateEnabled();
}

QString TablePanel::jog(Axis axis, int direction) {
  if (!state_) return move(axis, std::nan(""));
  const double from = state_->axis(axis).positionDeg;
  return move(axis, from + (direction < 0 ? -1.0 : 1.0) * stepSpin_->value());
}

QString TablePanel::home(Axis axis) { return move(axis, 0.0); }

QString TablePanel::goTo(Axis axis, double positionDeg) { return move(axis, positionDeg); }

QString TablePanel::move(Axis axis, double positionDeg) {
  QString why;
  if (!controller_) why = disabledReason();
  else if (runActive_) why = tr("A run drives the table; stop it first.");
  else if (!state_) why = tr("The table does not answer (%1); the table was not moved.").arg(unreachable_);
  else if (const std::string blocked = state_->blockingReason(); !blocked.empty())
    why = tr("The table cannot move: %1; the table was not moved.").arg(coreText(blocked));
  else if (auto check = table::checkPositionAgainstLimits(axis, positionDeg, limits_); !check.isOk())
    why = coreText(check.message());
  else if (auto sent = controller_->moveTo(axis, positionDeg); !sent.isOk())
    why = coreText(sent.message());
  if (!why.isEmpty()) {
    showMessage(why, true);
    return why;
  }
  showMessage(tr("%1 to %2°").arg(QString::fromLatin1(axisLabel(axis)), localNumber(positionDeg, 'f', 4)), false);
  poll();
  return QString();
}

QString TablePanel::emergencyStop() {
  if (!controller_) {
    showMessage(disabledReason(), true);
    return disabledReason();
  }
  if (auto s = controller_->emergencyStop(); !s.isOk()) {
    const QString why = tr("The emergency stop did not reach the controller: %1. Use the table's own stop button.")
                            .arg(coreText(s.message()));
    showMessage(why, true);
    return why;
  }
  showMessage(tr("Emergency stop sent: every axis stops. Reset it at the controller before the table moves again."),
              true);
  poll();
  return QString();
}

QString TablePanel::positionText(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].position->text(); }
QString TablePanel::stateText(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].state->text(); }
QString TablePanel::message() const { return messageLabel_->text(); }
QPushButton* TablePanel::jogButton(Axis axis, int direction) const {
  const auto& row = rows_[static_cast<std::size_t>(axis)];
  return direction < 0 ? row.minus : row.plus;
}
QPushButton* TablePanel::homeButton(Axis axis) const { return rows_[static_cast<std::size_t>(axis)].home; }

QString TablePanel::disabledReason() const {
  if (!controller_)
    return tr("No table is connected: press Connect (the address is the Configure view's remote table).");
  if (runActive_) return tr("A run drives the table; only the emergency stop is available.");
  return QString();
}

void TablePanel::showMessage(const QString& text, bool error) {
  messageLabel_->setText(text);
  messageLabel_->setStyleSheet(error ? "QLabel { color: #b00000; }" : QString());
}

void TablePanel::showState() {
  if (!controller_) statusLabel_->setText(tr("No table connected."));
  else
    statusLabel_->setText(state_ ? QString::fromStdString(controller_->description())
                                 : tr("Unreachable: %1").arg(unreachable_));
  for (int a = 0; a < kAxisCount; ++a) {
    auto& row = rows_[static_cast<std::size_t>(a)];
    if (!controller_) {
      row.position->setText(QStringLiteral("—"));
      row.state->setText(QStringLiteral("—"));
    } else if (!state_) {
      row.position->setText(QStringLiteral("—"));
      row.state->setText(tr("unreachable"));
    } else {
      const auto& axis = state_->axis(static_cast<Axis>(a));
      row.position->setText(state_->known ? localNumber(axis.positionDeg, 'f', 4) + QStringLiteral("°")
                                          : QStringLiteral("—"));
      row.state->setText(state_->emergencyStopped ? tr("emergency stop") : modeWord(axis.mode));
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
  stopButton_->setEnabled(connected());
  stopButton_->setToolTip(connected() ? tr("Stop every axis at once through the controller")
                                      : disabledReason());
}

}  // namespace fog::ui

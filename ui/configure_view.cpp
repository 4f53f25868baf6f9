#include "ui/configure_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

#include "core/common/gyro_signs.h"
#include "core/serial/serial_source.h"
#include "ui/commanded_motion.h"
#include "ui/core_text.h"
#include "ui/plan_editor.h"

namespace fog::ui {

ConfigureView::ConfigureView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  // The plan and the rest side by side, the operator moving the divider;
  // one above the other where the room is too narrow (fitLayout).
  auto* split = split_ = new QSplitter(Qt::Horizontal);
  split->setObjectName("configureSplitter");
  split->setChildrenCollapsible(false);
  layout->addWidget(split);
  split->addWidget(buildPlanGroup());

  auto* sideWidget = new QWidget();
  auto* side = new QVBoxLayout(sideWidget);
  side->setContentsMargins(0, 0, 0, 0);
  side->addWidget(buildSourceGroup());
  side->addWidget(buildSessionGroup());
  side->addWidget(buildConstantsGroup());

  message_ = new QLabel();
  message_->setObjectName("configureMessage");
  message_->setWordWrap(true);
  side->addWidget(message_);
  side->addStretch(1);
  split->addWidget(sideWidget);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  connect(this, &ConfigureView::sourceChanged, this, &ConfigureView::applyTableLimits);
  // A plan of wider or narrower points may need, or fit, the room beside it.
  connect(planEditor_, &PlanEditor::planChanged, this, &ConfigureView::fitLayoutLater);
  applyTableLimits();
}

void ConfigureView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  // The room is the parent's (a scroll area's viewport gives its widget at
  // least the widget's minimum width, so this view's own width cannot say).
  if (QWidget* room = parentWidget(); room && room != watchedRoom_) {
    if (watchedRoom_) watchedRoom_->removeEventFilter(this);
    watchedRoom_ = room;
    room->installEventFilter(this);
  }
  fitLayoutLater();
}

bool ConfigureView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == watchedRoom_ && event->type() == QEvent::Resize) fitLayoutLater();
  return QWidget::eventFilter(watched, event);
}

// After the layout has settled: the tables' header lengths against their
// viewports say what is cut.
void ConfigureView::fitLayoutLater() {
  if (fitPending_) return;
  fitPending_ = true;
  QTimer::singleShot(0, this, [this] {
    fitPending_ = false;
    fitLayout();
  });
}

void ConfigureView::fitLayout() {
  if (!watchedRoom_ || !isVisible()) return;
  const int room = watchedRoom_->width();
  QWidget* plan = split_->widget(0);
  const int planLength = planEditor_->table()->horizontalHeader()->length();
  if (split_->orientation() == Qt::Vertical) {
    // (a plan narrower than when the room was learnt may fit beside again)
    if (room < horizontalNeeds_ && planLength >= planLengthLearnt_) return;
    split_->setOrientation(Qt::Horizontal);
    plan->setMinimumHeight(0);
    fitLayoutLater();
    return;
  }
  int cut = 0;  // the most a table of the plan's is wider than its viewport, in pixels
  for (QTableWidget* t : {planEditor_->table(), commandedMotion_->table()})
    cut = std::max(cut, t->horizontalHeader()->length() - t->viewport()->width());
  const int viewCut = std::max(0, minimumSizeHint().width() - room);
  if (cut == 0 && viewCut == 0) return;
  // The side gives the plan what it has beyond its minimum, first.
  QList<int> sizes = split_->sizes();
  const int spare = sizes.value(1) - split_->widget(1)->minimumSizeHint().width();
  if (viewCut == 0 && spare >= cut + 2) {
    sizes[0] += cut + 2;
    sizes[1] -= cut + 2;
    split_->setSizes(sizes);
    fitLayoutLater();
    return;
  }
  // Too narrow side by side: the plan above the rest, at the height its
  // tables want (the view scrolls down), until the room grows by what was cut.
  horizontalNeeds_ = room + std::max(cut - std::max(spare, 0), viewCut) + 2;
  planLengthLearnt_ = planLength;
  split_->setOrientation(Qt::Vertical);
  plan->setMinimumHeight(plan->sizeHint().height());
}

void ConfigureView::setConnectedTable(const QString& description, const table::TableLimits& limits) {
  connected_ = ConnectedTable{description, limits};
  applyTableLimits();
}

void ConfigureView::clearConnectedTable() {
  connected_.reset();
  applyTableLimits();
}

// The plan is checked against the table that will swing it: the connected
// controller's limits when the bench drives a remote controller, the
// simulator's turntable when the simulator runs (or a session is replayed).
// A table the bench does not command has limits it cannot know: the
// simulator's stand in, and the label says so.
void ConfigureView::applyTableLimits() {
  table::TableLimits limits = simulatorLimits();
  QString source = tr("the simulator's turntable");
  if (sourceKind() == SourceKind::kSerial) {
    if (tableDriver() == TableDriver::kRemote && connected_) {
      limits = connected_->limits;
      source = tr("the connected controller %1").arg(connected_->description);
    } else if (tableDriver() == TableDriver::kRemote) {
      source = tr("the simulator's turntable (no controller connected: connect it in Table controls to check the "
                  "plan against its own limits)");
    } else {
      source = tr("the simulator's turntable (the bench does not command this table and cannot read its limits)");
    }
  }
  planEditor_->setLimits(limits);
  commandedMotion_->setLimits(limits, source);
}

QGroupBox* ConfigureView::buildPlanGroup() {
  auto* planBox = new QGroupBox(tr("Test plan"));
  auto* planLayout = new QVBoxLayout(planBox);
  planEditor_ = new PlanEditor();
  planEditor_->setObjectName("planEditor");
  planLayout->addWidget(planEditor_, 3);
  // What the table is asked to do, against its limits (issue 17).
  auto* motionBox = new QGroupBox(tr("Commanded table motion"));
  motionBox->setObjectName("commandedMotionBox");
  auto* motionLayout = new QVBoxLayout(motionBox);
  commandedMotion_ = new CommandedMotionTable();
  motionLayout->addWidget(commandedMotion_);
  planLayout->addWidget(motionBox, 2);
  commandedMotion_->setPlan(planEditor_->plan());
  connect(planEditor_, &PlanEditor::planChanged, this, [this] { commandedMotion_->setPlan(planEditor_->plan()); });
  return planBox;
}

QGroupBox* ConfigureView::buildSourceGroup() {
  auto* sourceBox = new QGroupBox(tr("Source"));
  auto* sourceForm = new QFormLayout(sourceBox);
  sourceCombo_ = new QComboBox();
  sourceCombo_->setObjectName("sourceCombo");
  sourceCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  sourceCombo_->setMinimumContentsLength(12);
  sourceCombo_->addItem(tr("Built-in simulator"), static_cast<int>(SourceKind::kSimulator));
  sourceCombo_->addItem(tr("Replay of a session"), static_cast<int>(SourceKind::kReplay));
  sourceCombo_->addItem(tr("Serial sampling board"), static_cast<int>(SourceKind::kSerial));
  speedCombo_ = new QComboBox();
  speedCombo_->setObjectName("speedCombo");
  speedCombo_->addItem(tr("Real time"), 1.0);
  speedCombo_->addItem(tr("5× real time"), 5.0);
  speedCombo_->addItem(tr("20× real time"), 20.0);
  speedCombo_->addItem(tr("As fast as possible"), 0.0);
  seedSpin_ = new QSpinBox();
  seedSpin_->setObjectName("seedSpin");
  seedSpin_->setRange(0, std::numeric_limits<int>::max());
  seedSpin_->setValue(1);
  seedSpin_->setToolTip(tr("Simulator seed: the same seed gives the same data"));
  auto* replayRow = new QHBoxLayout();
  replayEdit_ = new QLineEdit();
  replayEdit_->setObjectName("replayEdit");
  replayEdit_->setPlaceholderText(tr("session file (.fbs) to replay"));
  auto* browse = new QPushButton(tr("Browse…"));
  browse->setObjectName("browseReplayButton");
  replayRow->addWidget(replayEdit_, 1);
  replayRow->addWidget(browse);
  sourceForm->addRow(tr("Source"), sourceCombo_);
  // Pace and seed share a row: the column fits a laptop screen's height.
  auto* paceRow = new QHBoxLayout();
  paceRow->addWidget(speedCombo_, 1);
  paceRow->addWidget(new QLabel(tr("Seed")));
  paceRow->addWidget(seedSpin_);
  sourceForm->addRow(tr("Pace"), paceRow);
  sourceForm->addRow(tr("Replay"), replayRow);
  addSerialRows(sourceForm);

  connect(sourceCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConfigureView::sourceChanged);
  connect(speedCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConfigureView::paceChanged);
  connect(replayEdit_, &QLineEdit::textChanged, this, &ConfigureView::runnabilityChanged);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Session to replay"), sessionFolder(),
                                                      tr("fogbench sessions (*.fbs)"));
    if (!path.isEmpty()) replayEdit_->setText(path);
  });
  return sourceBox;
}

// The serial board's rows of the source: its port and baud rate, and the
// turntable.
void ConfigureView::addSerialRows(QFormLayout* sourceForm) {
  auto* serialRow = new QHBoxLayout();
  portCombo_ = new QComboBox();
  portCombo_->setObjectName("portCombo");
  portCombo_->setEditable(true);  // a device the system does not list, e.g. a pseudo-terminal
  portCombo_->setToolTip(tr("The sampling board's serial port"));
  portCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  portCombo_->setMinimumContentsLength(10);
  baudCombo_ = new QComboBox();
  baudCombo_->setObjectName("baudCombo");
  baudCombo_->setEditable(true);
  for (int baud : {921600, 460800, 230400, 115200, 1000000, 2000000}) baudCombo_->addItem(QString::number(baud));
  auto* rescan = new QPushButton(tr("Rescan"));
  rescan->setObjectName("rescanButton");
  serialRow->addWidget(portCombo_, 1);
  serialRow->addWidget(rescan);
  sourceForm->addRow(tr("Serial port"), serialRow);
  sourceForm->addRow(tr("Baud rate"), baudCombo_);
  // Who swings the table while a serial board records (docs/table-control.md).
  auto* tableRow = new QHBoxLayout();
  tableCombo_ = new QComboBox();
  tableCombo_->setObjectName("tableDriverCombo");
  tableCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  tableCombo_->setMinimumContentsLength(10);
  tableCombo_->addItem(tr("Not driven (the board's own plan)"), static_cast<int>(TableDriver::kNone));
  tableCombo_->addItem(tr("Remote controller"), static_cast<int>(TableDriver::kRemote));
  tableCombo_->addItem(tr("Manual (the operator sets it)"), static_cast<int>(TableDriver::kManual));
  tableCombo_->setToolTip(tr("Remote: the bench commands the turntable controller through the plan; manual: the "
                             "bench tells you what to set and records once the table angle shows it"));
  tableAddressEdit_ = new QLineEdit();
  tableAddressEdit_->setObjectName("tableAddressEdit");
  tableAddressEdit_->setPlaceholderText(tr("tcp:HOST:PORT or device"));
  tableAddressEdit_->setToolTip(tr("The turntable controller: tcp:HOST:PORT (numeric address) or its serial device"));
  tableRow->addWidget(tableCombo_, 1);
  tableRow->addWidget(tableAddressEdit_, 1);
  sourceForm->addRow(tr("Turntable"), tableRow);
  auto listPorts = [this] {
    const QString current = portCombo_->currentText();
    portCombo_->clear();
    for (const auto& p : serial::availablePorts())
      portCombo_->addItem(QString::fromStdString(p.systemLocation + (p.description.empty() ? "" : "  (" + p.description + ")")),
                          QString::fromStdString(p.systemLocation));
    if (!current.isEmpty()) portCombo_->setCurrentText(current);
  };
  connect(rescan, &QPushButton::clicked, this, listPorts);
  listPorts();

  connect(portCombo_, &QComboBox::currentTextChanged, this, &ConfigureView::runnabilityChanged);
  connect(tableCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConfigureView::sourceChanged);
  connect(tableCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ConfigureView::runnabilityChanged);
  connect(tableAddressEdit_, &QLineEdit::textChanged, this, &ConfigureView::runnabilityChanged);
}

QGroupBox* ConfigureView::buildSessionGroup() {
  auto* sessionBox = new QGroupBox(tr("Session"));
  auto* sessionForm = new QFormLayout(sessionBox);
  recordCheck_ = new QCheckBox(tr("Record a session file (crash-safe)"));
  recordCheck_->setObjectName("recordCheck");
  recordCheck_->setChecked(true);
  auto* folderRow = new QHBoxLayout();
  folderEdit_ = new QLineEdit();
  folderEdit_->setObjectName("sessionFolderEdit");
  auto* chooseFolder = new QPushButton(tr("Choose…"));
  chooseFolder->setObjectName("chooseFolderButton");
  folderRow->addWidget(folderEdit_, 1);
  folderRow->addWidget(chooseFolder);
  operatorEdit_ = new QLineEdit();
  operatorEdit_->setObjectName("operatorEdit");
  imuModelEdit_ = new QLineEdit();
  imuModelEdit_->setObjectName("imuModelEdit");
  imuSerialEdit_ = new QLineEdit();
  imuSerialEdit_->setObjectName("imuSerialEdit");
  lotEdit_ = new QLineEdit();
  lotEdit_->setObjectName("lotEdit");
  benchIdEdit_ = new QLineEdit();
  benchIdEdit_->setObjectName("benchIdEdit");
  notesEdit_ = new QLineEdit();
  sessionForm->addRow(recordCheck_);
  sessionForm->addRow(tr("Folder"), folderRow);
  // Who and where share a row, the unit's model, serial and lot another:
  // the form fits a 1366x768 laptop on Qt 5's taller fonts too.
  auto* whoRow = new QHBoxLayout();
  whoRow->addWidget(operatorEdit_, 1);
  whoRow->addWidget(new QLabel(tr("Bench id")));
  whoRow->addWidget(benchIdEdit_, 1);
  sessionForm->addRow(tr("Operator"), whoRow);
  auto* imuRow = new QHBoxLayout();
  imuRow->addWidget(imuModelEdit_, 1);
  imuRow->addWidget(new QLabel(tr("IMU serial")));
  imuRow->addWidget(imuSerialEdit_, 1);
  imuRow->addWidget(new QLabel(tr("Lot")));
  imuRow->addWidget(lotEdit_, 1);
  sessionForm->addRow(tr("IMU model"), imuRow);
  sessionForm->addRow(tr("Notes"), notesEdit_);

  for (QLineEdit* e : {operatorEdit_, imuModelEdit_, imuSerialEdit_, lotEdit_, benchIdEdit_})
    connect(e, &QLineEdit::textChanged, this, &ConfigureView::identityChanged);
  connect(chooseFolder, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Session folder"), sessionFolder());
    if (!dir.isEmpty()) emit folderChosen(dir);
  });
  // Only a folder the operator typed is chosen: leaving the field (focus
  // out, the window deactivated) or pressing Enter on a folder set by the
  // program (a one-off --session-folder) chooses nothing.
  connect(folderEdit_, &QLineEdit::editingFinished, this, [this] {
    if (!folderEdit_->isModified()) return;
    folderEdit_->setModified(false);
    emit folderChosen(folderEdit_->text());
  });
  connect(recordCheck_, &QCheckBox::toggled, folderEdit_, &QWidget::setEnabled);
  return sessionBox;
}

QGroupBox* ConfigureView::buildConstantsGroup() {
  auto* constantsBox = new QGroupBox(tr("Bench constants"));
  auto* constantsLayout = new QHBoxLayout(constantsBox);  // side by side: saves height on a laptop
  constantsLabel_ = new QLabel();
  constantsLabel_->setObjectName("constantsLabel");

  auto* edit = new QPushButton(tr("Edit…"));
  edit->setToolTip(tr("Edit the bench constants"));
  edit->setObjectName("editConstantsButton");
  constantsLayout->addWidget(constantsLabel_, 1);
  constantsLayout->addWidget(edit, 0, Qt::AlignTop);
  connect(edit, &QPushButton::clicked, this, &ConfigureView::editBenchSettingsRequested);
  return constantsBox;
}

ConfigureView::SourceKind ConfigureView::sourceKind() const {
  return static_cast<SourceKind>(sourceCombo_->currentData().toInt());
}

void ConfigureView::setSourceKind(SourceKind kind) {
  sourceCombo_->setCurrentIndex(sourceCombo_->findData(static_cast<int>(kind)));
}

double ConfigureView::pace() const { return speedCombo_->currentData().toDouble(); }

void ConfigureView::setPace(double pace) {
  const int i = speedCombo_->findData(pace);
  if (i >= 0) {
    speedCombo_->setCurrentIndex(i);
    return;
  }
  speedCombo_->addItem(tr("%1× real time").arg(pace), pace);
  speedCombo_->setCurrentIndex(speedCombo_->count() - 1);
}

int ConfigureView::seed() const { return seedSpin_->value(); }
void ConfigureView::setSeed(int seed) { seedSpin_->setValue(seed); }
QString ConfigureView::replayPath() const { return replayEdit_->text(); }
void ConfigureView::setReplayPath(const QString& path) { replayEdit_->setText(path); }

QString ConfigureView::serialPort() const {
  // A listed port carries its device as data; a typed one is the text itself.
  const int i = portCombo_->currentIndex();
  if (i >= 0 && portCombo_->itemText(i) == portCombo_->currentText()) return portCombo_->itemData(i).toString();
  return portCombo_->currentText().trimmed();
}

void ConfigureView::setSerialPort(const QString& port) { portCombo_->setCurrentText(port); }

bool ConfigureView::baudRate(int* baud) const {
  bool ok = false;
  *baud = baudCombo_->currentText().toInt(&ok);
  return ok;
}

ConfigureView::TableDriver ConfigureView::tableDriver() const {
  return static_cast<TableDriver>(tableCombo_->currentData().toInt());
}

void ConfigureView::setTableDriver(TableDriver driver, const QString& address) {
  tableCombo_->setCurrentIndex(tableCombo_->findData(static_cast<int>(driver)));
  if (!address.isNull()) tableAddressEdit_->setText(address);
}

QString ConfigureView::tableAddress() const { return tableAddressEdit_->text().trimmed(); }

QString ConfigureView::sessionFolder() const { return recordCheck_->isChecked() ? folderEdit_->text() : QString(); }

void ConfigureView::setSessionFolder(const QString& folder) {
  folderEdit_->setText(folder);
  recordCheck_->setChecked(!folder.isEmpty());
}

QString ConfigureView::operatorName() const { return operatorEdit_->text(); }
QString ConfigureView::imuModel() const { return imuModelEdit_->text(); }
QString ConfigureView::imuSerial() const { return imuSerialEdit_->text(); }
QString ConfigureView::lot() const { return lotEdit_->text(); }
QString ConfigureView::benchId() const { return benchIdEdit_->text(); }
QString ConfigureView::notes() const { return notesEdit_->text(); }

void ConfigureView::setLotAndBench(const QString& lot, const QString& benchId) {
  lotEdit_->setText(lot);
  benchIdEdit_->setText(benchId);
}

void ConfigureView::setIdentity(const QString& operatorName, const QString& imuModel, const QString& imuSerial) {
  operatorEdit_->setText(operatorName);
  imuModelEdit_->setText(imuModel);
  imuSerialEdit_->setText(imuSerial);
}

void ConfigureView::showBenchConstants(const BenchConstants& s, const std::array<int, kAxisCount>& gyroSign) {
  // Line breaks of its own, no word wrap: a wrapping label would let the
  // column be squeezed under its real height on a small screen.
  // Three lines, as before the signs and the frame joined them: a laptop's
  // 768 px leave no room for a fourth. The frame as its code (NED, FRD:30),
  // its words in the tooltip.
  const std::string frameCode = imuFrameToText(s.imuFrame);
  constantsLabel_->setText(tr("table read delay %1 ms · board delay %2 ms · latitude %3°\n"
                              "pulse equivalent %4° · counter %5 MHz / %6 bit\ngyro signs %7 · IMU frame %8")
                               .arg(s.tableReadDelayMs)
                               .arg(s.boardDelayMs)
                               .arg(s.latitudeDeg)
                               .arg(s.pulseEquivalentDeg)
                               .arg(s.counterHz / 1e6)
                               .arg(s.counterBits)
                               .arg(QString::fromStdString(describeGyroSigns(gyroSign)),
                                    frameCode.empty() ? tr("not stated") : QString::fromStdString(frameCode)));
  constantsLabel_->setToolTip(tr("IMU frame: %1").arg(coreText(describeImuFrame(s.imuFrame))));
}

void ConfigureView::setMessage(const QString& html) { message_->setText(html); }

void ConfigureView::setRunning(bool running) {
  planEditor_->setReadOnly(running);
  for (QWidget* w : std::initializer_list<QWidget*>{sourceCombo_, speedCombo_, seedSpin_, replayEdit_, recordCheck_,
                                                    folderEdit_, portCombo_, baudCombo_, tableCombo_,
                                                    tableAddressEdit_})
    w->setEnabled(!running);
  if (!running) {
    seedSpin_->setEnabled(sourceKind() == SourceKind::kSimulator);
    replayEdit_->setEnabled(sourceKind() == SourceKind::kReplay);
    const bool serial = sourceKind() == SourceKind::kSerial;
    portCombo_->setEnabled(serial);
    baudCombo_->setEnabled(serial);
    tableCombo_->setEnabled(serial);
    tableAddressEdit_->setEnabled(serial && tableDriver() == TableDriver::kRemote);
    // A board runs at its own pace; a driven table at the pace chosen (real
    // time, or faster for an emulator).
    speedCombo_->setEnabled(!serial || tableDriver() != TableDriver::kNone);
    folderEdit_->setEnabled(recordCheck_->isChecked());
  }
}

}  // namespace fog::ui

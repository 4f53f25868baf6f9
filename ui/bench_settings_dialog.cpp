#include "ui/bench_settings_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

#include "core/analysis/decision_rule.h"
#include "ui/core_text.h"

namespace fog::ui {

namespace {

QDoubleSpinBox* spin(double min, double max, int decimals, const QString& suffix, double value) {
  auto* s = new QDoubleSpinBox();
  s->setRange(min, max);
  s->setDecimals(decimals);
  s->setSuffix(suffix);
  s->setValue(value);
  return s;
}

}  // namespace

BenchConstants loadBenchConstants() {
  QSettings q;
  q.beginGroup("bench");
  const BenchConstants d;
  BenchConstants s;
  s.tableReadDelayMs = q.value("table_read_delay_ms", d.tableReadDelayMs).toDouble();
  s.tableReadDelayStdMs = q.value("table_read_delay_std_ms", d.tableReadDelayStdMs).toDouble();
  s.boardDelayMs = q.value("board_delay_ms", d.boardDelayMs).toDouble();
  s.boardDelayStdMs = q.value("board_delay_std_ms", d.boardDelayStdMs).toDouble();
  s.latitudeDeg = q.value("latitude_deg", d.latitudeDeg).toDouble();
  s.pulseEquivalentDeg = q.value("pulse_equivalent_deg", d.pulseEquivalentDeg).toDouble();
  s.counterHz = q.value("counter_hz", d.counterHz).toDouble();
  s.counterBits = q.value("counter_bits", d.counterBits).toInt();
  // A frame that does not read (edited by hand) is not stated: the diagnosis
  // then finds it from the data, never uses a half-read one.
  if (auto frame = imuFrameFromText(q.value("imu_frame", QString()).toString().toStdString())) s.imuFrame = *frame;
  s.gainToleranceFraction = q.value("gain_tolerance", d.gainToleranceFraction).toDouble();
  // A remembered value out of its range (settings edited by hand) is not
  // used: that constant reads its default (checkBenchConstants, the ranges
  // of the command line and the importer).
  for (const auto& problem : benchConstantProblems(s)) {
    using Field = BenchConstantProblem::Field;
    switch (problem.field) {
      case Field::kTableReadDelay: s.tableReadDelayMs = d.tableReadDelayMs; break;
      case Field::kTableReadDelayStd: s.tableReadDelayStdMs = d.tableReadDelayStdMs; break;
      case Field::kBoardDelay: s.boardDelayMs = d.boardDelayMs; break;
      case Field::kBoardDelayStd: s.boardDelayStdMs = d.boardDelayStdMs; break;
      case Field::kLatitude: s.latitudeDeg = d.latitudeDeg; break;
      case Field::kPulseEquivalent: s.pulseEquivalentDeg = d.pulseEquivalentDeg; break;
      case Field::kCounterHz: s.counterHz = d.counterHz; break;
      case Field::kCounterBits: s.counterBits = d.counterBits; break;
      case Field::kGyroSign: s.gyroSign = d.gyroSign; break;
      case Field::kGainTolerance: s.gainToleranceFraction = d.gainToleranceFraction; break;
    }
  }
  return s;
}

void saveBenchConstants(const BenchConstants& s) {
  QSettings q;
  q.beginGroup("bench");
  q.setValue("table_read_delay_ms", s.tableReadDelayMs);
  q.setValue("table_read_delay_std_ms", s.tableReadDelayStdMs);
  q.setValue("board_delay_ms", s.boardDelayMs);
  q.setValue("board_delay_std_ms", s.boardDelayStdMs);
  q.setValue("latitude_deg", s.latitudeDeg);
  q.setValue("pulse_equivalent_deg", s.pulseEquivalentDeg);
  q.setValue("counter_hz", s.counterHz);
  q.setValue("counter_bits", s.counterBits);
  q.setValue("imu_frame", QString::fromStdString(imuFrameToText(s.imuFrame)));
  q.setValue("gain_tolerance", s.gainToleranceFraction);
}

AnalysisChoices loadAnalysisChoices() {
  QSettings q;
  q.beginGroup("analysis");
  AnalysisChoices c;
  for (int a = 0; a < kAxisCount; ++a)
    c.gyroSign[static_cast<std::size_t>(a)] =
        q.value(QString("gyro_sign_%1").arg(axisName(static_cast<Axis>(a))), 1).toInt() < 0 ? -1 : 1;
  const double limit = q.value("imu_delay_limit_ms", c.imuDelayLimitMs).toDouble();
  if (limit > 0.0 && limit <= 1e6) c.imuDelayLimitMs = limit;
  const double k = q.value("coverage_factor_k", c.coverageK).toDouble();
  if (analysis::coverageFactorProblem(k).empty()) c.coverageK = k;  // a hand-edited bad k: the default
  return c;
}

void saveAnalysisChoices(const AnalysisChoices& c) {
  QSettings q;
  q.beginGroup("analysis");
  for (int a = 0; a < kAxisCount; ++a)
    q.setValue(QString("gyro_sign_%1").arg(axisName(static_cast<Axis>(a))), c.gyroSign[static_cast<std::size_t>(a)]);
  q.setValue("imu_delay_limit_ms", c.imuDelayLimitMs);
  q.setValue("coverage_factor_k", c.coverageK);
}

BenchSettingsDialog::BenchSettingsDialog(const BenchConstants& s, const AnalysisChoices& choices, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Bench constants"));
  setObjectName("benchSettingsDialog");
  auto* form = new QFormLayout();
  readDelay_ = spin(0.0, 100.0, 4, tr(" ms"), s.tableReadDelayMs);
  readDelayStd_ = spin(0.0, 100.0, 4, tr(" ms"), s.tableReadDelayStdMs);
  boardDelay_ = spin(0.0, 100.0, 4, tr(" ms"), s.boardDelayMs);
  boardDelayStd_ = spin(0.0, 100.0, 4, tr(" ms"), s.boardDelayStdMs);
  latitude_ = spin(-90.0, 90.0, 4, tr(" °"), s.latitudeDeg);
  pulseEquivalent_ = spin(0.0, 1.0, 9, tr(" °/pulse"), s.pulseEquivalentDeg);
  counterMHz_ = spin(0.001, 1000.0, 3, tr(" MHz"), s.counterHz / 1e6);
  counterBits_ = new QSpinBox();
  counterBits_->setRange(8, 32);
  counterBits_->setValue(s.counterBits);
  counterBits_->setSuffix(tr(" bit"));
  readDelay_->setObjectName("readDelaySpin");
  boardDelay_->setObjectName("boardDelaySpin");
  form->addRow(tr("Table angle read delay"), readDelay_);
  form->addRow(tr("  its standard uncertainty"), readDelayStd_);
  form->addRow(tr("Processing-board delay"), boardDelay_);
  form->addRow(tr("  its standard uncertainty"), boardDelayStd_);
  form->addRow(tr("Latitude"), latitude_);
  form->addRow(tr("Gyro pulse equivalent"), pulseEquivalent_);
  form->addRow(tr("Sampling-board counter"), counterMHz_);
  form->addRow(tr("Counter width"), counterBits_);
  gainTolerance_ = spin(0.0001, 99.9999, 4, tr(" %"), s.gainToleranceFraction * 100.0);
  gainTolerance_->setObjectName("gainToleranceSpin");
  gainTolerance_->setToolTip(tr("The gyro's stated scale tolerance: each test point's gyro/table amplitude ratio, "
                                "with the gyro's fitted dynamics taken out, must lie within 1 ± this, or the point "
                                "is invalid (a wrong pulse equivalent or frame period scales the gyro, not the "
                                "delay)"));
  form->addRow(tr("Gyro scale tolerance"), gainTolerance_);
  for (int a = 0; a < kAxisCount; ++a) {
    auto* sign = new QComboBox();
    sign->addItem(tr("+1 (turns with the table)"), 1);
    sign->addItem(tr("−1 (mounted the other way round)"), -1);
    sign->setCurrentIndex(choices.gyroSign[static_cast<std::size_t>(a)] < 0 ? 1 : 0);
    sign->setObjectName(QString("gyroSign%1Combo").arg(QString(axisName(static_cast<Axis>(a))).toUpper()));
    gyroSign_[static_cast<std::size_t>(a)] = sign;
    form->addRow(tr("Gyro sign, %1 axis").arg(QString(axisName(static_cast<Axis>(a))).toUpper()), sign);
  }
  imuFrame_ = new QComboBox();
  imuFrame_->setObjectName("imuFrameCombo");
  imuFrame_->addItem(tr("not stated (found from the data)"), int(ImuFrame::Convention::kUnstated));
  imuFrame_->addItem(tr("NED: x north, y east, z down"), int(ImuFrame::Convention::kNorthEastDown));
  imuFrame_->addItem(tr("ENU: x east, y north, z up"), int(ImuFrame::Convention::kEastNorthUp));
  imuFrame_->addItem(tr("FRD: x forward, y right, z down"), int(ImuFrame::Convention::kForwardRightDown));
  imuFrame_->addItem(tr("RFU: x right, y forward, z up"), int(ImuFrame::Convention::kRightForwardUp));
  imuFrame_->setCurrentIndex(std::max(0, imuFrame_->findData(int(s.imuFrame.convention))));
  imuFrame_->setToolTip(tr("Where the IMU's axes point with the table at zero. The Earth rate and gravity the "
                           "gyros see depend on it; the diagnosis replays the session in it and checks it "
                           "against the data."));
  // Headings within [-360, 360]; the one step below reads "not stated" (a
  // heading below -360 would make a frame no session could read back).
  forwardHeading_ = spin(-360.01, 360.0, 2, tr(" °"), s.imuFrame.forwardHeadingDeg.value_or(-360.01));
  forwardHeading_->setObjectName("forwardHeadingSpin");
  forwardHeading_->setSpecialValueText(tr("not stated"));
  forwardHeading_->setToolTip(tr("Azimuth of the IMU's forward axis, from north toward east"));
  auto forwardApplies = [this] {
    const auto c = ImuFrame::Convention(imuFrame_->currentData().toInt());
    forwardHeading_->setEnabled(c == ImuFrame::Convention::kForwardRightDown ||
                                c == ImuFrame::Convention::kRightForwardUp);
  };
  forwardApplies();
  connect(imuFrame_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, forwardApplies);
  form->addRow(tr("IMU frame at zero angles"), imuFrame_);
  form->addRow(tr("  forward axis heading"), forwardHeading_);
  limit_ = spin(0.001, 1000.0, 3, tr(" ms"), choices.imuDelayLimitMs);
  limit_->setObjectName("limitSpin");
  form->addRow(tr("IMU delay limit (acceptance)"), limit_);
  // Beside the limit: the rule is "IMU delay + k·σ < limit" (decision_rule.h).
  coverageK_ = spin(0.1, analysis::kMaxCoverageFactor, 2, QString(), choices.coverageK);
  coverageK_->setObjectName("coverageKSpin");
  coverageK_->setSingleStep(0.5);
  coverageK_->setToolTip(tr("PASS when IMU delay + k·σ < limit (one-sided guarded acceptance, ISO/IEC 17025:2017 "
                            "§7.8.6); the guard band below the limit is k·σ"));
  coverageRisk_ = new QLabel();
  coverageRisk_->setObjectName("coverageKRisk");
  auto showRisk = [this] {
    coverageRisk_->setText(tr("maximum false-accept risk 1 − Φ(k) = %1")
                               .arg(QString::fromStdString(analysis::probabilityText(
                                   analysis::maxFalseAcceptProbability(coverageK_->value())))));
  };
  showRisk();
  connect(coverageK_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, showRisk);
  auto* kRow = new QHBoxLayout();
  kRow->addWidget(coverageK_);
  kRow->addWidget(coverageRisk_, 1);
  form->addRow(tr("  coverage factor k (PASS: delay + k·σ < limit)"), kRow);

  auto* note = new QLabel(tr("IMU delay = measured lag + table read delay; gyro's own delay = IMU delay − "
                             "processing-board delay. The pulse equivalent is used only when the board's stream "
                             "does not state it; the simulator uses these values for the chain it simulates. "
                             "The gyro signs, the limit and k are stored with every result: changing them changes "
                             "no stored verdict; re-analyse a session to store a new result with them."));
  note->setWordWrap(true);
  // What checkBenchConstants refuses, shown here when OK is pressed (the
  // dialog then stays open).
  problem_ = new QLabel();
  problem_->setObjectName("benchConstantsProblem");
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #b00020;");
  problem_->hide();
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                       QDialogButtonBox::RestoreDefaults);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this, [this] {
    const BenchConstants d;
    readDelay_->setValue(d.tableReadDelayMs);
    readDelayStd_->setValue(d.tableReadDelayStdMs);
    boardDelay_->setValue(d.boardDelayMs);
    boardDelayStd_->setValue(d.boardDelayStdMs);
    latitude_->setValue(d.latitudeDeg);
    pulseEquivalent_->setValue(d.pulseEquivalentDeg);
    counterMHz_->setValue(d.counterHz / 1e6);
    counterBits_->setValue(d.counterBits);
    gainTolerance_->setValue(d.gainToleranceFraction * 100.0);
    for (auto* sign : gyroSign_) sign->setCurrentIndex(0);
    imuFrame_->setCurrentIndex(0);
    forwardHeading_->setValue(forwardHeading_->minimum());
    limit_->setValue(AnalysisChoices{}.imuDelayLimitMs);
    coverageK_->setValue(AnalysisChoices{}.coverageK);
  });
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(note);
  layout->addWidget(problem_);
  layout->addWidget(buttons);
}

void BenchSettingsDialog::accept() {
  // The ranges the command line and the importer check (checkBenchConstants):
  // the spin boxes keep most values within them; what is still out is said
  // and the dialog stays open.
  BenchConstants s = settings();
  s.gyroSign = analysisChoices().gyroSign;
  if (const Status status = checkBenchConstants(s); !status.isOk()) {
    problem_->setText(coreText(status.message()));
    problem_->show();
    return;
  }
  problem_->hide();
  QDialog::accept();
}

BenchConstants BenchSettingsDialog::settings() const {
  BenchConstants s;
  s.tableReadDelayMs = readDelay_->value();
  s.tableReadDelayStdMs = readDelayStd_->value();
  s.boardDelayMs = boardDelay_->value();
  s.boardDelayStdMs = boardDelayStd_->value();
  s.latitudeDeg = latitude_->value();
  s.pulseEquivalentDeg = pulseEquivalent_->value();
  s.counterHz = counterMHz_->value() * 1e6;
  s.counterBits = counterBits_->value();
  s.gainToleranceFraction = gainTolerance_->value() / 100.0;
  s.imuFrame.convention = ImuFrame::Convention(imuFrame_->currentData().toInt());
  if (forwardHeading_->isEnabled() && forwardHeading_->value() > forwardHeading_->minimum())
    s.imuFrame.forwardHeadingDeg = forwardHeading_->value();
  return s;
}

AnalysisChoices BenchSettingsDialog::analysisChoices() const {
  AnalysisChoices c;
  for (std::size_t a = 0; a < gyroSign_.size(); ++a) c.gyroSign[a] = gyroSign_[a]->currentData().toInt() < 0 ? -1 : 1;
  c.imuDelayLimitMs = limit_->value();
  c.coverageK = coverageK_->value();
  return c;
}

}  // namespace fog::ui

#include "ui/import_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/analysis/swing_windows.h"
#include "ui/core_text.h"

namespace fog::ui {

namespace {
// Combo data: the words of the metadata and the CLI.
constexpr const char* kSegmentNone = "";
constexpr const char* kSegmentAuto = "auto";
constexpr const char* kSegmentGiven = "given";
}  // namespace

ImportDialog::ImportDialog(const QString& folder, QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Import CSV data"));
  auto* layout = new QVBoxLayout(this);
  auto* where = new QLabel(tr("From %1").arg(QDir::toNativeSeparators(folder)));
  where->setWordWrap(true);
  layout->addWidget(where);
  auto* form = new QFormLayout();
  layout->addLayout(form);

  rateConvention_ = new QComboBox();
  rateConvention_->setObjectName("importRateConvention");
  rateConvention_->addItem(tr("as metadata.json states (increments need none)"), QString());
  rateConvention_->addItem(tr("frame average: each rate is its frame's increment / frame period"),
                           QStringLiteral("frame_average"));
  rateConvention_->addItem(tr("sample at stamp: each rate is the rate at its row's time"),
                           QStringLiteral("sample_at_stamp"));
  rateConvention_->setToolTip(tr("How a gyro file of rates (x_rate_deg_s …) was sampled. The choice moves the delay "
                                 "by about half a frame, so it is never guessed; a metadata.json that states "
                                 "another one is refused."));
  form->addRow(tr("Gyro rates"), rateConvention_);

  framePeriodMs_ = new QDoubleSpinBox();
  framePeriodMs_->setObjectName("importFramePeriod");
  framePeriodMs_->setRange(0.0, 1000.0);
  framePeriodMs_->setDecimals(4);
  framePeriodMs_->setSuffix(tr(" ms"));
  framePeriodMs_->setSpecialValueText(tr("as metadata.json states"));
  framePeriodMs_->setToolTip(tr("The IMU's own frame period, for rates averaged over a frame"));
  form->addRow(tr("IMU frame period"), framePeriodMs_);

  segmentation_ = new QComboBox();
  segmentation_->setObjectName("importSegmentation");
  segmentation_->addItem(tr("the files' test points"), QString::fromLatin1(kSegmentNone));
  segmentation_->addItem(tr("cut one continuous recording at the steady swings found"), QString::fromLatin1(kSegmentAuto));
  segmentation_->addItem(tr("cut one continuous recording at the windows given"), QString::fromLatin1(kSegmentGiven));
  form->addRow(tr("Test points"), segmentation_);

  windows_ = new QLineEdit();
  windows_->setObjectName("importWindows");
  windows_->setPlaceholderText(tr("start-end in seconds, e.g. 12.5-42,50-80.25"));
  form->addRow(tr("Swing windows"), windows_);

  problemLabel_ = new QLabel();
  problemLabel_->setObjectName("importProblem");
  problemLabel_->setWordWrap(true);
  problemLabel_->setStyleSheet("color: #b00020");
  layout->addWidget(problemLabel_);

  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons_->button(QDialogButtonBox::Ok)->setText(tr("Import"));
  layout->addWidget(buttons_);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(rateConvention_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ImportDialog::check);
  connect(segmentation_, qOverload<int>(&QComboBox::currentIndexChanged), this, &ImportDialog::check);
  connect(windows_, &QLineEdit::textChanged, this, &ImportDialog::check);
  check();
}

io::ImportOptions ImportDialog::options() const {
  io::ImportOptions o;
  o.gyroRateConvention = rateConvention_->currentData().toString().toStdString();
  if (!o.gyroRateConvention.empty()) o.gyroFramePeriodMs = framePeriodMs_->value();
  const QString segment = segmentation_->currentData().toString();
  if (segment == kSegmentAuto) o.segmentation = "auto";
  else if (segment == kSegmentGiven) o.segmentation = windows_->text().trimmed().toStdString();
  return o;
}

void ImportDialog::check() {
  const bool given = segmentation_->currentData().toString() == kSegmentGiven;
  windows_->setEnabled(given);
  framePeriodMs_->setEnabled(!rateConvention_->currentData().toString().isEmpty());
  problem_.clear();
  if (given) {
    auto parsed = analysis::parseSwingWindows(windows_->text().trimmed().toStdString());
    if (!parsed) problem_ = coreText(parsed.status().message());
  }
  problemLabel_->setText(problem_);
  problemLabel_->setVisible(!problem_.isEmpty());
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(problem_.isEmpty());
}

}  // namespace fog::ui

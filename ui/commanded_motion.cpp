#include "ui/commanded_motion.h"

#include <QBrush>
#include <QColor>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace fog::ui {

namespace {

QString axisLetter(Axis a) { return QString(QChar('X' + static_cast<int>(a))); }

}  // namespace

CommandedMotionTable::CommandedMotionTable(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  limitsLabel_ = new QLabel();
  limitsLabel_->setObjectName("commandedMotionLimits");
  limitsLabel_->setWordWrap(true);
  table_ = new QTableWidget(0, kColumnCount);
  table_->setObjectName("commandedMotionTable");
  table_->setHorizontalHeaderLabels({tr("Point"), tr("Axis"), tr("Frequency (Hz)"), tr("Angle (°)"),
                                     tr("Peak rate (°/s)"), tr("Peak accel. (°/s²)")});
  table_->verticalHeader()->setVisible(false);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionMode(QAbstractItemView::NoSelection);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  layout->addWidget(limitsLabel_);
  layout->addWidget(table_, 1);
  source_ = tr("the simulator's turntable");
  rebuild();
}

void CommandedMotionTable::setPlan(const TestPlan& plan) {
  plan_ = plan;
  rebuild();
}

void CommandedMotionTable::setLimits(const TurntableLimits& limits, double maxPositionDeg, const QString& source) {
  limits_ = limits;
  maxPositionDeg_ = maxPositionDeg;
  source_ = source;
  rebuild();
}

void CommandedMotionTable::rebuild() {
  limitsLabel_->setText(tr("Limits of %1, per axis: amplitude %2°, frequency %3 Hz, peak rate %4 °/s, "
                           "peak acceleration %5 °/s², angle within ±%6°. Red: beyond a limit.")
                            .arg(source_)
                            .arg(limits_.maxAmplitudeDeg)
                            .arg(limits_.maxFrequencyHz)
                            .arg(limits_.maxRateDegPerS)
                            .arg(limits_.maxAccelDegPerS2)
                            .arg(maxPositionDeg_));
  flagged_ = 0;
  table_->setRowCount(static_cast<int>(plan_.points.size()));
  const QBrush over(QColor(255, 205, 205));
  for (int row = 0; row < static_cast<int>(plan_.points.size()); ++row) {
    const TestPoint& p = plan_.points[static_cast<std::size_t>(row)];
    const QString axis = axisLetter(p.axis);
    const bool swing = !p.isStatic();
    const double amp = swing ? p.amplitudeDeg : 0.0;
    const double w = swing ? 2.0 * std::numbers::pi * p.frequencyHz : 0.0;
    const double centre = p.positionDeg[static_cast<std::size_t>(p.axis)];
    const double rate = w * amp, accel = w * w * amp;
    auto put = [&](int column, const QString& text, const QString& problem) {
      auto* item = new QTableWidgetItem(text);
      item->setTextAlignment(column <= kAxis ? Qt::AlignCenter : Qt::AlignRight | Qt::AlignVCenter);
      if (!problem.isEmpty()) {
        item->setBackground(over);
        item->setForeground(QBrush(QColor(150, 0, 0)));
        item->setToolTip(problem);
        ++flagged_;
      }
      table_->setItem(row, column, item);
    };
    put(kPoint, QString::number(row + 1), {});
    put(kAxis, axis, {});
    QString freqProblem;
    if (swing && p.frequencyHz > limits_.maxFrequencyHz)
      freqProblem = tr("frequency beyond the table's %1 Hz on %2").arg(limits_.maxFrequencyHz).arg(axis);
    put(kFrequency, swing ? QString::number(p.frequencyHz, 'g', 6) : tr("at rest"), freqProblem);
    // The angle the swing axis covers; the others hold their positions.
    QString angleProblem;
    if (amp > limits_.maxAmplitudeDeg)
      angleProblem = tr("amplitude %1° is beyond the table's %2° on %3")
                         .arg(amp)
                         .arg(limits_.maxAmplitudeDeg)
                         .arg(axis);
    else if (std::abs(centre) + amp > maxPositionDeg_)
      angleProblem = tr("the angle leaves the table's ±%1°").arg(maxPositionDeg_);
    put(kAngle,
        tr("%1 … %2 (±%3)")
            .arg(centre - amp, 0, 'f', 2)
            .arg(centre + amp, 0, 'f', 2)
            .arg(QString::number(amp, 'g', 6)),
        angleProblem);
    put(kRate, tr("%1 / %2").arg(rate, 0, 'f', 2).arg(limits_.maxRateDegPerS),
        rate > limits_.maxRateDegPerS
            ? tr("peak rate beyond the table's %1 °/s on %2").arg(limits_.maxRateDegPerS).arg(axis)
            : QString());
    put(kAccel, tr("%1 / %2").arg(accel, 0, 'f', 1).arg(limits_.maxAccelDegPerS2),
        accel > limits_.maxAccelDegPerS2
            ? tr("peak acceleration beyond the table's %1 °/s² on %2").arg(limits_.maxAccelDegPerS2).arg(axis)
            : QString());
  }
}

}  // namespace fog::ui

#include "ui/commanded_motion.h"

#include <QBrush>
#include <QColor>
#include <QHeaderView>
#include <QLabel>
#include <QStringList>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace fog::ui {

namespace {

QString axisLetter(Axis a) { return QString(QChar('X' + static_cast<int>(a))); }

bool sameLimits(const TurntableLimits& a, const TurntableLimits& b) {
  return a.maxAmplitudeDeg == b.maxAmplitudeDeg && a.maxFrequencyHz == b.maxFrequencyHz &&
         a.maxRateDegPerS == b.maxRateDegPerS && a.maxAccelDegPerS2 == b.maxAccelDegPerS2;
}

QString axisLimitsText(const TurntableLimits& l) {
  return CommandedMotionTable::tr("amplitude %1°, frequency %2 Hz, peak rate %3 °/s, peak acceleration %4 °/s²")
      .arg(l.maxAmplitudeDeg)
      .arg(l.maxFrequencyHz)
      .arg(l.maxRateDegPerS)
      .arg(l.maxAccelDegPerS2);
}

}  // namespace

table::TableLimits simulatorLimits() {
  table::TableLimits l;
  l.axes.fill(TurntableLimits{});
  l.maxPositionDeg = kMaxPositionDeg;
  return l;
}

CommandedMotionTable::CommandedMotionTable(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  limitsLabel_ = new QLabel();
  limitsLabel_->setObjectName("commandedMotionLimits");
  limitsLabel_->setWordWrap(true);
  table_ = new QTableWidget(0, kColumnCount);
  table_->setObjectName("commandedMotionTable");
  // Name and unit on two lines: the six columns fit beside Configure's
  // source and session on a laptop's 1024 px.
  table_->setHorizontalHeaderLabels({tr("Point"), tr("Axis"), tr("Frequency\n(Hz)"), tr("Angle\n(°)"),
                                     tr("Peak rate\n(°/s)"), tr("Peak accel.\n(°/s²)")});
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

void CommandedMotionTable::setLimits(const table::TableLimits& limits, const QString& source) {
  limits_ = limits;
  source_ = source;
  rebuild();
}

QString CommandedMotionTable::limitsText() const { return limitsLabel_->text(); }

void CommandedMotionTable::rebuild() {
  const auto& axes = limits_.axes;
  QString perAxis;
  if (sameLimits(axes[0], axes[1]) && sameLimits(axes[0], axes[2])) {
    perAxis = tr("per axis: %1").arg(axisLimitsText(axes[0]));
  } else {
    QStringList each;
    for (std::size_t a = 0; a < axes.size(); ++a)
      each << tr("%1: %2").arg(axisLetter(static_cast<Axis>(a)), axisLimitsText(axes[a]));
    perAxis = each.join(tr("; "));
  }
  limitsLabel_->setText(tr("Limits of %1, %2; angle within ±%3°. Red: beyond a limit.")
                            .arg(source_, perAxis)
                            .arg(limits_.maxPositionDeg));
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
    const TurntableLimits& lim = limits_.axes[static_cast<std::size_t>(p.axis)];
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
    if (swing && p.frequencyHz > lim.maxFrequencyHz)
      freqProblem = tr("frequency beyond the table's %1 Hz on %2").arg(lim.maxFrequencyHz).arg(axis);
    put(kFrequency, swing ? QString::number(p.frequencyHz, 'g', 6) : tr("at rest"), freqProblem);
    // The angle the swing axis covers; the others hold their positions.
    QString angleProblem;
    if (amp > lim.maxAmplitudeDeg)
      angleProblem = tr("amplitude %1° is beyond the table's %2° on %3")
                         .arg(amp)
                         .arg(lim.maxAmplitudeDeg)
                         .arg(axis);
    else if (std::abs(centre) + amp > limits_.maxPositionDeg)
      angleProblem = tr("the angle leaves the table's ±%1°").arg(limits_.maxPositionDeg);
    // About 0 the amplitude says it all (and the column stays narrow).
    put(kAngle,
        centre == 0.0 ? tr("±%1").arg(amp, 0, 'f', 2)
                      : tr("%1 … %2").arg(centre - amp, 0, 'f', 2).arg(centre + amp, 0, 'f', 2),
        angleProblem);
    put(kRate, tr("%1 / %2").arg(rate, 0, 'f', 2).arg(lim.maxRateDegPerS),
        rate > lim.maxRateDegPerS
            ? tr("peak rate beyond the table's %1 °/s on %2").arg(lim.maxRateDegPerS).arg(axis)
            : QString());
    put(kAccel, tr("%1 / %2").arg(accel, 0, 'f', 1).arg(lim.maxAccelDegPerS2),
        accel > lim.maxAccelDegPerS2
            ? tr("peak acceleration beyond the table's %1 °/s² on %2").arg(lim.maxAccelDegPerS2).arg(axis)
            : QString());
  }
}

}  // namespace fog::ui

#include "ui/noise_view.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPen>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_grid.h>

#include "ui/core_text.h"
#include "ui/plot_data/allan_curves.h"
#include "ui/language/language.h"
#include "ui/messages.h"
#include "ui/plots/plot_interaction.h"

namespace fog::ui {


NoiseView::NoiseView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout();
  summary_ = new QLabel();
  summary_->setObjectName("noiseSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  top->addWidget(summary_, 1);
  segmentLabel_ = new QLabel(tr("Static segment"));
  top->addWidget(segmentLabel_);
  segmentCombo_ = new QComboBox();
  segmentCombo_->setObjectName("noiseSegmentCombo");
  segmentCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  top->addWidget(segmentCombo_);
  layout->addLayout(top);

  plot_ = new QwtPlot();
  plot_->setObjectName("allanPlot");
  plot_->setTitle(tr("Overlapping Allan deviation of the gyro"));
  plot_->setCanvasBackground(Qt::white);
  plot_->insertLegend(new QwtLegend(), QwtPlot::RightLegend);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(215, 215, 215), 0, Qt::DotLine));
  grid->enableXMin(true);
  grid->enableYMin(true);
  grid->setMinorPen(QPen(QColor(235, 235, 235), 0, Qt::DotLine));
  grid->attach(plot_);
  PlotInteraction::Options options;
  options.timeAxis = false;
  interaction_ = new PlotInteraction(plot_, options);

  table_ = new QTableWidget(0, 5);
  table_->setObjectName("noiseTermTable");
  table_->setHorizontalHeaderLabels({tr("noise term"), tr("value"), tr("± 1σ"), tr("unit"), tr("from τ (s)")});
  table_->verticalHeader()->setVisible(false);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);

  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(plot_);
  split->addWidget(table_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 1);
  layout->addWidget(split, 1);
  content_ = split;
  layout->addStretch(0);
  connect(segmentCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &NoiseView::showSegment);
  showMessage(tr("No noise analysis yet."));
}

QString NoiseView::summaryText() const { return summary_->text(); }

bool NoiseView::plotShown() const { return !content_->isHidden(); }

void NoiseView::showMessage(const QString& message) {
  reports_.clear();
  {
    const QSignalBlocker block(segmentCombo_);
    segmentCombo_->clear();
  }
  summary_->setText(message);
  content_->hide();
  segmentLabel_->hide();
  segmentCombo_->hide();
  plot_->detachItems(QwtPlotItem::Rtti_PlotCurve);
  plot_->detachItems(QwtPlotItem::Rtti_PlotIntervalCurve);
  plot_->replot();
  table_->setRowCount(0);
}

void NoiseView::showReports(std::vector<noise::GyroNoiseReport> reports) {
  reports_ = std::move(reports);
  content_->show();
  segmentLabel_->show();
  segmentCombo_->show();
  {
    const QSignalBlocker block(segmentCombo_);
    segmentCombo_->clear();
    for (const auto& r : reports_)
      segmentCombo_->addItem(tr("%1: %2 gyro, %3 s").arg(r.testPointIndex + 1)
                                 .arg(QString(axisName(r.gyroAxis)).toUpper())
                                 .arg(localNumber(r.durationS, 'f', 0)));
  }
  showSegment(0);
}

void NoiseView::showSegment(int position) {
  plot_->detachItems(QwtPlotItem::Rtti_PlotCurve);
  plot_->detachItems(QwtPlotItem::Rtti_PlotIntervalCurve);
  table_->setRowCount(0);
  if (position < 0 || position >= static_cast<int>(reports_.size())) {
    plot_->replot();
    return;
  }
  const auto& r = reports_[static_cast<std::size_t>(position)];
  summary_->setText(tr("<b>Test point %1, %2 gyro at rest for %3 s</b> (%4 samples, %5 frames lost): bias %6 ± %7 °/h; "
                       "Earth rate on this gyro %8 °/h; Earth-corrected bias <b>%9 °/h</b>")
                        .arg(r.testPointIndex + 1)
                        .arg(QString(axisName(r.gyroAxis)).toUpper())
                        .arg(localNumber(r.durationS, 'f', 0))
                        .arg(r.samples)
                        .arg(r.lostFrames)
                        .arg(localNumber(r.biasDegPerH, 'f', 3), localNumber(r.biasStdDegPerH, 'f', 3),
                             localNumber(r.earthRateDegPerH, 'f', 3), localNumber(r.earthCorrectedBiasDegPerH, 'f', 3)));
  // What the fit could not model is said, not hidden (a poor chi-square, a
  // term at the edge of the tau range, lost frames).
  if (!r.warnings.empty() || r.model.dof > 0) {
    QString more = tr("<br>noise model: χ²/dof %1").arg(localNumber(r.model.dof > 0 ? r.model.chiSquare / r.model.dof : 0.0, 'f', 2));
    for (const auto& w : r.warnings) more += "<br><span style='color:#a05000'>" + coreText(w).toHtmlEscaped() + "</span>";
    summary_->setText(summary_->text() + more);
  }

  drawAllanCurves(plot_, r,
                  {tr("averaging time τ (s)"), tr("Allan deviation (°/h)"), tr("confidence interval (%1 %)"),
                   tr("measured"), tr("noise model (sum)"),
                   {tr("quantisation"), tr("angle random walk"), tr("bias instability"), tr("rate random walk"),
                    tr("rate ramp"), tr("Gauss–Markov bias")}});
  plot_->setAxisAutoScale(QwtPlot::xBottom);
  plot_->setAxisAutoScale(QwtPlot::yLeft);
  plot_->replot();
  interaction_->setHome();

  for (const auto& term : r.model.terms) {
    const auto u = noise::termInGyroUnits(term);
    const int row = table_->rowCount();
    table_->insertRow(row);
    const QStringList cells = {coreText(noise::noiseTermName(term.kind)), localNumber(u.value, 'g', 4),
                               localNumber(u.stdError, 'g', 2), displayUnits(QString::fromUtf8(u.unit)),
                               tr("%1 – %2").arg(localNumber(term.tauLowS, 'g', 3), localNumber(term.tauHighS, 'g', 3))};
    for (int col = 0; col < cells.size(); ++col) table_->setItem(row, col, new QTableWidgetItem(cells[col]));
  }
}

}  // namespace fog::ui

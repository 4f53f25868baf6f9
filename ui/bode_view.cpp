#include "ui/bode_view.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPen>
#include <QScrollBar>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_grid.h>
#include <qwt_global.h>
#include <qwt_plot_legenditem.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_widget.h>

#include "ui/core_text.h"
#include "ui/language/language.h"
#include "ui/plots/plot_interaction.h"

namespace fog::ui {

namespace {

constexpr int kPColumn = 3;
constexpr int kNotesColumn = 9;
const QColor kSingle(8, 48, 107);
const QColor kA(31, 119, 180);
const QColor kB(230, 110, 0);
const QColor kDifference(90, 90, 90);

// Decimals that show a value to its uncertainty's second significant digit
// (valueWithStdText's rule).
int decimalsFor(double stdDev) {
  if (!(stdDev > 0.0) || !std::isfinite(stdDev)) return 4;
  return std::clamp(1 - static_cast<int>(std::floor(std::log10(stdDev))), 0, 8);
}

QString axisText(Axis axis) { return BodeView::tr("%1 axis").arg(QString(axisName(axis)).toUpper()); }

const analysis::ResponseAnalysis* forAxis(const std::vector<analysis::ResponseAnalysis>& responses, Axis axis) {
  for (const auto& r : responses)
    if (r.axis == axis) return &r;
  return nullptr;
}

const analysis::ResponseModelFit* chosenModel(const analysis::ResponseAnalysis& r) {
  return r.chosen >= 0 && r.chosen < static_cast<int>(r.models.size()) ? &r.models[static_cast<std::size_t>(r.chosen)]
                                                                         : nullptr;
}

// No title: the axis titles say what each plot is, and a laptop's Results
// view has no height to spare.
QwtPlot* makeBodePlot(const QString& objectName, const QString& toolTip) {
  auto* plot = new QwtPlot();
  plot->setObjectName(objectName);
  plot->setToolTip(toolTip);
  plot->setCanvasBackground(Qt::white);
  plot->setMinimumSize(200, 110);
  // A short plot: few value labels, so that they never touch.
  plot->setAxisMaxMajor(QwtPlot::yLeft, 4);
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(215, 215, 215), 0, Qt::DotLine));
  grid->enableXMin(true);
  grid->setMinorPen(QPen(QColor(235, 235, 235), 0, Qt::DotLine));
  grid->attach(plot);
  useCompactTitles(plot);
  return plot;
}

}  // namespace

BodeView::BodeView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  message_ = new QLabel();
  message_->setObjectName("bodeMessage");
  message_->setWordWrap(true);
  message_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(message_);

  content_ = new QWidget();
  auto* contentLayout = new QVBoxLayout(content_);
  contentLayout->setContentsMargins(0, 0, 0, 0);
  auto* top = new QHBoxLayout();
  axisCombo_ = new QComboBox();
  axisCombo_->setObjectName("bodeAxisCombo");
  axisCombo_->setToolTip(tr("The axis whose response is shown"));
  top->addWidget(axisCombo_);
  summary_ = new QLabel();
  summary_->setObjectName("bodeSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  top->addWidget(summary_, 1);
  contentLayout->addLayout(top);

  magnitudePlot_ = makeBodePlot("bodeMagnitudePlot", tr("Magnitude of gyro angle / table angle at each test frequency, ±1σ, and the chosen model"));
  // The phase plot below carries the frequency labels for both.
  magnitudePlot_->axisScaleDraw(QwtPlot::xBottom)->enableComponent(QwtAbstractScaleDraw::Labels, false);
  phasePlot_ = makeBodePlot("bodePhasePlot", tr("Phase of gyro angle / table angle (negative: the gyro lags), ±1σ, and the chosen model"));
  // One legend, inside the magnitude plot's canvas (where a lagging gyro's
  // points are not: low frequencies, low values): the view's width goes to
  // the plots.
  auto* legend = new QwtPlotLegendItem();
#if QWT_VERSION >= 0x060200
  legend->setAlignmentInCanvas(Qt::AlignBottom | Qt::AlignLeft);
#else
  legend->setAlignment(Qt::AlignBottom | Qt::AlignLeft);
#endif
  legend->setMaxColumns(3);
  legend->setBackgroundBrush(QColor(255, 255, 255, 215));
  legend->setBorderPen(QPen(QColor(190, 190, 190)));
  legend->setBorderRadius(2);
  QFont legendFont = font();
  legendFont.setPointSizeF(legendFont.pointSizeF() * 0.85);
  legend->setFont(legendFont);
  legend->attach(magnitudePlot_);
  PlotInteraction::Options options;
  options.cursors = true;
  options.timeAxis = false;
  options.xUnit = tr("Hz");
  options.xName = QStringLiteral("f");
  options.yUnit = tr("dB");
  magnitudeInteraction_ = new PlotInteraction(magnitudePlot_, options);
  options.yUnit = QStringLiteral("°");
  phaseInteraction_ = new PlotInteraction(phasePlot_, options);
  // One frequency axis: zoom or pan one plot, the other follows.
  auto* link = new TimeAxisLink(this);
  link->add(magnitudeInteraction_);
  link->add(phaseInteraction_);
  for (auto [interaction, part] : {std::pair{magnitudeInteraction_, BodePart::kMagnitudeDb},
                                   std::pair{phaseInteraction_, BodePart::kPhaseDeg}}) {
    interaction->setValuesAt([this, part = part](double f) {
      PlotInteraction::Values values;
      for (const auto& s : series_) {
        if (const double v = bodePointsAt(s.points, part, f); std::isfinite(v)) values.push_back({s.name, v});
        if (s.model) values.push_back({s.modelName, bodeModelValue(*s.model, part, f)});
      }
      return values;
    });
  }

  modelTable_ = new QTableWidget(0, 10);
  modelTable_->setObjectName("bodeModelTable");
  modelTable_->setHorizontalHeaderLabels({tr("series"), tr("model"), tr("χ²/dof"), tr("p (fit)"), tr("AIC"), tr("BIC"),
                                          tr("parameters (± 1σ)"), tr("−3 dB bandwidth"), tr("group delay"),
                                          tr("what the points cannot tell")});
  modelTable_->verticalHeader()->setVisible(false);
  modelTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  modelTable_->setSelectionBehavior(QAbstractItemView::SelectRows);
  modelTable_->setWordWrap(false);
  modelTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // The notes take the width the other columns leave (at least their
  // header's), shortened with "…", each whole in its tooltip: a note never
  // makes the table scroll sideways by thousands of pixels.
  modelTable_->horizontalHeader()->setSectionResizeMode(kNotesColumn, QHeaderView::Fixed);
  modelTable_->setTextElideMode(Qt::ElideRight);
  modelTable_->viewport()->installEventFilter(this);
  connect(modelTable_->horizontalHeader(), &QHeaderView::sectionResized, this, [this](int column) {
    if (column != kNotesColumn) fitNotesColumn();
  });
  // As tall as its rows (Compare has six) where there is room; squeezed,
  // the header and two models in view, the third a scroll away: three rows
  // made Results at 1024 x 700 scroll 17-23 px (desk test
  // resultsNeedNoScrolling), and the plots above keep their minimum.
  modelTable_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
  modelTable_->setMinimumHeight(modelTable_->horizontalHeader()->sizeHint().height() +
                                2 * modelTable_->verticalHeader()->defaultSectionSize() +
                                modelTable_->horizontalScrollBar()->sizeHint().height() + 4);

  pointTable_ = new QTableWidget(0, 9);
  pointTable_->setObjectName("bodePointTable");
  pointTable_->setHorizontalHeaderLabels({tr("series"), tr("point"), tr("f (Hz)"), tr("|H| (dB) ± 1σ"),
                                          tr("phase (°) ± 1σ"), tr("phase vs motion (°)"), tr("U (k = 2), °"),
                                          tr("U (k = 2), ms"), tr("lag (ms) ± 1σ")});
  const QString motionTip = tr("The phase against the table's motion: the phase against the stamped table angle "
                               "corrected by the table read delay (the bench constant), as a certificate states it");
  const QString expandedTip = tr("Expanded uncertainty of the phase against the table's motion, k = 2: the point's "
                                 "phase σ and the table read delay's uncertainty in quadrature, times 2");
  pointTable_->horizontalHeaderItem(4)->setToolTip(
      tr("Against the stamped table angle (−ω·lag), as the models are fitted; ±1σ"));
  pointTable_->horizontalHeaderItem(5)->setToolTip(motionTip);
  pointTable_->horizontalHeaderItem(6)->setToolTip(expandedTip);
  pointTable_->horizontalHeaderItem(7)->setToolTip(expandedTip + tr(", as a time (U / ω)"));
  pointTable_->verticalHeader()->setVisible(false);
  pointTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  pointTable_->setSelectionBehavior(QAbstractItemView::SelectRows);
  pointTable_->setWordWrap(false);
  pointTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  // The tabs take the model table's place: a tab bar more, the same rows.
  tableTabs_ = new QTabWidget();
  tableTabs_->setObjectName("bodeTableTabs");
  tableTabs_->setDocumentMode(true);
  tableTabs_->addTab(modelTable_, tr("Models"));
  tableTabs_->addTab(pointTable_, tr("Points, phase U (k = 2)"));
  tableTabs_->setTabToolTip(0, tr("Every model fitted to the points"));
  tableTabs_->setTabToolTip(1, tr("Every point with its phase against the table's motion and that phase's expanded "
                                  "uncertainty (k = 2), the table read delay's uncertainty in the budget"));

  auto* split = new QSplitter(Qt::Vertical);
  split->setObjectName("bodeSplitter");
  split->addWidget(magnitudePlot_);
  split->addWidget(phasePlot_);
  split->addWidget(tableTabs_);
  // The plots share what the table (as tall as its rows) leaves.
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  split->setStretchFactor(2, 0);
  split->setChildrenCollapsible(false);
  contentLayout->addWidget(split, 1);
  layout->addWidget(content_, 1);
  connect(axisCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &BodeView::showAxis);
  showMessage(tr("No frequency response yet."));
}

BodeView::~BodeView() {
  disconnect(modelTable_->horizontalHeader(), nullptr, this, nullptr);
  modelTable_->viewport()->removeEventFilter(this);
}

bool BodeView::plotShown() const { return !content_->isHidden(); }
QString BodeView::summaryText() const { return summary_->text(); }
QString BodeView::notesText() const {
  QStringList notes;
  for (int row = 0; row < modelTable_->rowCount(); ++row)
    if (auto* item = modelTable_->item(row, kNotesColumn); item && !item->text().isEmpty()) notes << item->text();
  return notes.join(QStringLiteral("\n"));
}

void BodeView::showMessage(const QString& message) {
  series_.clear();  // before what it points into
  a_.clear();
  b_.clear();
  magnitudeInteraction_->dataChanged();
  phaseInteraction_->dataChanged();
  {
    const QSignalBlocker block(axisCombo_);
    axisCombo_->clear();
  }
  message_->setText(message);
  message_->show();
  content_->hide();
}

void BodeView::showResponses(std::vector<analysis::ResponseAnalysis> responses, const QString& emptyReason) {
  if (responses.empty()) return showMessage(emptyReason);
  series_.clear();  // before what it points into
  a_ = std::move(responses);
  b_.clear();
  comparison_ = false;
  std::vector<int> axes;
  for (const auto& r : a_) axes.push_back(static_cast<int>(r.axis));
  showAxes(axes);
}

void BodeView::showComparison(std::vector<analysis::ResponseAnalysis> a, std::vector<analysis::ResponseAnalysis> b,
                              const QString& aName, const QString& bName, const QString& emptyReason) {
  std::vector<int> axes;
  for (const auto& r : a)
    if (forAxis(b, r.axis)) axes.push_back(static_cast<int>(r.axis));
  if (axes.empty()) return showMessage(emptyReason);
  series_.clear();  // before what it points into
  a_ = std::move(a);
  b_ = std::move(b);
  comparison_ = true;
  aName_ = aName;
  bName_ = bName;
  showAxes(axes);
}

void BodeView::showAxes(const std::vector<int>& axes) {
  message_->hide();
  content_->show();
  {
    const QSignalBlocker block(axisCombo_);
    axisCombo_->clear();
    for (int axis : axes) axisCombo_->addItem(axisText(static_cast<Axis>(axis)), axis);
  }
  axisCombo_->setVisible(axes.size() > 1);
  axisCombo_->setCurrentIndex(0);
  showAxis(0);
}

void BodeView::addModelRow(const QString& series, const analysis::ResponseModelFit& m, bool chosen, double atHz) {
  QStringList noteList;
  for (const auto& why : m.inadmissible) noteList << tr("not admissible: %1").arg(coreText(why));
  for (const auto& n : m.notes) noteList << coreText(n);
  const QString notes = noteList.join(QStringLiteral("; "));
  const int row = modelTable_->rowCount();
  modelTable_->insertRow(row);
  const QStringList cells = {
      series,
      responseModelTitle(m.kind),
      m.dof > 0 ? localNumber(m.chiSquare / m.dof, 'f', 2) : tr("—"),
      m.adequate ? localNumber(m.pValue, 'g', 2) : tr("%1 (rejected)").arg(localNumber(m.pValue, 'g', 2)),
      localNumber(m.aic, 'f', 1),
      localNumber(m.bic, 'f', 1),
      responseParametersText(m),
      m.bandwidthHz ? valueWithStdText(m.bandwidthHz->value, m.bandwidthHz->stdDev, tr("Hz")) : tr("none (flat)"),
      tr("%1 at %2 Hz").arg(valueWithStdText(m.groupDelayMs.value, m.groupDelayMs.stdDev, tr("ms")),
                            localNumber(atHz, 'g', 4)),
      notes};
  for (int col = 0; col < cells.size(); ++col) {
    auto* item = new QTableWidgetItem(cells[col]);
    item->setToolTip(col == kNotesColumn ? QStringLiteral("<p>") + noteList.join(QStringLiteral("</p><p>")).toHtmlEscaped() + QStringLiteral("</p>")
                                         : cells[col]);
    if (col == kPColumn)
      item->setToolTip(tr("The probability of a χ² this large were the model true: below %1 the model is rejected "
                          "and never chosen").arg(localNumber(analysis::kModelAdequacyP, 'g', 2)));
    if (!m.eligible()) item->setForeground(QColor(150, 150, 150));
    if (chosen) {
      if (col != kNotesColumn) item->setToolTip(tr("The model chosen: the lowest AIC; a larger model over a simpler one it contains only when it lowers χ² by 3σ for its extra parameters (9 for one, 11.83 for two)"));
      QFont bold = item->font();
      bold.setBold(true);
      item->setFont(bold);
    }
    modelTable_->setItem(row, col, item);
  }
}

void BodeView::fitNotesColumn() {
  int others = 0;
  for (int c = 0; c < kNotesColumn; ++c)
    if (!modelTable_->isColumnHidden(c)) others += modelTable_->columnWidth(c);
  const int width = std::max(modelTable_->horizontalHeader()->sectionSizeHint(kNotesColumn),
                             modelTable_->viewport()->width() - others);
  if (modelTable_->columnWidth(kNotesColumn) != width) modelTable_->setColumnWidth(kNotesColumn, width);
}

bool BodeView::eventFilter(QObject* watched, QEvent* event) {
  if (watched == modelTable_->viewport() && event->type() == QEvent::Resize) fitNotesColumn();
  return QWidget::eventFilter(watched, event);
}

void BodeView::addPointRows(const QString& series, const analysis::ResponseAnalysis& r) {
  for (const auto& p : r.points) {
    const analysis::CertifiedPhase c = analysis::certifiedPhase(p, r);
    const int row = pointTable_->rowCount();
    pointTable_->insertRow(row);
    const QStringList cells = {series,
                               QString::number(p.index + 1),
                               localNumber(p.frequencyHz, 'g', 4),
                               valueWithStdText(p.magnitudeDb, p.magnitudeDbStd),
                               valueWithStdText(p.phaseDeg, p.phaseStdDeg),
                               QString::number(c.phaseDeg, 'f', decimalsFor(c.standardDeg)),
                               localNumber(c.expandedDeg, 'g', 2),
                               localNumber(c.expandedMs, 'g', 2),
                               valueWithStdText(p.lagMs, p.lagStdMs)};
    for (int col = 0; col < cells.size(); ++col) {
      auto* item = new QTableWidgetItem(cells[col]);
      if (col >= 2) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      item->setToolTip(col >= 5 && col <= 7
                           ? tr("U (k = %1) = %2° = %3 ms: the fit's σ %4° and the table read delay's %5° (its "
                                "uncertainty %6 ms of the read delay %7 ms) in quadrature")
                                 .arg(localNumber(c.coverageK, 'g', 2), localNumber(c.expandedDeg, 'g', 3),
                                      localNumber(c.expandedMs, 'g', 3), localNumber(c.fitStdDeg, 'g', 2),
                                      localNumber(c.readDelayStdDeg, 'g', 2), localNumber(r.tableReadDelayStdMs, 'g', 3),
                                      localNumber(r.tableReadDelayMs, 'g', 4))
                           : cells[col]);
      pointTable_->setItem(row, col, item);
    }
  }
}

std::optional<Axis> BodeView::shownAxis() const {
  if (!plotShown() || axisCombo_->currentIndex() < 0) return std::nullopt;
  return static_cast<Axis>(axisCombo_->currentData().toInt());
}

void BodeView::showAxis(int position) {
  if (position < 0 || position >= axisCombo_->count()) return;
  const auto axis = static_cast<Axis>(axisCombo_->itemData(position).toInt());
  series_.clear();
  modelTable_->setRowCount(0);
  pointTable_->setRowCount(0);
  QStringList summary;
  auto describe = [&](const QString& who, const analysis::ResponseAnalysis& r) {
    const auto* m = chosenModel(r);
    QString line = tr("%1%2 points, %3 – %4 Hz")
                       .arg(who.isEmpty() ? QString() : who + QStringLiteral(": "))
                       .arg(r.points.size())
                       .arg(localNumber(r.points.front().frequencyHz, 'g', 3), localNumber(r.points.back().frequencyHz, 'g', 4));
    if (m) {
      line += tr("; <b>%1</b> (chosen): group delay at %2 Hz <b>%3</b>")
                  .arg(responseModelTitle(m->kind), localNumber(r.groupDelayAtHz, 'g', 4),
                       valueWithStdText(m->groupDelayMs.value, m->groupDelayMs.stdDev, tr("ms")));
      if (m->bandwidthHz) {
        line += tr(", −3 dB bandwidth %1").arg(valueWithStdText(m->bandwidthHz->value, m->bandwidthHz->stdDev, tr("Hz")));
        if (m->bandwidthHz->value > r.points.back().frequencyHz)
          line += tr(" (extrapolated beyond the highest point, %1 Hz)").arg(localNumber(r.points.back().frequencyHz, 'g', 4));
      }
    } else {
      line += tr("; <b>no model fits</b>: the points alone are the response");
    }
    summary << line;
    if (!m) summary << coreText(r.noModelReason).toHtmlEscaped();
    for (std::size_t i = 0; i < r.models.size(); ++i)
      addModelRow(who.isEmpty() ? axisText(r.axis) : who, r.models[i], static_cast<int>(i) == r.chosen, r.groupDelayAtHz);
    addPointRows(who.isEmpty() ? axisText(r.axis) : who, r);
    for (const auto& s : r.skipped) summary << tr("model left out: %1").arg(coreText(s));
  };
  if (!comparison_) {
    const auto* r = forAxis(a_, axis);
    const auto* m = chosenModel(*r);
    series_.push_back({tr("measured ±1σ"), kSingle, r->points, m, tr("model (chosen)")});
    describe(QString(), *r);
  } else {
    const auto* a = forAxis(a_, axis);
    const auto* b = forAxis(b_, axis);
    const auto* ma = chosenModel(*a);
    const auto* mb = chosenModel(*b);
    series_.push_back({aName_, kA, a->points, ma, tr("%1 model").arg(aName_)});
    series_.push_back({bName_, kB, b->points, mb, tr("%1 model").arg(bName_)});
    auto difference = analysis::responseDifference(*a, *b);
    if (!difference.empty())
      series_.push_back({tr("%1 − %2").arg(bName_, aName_), kDifference, std::move(difference), nullptr, QString()});
    describe(aName_, *a);
    describe(bName_, *b);
    if (series_.size() < 3) summary << tr("%1 and %2 share no test frequency (within 0.5 %): no difference is drawn.").arg(aName_, bName_);
  }
  drawBodeCurves(magnitudePlot_, BodePart::kMagnitudeDb, series_, {QString(), tr("|H| (dB)")});
  drawBodeCurves(phasePlot_, BodePart::kPhaseDeg, series_, {tr("frequency (Hz)"), tr("phase (°)")});
  // The two canvases start at the same x: the value axes as wide as the
  // wider one's labels.
  for (QwtPlot* plot : {magnitudePlot_, phasePlot_}) {
    plot->axisScaleDraw(QwtPlot::yLeft)->setMinimumExtent(0);
    plot->updateAxes();
  }
  double extent = 0.0;
  for (QwtPlot* plot : {magnitudePlot_, phasePlot_})
    extent = std::max(extent, plot->axisScaleDraw(QwtPlot::yLeft)->extent(plot->axisWidget(QwtPlot::yLeft)->font()));
  for (QwtPlot* plot : {magnitudePlot_, phasePlot_}) plot->axisScaleDraw(QwtPlot::yLeft)->setMinimumExtent(extent);
  for (auto* interaction : {magnitudeInteraction_, phaseInteraction_}) {
    interaction->plot()->replot();
    interaction->setHome();
    interaction->dataChanged();
  }
  summary_->setText(summary.join(QStringLiteral("<br>")));
}

QString responseMissingText(const analysis::DelayReport& report) {
  QStringList counts;
  for (int a = 0; a < kAxisCount; ++a) {
    const auto axis = static_cast<Axis>(a);
    auto points = analysis::responsePoints(report, axis);
    if (points.empty()) continue;
    QString count = BodeView::tr("%1 axis: %2").arg(QString(axisName(axis)).toUpper()).arg(points.size());
    // Two or more points whose analysis failed: why.
    if (points.size() >= 2)
      if (auto r = analysis::analyzeResponse(std::move(points), axis, analysis::kDefaultGroupDelayAtHz); !r)
        count += BodeView::tr(" (no response: %1)").arg(coreText(r.status().message()));
    counts << count;
  }
  return BodeView::tr("No frequency response: it needs two or more test points of one axis that passed their checks, "
                      "and this result has %1. The plan preset \"Frequency response\" (run --preset response) records "
                      "20 frequencies of the X axis.")
      .arg(counts.isEmpty() ? BodeView::tr("none") : counts.join(QStringLiteral(", ")));
}

}  // namespace fog::ui

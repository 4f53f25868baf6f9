#include "ui/compare_view.h"

#include "ui/result_view.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QPushButton>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <map>
#include <qwt_date.h>
#include <qwt_date_scale_draw.h>
#include <qwt_date_scale_engine.h>
#include <qwt_interval_symbol.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_intervalcurve.h>
#include <qwt_symbol.h>
#include <qwt_text.h>

#include "ui/bode_view.h"
#include "ui/core_text.h"
#include "ui/verdict_text.h"
#include "ui/data_export.h"
#include "ui/messages.h"
#include "ui/language/language.h"
#include "ui/plots/plot_interaction.h"
#include "ui/plots/series_plot.h"

namespace fog::ui {

namespace {

// A's colours are blues, B's oranges; the trend's series cycle.
const QColor kATable(8, 48, 107), kAGyro(31, 119, 180), kBTable(140, 60, 0), kBGyro(255, 127, 14);
const QColor kSeries[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44), QColor(148, 103, 189),
                          QColor(255, 127, 14), QColor(23, 190, 207)};

QString letter(int position) { return QString(QChar('A' + std::min(position, 25))); }

QString num(double v, int decimals) { return localNumber(v, 'f', decimals); }

QTableWidget* makeTable(const QStringList& headers) {
  auto* t = new QTableWidget(0, static_cast<int>(headers.size()));
  t->setHorizontalHeaderLabels(headers);
  t->verticalHeader()->setVisible(false);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setSelectionMode(QAbstractItemView::SingleSelection);
  t->setWordWrap(false);
  t->setTextElideMode(Qt::ElideRight);
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  t->horizontalHeader()->setStretchLastSection(true);
  return t;
}

void setCell(QTableWidget* t, int row, int column, const QString& text, bool number = false) {
  auto* item = new QTableWidgetItem(text);
  item->setToolTip(text);
  item->setTextAlignment((number ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter);
  t->setItem(row, column, item);
}

QwtPlot* makePlot(const QString& title, const QString& xTitle, const QString& yTitle) {
  auto* plot = new QwtPlot();
  plot->setTitle(title);
  plot->setAxisTitle(QwtPlot::xBottom, xTitle);
  plot->setAxisTitle(QwtPlot::yLeft, yTitle);
  plot->setCanvasBackground(Qt::white);
  plot->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  plot->setMinimumSize(200, 150);
  useCompactTitles(plot);
  return plot;
}

void addGrid(QwtPlot* plot) {
  auto* grid = new QwtPlotGrid();
  grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
  grid->attach(plot);
}

// Points with ±1σ bars as one legend entry.
void addPoints(QwtPlot* plot, const QString& title, const QColor& colour, const QVector<QPointF>& points,
               const QVector<QwtIntervalSample>& bars, QwtSymbol::Style style, bool line) {
  auto* curve = new QwtPlotCurve(title);
  curve->setStyle(line ? QwtPlotCurve::Lines : QwtPlotCurve::NoCurve);
  curve->setPen(QPen(colour, 1.0, Qt::DotLine));
  curve->setSymbol(new QwtSymbol(style, QBrush(colour), QPen(colour), QSize(8, 8)));
  curve->setSamples(points);
  curve->attach(plot);
  auto* errors = new QwtPlotIntervalCurve();
  errors->setStyle(QwtPlotIntervalCurve::NoCurve);
  auto* bar = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
  bar->setPen(QPen(colour, 1.2));
  errors->setSymbol(bar);
  errors->setPen(QPen(colour, 1.2));
  errors->setSamples(bars);
  errors->setItemAttribute(QwtPlotItem::Legend, false);
  errors->attach(plot);
}

// The y range that holds every bar, with room above for nothing to touch
// the frame.
void fitY(QwtPlot* plot, double lo, double hi) {
  if (!(hi >= lo) || !std::isfinite(hi - lo)) {
    plot->setAxisAutoScale(QwtPlot::yLeft);
    return;
  }
  const double span = std::max(hi - lo, 1e-3);
  plot->setAxisScale(QwtPlot::yLeft, lo - 0.15 * span, hi + 0.15 * span);
}

}  // namespace

CompareView::CompareView(const QStringList& paths, QWidget* parent)
    : QWidget(parent), paths_(paths), outcomes_(static_cast<std::size_t>(paths.size())),
      arrived_(static_cast<std::size_t>(paths.size()), false) {
  auto* layout = new QVBoxLayout(this);

  sessionTable_ = makeTable({tr("session"), tr("file"), tr("recorded (UTC)"), tr("IMU"), tr("operator"),
                             tr("result compared")});
  sessionTable_->setObjectName("compareSessionTable");
  sessionTable_->setRowCount(static_cast<int>(paths.size()));
  for (int i = 0; i < paths.size(); ++i) {
    setCell(sessionTable_, i, 0, letter(i));
    setCell(sessionTable_, i, 1, QFileInfo(paths[i]).fileName());
    setCell(sessionTable_, i, 2, tr("loading …"));
  }
  // Up to four sessions without scrolling.
  sessionTable_->setMinimumHeight(sessionTable_->horizontalHeader()->sizeHint().height() +
                                  std::min(4, static_cast<int>(paths.size())) * sessionTable_->verticalHeader()->defaultSectionSize() +
                                  2 * sessionTable_->frameWidth() + 2);
  sessionTable_->setMaximumHeight(sessionTable_->minimumHeight());

  auto* chooser = new QHBoxLayout();
  aCombo_ = new QComboBox();
  aCombo_->setObjectName("compareA");
  bCombo_ = new QComboBox();
  bCombo_->setObjectName("compareB");
  for (int i = 0; i < paths.size(); ++i) {
    aCombo_->addItem(letter(i), i);
    bCombo_->addItem(letter(i), i);
  }
  bCombo_->setCurrentIndex(std::min(1, static_cast<int>(paths.size()) - 1));
  chooser->addWidget(new QLabel(tr("Compare")));
  chooser->addWidget(bCombo_);
  chooser->addWidget(new QLabel(tr("against")));
  chooser->addWidget(aCombo_);
  chooser->addSpacing(20);
  chooser->addWidget(new QLabel(tr("Test point")));
  pointCombo_ = new QComboBox();
  pointCombo_->setObjectName("comparePointCombo");
  pointCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  pointCombo_->setMinimumContentsLength(16);
  chooser->addWidget(pointCombo_);
  chooser->addStretch(1);
  exportButton_ = new QPushButton(tr("Export CSV…"));
  exportButton_->setObjectName("compareExportButton");
  exportButton_->setToolTip(tr("Save the rows of the comparison (each test point's IMU delay in A and B, B − A, "
                               "its σ and |B − A|/σ) as a CSV file"));
  exportButton_->setEnabled(false);
  connect(exportButton_, &QPushButton::clicked, this, [this] {
    const QString folder = QFileInfo(paths_.value(chosenB())).absolutePath();
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the comparison (CSV)"),
                                                      QDir(folder).filePath("comparison.csv"), tr("CSV file (*.csv)"));
    if (path.isEmpty()) return;
    if (const QString why = exportTo(path); !why.isEmpty())
      showMessage(this, MessageKind::kError, tr("Export the comparison (CSV)"), tr("The comparison was not saved"),
                  why);
  });
  chooser->addWidget(exportButton_);
  for (QComboBox* c : {aCombo_, bCombo_})
    connect(c, qOverload<int>(&QComboBox::activated), this, [this] { recompare(); });

  summary_ = new QLabel();
  summary_->setObjectName("compareSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  differenceTable_ = makeTable({tr("test point"), QString(), QString(), QString(), QString(), QString(), QString()});
  differenceTable_->setObjectName("differenceTable");
  differenceTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  differenceTable_->horizontalHeader()->setSectionResizeMode(6, QHeaderView::Stretch);
  differenceTable_->setMinimumSize(200, 80);

  zeroCrossingPlot_ = new SeriesPlot(tr("Zero crossing of A and B"), tr("(angle − offset) / amplitude"));
  zeroCrossingPlot_->setObjectName("compareZeroCrossingPlot");
  zeroCrossingPlot_->setTimeAxis(tr("time from each session's table-fit zero crossing (ms)"), 1e-3);
  zeroCrossingPlot_->setMinimumSize(200, 150);
  frequencyPlot_ = makePlot(tr("Lag against swing frequency"), tr("swing frequency (Hz)"), tr("lag (ms), ±1σ"));
  frequencyPlot_->setObjectName("compareFrequencyPlot");
  trendPlot_ = makePlot(tr("IMU delay against the recording date"), tr("recorded"), tr("IMU delay (ms), ±1σ"));
  trendPlot_->setObjectName("trendPlot");
  auto* dateDraw = new QwtDateScaleDraw(Qt::UTC);
  dateDraw->setDateFormat(QwtDate::Day, "yyyy-MM-dd");
  dateDraw->setDateFormat(QwtDate::Hour, "MM-dd HH:mm");
  dateDraw->setDateFormat(QwtDate::Minute, "HH:mm");
  dateDraw->setDateFormat(QwtDate::Second, "HH:mm:ss");
  trendPlot_->setAxisScaleDraw(QwtPlot::xBottom, dateDraw);
  trendPlot_->setAxisScaleEngine(QwtPlot::xBottom, new QwtDateScaleEngine(Qt::UTC));
  PlotInteraction::Options plain;
  plain.timeAxis = false;
  new PlotInteraction(frequencyPlot_, plain);
  new PlotInteraction(trendPlot_, plain);

  tabs_ = new QTabWidget();
  tabs_->setObjectName("compareTabs");
  tabs_->addTab(zeroCrossingPlot_, tr("Zero crossing"));
  tabs_->addTab(frequencyPlot_, tr("Lag vs frequency"));
  tabs_->addTab(trendPlot_, tr("Trend"));
  bodeView_ = new BodeView();
  bodeView_->setObjectName("compareBodeView");
  tabs_->addTab(bodeView_, tr("Frequency response"));

  auto* top = new QWidget();
  auto* topLayout = new QVBoxLayout(top);
  topLayout->setContentsMargins(0, 0, 0, 0);
  topLayout->addWidget(sessionTable_);
  topLayout->addLayout(chooser);
  topLayout->addWidget(summary_);
  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(top);
  split->addWidget(differenceTable_);
  split->addWidget(tabs_);
  split->setStretchFactor(0, 0);
  split->setStretchFactor(1, 1);
  split->setStretchFactor(2, 3);
  split->setCollapsible(0, false);
  layout->addWidget(split, 1);

  // One selector for every plot and the table.
  connect(pointCombo_, qOverload<int>(&QComboBox::currentIndexChanged), this, &CompareView::showComparison);
  connect(differenceTable_, &QTableWidget::currentCellChanged, this, [this](int row) {
    if (row >= 0 && row != pointCombo_->currentIndex()) pointCombo_->setCurrentIndex(row);
  });
  summary_->setText(tr("Loading the sessions …"));
}

bool CompareView::allLoaded() const { return std::all_of(arrived_.begin(), arrived_.end(), [](bool b) { return b; }); }

int CompareView::chosenA() const { return aCombo_->currentData().toInt(); }
int CompareView::chosenB() const { return bCombo_->currentData().toInt(); }

void CompareView::choose(int a, int b) {
  aCombo_->setCurrentIndex(a);
  bCombo_->setCurrentIndex(b);
  recompare();
}

QString CompareView::summary() const { return summary_->text(); }

void CompareView::setOutcome(int position, std::shared_ptr<const RunOutcome> outcome, const QString& error) {
  if (position < 0 || position >= paths_.size()) return;
  const auto i = static_cast<std::size_t>(position);
  outcomes_[i] = std::move(outcome);
  arrived_[i] = true;
  if (!outcomes_[i]) {
    setCell(sessionTable_, position, 2, tr("unreadable: %1").arg(error));
  } else {
    fillSessionRow(position);
  }
  if (allLoaded()) {
    sessionTable_->resizeColumnsToContents();
    recompare();
    showTrend();
    emit loaded();
  }
}

void CompareView::fillSessionRow(int position) {
  const RunOutcome& o = *outcomes_[static_cast<std::size_t>(position)];
  const QDateTime when = QDateTime::fromString(QString::fromStdString(o.info.createdUtc), Qt::ISODate);
  setCell(sessionTable_, position, 2,
          when.isValid() ? when.toUTC().toString("yyyy-MM-dd HH:mm:ss") : QString::fromStdString(o.info.createdUtc));
  setCell(sessionTable_, position, 3,
          QString("%1 %2").arg(QString::fromStdString(o.info.imuModel), QString::fromStdString(o.info.imuSerial))
              .trimmed());
  setCell(sessionTable_, position, 4, QString::fromStdString(o.info.operatorName));
  QString result;
  if (!o.report) {
    result = tr("no delay: %1").arg(coreText(o.report.status().message()));
  } else {
    const auto& c = o.report->constants;
    result = tr("result %1 of %2; table read %3 ± %4 ms, board %5 ms")
                 .arg(o.shownResultNumber())
                 .arg(o.results.size())
                 .arg(num(c.tableReadDelayMs, 4), num(c.tableReadDelayStdMs, 4), num(c.boardDelayMs, 4));
  }
  // The shown verdict leads (core's rule): Compare sets delays side by side,
  // it never re-judges them (a result stored INVALID stays INVALID here).
  const session::ShownVerdict v = o.shownVerdict();
  if (o.report || o.shownResult()) {
    result = (v.stored ? tr("%1 (stored, limit %2 ms) · %3") : tr("%1 (not stored, limit %2 ms) · %3"))
                 .arg(verdictWord(v.verdict), num(v.limitMs, 3), result);
    if (!o.differences.empty())
      result += tr(" · this version's analysis differs from the stored result; re-analyse to store it");
  }
  setCell(sessionTable_, position, 5, result);
  sessionTable_->item(position, 5)->setForeground(QColor(verdictColour(v.verdict)));
}

QString CompareView::exportTo(const QString& path) {
  const int a = chosenA(), b = chosenB();
  const auto& oa = outcomes_[static_cast<std::size_t>(a)];
  const auto& ob = outcomes_[static_cast<std::size_t>(b)];
  if (comparisons_.empty() || !oa || !ob || !oa->report || !ob->report)
    return tr("There is no comparison to export.");
  return writeTextFile(path, comparisonCsv(comparisons_, *oa->report, *ob->report, paths_.value(a).toStdString(),
                                           paths_.value(b).toStdString()));
}

void CompareView::recompare() {
  comparisons_.clear();
  exportButton_->setEnabled(false);
  differenceTable_->setRowCount(0);
  {
    const QSignalBlocker block(pointCombo_);
    pointCombo_->clear();
  }
  const int a = chosenA(), b = chosenB();
  const auto& oa = outcomes_[static_cast<std::size_t>(a)];
  const auto& ob = outcomes_[static_cast<std::size_t>(b)];
  if (a == b || !oa || !ob || !oa->report || !ob->report) {
    summary_->setText(a == b ? tr("Choose two different sessions.")
                             : tr("Session %1 or %2 has no delay result to compare.").arg(letter(a), letter(b)));
    showComparison(-1);
    showFrequencies();
    showResponses();
    return;
  }
  comparisons_ = compareReports(*oa->report, oa->shownVerdict(), *ob->report, ob->shownVerdict());
  exportButton_->setEnabled(!comparisons_.empty());
  differenceTable_->setHorizontalHeaderLabels({tr("test point"), tr("%1: IMU delay (ms)").arg(letter(a)),
                                               tr("%1: IMU delay (ms)").arg(letter(b)),
                                               tr("%1 − %2 (ms)").arg(letter(b), letter(a)), tr("±σ (ms)"),
                                               tr("|%1 − %2|/σ").arg(letter(b), letter(a)), QString()});
  differenceTable_->setRowCount(static_cast<int>(comparisons_.size()));
  int significant = 0, both = 0, refused = 0;
  const bool commonConstant = !comparisons_.empty() && comparisons_.front().commonTableConstant;
  for (int r = 0; r < static_cast<int>(comparisons_.size()); ++r) {
    const auto& c = comparisons_[static_cast<std::size_t>(r)];
    setCell(differenceTable_, r, 0, c.label);
    // A delay carries its verdict when it is not a pass; a refused one is
    // marked refused, and no difference is taken with it.
    auto delayCell = [&](std::optional<std::size_t> at, const session::ShownPoint& shown, double ms, double stdMs) {
      if (!at) return QString("—");
      if (!shown.vouched()) return shownNumber(shown, ms, 4);
      QString text = tr("%1 ± %2").arg(num(ms, 4), num(stdMs, 4));
      if (shown.verdict != session::ShownVerdictKind::kPass) text += " " + verdictWord(shown.verdict);
      return text;
    };
    setCell(differenceTable_, r, 1, delayCell(c.a, c.aShown, c.aMs, c.aStdMs), true);
    setCell(differenceTable_, r, 2, delayCell(c.b, c.bShown, c.bMs, c.bStdMs), true);
    if (c.comparable()) {
      ++both;
      setCell(differenceTable_, r, 3, (c.differenceMs >= 0 ? "+" : "") + num(c.differenceMs, 4), true);
      setCell(differenceTable_, r, 4, num(c.differenceStdMs, 4), true);
      setCell(differenceTable_, r, 5, num(c.significance, 1), true);
      if (c.significant()) ++significant;
      setCell(differenceTable_, r, 6,
              c.significant() ? tr("differs (more than 2σ)") : tr("consistent (within 2σ)"));
      if (c.significant())
        for (int col = 3; col <= 6; ++col) differenceTable_->item(r, col)->setForeground(QColor(176, 0, 0));
    } else if (c.both()) {
      ++refused;
      const bool aRefused = !c.aShown.vouched();
      setCell(differenceTable_, r, 6,
              tr("not compared: %1's delay is refused (%2)")
                  .arg(aRefused ? letter(a) : letter(b), refusalText(aRefused ? c.aShown : c.bShown)));
      differenceTable_->item(r, 6)->setForeground(QColor(verdictColour(aRefused ? c.aShown.verdict : c.bShown.verdict)));
    } else {
      setCell(differenceTable_, r, 6, c.a ? tr("only in %1").arg(letter(a)) : tr("only in %1").arg(letter(b)));
    }
    const QSignalBlocker block(pointCombo_);
    pointCombo_->addItem(c.label);
  }
  QString text = tr("%1 against %2: %3 test point(s) compared, %4 differ by more than 2σ.")
                     .arg(letter(b), letter(a))
                     .arg(both)
                     .arg(significant);
  if (refused > 0)
    text += " " + tr("%1 test point(s) in both are not compared: a delay not vouched for (INVALID, INCOMPLETE) is "
                     "never subtracted.")
                      .arg(refused);
  if (both > 0)
    text += " " + (commonConstant ? tr("Both used the same table read delay: its uncertainty cancels in the "
                                       "difference, σ combines the two lags' uncertainties.")
                                  : tr("The table read delays differ: σ combines the two IMU delays' uncertainties."));
  summary_->setText(text);
  showFrequencies();
  showResponses();
  if (!comparisons_.empty()) {
    pointCombo_->setCurrentIndex(0);
    showComparison(0);
  }
}

void CompareView::showComparison(int row) {
  zeroCrossingPlot_->clearCurves();
  if (row < 0 || row >= static_cast<int>(comparisons_.size())) {
    zeroCrossingPlot_->showAll();
    return;
  }
  if (differenceTable_->currentRow() != row) {
    const QSignalBlocker block(differenceTable_);
    differenceTable_->selectRow(row);
  }
  const auto& c = comparisons_[static_cast<std::size_t>(row)];
  // Each session around its own table fit's rising zero crossing, normalised:
  // the table curves coincide, the gyro curves stand apart by the lags'
  // difference.
  auto add = [this](const std::shared_ptr<const RunOutcome>& o, std::optional<std::size_t> index, const QString& name,
                    const QColor& tableColour, const QColor& gyroColour) {
    if (!o || !index || *index >= o->traces.size()) return;
    const std::shared_ptr<const TestPointTraces> traces(o, &o->traces[*index]);
    const auto& tx = traces->tableNormalised.x;
    if (tx.size() < 2) return;
    const double tc = risingZeroCrossingS(traces->tableFit, 0.5 * (tx.front() + tx.back()));
    if (!std::isfinite(tc)) return;
    const double lagMs = o->report ? o->report->points[*index].lagMs : 0.0;
    const double halfMs = std::max(5.0, 8.0 * std::abs(lagMs));
    auto window = [tc, halfMs](const Trace& t) {
      auto out = std::make_shared<Trace>();
      const auto lo = std::lower_bound(t.x.begin(), t.x.end(), tc - halfMs * 1e-3);
      const auto hi = std::upper_bound(t.x.begin(), t.x.end(), tc + halfMs * 1e-3);
      for (auto it = lo; it != hi; ++it) {
        out->x.push_back((*it - tc) * 1e3);
        out->y.push_back(t.y[static_cast<std::size_t>(it - t.x.begin())]);
      }
      return std::shared_ptr<const Trace>(std::move(out));
    };
    zeroCrossingPlot_->addData(tr("%1: table").arg(name), QPen(tableColour), window(traces->tableNormalised), true);
    zeroCrossingPlot_->addData(tr("%1: gyro").arg(name), QPen(gyroColour), window(traces->gyroNormalised), true);
    zeroCrossingPlot_->addFunction(tr("%1: gyro fit").arg(name), QPen(gyroColour, 1.5, Qt::DashLine),
                                   [traces, tc](double ms) { return traces->gyroFitNormalised(tc + ms * 1e-3); });
  };
  add(outcomes_[static_cast<std::size_t>(chosenA())], c.a, letter(chosenA()), kATable, kAGyro);
  add(outcomes_[static_cast<std::size_t>(chosenB())], c.b, letter(chosenB()), kBTable, kBGyro);
  zeroCrossingPlot_->showAll();
}

void CompareView::showFrequencies() {
  frequencyPlot_->detachItems();
  addGrid(frequencyPlot_);
  double lo = 1e300, hi = -1e300, fMax = 0.0;
  const int chosen[2] = {chosenA(), chosenB()};
  for (int k = 0; k < 2; ++k) {
    const auto& o = outcomes_[static_cast<std::size_t>(chosen[k])];
    if (!o || !o->report || (k == 1 && chosen[1] == chosen[0])) continue;
    QVector<QPointF> points;
    QVector<QwtIntervalSample> bars;
    for (const auto& p : o->report->points) {
      const double f = p.joint.frequencyHz > 0.0 ? p.joint.frequencyHz : p.nominalFrequencyHz;
      points.push_back({f, p.lagMs});
      bars.push_back(QwtIntervalSample(f, p.lagMs - p.lagStdMs, p.lagMs + p.lagStdMs));
      lo = std::min(lo, p.lagMs - p.lagStdMs);
      hi = std::max(hi, p.lagMs + p.lagStdMs);
      fMax = std::max(fMax, f);
    }
    addPoints(frequencyPlot_, letter(chosen[k]), k == 0 ? kAGyro : kBGyro, points, bars,
              k == 0 ? QwtSymbol::Ellipse : QwtSymbol::Diamond, false);
  }
  if (fMax > 0.0) frequencyPlot_->setAxisScale(QwtPlot::xBottom, 0.0, 1.15 * fMax);
  fitY(frequencyPlot_, lo, hi);
  frequencyPlot_->replot();
}

void CompareView::showResponses() {
  const int a = chosenA(), b = chosenB();
  const auto& oa = outcomes_[static_cast<std::size_t>(a)];
  const auto& ob = outcomes_[static_cast<std::size_t>(b)];
  if (a == b || !oa || !ob || !oa->report || !ob->report) {
    bodeView_->showMessage(a == b ? tr("Choose two different sessions.")
                                  : tr("Session %1 or %2 has no delay result to compare.").arg(letter(a), letter(b)));
    return;
  }
  // What each has: its axes with a response, else why none.
  auto has = [this](const RunOutcome& o) {
    QStringList axes;
    for (const auto& r : o.responses) axes << QString(axisName(r.axis)).toUpper();
    return axes.isEmpty() ? responseMissingText(*o.report)
                          : tr("a frequency response of the %1 axis").arg(axes.join(QStringLiteral(", ")));
  };
  bodeView_->showComparison(oa->responses, ob->responses, letter(a), letter(b),
                            tr("%1 and %2 have no axis with a frequency response in common. %1: %3 %2: %4")
                                .arg(letter(a), letter(b), has(*oa), has(*ob)));
}

void CompareView::showTrend() {
  trendPlot_->detachItems();
  addGrid(trendPlot_);
  // One series per test point kind, over every session with a result; a
  // delay not vouched for (INVALID, INCOMPLETE, no verdict) goes into a
  // series of its own, marked with a cross and never joined to the others.
  struct Series {
    QVector<QPointF> points;
    QVector<QwtIntervalSample> bars;
  };
  std::map<QString, Series> series, refusedSeries;
  QStringList imus;
  double lo = 1e300, hi = -1e300, t0 = 1e300, t1 = -1e300;
  for (const auto& o : outcomes_) {
    if (!o || !o->report) continue;
    const QDateTime when = QDateTime::fromString(QString::fromStdString(o->info.createdUtc), Qt::ISODate);
    if (!when.isValid()) continue;
    const double x = QwtDate::toDouble(when.toUTC());
    t0 = std::min(t0, x);
    t1 = std::max(t1, x);
    const QString imu =
        QString("%1 %2").arg(QString::fromStdString(o->info.imuModel), QString::fromStdString(o->info.imuSerial)).trimmed();
    if (!imus.contains(imu)) imus << imu;
    const session::ShownVerdict shown = o->shownVerdict();
    for (const auto& p : o->report->points) {
      const auto* sp = shown.point(p.index);
      auto& into = (sp && sp->vouched() ? series : refusedSeries)[comparisonLabel(p)];
      into.points.push_back({x, p.imuDelayMs});
      into.bars.push_back(QwtIntervalSample(x, p.imuDelayMs - p.imuDelayStdMs, p.imuDelayMs + p.imuDelayStdMs));
      lo = std::min(lo, p.imuDelayMs - p.imuDelayStdMs);
      hi = std::max(hi, p.imuDelayMs + p.imuDelayStdMs);
    }
  }
  int k = 0;
  std::map<QString, int> colourOf;
  for (auto& [label, one] : series) {
    // In date order, joined by a dotted line.
    std::vector<int> order(static_cast<std::size_t>(one.points.size()));
    for (int i = 0; i < one.points.size(); ++i) order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](int x, int y) { return one.points[x].x() < one.points[y].x(); });
    QVector<QPointF> p;
    QVector<QwtIntervalSample> b;
    for (int i : order) {
      p.push_back(one.points[i]);
      b.push_back(one.bars[i]);
    }
    colourOf[label] = k;
    addPoints(trendPlot_, label, kSeries[k++ % 6], p, b, QwtSymbol::Ellipse, true);
  }
  for (auto& [label, one] : refusedSeries) {
    const int colour = colourOf.count(label) ? colourOf[label] : k++;
    addPoints(trendPlot_, tr("%1: refused (INVALID or INCOMPLETE)").arg(label), kSeries[colour % 6], one.points,
              one.bars, QwtSymbol::XCross, false);
  }
  QwtText title(imus.size() == 1 && imus.front().isEmpty() ? tr("IMU delay against the recording date (IMU not named)")
                : imus.size() == 1 ? tr("IMU delay of %1 against the recording date").arg(imus.front())
                                 : tr("IMU delay against the recording date (%1 IMUs: %2)")
                                       .arg(imus.size())
                                       .arg(imus.join(", ")));
  QFont bold = trendPlot_->font();
  bold.setBold(true);
  title.setFont(bold);
  trendPlot_->setTitle(title);
  if (t1 >= t0 && t0 < 1e300) {
    const double pad = std::max(0.1 * (t1 - t0), 60e3);  // ms: at least a minute either side
    trendPlot_->setAxisScale(QwtPlot::xBottom, t0 - pad, t1 + pad);
  }
  fitY(trendPlot_, lo, hi);
  trendPlot_->replot();
}

}  // namespace fog::ui

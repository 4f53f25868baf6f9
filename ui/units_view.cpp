#include "ui/units_view.h"

#include <QBrush>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
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

#include "core/analysis/verdict.h"
#include "ui/core_text.h"
#include "ui/language/language.h"
#include "ui/messages.h"
#include "ui/plots/plot_interaction.h"
#include "ui/verdict_text.h"

namespace fog::ui {

using catalog::CatalogResult;

namespace {

enum UnitColumn { kSerial = 0, kModel, kLots, kBenches, kSessions, kResults, kLatest, kLatestVerdict, kUnitColumns };
enum HistoryColumn {
  kDate = 0, kResult, kBench, kOperator, kTemperature, kVerdict, kDelay, kConstants, kSoftware, kAnalysedBy,
  kHistoryColumns
};

// The catalog a target names: a folder's is its fogbench-catalog.sqlite.
QString catalogPathOf(const QString& target) {
  if (target.isEmpty() || catalog::isPostgresTarget(target.toStdString())) return target;
  if (QFileInfo(target).isDir()) return QDir(target).filePath(QString::fromUtf8(catalog::kDefaultCatalogFileName));
  return target;
}

// Runs on the thread pool: opens the catalog for this job alone and reads
// every result. A SQLite file that is not there is not made (a query never
// leaves an empty catalog where one was mistyped), as the CLI does.
std::shared_ptr<UnitsView::Loaded> readCatalog(const QString& target);

template <typename T, typename Work, typename Done>
void inBackground(QObject* owner, Work work, Done done) {
  auto* watcher = new QFutureWatcher<T>(owner);
  QObject::connect(watcher, &QFutureWatcherBase::finished, owner, [watcher, done]() {
    T result = watcher->result();
    watcher->deleteLater();
    done(result);
  });
  watcher->setFuture(QtConcurrent::run(work));
}

QString fixed(double v, int decimals) { return std::isfinite(v) ? localNumber(v, 'f', decimals) : QStringLiteral("-"); }

QString orDash(const std::string& s) { return s.empty() ? QStringLiteral("-") : QString::fromStdString(s); }

QString joined(const std::vector<std::string>& v) {
  QStringList parts;
  for (const auto& s : v) parts << QString::fromStdString(s);
  return parts.isEmpty() ? QStringLiteral("-") : parts.join(", ");
}

// A point as the history shows it: its number with σ and verdict when it
// is vouched for, else "refused (why)" and no number (shown_verdict.h).
QString pointText(const catalog::CatalogPoint& p) {
  const QString where =
      UnitsView::tr("%1 %2 Hz").arg(QString::fromStdString(p.axis), fixed(p.frequencyHz, 3));
  if (p.vouched()) {
    const int d = analysis::decimalsFor(p.imuDelayStdMs);
    return UnitsView::tr("%1: %2 ± %3 ms %4")
        .arg(where, fixed(p.imuDelayMs, d), fixed(p.imuDelayStdMs, d), verdictWord(p.verdict));
  }
  return UnitsView::tr("%1: refused (%2)")
      .arg(where, p.refusal.empty() ? verdictWord(p.verdict) : coreText(p.refusal));
}

QTableWidget* makeTable(int columns, const QStringList& headers) {
  auto* t = new QTableWidget(0, columns);
  t->setHorizontalHeaderLabels(headers);
  t->verticalHeader()->setVisible(false);
  t->setSelectionBehavior(QAbstractItemView::SelectRows);
  t->setSelectionMode(QAbstractItemView::SingleSelection);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->setWordWrap(false);
  t->setTextElideMode(Qt::ElideRight);
  t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  t->horizontalHeader()->setMinimumSectionSize(50);
  t->setMinimumSize(200, 70);
  return t;
}

QTableWidgetItem* setCell(QTableWidget* t, int row, int column, const QString& text, const QString& tip = QString()) {
  auto* item = new QTableWidgetItem(text);
  item->setToolTip(tip.isEmpty() ? text : tip);
  t->setItem(row, column, item);
  return item;
}

QwtPlot* makePlot(const QString& title, const QString& xTitle) {
  auto* plot = new QwtPlot();
  plot->setTitle(title);
  plot->setAxisTitle(QwtPlot::xBottom, xTitle);
  plot->setAxisTitle(QwtPlot::yLeft, UnitsView::tr("IMU delay (ms), ±1σ"));
  plot->setCanvasBackground(Qt::white);
  plot->insertLegend(new QwtLegend(), QwtPlot::BottomLegend);
  plot->setMinimumSize(200, 150);
  useCompactTitles(plot);
  PlotInteraction::Options plain;
  plain.timeAxis = false;
  new PlotInteraction(plot, plain);
  return plot;
}

// Points with their ±1σ bars, never joined by a line: the results are
// separate measurements, and a line would run across the refused ones.
void addPoints(QwtPlot* plot, const QString& title, const QColor& colour, const QVector<QPointF>& points,
               const QVector<QwtIntervalSample>& bars, QwtSymbol::Style style) {
  auto* curve = new QwtPlotCurve(title);
  curve->setStyle(QwtPlotCurve::NoCurve);
  curve->setSymbol(new QwtSymbol(style, QBrush(colour), QPen(colour, 1.5), QSize(8, 8)));
  curve->setSamples(points);
  curve->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true);
  curve->attach(plot);
  if (bars.isEmpty()) return;
  auto* errors = new QwtPlotIntervalCurve();
  errors->setStyle(QwtPlotIntervalCurve::NoCurve);
  auto* bar = new QwtIntervalSymbol(QwtIntervalSymbol::Bar);
  bar->setPen(QPen(colour, 1.2));
  errors->setSymbol(bar);
  errors->setSamples(bars);
  errors->setItemAttribute(QwtPlotItem::Legend, false);
  errors->attach(plot);
}

std::shared_ptr<UnitsView::Loaded> readCatalog(const QString& target) {
  auto out = std::make_shared<UnitsView::Loaded>();
  const std::string t = target.toStdString();
  if (!catalog::isPostgresTarget(t) && !QFileInfo::exists(target)) {
    out->error = UnitsView::tr("No catalog at %1 yet. Index folder… makes one from the sessions of a folder; "
                               "Open catalog… opens another.")
                     .arg(QDir::toNativeSeparators(target));
    return out;
  }
  auto db = catalog::CatalogDb::open(t);
  if (!db) {
    out->error = coreText(db.status().message());
    return out;
  }
  auto cat = catalog::Catalog::open(std::move(*db));
  if (!cat) {
    out->error = coreText(cat.status().message());
    return out;
  }
  out->describe = QString::fromStdString((*cat)->describe());
  auto results = (*cat)->results("", "", false);
  if (!results) {
    out->error = coreText(results.status().message());
    return out;
  }
  out->results = std::move(*results);
  if (auto refused = (*cat)->refusals()) out->refusedFiles = static_cast<int>(refused->size());
  out->ok = true;
  return out;
}

struct IndexOutcome {
  bool ok = false;
  QString error;
  QString describe;
  catalog::IndexReport report;
};

}  // namespace

UnitsView::UnitsView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout();
  top->addWidget(new QLabel(tr("Catalog")));
  catalogEdit_ = new QLineEdit();
  catalogEdit_->setObjectName("catalogEdit");
  catalogEdit_->setPlaceholderText(tr("a catalog file (.sqlite), a sessions folder, or postgresql://…"));
  catalogEdit_->setToolTip(tr("By default the catalog of the sessions folder (fogbench-catalog.sqlite there). "
                              "A PostgreSQL address (postgresql://host/db) shows a catalog shared by benches."));
  top->addWidget(catalogEdit_, 1);
  openCatalogButton_ = new QPushButton(tr("Open catalog…"));
  openCatalogButton_->setObjectName("openCatalogButton");
  indexButton_ = new QPushButton(tr("Index folder…"));
  indexButton_->setObjectName("indexFolderButton");
  indexButton_->setToolTip(tr("Reads the sessions under a folder into this catalog, in the background; files "
                              "unchanged since they were last indexed are not read again"));
  reloadButton_ = new QPushButton(tr("Reload"));
  reloadButton_->setObjectName("reloadCatalogButton");
  for (auto* b : {openCatalogButton_, indexButton_, reloadButton_}) top->addWidget(b);
  layout->addLayout(top);
  stateLabel_ = new QLabel();
  stateLabel_->setObjectName("catalogState");
  stateLabel_->setWordWrap(true);
  stateLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(stateLabel_);

  // Units and the lot, side by side.
  unitTable_ = makeTable(kUnitColumns, {tr("IMU serial"), tr("Model"), tr("Lots"), tr("Benches"), tr("Sessions"),
                                        tr("Results"), tr("Latest session (UTC)"), tr("Its verdict")});
  unitTable_->setObjectName("unitTable");
  unitTable_->horizontalHeader()->setSectionResizeMode(kLots, QHeaderView::Stretch);
  auto* lotBox = new QWidget();
  auto* lotLayout = new QVBoxLayout(lotBox);
  lotLayout->setContentsMargins(0, 0, 0, 0);
  auto* lotRow = new QHBoxLayout();
  lotRow->addWidget(new QLabel(tr("Lot")));
  lotCombo_ = new QComboBox();
  lotCombo_->setObjectName("lotCombo");
  lotCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  lotCombo_->setMinimumContentsLength(10);
  lotRow->addWidget(lotCombo_, 1);
  lotLayout->addLayout(lotRow);
  lotSummary_ = new QLabel();
  lotSummary_->setObjectName("lotSummary");
  lotSummary_->setWordWrap(true);
  lotSummary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  lotSummary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // A long lot (many axes) scrolls here rather than pushing the tables.
  auto* lotScroll = new QScrollArea();
  lotScroll->setObjectName("lotSummaryScroll");
  lotScroll->setWidget(lotSummary_);
  lotScroll->setWidgetResizable(true);
  lotScroll->setFrameShape(QFrame::NoFrame);
  lotLayout->addWidget(lotScroll, 1);
  auto* unitsSplit = new QSplitter(Qt::Horizontal);
  unitsSplit->setObjectName("unitsLotSplitter");
  unitsSplit->addWidget(unitTable_);
  unitsSplit->addWidget(lotBox);
  unitsSplit->setStretchFactor(0, 3);
  unitsSplit->setStretchFactor(1, 2);

  // The chosen unit's history.
  auto* historyBox = new QWidget();
  auto* historyLayout = new QVBoxLayout(historyBox);
  historyLayout->setContentsMargins(0, 0, 0, 0);
  auto* historyRow = new QHBoxLayout();
  historyTitle_ = new QLabel();
  historyTitle_->setObjectName("historyTitle");
  historyTitle_->setWordWrap(true);
  historyRow->addWidget(historyTitle_, 1);
  openButton_ = new QPushButton(tr("Open in Results"));
  openButton_->setObjectName("openResultButton");
  openButton_->setToolTip(tr("Opens the chosen result's session read-only in Results (double-click a row does "
                             "the same); Results shows its newest result, the others are chosen there"));
  historyRow->addWidget(openButton_);
  historyLayout->addLayout(historyRow);
  historyTable_ = makeTable(kHistoryColumns, {tr("Session (UTC)"), tr("Result"), tr("Bench"), tr("Operator"),
                                              tr("Temp. (°C)"), tr("Verdict"), tr("IMU delay per test point"),
                                              tr("Constants"), tr("Software"), tr("Analysed by")});
  historyTable_->setObjectName("historyTable");
  // The delays are what the history is for: their column is as wide as
  // they are (up to a bound, a many-point session's whole list is in the
  // tooltip) and never elided to make room for the hash or the software;
  // the table scrolls sideways instead.
  historyTable_->horizontalHeader()->setMaximumSectionSize(440);
  historyTable_->horizontalHeader()->setStretchLastSection(true);
  historyLayout->addWidget(historyTable_, 1);

  datePlot_ = makePlot(tr("IMU delay against the session date"), tr("session recorded (UTC)"));
  datePlot_->setObjectName("unitDatePlot");
  auto* dateDraw = new QwtDateScaleDraw(Qt::UTC);
  dateDraw->setDateFormat(QwtDate::Day, "yyyy-MM-dd");
  dateDraw->setDateFormat(QwtDate::Week, "yyyy-MM-dd");  // a date, not "W42 2026"
  dateDraw->setDateFormat(QwtDate::Month, "yyyy-MM");
  dateDraw->setDateFormat(QwtDate::Hour, "MM-dd HH:mm");
  dateDraw->setDateFormat(QwtDate::Minute, "HH:mm");
  dateDraw->setDateFormat(QwtDate::Second, "HH:mm:ss");
  datePlot_->setAxisScaleDraw(QwtPlot::xBottom, dateDraw);
  datePlot_->setAxisScaleEngine(QwtPlot::xBottom, new QwtDateScaleEngine(Qt::UTC));
  datePlot_->setAxisMaxMajor(QwtPlot::xBottom, 4);  // whole dates, side by side at 1024 px
  temperaturePlot_ = makePlot(tr("IMU delay against the IMU temperature"), tr("mean IMU temperature (°C)"));
  temperaturePlot_->setObjectName("unitTemperaturePlot");
  auto* plots = new QSplitter(Qt::Horizontal);
  plots->setObjectName("unitPlotsSplitter");
  plots->addWidget(datePlot_);
  plots->addWidget(temperaturePlot_);
  plots->setSizes({1000, 1000});  // halves, whatever the legends' widths

  auto* split = new QSplitter(Qt::Vertical);
  split->setObjectName("unitsSplitter");
  split->addWidget(unitsSplit);
  split->addWidget(historyBox);
  split->addWidget(plots);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 3);
  split->setStretchFactor(2, 5);
  split->setChildrenCollapsible(false);
  layout->addWidget(split, 1);

  progressTimer_ = new QTimer(this);
  progressTimer_->setInterval(150);
  connect(progressTimer_, &QTimer::timeout, this, [this] {
    if (!indexing_) return;
    const int total = indexing_->total.load();
    emit statusMessage(total > 0 ? tr("Indexing %1: %2 of %3 files…")
                                       .arg(QDir::toNativeSeparators(indexedFolder_))
                                       .arg(indexing_->done.load())
                                       .arg(total)
                                 : tr("Indexing %1: looking for session files…")
                                       .arg(QDir::toNativeSeparators(indexedFolder_)));
  });

  connect(catalogEdit_, &QLineEdit::editingFinished, this, [this] {
    const QString typed = QDir::fromNativeSeparators(catalogEdit_->text().trimmed());
    if (typed != target_ && !typed.isEmpty()) setCatalog(typed);
  });
  connect(openCatalogButton_, &QPushButton::clicked, this, [this] {
    const QString start = target_.isEmpty() || catalog::isPostgresTarget(target_.toStdString())
                              ? folder_
                              : QFileInfo(target_).absolutePath();
    const QString file = QFileDialog::getOpenFileName(this, tr("Open catalog"), start,
                                                      tr("Catalogs (*.sqlite *.db);;All files (*)"));
    if (!file.isEmpty()) setCatalog(file);
  });
  connect(indexButton_, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder of sessions to index"), folder_);
    if (!dir.isEmpty()) indexFolder(dir);
  });
  connect(reloadButton_, &QPushButton::clicked, this, &UnitsView::reload);
  connect(lotCombo_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    fillUnits();
    showLotSummary();
  });
  connect(unitTable_, &QTableWidget::itemSelectionChanged, this, &UnitsView::showHistory);
  connect(historyTable_, &QTableWidget::itemSelectionChanged, this, &UnitsView::updateButtons);
  connect(historyTable_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    const QString path = historyPath(row);
    if (!path.isEmpty()) emit openSessionRequested(path);
  });
  connect(openButton_, &QPushButton::clicked, this, [this] {
    const auto rows = historyTable_->selectionModel()->selectedRows();
    if (!rows.isEmpty() && !historyPath(rows.front().row()).isEmpty())
      emit openSessionRequested(historyPath(rows.front().row()));
  });
  fillLots();
  showHistory();
  stateLabel_->setText(tr("Choose a catalog: the sessions folder's, a catalog file, or a PostgreSQL address."));
}

UnitsView::~UnitsView() = default;

void UnitsView::setSessionFolder(const QString& folder) {
  folder_ = folder;
  if (followsFolder_ && !folder.isEmpty()) {
    const QString target = catalogPathOf(QDir(folder).filePath(QString::fromUtf8(catalog::kDefaultCatalogFileName)));
    if (target != target_) {
      target_ = target;
      catalogEdit_->setText(QDir::toNativeSeparators(target_));
      reload();
    }
  }
}

void UnitsView::setCatalog(const QString& target) {
  target_ = catalogPathOf(target);
  // Another catalog than the folder's stays when the folder changes.
  followsFolder_ = !folder_.isEmpty() &&
                   target_ == QDir(folder_).filePath(QString::fromUtf8(catalog::kDefaultCatalogFileName));
  catalogEdit_->setText(catalog::isPostgresTarget(target_.toStdString()) ? target_
                                                                         : QDir::toNativeSeparators(target_));
  reload();
}

void UnitsView::reload() {
  const int generation = ++generation_;
  const QString target = target_;
  if (target.isEmpty()) {
    emit loaded(false);
    return;
  }
  stateLabel_->setText(tr("Reading %1…").arg(QDir::toNativeSeparators(target)));
  inBackground<std::shared_ptr<Loaded>>(
      this, [target] { return readCatalog(target); },
      [this, generation](const std::shared_ptr<Loaded>& loaded) {
        if (generation != generation_) return;  // a newer catalog was asked for meanwhile
        showLoaded(loaded);
      });
}

void UnitsView::showLoaded(const std::shared_ptr<Loaded>& got) {
  if (!got || !got->ok) {
    results_.clear();
    stateLabel_->setText(got ? got->error : tr("The catalog could not be read."));
    stateLabel_->setStyleSheet(QStringLiteral("color: #a05000;"));
  } else {
    results_ = std::move(got->results);
    std::set<std::string> serials;
    for (const auto& r : results_) serials.insert(r.imuSerial);
    QString text = tr("%1: %2 results of %3 units.")
                       .arg(coreText(got->describe))
                       .arg(results_.size())
                       .arg(serials.size());
    if (got->refusedFiles > 0)
      text += " " + tr("%1 files refused when indexed (unreadable or damaged): `fogbench-cli catalog refused` "
                       "lists them with why.")
                        .arg(got->refusedFiles);
    stateLabel_->setText(text);
    stateLabel_->setStyleSheet(QString());
  }
  fillLots();  // keeps the chosen lot and unit when they are still there
  emit loaded(got && got->ok);
}

void UnitsView::indexFolder(const QString& folder) {
  if (indexing_) {
    emit statusMessage(tr("An indexing is under way; it ends before another starts."));
    emit indexed(false);
    return;
  }
  if (target_.isEmpty()) setCatalog(folder);
  const QString target = target_;
  const std::string dir = folder.toStdString();
  auto progress = std::make_shared<IndexProgress>();
  indexing_ = progress;
  indexedFolder_ = folder;
  indexButton_->setEnabled(false);
  progressTimer_->start();
  emit statusMessage(tr("Indexing %1: looking for session files…").arg(QDir::toNativeSeparators(folder)));
  inBackground<std::shared_ptr<IndexOutcome>>(
      this,
      [target, dir, progress] {
        auto out = std::make_shared<IndexOutcome>();
        auto db = catalog::CatalogDb::open(target.toStdString());
        if (!db) {
          out->error = QString::fromStdString(db.status().message());
          return out;
        }
        auto cat = catalog::Catalog::open(std::move(*db));
        if (!cat) {
          out->error = QString::fromStdString(cat.status().message());
          return out;
        }
        out->describe = QString::fromStdString((*cat)->describe());
        // The counts only: the GUI polls them (no call into the view from here).
        auto report = (*cat)->index({dir}, [progress](int done, int total) {
          progress->done = done;
          progress->total = total;
        });
        if (!report) {
          out->error = QString::fromStdString(report.status().message());
          return out;
        }
        out->report = std::move(*report);
        out->ok = true;
        return out;
      },
      [this, folder](const std::shared_ptr<IndexOutcome>& out) {
        indexing_.reset();
        progressTimer_->stop();
        indexButton_->setEnabled(true);
        if (!out->ok) {
          emit statusMessage(tr("Indexing %1 failed").arg(QDir::toNativeSeparators(folder)));
          showMessage(this, MessageKind::kError, tr("Index folder"),
                      tr("Indexing %1 failed").arg(QDir::toNativeSeparators(folder)), coreText(out->error));
          emit indexed(false);
          return;
        }
        const auto& r = out->report;
        const QString line = tr("Indexed %1: %2 session files, %3 read (%4 results), %5 unchanged, %6 refused")
                                 .arg(QDir::toNativeSeparators(folder))
                                 .arg(r.filesFound)
                                 .arg(r.indexed)
                                 .arg(r.resultsStored)
                                 .arg(r.unchanged)
                                 .arg(r.refused);
        emit statusMessage(line);
        if (!r.refusals.empty()) {
          QStringList lines;
          for (const auto& [path, why] : r.refusals)
            lines << tr("%1: %2").arg(QDir::toNativeSeparators(QString::fromStdString(path)), coreText(why));
          showMessage(this, MessageKind::kInformation, tr("Index folder"),
                      tr("%1 files were refused and are not in the catalog").arg(r.refusals.size()),
                      lines.join("\n") + "\n\n" +
                          tr("A refused file is read again at the next indexing once it changes; restore a damaged "
                             "one from a backup."));
        }
        emit indexed(true);
        reload();
      });
}

void UnitsView::fillLots() {
  const QString current = lotCombo_->currentData().toString();
  std::set<std::string> lots;
  for (const auto& r : results_)
    if (!r.lot.empty()) lots.insert(r.lot);
  const QSignalBlocker block(lotCombo_);
  lotCombo_->clear();
  lotCombo_->addItem(tr("All lots"), QString());
  for (const auto& lot : lots) lotCombo_->addItem(QString::fromStdString(lot), QString::fromStdString(lot));
  const int index = lotCombo_->findData(current);
  lotCombo_->setCurrentIndex(index >= 0 ? index : 0);
  fillUnits();
  showLotSummary();
}

bool UnitsView::selectLot(const QString& lot) {
  const int index = lotCombo_->findData(lot);
  if (index < 0) return false;
  lotCombo_->setCurrentIndex(index);
  return true;
}

void UnitsView::fillUnits() {
  const QString keep = selectedSerial();
  const std::string lot = lotCombo_->currentData().toString().toStdString();
  std::vector<CatalogResult> inLot;
  for (const auto& r : results_)
    if (lot.empty() || r.lot == lot) inLot.push_back(r);
  const auto units = catalog::summariseUnits(inLot);
  const QSignalBlocker block(unitTable_);
  unitTable_->setRowCount(0);
  for (const auto& u : units) {
    const int row = unitTable_->rowCount();
    unitTable_->insertRow(row);
    setCell(unitTable_, row, kSerial, u.serial.empty() ? tr("(none)") : QString::fromStdString(u.serial))
        ->setData(Qt::UserRole, QString::fromStdString(u.serial));
    setCell(unitTable_, row, kModel, orDash(u.model));
    setCell(unitTable_, row, kLots, joined(u.lots));
    setCell(unitTable_, row, kBenches, joined(u.benches));
    setCell(unitTable_, row, kSessions, QString::number(u.sessions));
    setCell(unitTable_, row, kResults, QString::number(u.results));
    setCell(unitTable_, row, kLatest, orDash(u.latestUtc));
    // The newest session's shown verdict, as stored (never re-judged).
    auto* verdict = setCell(unitTable_, row, kLatestVerdict,
                            u.latestUtc.empty() ? QStringLiteral("-") : verdictWord(u.latestVerdict));
    if (!u.latestUtc.empty())
      verdict->setForeground(QColor(verdictColour(session::shownVerdictKind(u.latestVerdict))));
  }
  bool kept = false;
  for (int row = 0; row < unitTable_->rowCount() && !keep.isNull(); ++row)
    if (unitTable_->item(row, kSerial)->data(Qt::UserRole).toString() == keep) {
      unitTable_->selectRow(row);
      kept = true;
    }
  if (!kept) unitTable_->clearSelection();
  showHistory();
}

bool UnitsView::selectUnit(const QString& serial) {
  for (int row = 0; row < unitTable_->rowCount(); ++row)
    if (unitTable_->item(row, kSerial)->data(Qt::UserRole).toString() == serial) {
      unitTable_->selectRow(row);
      return true;
    }
  return false;
}

QString UnitsView::selectedSerial() const {
  const auto rows = unitTable_->selectionModel()->selectedRows();
  if (rows.isEmpty()) return QString();
  return unitTable_->item(rows.front().row(), kSerial)->data(Qt::UserRole).toString();
}

void UnitsView::showLotSummary() {
  const QString lot = lotCombo_->currentData().toString();
  const QString definitions =
      tr("Pass rate: %1.\nFirst-pass yield: %2.\nIMU delay mean and s: %3.\nCpk: %4.")
          .arg(coreText(catalog::kPassRateDefinition), coreText(catalog::kFirstPassYieldDefinition),
               coreText(catalog::kLotDelayDefinition), coreText(catalog::kCpkDefinition));
  lotSummary_->setToolTip(definitions);
  if (lot.isEmpty()) {
    lotSummary_->setText(results_.empty() ? QString()
                                          : tr("Choose a lot for its statistics: pass rate, first-pass yield, the "
                                               "IMU delay's mean and spread, Cpk against the limit."));
    return;
  }
  std::vector<CatalogResult> inLot;
  for (const auto& r : results_)
    if (r.lot == lot.toStdString()) inLot.push_back(r);
  auto stats = catalog::lotStatistics(lot.toStdString(), inLot, catalog::kNaN);
  if (!stats) {
    lotSummary_->setText(tr("Lot %1: %2").arg(lot, coreText(stats.status().message())));
    return;
  }
  const auto& s = *stats;
  auto pct = [](double f, int of) {
    if (!std::isfinite(f)) return QStringLiteral("-");
    return tr("%1 % (%2 of %3)").arg(localNumber(f * 100.0, 'f', 1)).arg(std::lround(f * of)).arg(of);
  };
  // Four short lines: the counts, the rates, the delay per axis with its
  // Cpk; the definitions are in the tooltip.
  QStringList lines;
  QString counts = tr("<b>Lot %1</b>: %2 units, %3 sessions").arg(lot.toHtmlEscaped()).arg(s.units).arg(s.sessions) +
                   " — " +
                   tr("<span style='color:%1'>%2 %3</span>, <span style='color:%4'>%5 %6</span>, "
                      "<span style='color:%7'>%8 %9</span>, %10 %11")
                       .arg(verdictColour(session::ShownVerdictKind::kPass), verdictWord(session::ShownVerdictKind::kPass))
                       .arg(s.pass)
                       .arg(verdictColour(session::ShownVerdictKind::kFail), verdictWord(session::ShownVerdictKind::kFail))
                       .arg(s.fail)
                       .arg(verdictColour(session::ShownVerdictKind::kInvalid),
                            verdictWord(session::ShownVerdictKind::kInvalid))
                       .arg(s.invalid)
                       .arg(verdictWord(session::ShownVerdictKind::kIncomplete))
                       .arg(s.incomplete);
  if (s.superseded > 0) counts += "; " + tr("%1 superseded results (re-analysed) not counted").arg(s.superseded);
  lines << counts;
  lines << tr("Pass rate: %1").arg(pct(s.passRate, s.units)) + " · " +
               tr("First-pass yield: %1").arg(pct(s.firstPassYield, s.units));
  const QString limit = std::isfinite(s.limitMs) ? tr("%1 ms (%2)").arg(fixed(s.limitMs, 3), coreText(s.limitSource))
                                                 : tr("no limit");
  for (const auto& d : s.delay)
    lines << tr("IMU delay %1: %2 points, mean %3 ms, s %4 ms, Cpk %5")
                 .arg(d.axis == "all" ? tr("all axes") : QString::fromStdString(d.axis))
                 .arg(d.n)
                 .arg(fixed(d.meanMs, 4), fixed(d.stdMs, 4), fixed(d.cpk, 2));
  if (s.delay.empty()) lines << tr("IMU delay: no vouched test point in this lot");
  lines << tr("Cpk against %1; definitions in the tooltip").arg(limit);
  lotSummary_->setText(lines.join("<br>"));
}

void UnitsView::showHistory() {
  historyTable_->setRowCount(0);
  const QString serial = selectedSerial();
  std::vector<const CatalogResult*> shown;
  if (unitTable_->selectionModel()->selectedRows().isEmpty()) {
    historyTitle_->setText(results_.empty() ? QString() : tr("Choose a unit for its history."));
    plotHistory(shown);
    updateButtons();
    return;
  }
  int superseded = 0;
  QString model;
  for (const auto& r : results_) {
    if (QString::fromStdString(r.imuSerial) != serial) continue;
    if (model.isEmpty()) model = QString::fromStdString(r.imuModel);
    if (r.shown) shown.push_back(&r);
    else ++superseded;
    const int row = historyTable_->rowCount();
    historyTable_->insertRow(row);
    setCell(historyTable_, row, kDate, orDash(r.sessionCreatedUtc),
            tr("%1\nresult analysed %2").arg(QDir::toNativeSeparators(QString::fromStdString(r.path)),
                                             orDash(r.resultCreatedUtc)))
        ->setData(Qt::UserRole, QString::fromStdString(r.path));
    setCell(historyTable_, row, kResult,
            r.shown ? tr("%1, shown").arg(r.resultNumber) : tr("%1, superseded").arg(r.resultNumber),
            r.shown ? tr("The session's shown result") : tr("A later analysis of the same session is shown"));
    setCell(historyTable_, row, kBench, orDash(r.benchId));
    setCell(historyTable_, row, kOperator, orDash(r.operatorName));
    setCell(historyTable_, row, kTemperature, fixed(r.meanTemperatureC, 1));
    auto* verdict = setCell(historyTable_, row, kVerdict, verdictWord(r.verdict),
                            r.verdictReason.empty() ? verdictWord(r.verdict) : coreText(r.verdictReason));
    verdict->setForeground(QColor(verdictColour(session::shownVerdictKind(r.verdict))));
    QStringList points;
    for (const auto& p : r.points) points << pointText(p);
    if (points.isEmpty()) points << (r.verdictReason.empty() ? QStringLiteral("-") : coreText(r.verdictReason));
    setCell(historyTable_, row, kDelay, points.join(" / "), points.join("\n"));
    setCell(historyTable_, row, kConstants, orDash(r.constantsHash),
            r.constantsJson.empty() ? QString() : QString::fromStdString(r.constantsJson));
    setCell(historyTable_, row, kSoftware, orDash(r.softwareVersion));
    setCell(historyTable_, row, kAnalysedBy, coreText(catalog::analysedByText(r)));
    if (!r.shown)
      for (int c = 0; c < kHistoryColumns; ++c)
        if (c != kVerdict) historyTable_->item(row, c)->setForeground(QColor(120, 120, 120));
  }
  const QString who = serial.isEmpty() ? tr("(no serial)") : serial;
  historyTitle_->setText(tr("<b>%1</b>%2: %3 results, oldest session first (%4 superseded by a later analysis of "
                            "their session); the plots show the shown results")
                             .arg(who.toHtmlEscaped(), model.isEmpty() ? QString() : " (" + model.toHtmlEscaped() + ")")
                             .arg(historyTable_->rowCount())
                             .arg(superseded));
  plotHistory(shown);
  updateButtons();
}

void UnitsView::plotHistory(const std::vector<const CatalogResult*>& shown) {
  // PASS and FAIL points at their value with ±σ; refused results (no
  // delay) as crosses at the foot of the value axis.
  struct Series {
    QVector<QPointF> pass, fail;
    QVector<QwtIntervalSample> passBars, failBars;
    QVector<double> refusedX;
    double x0 = 1e300, x1 = -1e300;
  };
  Series byDate, byTemperature;
  double lo = 1e300, hi = -1e300;
  int noTemperature = 0;
  for (const CatalogResult* r : shown) {
    const QDateTime when = QDateTime::fromString(QString::fromStdString(r->sessionCreatedUtc), Qt::ISODate);
    const double date = when.isValid() ? QwtDate::toDouble(when.toUTC()) : std::nan("");
    const double temperature = r->meanTemperatureC;
    if (!std::isfinite(temperature)) ++noTemperature;
    // A point not vouched for (INVALID, INCOMPLETE, no verdict) has no
    // delay to plot: it is marked as refused, as is a result without points.
    auto mark = [&](double x, Series* series) {
      if (!std::isfinite(x)) return;
      series->x0 = std::min(series->x0, x);
      series->x1 = std::max(series->x1, x);
    };
    if (r->points.empty())
      for (auto [series, x] : {std::pair{&byDate, date}, std::pair{&byTemperature, temperature}})
        if (std::isfinite(x)) {
          series->refusedX.push_back(x);
          mark(x, series);
        }
    for (const auto& p : r->points) {
      const bool vouched = p.vouched() && std::isfinite(p.imuDelayMs);
      const double sd = std::isfinite(p.imuDelayStdMs) ? p.imuDelayStdMs : 0.0;
      if (vouched) {
        lo = std::min(lo, p.imuDelayMs - sd);
        hi = std::max(hi, p.imuDelayMs + sd);
      }
      const bool pass = session::shownVerdictKind(p.verdict) == session::ShownVerdictKind::kPass;
      for (auto [series, x] : {std::pair{&byDate, date}, std::pair{&byTemperature, temperature}}) {
        if (!std::isfinite(x)) continue;
        mark(x, series);
        if (!vouched) {
          series->refusedX.push_back(x);
          continue;
        }
        (pass ? series->pass : series->fail).push_back({x, p.imuDelayMs});
        (pass ? series->passBars : series->failBars).push_back(QwtIntervalSample(x, p.imuDelayMs - sd, p.imuDelayMs + sd));
      }
    }
  }
  // The value axis: the vouched values with room; with none, an axis
  // around nothing (0 … 1 ms) where only the refused crosses sit.
  double yLo = 0.0, yHi = 1.0;
  if (hi >= lo) {
    const double span = std::max(hi - lo, 1e-3);
    yLo = lo - 0.4 * span;  // room below the values for the refused marks
    yHi = hi + 0.15 * span;
  }
  const QColor pass(verdictColour(session::ShownVerdictKind::kPass));
  const QColor fail(verdictColour(session::ShownVerdictKind::kFail));
  const QColor refused(verdictColour(session::ShownVerdictKind::kInvalid));
  for (auto [plot, series, minPad] :
       {std::tuple{datePlot_, &byDate, 60e3}, std::tuple{temperaturePlot_, &byTemperature, 0.5}}) {
    plot->detachItems();
    auto* grid = new QwtPlotGrid();
    grid->setMajorPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
    grid->attach(plot);
    if (!series->pass.isEmpty())
      addPoints(plot, verdictWord(session::ShownVerdictKind::kPass), pass, series->pass, series->passBars,
                QwtSymbol::Ellipse);
    if (!series->fail.isEmpty())
      addPoints(plot, verdictWord(session::ShownVerdictKind::kFail), fail, series->fail, series->failBars,
                QwtSymbol::Rect);
    if (!series->refusedX.isEmpty()) {
      // Not a value: a mark on the axis's foot saying a result is there.
      QVector<QPointF> marks;
      // Above the canvas's own hint line at its foot, below every value.
      const double foot = yLo + 0.12 * (yHi - yLo);
      for (double x : series->refusedX) marks.push_back({x, foot});
      addPoints(plot, tr("refused (INVALID or INCOMPLETE): no delay"), refused, marks, {}, QwtSymbol::XCross);
    }
    plot->setAxisScale(QwtPlot::yLeft, yLo, yHi);
    if (series->x1 >= series->x0) {
      const double pad = std::max(0.1 * (series->x1 - series->x0), minPad);
      plot->setAxisScale(QwtPlot::xBottom, series->x0 - pad, series->x1 + pad);
    } else {
      plot->setAxisAutoScale(QwtPlot::xBottom);
    }
  }
  // The slope the CLI states (`catalog unit`), under the temperature plot.
  std::vector<CatalogResult> unit;
  for (const CatalogResult* r : shown) unit.push_back(*r);
  const auto slope = catalog::delayAgainstTemperature(unit);
  QString footer = std::isfinite(slope.msPerC)
                       ? tr("slope %1 ± %2 µs/°C over %3 points")
                             .arg(fixed(slope.msPerC * 1000.0, 3), fixed(slope.stdMsPerC * 1000.0, 3))
                             .arg(slope.n)
                       : tr("slope: needs 3 or more vouched points at two or more temperatures (has %1)").arg(slope.n);
  if (noTemperature > 0) footer += "; " + tr("%1 results without a temperature not plotted").arg(noTemperature);
  temperaturePlot_->setFooter(shown.empty() ? QString() : footer);
  datePlot_->replot();
  temperaturePlot_->replot();
}

void UnitsView::updateButtons() {
  openButton_->setEnabled(!historyTable_->selectionModel()->selectedRows().isEmpty());
}

QString UnitsView::stateText() const { return stateLabel_->text(); }

QString UnitsView::historyPath(int row) const {
  if (row < 0 || row >= historyTable_->rowCount() || !historyTable_->item(row, kDate)) return QString();
  return historyTable_->item(row, kDate)->data(Qt::UserRole).toString();
}

}  // namespace fog::ui

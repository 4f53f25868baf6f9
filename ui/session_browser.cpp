#include "ui/session_browser.h"

#include <QColor>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>
#include <utility>

#include "core/session/session_list.h"
#include "ui/core_text.h"
#include "ui/verdict_text.h"
#include "ui/language/language.h"
#include "ui/messages.h"

namespace fog::ui {

namespace {

enum Column { kFile = 0, kCreated, kOperator, kImu, kAxes, kState, kVerdict, kLag, kImuDelay, kColumns };

// The shown (latest intact) result's verdict as stored, with which result it
// is: "INVALID (2 of 2)", "PASS (1 of 3; 2 damaged)", "damaged (1 of 1)",
// "-" — the words of `fogbench-cli sessions`.
QString verdictText(const session::SessionSummary& s) {
  if (s.results == 0) return QStringLiteral("-");
  const QString damaged = s.damagedResults > 0 ? QObject::tr("; %1 damaged").arg(s.damagedResults) : QString();
  if (s.shownResult == 0) return QObject::tr("damaged (%1 of %2)").arg(s.damagedResults).arg(s.results);
  return QObject::tr("%1 (%2 of %3%4)").arg(verdictWord(s.shown.verdict)).arg(s.shownResult).arg(s.results).arg(damaged);
}

// Each point's number with its mark: "0.4655 / refused (0.5155, INVALID)".
// Up to this many points a delay column lists them all; beyond, it gives the
// range of those vouched for, the Axes column the count (a 20-point
// response session would otherwise push the columns off screen), the list
// in the tooltip. The range is no wider than the column's header, so the
// delays stay in view at 1024 px whatever the fonts.
constexpr int kListedPoints = 3;

// The column's text and tooltip for one delay quantity of every point.
std::pair<QString, QString> delaysMs(const session::ShownVerdict& shown, double session::ShownPoint::*value) {
  QStringList parts;
  for (const auto& p : shown.points) parts << shownNumber(p, p.*value, 4);
  if (parts.isEmpty()) return {QStringLiteral("-"), QString()};
  const QString all = parts.join(" / ");
  if (parts.size() <= kListedPoints) return {all, all};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  int refused = 0;
  for (const auto& p : shown.points) {
    if (!p.vouched()) {
      ++refused;
      continue;
    }
    lo = std::min(lo, p.*value);
    hi = std::max(hi, p.*value);
  }
  const int n = static_cast<int>(parts.size());
  QString text = refused == n ? SessionBrowser::tr("all refused")
                              : QStringLiteral("%1–%2").arg(QString::number(lo, 'f', 4), QString::number(hi, 'f', 4));
  if (refused > 0 && refused < n) text += SessionBrowser::tr(", %1 refused").arg(refused);
  return {text, parts.join("\n")};
}

}  // namespace

SessionBrowser::SessionBrowser(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* top = new QHBoxLayout();
  top->addWidget(new QLabel(tr("Folder")));
  folderEdit_ = new QLineEdit();
  folderEdit_->setObjectName("sessionFolderEdit");
  top->addWidget(folderEdit_, 1);
  auto* choose = new QPushButton(tr("Choose…"));
  auto* refreshButton = new QPushButton(tr("Refresh"));
  refreshButton->setObjectName("refreshSessionsButton");
  top->addWidget(choose);
  top->addWidget(refreshButton);
  layout->addLayout(top);

  table_ = new QTableWidget(0, kColumns);
  table_->setObjectName("sessionTable");
  table_->setHorizontalHeaderLabels({tr("File"), tr("Recorded (UTC)"), tr("Operator"), tr("IMU"), tr("Axes"),
                                     tr("State"), tr("Verdict"), tr("Lag (ms)"), tr("IMU delay (ms)")});
  // The state (a damaged file's reason can be long) takes the room that is
  // left and is elided; its whole text is in the tooltip. The delays stay
  // in view.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(kState, QHeaderView::Stretch);
  table_->horizontalHeader()->setStretchLastSection(false);
  table_->horizontalHeader()->setMinimumSectionSize(60);
  table_->setWordWrap(false);
  table_->setTextElideMode(Qt::ElideRight);
  table_->verticalHeader()->setVisible(false);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSortingEnabled(false);
  layout->addWidget(table_, 1);

  auto* buttons = new QHBoxLayout();
  openButton_ = new QPushButton(tr("Open (read-only)"));
  openButton_->setObjectName("openSessionButton");
  reanalyseButton_ = new QPushButton(tr("Re-analyse with the bench constants"));
  reanalyseButton_->setObjectName("reanalyseButton");
  reanalyseButton_->setToolTip(tr("Adds a new result to the session, analysed with the bench constants, gyro signs "
                                  "and limit (Tools → Bench constants); its raw data and earlier results never change"));
  compareButton_ = new QPushButton(tr("Compare the selected"));
  compareButton_->setObjectName("compareButton");
  compareButton_->setToolTip(tr("Two sessions: their delays per test point and the difference with its significance "
                                "(A is the session chosen first, B the second); more sessions of one IMU: the delay "
                                "against the date as well"));
  importButton_ = new QPushButton(tr("Import CSV data…"));
  importButton_->setObjectName("importButton");
  importButton_->setToolTip(tr("Data from another bench (metadata.json, table.csv, gyro.csv) becomes a session here"));
  summary_ = new QLabel();
  summary_->setObjectName("sessionSummary");
  summary_->setWordWrap(true);
  for (auto* b : {openButton_, reanalyseButton_, compareButton_, importButton_}) buttons->addWidget(b);
  buttons->addStretch(1);
  layout->addLayout(buttons);
  layout->addWidget(summary_);

  connect(choose, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Session folder"), folder());
    if (!dir.isEmpty()) setFolder(dir);
  });
  connect(refreshButton, &QPushButton::clicked, this, &SessionBrowser::refresh);
  connect(folderEdit_, &QLineEdit::editingFinished, this, [this] {
    refresh();
    emit folderChanged(folder());
  });
  // The order the rows were chosen in (Compare takes the first chosen as A):
  // rows newly selected are appended in the order the selection model gives
  // them, rows deselected leave the list.
  connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          [this](const QItemSelection& selected, const QItemSelection& deselected) {
            for (const QModelIndex& index : deselected.indexes())
              if (index.column() == kFile) chosenRows_.removeAll(index.row());
            for (const QModelIndex& index : selected.indexes())
              if (index.column() == kFile && !chosenRows_.contains(index.row())) chosenRows_.append(index.row());
          });
  connect(table_, &QTableWidget::itemSelectionChanged, this, &SessionBrowser::updateButtons);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    emit openRequested(table_->item(row, kFile)->data(Qt::UserRole).toString());
  });
  connect(openButton_, &QPushButton::clicked, this, [this] {
    const auto paths = selectedPaths();
    if (!paths.isEmpty()) emit openRequested(paths.front());
  });
  connect(reanalyseButton_, &QPushButton::clicked, this, [this] {
    const auto paths = selectedPaths();
    if (!paths.isEmpty()) emit reanalyseRequested(paths.front());
  });
  connect(compareButton_, &QPushButton::clicked, this, [this] {
    const auto paths = selectedPaths();
    if (paths.size() >= 2) emit compareRequested(paths);
  });
  connect(importButton_, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder with metadata.json, table.csv, gyro.csv"));
    if (!dir.isEmpty()) emit importRequested(dir);
  });
  updateButtons();
}

void SessionBrowser::setFolder(const QString& folder) {
  folderEdit_->setText(QDir::toNativeSeparators(folder));
  refresh();
  emit folderChanged(folder);
}

QString SessionBrowser::folder() const { return QDir::fromNativeSeparators(folderEdit_->text()); }

void SessionBrowser::refresh() {
  table_->setRowCount(0);
  chosenRows_.clear();
  const QString dir = folder();
  if (dir.isEmpty()) {
    summary_->setText(tr("Choose the folder that holds the session files (.fbs)."));
    updateButtons();
    return;
  }
  if (!QFileInfo::exists(dir)) {
    // A first start: the default folder is made when the first session is
    // recorded, so a folder not made yet is no error.
    summary_->setText(tr("No sessions yet: %1 is made when the first session is recorded. "
                         "Run a test plan (Run), or choose a folder that holds session files.")
                          .arg(QDir::toNativeSeparators(dir)));
    updateButtons();
    return;
  }
  auto listing = session::listSessions(dir.toStdString());
  if (!listing) {
    summary_->setText(coreText(listing.status().message()));
    updateButtons();
    return;
  }
  int unreadable = 0;
  for (const auto& s : listing->sessions) {
    const int row = table_->rowCount();
    table_->insertRow(row);
    auto set = [&](int column, const QString& text) {
      auto* item = new QTableWidgetItem(text);
      item->setToolTip(text);
      table_->setItem(row, column, item);
    };
    set(kFile, QString::fromStdString(s.fileName));
    table_->item(row, kFile)->setData(Qt::UserRole, QString::fromStdString(s.path));
    if (!s.error.empty()) {
      ++unreadable;
      set(kState, tr("unreadable: %1").arg(coreText(s.error)));
      table_->item(row, kState)->setForeground(QColor(190, 0, 0));
      continue;
    }
    QString imu = QString::fromStdString(s.info.imuModel);
    if (!s.info.imuSerial.empty()) imu += (imu.isEmpty() ? "" : " ") + QString::fromStdString(s.info.imuSerial);
    set(kCreated, QString::fromStdString(s.info.createdUtc));
    set(kOperator, QString::fromStdString(s.info.operatorName));
    set(kImu, imu);
    QString axes = QString::fromStdString(session::axesOf(s.info.plan)).toUpper();
    // Many points: their count here, their delays as a range (delaysMs).
    if (static_cast<int>(s.shown.points.size()) > kListedPoints)
      axes += tr(", %1 points").arg(static_cast<int>(s.shown.points.size()));
    set(kAxes, axes);
    set(kState, s.complete ? tr("complete") : tr("incomplete: %1").arg(coreText(s.incompleteReason)));
    if (!s.complete) table_->item(row, kState)->setForeground(QColor(170, 90, 0));
    if (!s.rawDamage.empty()) {
      // The source of truth is damaged: said in the list, whole in the tooltip.
      set(kState, tr("%1; raw stream damaged: restore the file from a backup").arg(table_->item(row, kState)->text()));
      table_->item(row, kState)->setForeground(QColor(190, 0, 0));
      table_->item(row, kState)->setToolTip(coreText(s.rawDamage));
    }
    // The stored verdict, never a re-judgement (docs/sessions.md).
    set(kVerdict, verdictText(s));
    if (s.results > 0) table_->item(row, kVerdict)->setForeground(QColor(verdictColour(s.shown.verdict)));
    for (const auto& [column, value] : {std::pair{kLag, &session::ShownPoint::lagMs},
                                        std::pair{kImuDelay, &session::ShownPoint::imuDelayMs}}) {
      const auto [text, tooltip] = delaysMs(s.shown, value);
      set(column, text);
      table_->item(row, column)->setToolTip(tooltip);
    }
  }
  const int sessions = static_cast<int>(listing->sessions.size()) - unreadable;
  QString summary = tr("%n session(s)", nullptr, sessions);
  if (unreadable > 0) summary += "; " + tr("%n unreadable (the reason is in the State column)", nullptr, unreadable);
  summary_->setText(summary + "; " + tr("%n other file(s) skipped", nullptr, listing->skippedFiles));
  updateButtons();
}

QStringList SessionBrowser::selectedPaths() const {
  QStringList paths;
  for (int row : chosenRows_)
    if (row < table_->rowCount() && table_->item(row, kFile)->isSelected())
      paths << table_->item(row, kFile)->data(Qt::UserRole).toString();
  // Rows selected without a selection signal (none known): in row order, last.
  for (int row = 0; row < table_->rowCount(); ++row)
    if (!chosenRows_.contains(row) && table_->item(row, kFile)->isSelected())
      paths << table_->item(row, kFile)->data(Qt::UserRole).toString();
  return paths;
}

bool SessionBrowser::selectPath(const QString& path) {
  for (int row = 0; row < table_->rowCount(); ++row)
    if (table_->item(row, kFile)->data(Qt::UserRole).toString() == path) {
      table_->selectRow(row);
      return true;
    }
  return false;
}

void SessionBrowser::updateButtons() {
  const int n = static_cast<int>(selectedPaths().size());
  openButton_->setEnabled(n >= 1);
  reanalyseButton_->setEnabled(n >= 1);
  compareButton_->setEnabled(n >= 2);
}

}  // namespace fog::ui

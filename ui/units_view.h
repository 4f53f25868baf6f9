#pragma once
// Units: the lab's catalog (core/catalog/catalog.h, docs/catalog.md) seen by
// unit and by lot, the GUI's face of `fogbench-cli catalog units|unit|lot`.
//
//   catalog   by default the sessions folder's (its fogbench-catalog.sqlite);
//             "Open catalog…" picks another SQLite file, the field takes a
//             PostgreSQL address too. "Index folder…" indexes a folder into
//             it in the background (progress in the status bar, the files it
//             refused listed after).
//   units     one row per IMU serial: model, lots, benches, sessions,
//             results, the latest session's shown verdict; a lot filter, and
//             the lot's statistics (lotStatistics) when one is chosen.
//   history   the chosen unit's results, oldest session first, superseded
//             ones included and marked; per point the IMU delay ± σ when
//             vouched for, else "refused (why)". Double-click or "Open in
//             Results" asks for the session to be opened (the window does it).
//   plots     the unit's IMU delay against the date and against the mean IMU
//             temperature, shown results only: PASS and FAIL points with ±σ
//             bars, never joined by a line; an INVALID or INCOMPLETE result
//             has no delay, so it is a cross on the axis's foot in a series
//             of its own ("refused"), never a value.
//
// Every catalog read runs on the thread pool with a catalog opened for that
// job alone (a Catalog is not shared across threads); the GUI thread only
// sorts and shows what came back. A job outlives the view safely: it holds
// nothing of it.

#include <QString>
#include <QWidget>
#include <atomic>
#include <memory>
#include <vector>

#include "core/catalog/catalog.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTimer;
class QwtPlot;

namespace fog::ui {

class UnitsView : public QWidget {
  Q_OBJECT

 public:
  explicit UnitsView(QWidget* parent = nullptr);
  ~UnitsView() override;

  // The sessions folder the Sessions view shows: its catalog is the one
  // shown, unless another catalog was opened (then it stays).
  void setSessionFolder(const QString& folder);
  // A SQLite file, a folder (its fogbench-catalog.sqlite) or a PostgreSQL
  // address; read in the background (loaded() follows).
  void setCatalog(const QString& target);
  QString catalogTarget() const { return target_; }
  // Reads the catalog again (a missing SQLite file is not created).
  void reload();
  // Indexes `folder` into the catalog in the background (a SQLite catalog
  // is created when new); indexed() follows, then loaded().
  void indexFolder(const QString& folder);
  bool isIndexing() const { return indexing_ != nullptr; }

  // Chooses a lot ("" for all lots) and a unit; false when not listed.
  bool selectLot(const QString& lot);
  bool selectUnit(const QString& serial);

  QTableWidget* unitTable() const { return unitTable_; }
  QTableWidget* historyTable() const { return historyTable_; }
  QComboBox* lotCombo() const { return lotCombo_; }
  QLabel* lotSummary() const { return lotSummary_; }
  QwtPlot* datePlot() const { return datePlot_; }
  QwtPlot* temperaturePlot() const { return temperaturePlot_; }
  QString stateText() const;
  // The session file of history row `row` ("" when none).
  QString historyPath(int row) const;

  // What one background read of the catalog gives.
  struct Loaded {
    bool ok = false;
    QString error;     // why not, in the GUI's language
    QString describe;  // "SQLite catalog …" (the core's words)
    std::vector<catalog::CatalogResult> results;
    int refusedFiles = 0;
  };

 signals:
  // Every reload (and setCatalog) ends with this.
  void loaded(bool succeeded);
  // Every indexFolder ends with this.
  void indexed(bool succeeded);
  // A line for the window's status bar (indexing progress, its outcome).
  void statusMessage(const QString& message);
  // The operator asked to see this session in Results.
  void openSessionRequested(const QString& path);

 private:
  struct IndexProgress {
    std::atomic<int> done{0}, total{0};
  };
  void showLoaded(const std::shared_ptr<Loaded>& loaded);
  void fillLots();
  void fillUnits();
  void showLotSummary();
  void showHistory();
  void plotHistory(const std::vector<const catalog::CatalogResult*>& shown);
  void updateButtons();
  QString selectedSerial() const;

  QString folder_;           // the sessions folder
  QString target_;           // the catalog shown
  bool followsFolder_ = true;  // target_ is the folder's catalog
  int generation_ = 0;       // the newest load; older answers are dropped
  std::vector<catalog::CatalogResult> results_;
  std::shared_ptr<IndexProgress> indexing_;  // null when no indexing runs
  QString indexedFolder_;

  QLineEdit* catalogEdit_ = nullptr;
  QPushButton* openCatalogButton_ = nullptr;
  QPushButton* indexButton_ = nullptr;
  QPushButton* reloadButton_ = nullptr;
  QLabel* stateLabel_ = nullptr;
  QComboBox* lotCombo_ = nullptr;
  QLabel* lotSummary_ = nullptr;
  QTableWidget* unitTable_ = nullptr;
  QLabel* historyTitle_ = nullptr;
  QPushButton* openButton_ = nullptr;
  QTableWidget* historyTable_ = nullptr;
  QwtPlot* datePlot_ = nullptr;
  QwtPlot* temperaturePlot_ = nullptr;
  QTimer* progressTimer_ = nullptr;
};

}  // namespace fog::ui

#pragma once
// Compare: two or more sessions as a comparison, not as panes side by side.
//
//   sessions      one row each (letter, file, recorded, IMU, operator, the
//                 result compared), A and B chosen among them
//   differences   per test point: A's and B's IMU delay ± 1σ, B − A ± the
//                 combined σ, |d|/σ and whether it is significant
//                 (ui/session_compare.h)
//   plots         on common axes, the chosen test point selecting in every
//                 plot at once: the zero crossing of A and B (each from its
//                 own table fit's crossing, so the gyro curves stand apart by
//                 the difference in lag; measurable by cursor), the lag
//                 against frequency of both, and the trend of the IMU delay
//                 against the recording date of every session (several
//                 sessions of one IMU); the frequency response of both
//                 (Bode plot, ui/bode_view.h) with B − A at the frequencies
//                 both have.
//   Export CSV…   the differences' rows as a CSV file.

#include <QWidget>
#include <memory>
#include <vector>

#include "ui/run_outcome.h"
#include "ui/session_compare.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTabWidget;
class QwtPlot;

namespace fog::ui {

class BodeView;
class SeriesPlot;

class CompareView : public QWidget {
  Q_OBJECT

 public:
  // `paths`: the sessions compared, in this order (A, B, C, ...).
  explicit CompareView(const QStringList& paths, QWidget* parent = nullptr);

  // The outcome of session `position` arrived (null: it could not be read).
  void setOutcome(int position, std::shared_ptr<const RunOutcome> outcome, const QString& error = QString());
  bool allLoaded() const;

  // Which sessions are A and B (positions in `paths`).
  void choose(int a, int b);
  int chosenA() const;
  int chosenB() const;
  const std::vector<PointComparison>& comparisons() const { return comparisons_; }
  // The comparison row whose plots are shown.
  void showComparison(int row);

  QTableWidget* sessionTable() const { return sessionTable_; }
  QTableWidget* differenceTable() const { return differenceTable_; }
  QComboBox* pointCombo() const { return pointCombo_; }
  SeriesPlot* zeroCrossingPlot() const { return zeroCrossingPlot_; }
  QwtPlot* frequencyPlot() const { return frequencyPlot_; }
  QwtPlot* trendPlot() const { return trendPlot_; }
  BodeView* bodeView() const { return bodeView_; }
  QString summary() const;
  // The comparison's rows (A and B as chosen) as CSV (ui/data_export.h):
  // empty, or why not (a file already at `path` is then as it was). The
  // "Export CSV…" button asks for the path.
  QString exportTo(const QString& path);
  QPushButton* exportButton() const { return exportButton_; }

 signals:
  // Every session has arrived (readable or not) and the comparison is shown.
  void loaded();

 private:
  void fillSessionRow(int position);
  void recompare();
  void showFrequencies();
  void showTrend();
  void showResponses();

  QStringList paths_;
  std::vector<std::shared_ptr<const RunOutcome>> outcomes_;
  std::vector<bool> arrived_;
  std::vector<PointComparison> comparisons_;
  QTableWidget* sessionTable_ = nullptr;
  QComboBox* aCombo_ = nullptr;
  QComboBox* bCombo_ = nullptr;
  QLabel* summary_ = nullptr;
  QTableWidget* differenceTable_ = nullptr;
  QPushButton* exportButton_ = nullptr;
  QComboBox* pointCombo_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  SeriesPlot* zeroCrossingPlot_ = nullptr;
  QwtPlot* frequencyPlot_ = nullptr;
  QwtPlot* trendPlot_ = nullptr;
  BodeView* bodeView_ = nullptr;
};

}  // namespace fog::ui

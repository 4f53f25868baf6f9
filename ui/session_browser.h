#pragma once
// The session browser: the sessions in a folder (date, operator, IMU, axes,
// state, headline delay), opened read-only for review. Opening, re-analysing
// and comparing are requested through signals; the window that owns the
// browser does the (background) work, so the browser never blocks.

#include <QList>
#include <QString>
#include <QWidget>

class QLineEdit;
class QLabel;
class QPushButton;
class QTableWidget;

namespace fog::ui {

class SessionBrowser : public QWidget {
  Q_OBJECT

 public:
  explicit SessionBrowser(QWidget* parent = nullptr);

  void setFolder(const QString& folder);
  QString folder() const;
  // Reads the folder again.
  void refresh();
  QTableWidget* table() const { return table_; }
  // The paths of the selected rows, in the order they were chosen (Compare's
  // A is the first).
  QStringList selectedPaths() const;
  // Selects the row of `path`; false when it is not listed.
  bool selectPath(const QString& path);

 signals:
  void openRequested(const QString& path);
  void reanalyseRequested(const QString& path);
  // Two or more sessions, in table order.
  void compareRequested(const QStringList& paths);
  // A folder in the CSV layout of docs/formats.md to import as a session.
  void importRequested(const QString& csvFolder);
  void folderChanged(const QString& folder);

 private:
  void updateButtons();

  QLineEdit* folderEdit_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* summary_ = nullptr;
  QPushButton* openButton_ = nullptr;
  QPushButton* reanalyseButton_ = nullptr;
  QPushButton* compareButton_ = nullptr;
  QPushButton* importButton_ = nullptr;
  QList<int> chosenRows_;  // selected rows in the order they were chosen
};

}  // namespace fog::ui

#pragma once
// What an import of another bench's CSV files is told besides the files (the
// CLI's --rate-convention, --frame-period-ms and --segment): how a gyro file
// of rates was sampled when its metadata does not say, and how one
// continuous recording is cut into test points. What the import applies is
// stored with the session and every result of it (SessionInfo::imported).

#include <QDialog>

#include "core/io/csv_import.h"

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace fog::ui {

class ImportDialog : public QDialog {
  Q_OBJECT

 public:
  explicit ImportDialog(const QString& folder, QWidget* parent = nullptr);
  io::ImportOptions options() const;
  // Why the choices cannot be used (empty: they can); OK is disabled while
  // there is a problem.
  QString problem() const { return problem_; }

 private:
  void check();

  QComboBox* rateConvention_ = nullptr;
  QDoubleSpinBox* framePeriodMs_ = nullptr;
  QComboBox* segmentation_ = nullptr;
  QLineEdit* windows_ = nullptr;
  QLabel* problemLabel_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  QString problem_;
};

}  // namespace fog::ui

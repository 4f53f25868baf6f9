#include "app/gui_screenshot.h"

#include <QApplication>
#include <QPixmap>
#include <QComboBox>
#include <QTableWidget>
#include <QTimer>
#include <memory>
#include <cstdio>

#include "ui/compare_view.h"
#include "ui/main_window.h"
#include "ui/units_view.h"

namespace fog::app {
namespace {

void saveAndQuit(QWidget& window, const QString& path, bool succeeded) {
  // Let pending layout and paint events settle before grabbing.
  QTimer::singleShot(300, &window, [&window, path, succeeded] {
    const bool saved = window.grab().save(path);
    if (!saved) std::fprintf(stderr, "fogbench: cannot write '%s'\n", qPrintable(path));
    QApplication::exit(saved && succeeded ? 0 : 1);
  });
}

}  // namespace

bool screenshotNeedsRun(const ScreenshotRequest& request) {
  const QString& view = request.view;
  return !request.path.isEmpty() && !request.opensSession &&
         (view == "live" || view == "results" || view == "response" || view == "sessions" || view == "diagnosis" || view == "noise");
}

void armScreenshot(fog::ui::MainWindow& window, const ScreenshotRequest& request, bool run) {
  using fog::ui::MainWindow;
  const QString screenshot = request.path;
  const QString view = request.view;
  if (view == "configure" || (view.isEmpty() && !run && !request.opensSession)) {
    QTimer::singleShot(0, &window, [&window, screenshot] { saveAndQuit(window, screenshot, true); });
  } else if (view == "live") {
    QTimer::singleShot(static_cast<int>(request.afterS * 1000.0) + 200, &window,
                       [&window, screenshot] { saveAndQuit(window, screenshot, window.isRunning()); });
  } else if (view == "units") {
    // The catalog is read in the background; once it is there, the first
    // lot (its statistics) and the first unit (its history and plots).
    auto* units = window.unitsView();
    auto once = std::make_shared<QMetaObject::Connection>();
    *once = QObject::connect(units, &fog::ui::UnitsView::loaded, &window, [&window, units, screenshot, once](bool ok) {
      QObject::disconnect(*once);
      if (units->lotCombo()->count() > 1) units->lotCombo()->setCurrentIndex(1);
      // The unit with the most results (the first of equals): the richest history.
      int richest = -1, most = -1;
      for (int row = 0; row < units->unitTable()->rowCount(); ++row)
        if (const int n = units->unitTable()->item(row, 5)->text().toInt(); n > most) {
          most = n;
          richest = row;
        }
      if (richest >= 0) units->unitTable()->selectRow(richest);
      window.showView(MainWindow::kUnits);
      saveAndQuit(window, screenshot, ok);
    });
  } else if (view == "noise") {
    QObject::connect(&window, &MainWindow::noiseAnalysed, &window, [&window, screenshot](bool succeeded) {
      window.showView(MainWindow::kNoise);
      saveAndQuit(window, screenshot, succeeded);
    });
  } else if (view == "diagnosis") {
    // The diagnosis of the run's (or the opened session's) result.
    auto diagnose = [&window](bool succeeded) {
      if (succeeded) window.diagnoseShown();
      else QApplication::exit(1);
    };
    QObject::connect(&window, &MainWindow::runEnded, &window, diagnose);
    QObject::connect(&window, &MainWindow::sessionOpened, &window, diagnose);
    if (request.afterGiven) {
      // S seconds into the diagnosis: its progress.
      auto during = [&window, screenshot, after = request.afterS](bool succeeded) {
        if (!succeeded) return;
        QTimer::singleShot(static_cast<int>(after * 1000.0), &window,
                           [&window, screenshot] { saveAndQuit(window, screenshot, window.isDiagnosing()); });
      };
      QObject::connect(&window, &MainWindow::runEnded, &window, during);
      QObject::connect(&window, &MainWindow::sessionOpened, &window, during);
    } else {
      QObject::connect(&window, &MainWindow::diagnosisEnded, &window,
                       [&window, screenshot](bool succeeded) { saveAndQuit(window, screenshot, succeeded); });
    }
  } else {
    auto done = [&window, screenshot, view](bool succeeded) {
      if (view == "sessions") window.showView(MainWindow::kSessions);
      saveAndQuit(window, screenshot, succeeded);
    };
    QObject::connect(&window, &MainWindow::runEnded, &window, done);
    QObject::connect(&window, &MainWindow::sessionOpened, &window, done);
  }
}

void armCompareScreenshot(QWidget* compareWindow, const QString& path) {
  auto* view = compareWindow->findChild<fog::ui::CompareView*>();
  if (view == nullptr) {
    QApplication::exit(1);
    return;
  }
  QObject::connect(view, &fog::ui::CompareView::loaded, compareWindow,
                   [compareWindow, path] { saveAndQuit(*compareWindow, path, true); });
}

}  // namespace fog::app

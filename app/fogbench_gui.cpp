// fogbench: the desktop bench. Wires the application, the command line and
// the main window; everything else lives in ui/ and core/.
//
//   fogbench [--preset NAME] [--seed N] [--run] [--screenshot FILE]
//
// --screenshot FILE waits for the run (so it implies --run), saves an image
// of the window to FILE and quits; exit code 1 when the run gave no result
// or the image could not be written.

#include <QApplication>
#include <QCommandLineParser>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

#include "common/version.h"
#include "ui/bench_presets.h"
#include "ui/main_window.h"

int main(int argc, char* argv[]) {
  QApplication app(argc, argv);
  QApplication::setApplicationName("fogbench");
  QApplication::setApplicationVersion(FOG_VERSION);

  QStringList presetNames;
  for (const auto& p : fog::ui::benchPresets()) presetNames << p.name;

  QCommandLineParser parser;
  parser.setApplicationDescription("Fiber-optic gyro IMU delay test bench");
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption runOption("run", "Start the selected plan at once.");
  const QCommandLineOption presetOption(
      "preset", QString("Plan preset: %1 (default %2).").arg(presetNames.join(", "), presetNames.front()), "NAME");
  const QCommandLineOption seedOption("seed", "Simulator seed (default 1).", "N");
  const QCommandLineOption screenshotOption(
      "screenshot", "Run, save an image of the window with the results to FILE, and quit.", "FILE");
  parser.addOptions({runOption, presetOption, seedOption, screenshotOption});
  parser.process(app);

  fog::ui::MainWindow window;
  if (parser.isSet(presetOption) && !window.selectPreset(parser.value(presetOption))) {
    std::fprintf(stderr, "fogbench: unknown preset '%s' (%s)\n", qPrintable(parser.value(presetOption)),
                 qPrintable(presetNames.join(", ")));
    return 2;
  }
  if (parser.isSet(seedOption)) {
    bool ok = false;
    const int seed = parser.value(seedOption).toInt(&ok);
    if (!ok || seed < 0) {
      std::fprintf(stderr, "fogbench: --seed needs a whole number >= 0\n");
      return 2;
    }
    window.setSeed(seed);
  }

  const QString screenshot = parser.value(screenshotOption);
  if (!screenshot.isEmpty()) {
    QObject::connect(&window, &fog::ui::MainWindow::runEnded, &window, [&window, screenshot](bool succeeded) {
      // Let pending layout and paint events settle before grabbing.
      QTimer::singleShot(200, &window, [&window, screenshot, succeeded] {
        const bool saved = window.grab().save(screenshot);
        if (!saved) std::fprintf(stderr, "fogbench: cannot write '%s'\n", qPrintable(screenshot));
        QApplication::exit(saved && succeeded ? 0 : 1);
      });
    });
  }

  window.resize(1400, 900);
  window.show();
  if (parser.isSet(runOption) || !screenshot.isEmpty()) QTimer::singleShot(0, &window, &fog::ui::MainWindow::startRun);
  return QApplication::exec();
}

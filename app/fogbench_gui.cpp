// fogbench: the desktop bench. Wires the application, the command line and
// the main window; everything else lives in ui/ and core/.
//
//   fogbench [--preset NAME] [--seed N] [--speed X] [--replay SESSION.fbs]
//            [--plan PLAN.json] [--port DEV [--table remote:ADDRESS|manual]]
//            [--session-folder DIR] [--open SESSION.fbs] [--run]
//            [--compare A.fbs --compare B.fbs ...]
//            [--view configure|live|results|response|sessions|diagnosis|noise]
//            [--screenshot FILE [--screenshot-after S]] [--language system|en|zh_CN]
//
// --screenshot FILE saves an image of the view and quits once it shows what
// it is for (gui_screenshot.h says when for each view).
//
// --port DEV records a serial sampling board; with --table the bench drives
// the turntable through the plan (docs/table-control.md): remote:tcp:HOST:PORT
// or remote:DEVICE for a controller speaking the remote protocol, manual for
// one the operator sets. --speed then paces the table (> 1 only for
// fogbench-table-emu at the same --speed).
//
// --help and --version print and exit 0 without a display: they are answered
// by a QCoreApplication before any GUI is created.
//
// Choices made on the command line (--session-folder, --preset, --speed,
// --seed, --replay) are for this start only: they do not replace what the
// window remembers for the next one.

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTabWidget>
#include <QTimer>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>

#include "core/common/version.h"
#include "app/gui_screenshot.h"
#include "ui/bench_presets.h"
#include "core/common/memory.h"
#include "ui/language/language.h"
#include "ui/bode_view.h"
#include "ui/compare_view.h"
#include "ui/main_window.h"
#include "ui/result_view.h"
#include "ui/plan_editor.h"
#include "ui/window_host.h"

namespace {

int fail(const QString& message) {
  std::fprintf(stderr, "fogbench: %s\n", qPrintable(message));
  return 2;
}

struct Options {
  QStringList presetNames;
  // response: Results (or Compare) with the frequency response shown.
  QStringList views = {"configure", "live", "results", "response", "sessions", "units", "diagnosis", "noise"};
  QCommandLineOption runOption{"run", "Start the run at once."};
  QCommandLineOption presetOption{"preset", "", "NAME"};
  QCommandLineOption seedOption{"seed", "Simulator seed (default 1).", "N"};
  QCommandLineOption speedOption{"speed", "Pace: X times real time, 0 as fast as possible (default 1).", "X"};
  QCommandLineOption replayOption{"replay", "Replay this session instead of simulating.", "SESSION"};
  QCommandLineOption folderOption{"session-folder",
                                  "Record sessions into DIR (and browse it), for this start only.", "DIR"};
  QCommandLineOption openOption{"open", "Open this session for review.", "SESSION"};
  QCommandLineOption viewOption{"view", "", "NAME"};
  QCommandLineOption screenshotOption{"screenshot", "Save an image of the window to FILE and quit.", "FILE"};
  QCommandLineOption afterOption{"screenshot-after", "Live view: seconds into the run (default 3).", "S"};
  QCommandLineOption languageOption{"language", "GUI language for this run: system, en or zh_CN.", "CODE"};
  QCommandLineOption planOption{"plan", "Load this test plan (JSON, as fogbench-cli run --plan).", "FILE"};
  QCommandLineOption portOption{"port", "Record the sampling board on this serial port.", "DEV"};
  QCommandLineOption tableOption{"table",
                                 "With --port: drive the turntable, remote:tcp:HOST:PORT, remote:DEVICE or manual.",
                                 "DRIVER"};
  QCommandLineOption compareOption{"compare", "Compare these sessions (give it two or more times: A, B, ...).",
                                   "SESSION"};

  explicit Options(QCommandLineParser& parser) {
    for (const auto& p : fog::ui::benchPresets()) presetNames << p.name;
    presetOption.setDescription(
        QString("Test plan preset: %1 (default: the remembered plan).").arg(presetNames.join(", ")));
    viewOption.setDescription("Show this view: " + views.join(", ") + ".");
    parser.setApplicationDescription("Fiber-optic gyro IMU delay test bench");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({runOption, presetOption, seedOption, speedOption, replayOption, folderOption, openOption,
                       viewOption, screenshotOption, afterOption, languageOption, planOption, portOption,
                       tableOption, compareOption});
  }
};

void nameApplication() {
  QCoreApplication::setOrganizationName("fogbench");
  QCoreApplication::setApplicationName("fogbench");
  QCoreApplication::setApplicationVersion(FOG_VERSION);
}

}  // namespace

int main(int argc, char* argv[]) {
  fog::keepFreedMemoryForReuse();
  // --help and --version need no display: answer them before the GUI exists.
  for (int i = 1; i < argc; ++i)
    for (const char* flag : {"-h", "--help", "-?", "--help-all", "-v", "--version"})
      if (std::strcmp(argv[i], flag) == 0) {
        QCoreApplication core(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        Options options(parser);
        parser.process(core);  // prints and exits 0
        return 0;
      }

  // --language overrides the remembered choice for this run (tests, screenshots).
  nameApplication();
  QString language = fog::ui::languageSetting();
  for (int i = 1; i + 1 < argc; ++i)
    if (QString(argv[i]) == "--language") language = argv[i + 1];
  fog::ui::setSystemTimeLocaleFor(language);  // before the application object
  QApplication app(argc, argv);
  fog::ui::installTranslations(app, language);

  QCommandLineParser parser;
  const Options o(parser);
  parser.process(app);
  const auto& [presetNames, views, runOption, presetOption, seedOption, speedOption, replayOption, folderOption,
               openOption, viewOption, screenshotOption, afterOption, languageOption, planOption, portOption,
               tableOption, compareOption] = o;

  // The host makes the window again when the operator picks another language.
  fog::ui::WindowHost host(app);
  fog::ui::MainWindow& window = *host.window();
  // What the command line chooses is for this start only.
  window.setRemembering(false);
  if (parser.isSet(presetOption) && !window.planEditor()->loadPreset(parser.value(presetOption)))
    return fail(QString("unknown preset '%1' (%2)").arg(parser.value(presetOption), presetNames.join(", ")));
  bool ok = true;
  const int seed = parser.isSet(seedOption) ? parser.value(seedOption).toInt(&ok) : 1;
  if (!ok || seed < 0) return fail("--seed needs a whole number >= 0");
  const double speed = parser.isSet(speedOption) ? parser.value(speedOption).toDouble(&ok) : 1.0;
  if (!ok || speed < 0) return fail("--speed needs a number >= 0 (1 = real time, 0 = as fast as possible)");
  if (parser.isSet(speedOption) || parser.isSet(seedOption)) window.useSimulator(speed, seed);
  if (parser.isSet(replayOption)) window.useReplay(parser.value(replayOption), speed);
  if (parser.isSet(planOption))
    if (auto s = window.loadPlanFile(parser.value(planOption)); !s.isOk()) return fail(QString::fromStdString(s.message()));
  if (parser.isSet(tableOption) && !parser.isSet(portOption))
    return fail("--table records a real sampling board: give --port DEV (the board's port)");
  if (parser.isSet(portOption)) {
    using Driver = fog::ui::ConfigureView::TableDriver;
    Driver driver = Driver::kNone;
    QString address;
    const QString table = parser.value(tableOption);
    if (table == "manual") driver = Driver::kManual;
    else if (table.startsWith("remote:") && table.size() > 7) {
      driver = Driver::kRemote;
      address = table.mid(7);
    } else if (!table.isEmpty()) {
      return fail("--table must be manual or remote:ADDRESS (tcp:HOST:PORT or a serial device)");
    }
    window.useSerialBoard(parser.value(portOption), driver, address);
    if (parser.isSet(speedOption)) window.configureView()->setPace(speed);
  }
  if (parser.isSet(folderOption)) window.setSessionFolder(parser.value(folderOption));
  const QString view = parser.value(viewOption);
  if (!view.isEmpty() && !views.contains(view)) return fail("--view must be one of " + views.join(", "));
  const double after = parser.isSet(afterOption) ? parser.value(afterOption).toDouble(&ok) : 3.0;
  if (!ok || after < 0) return fail("--screenshot-after needs seconds >= 0");

  const QStringList compared = parser.values(compareOption);
  if (compared.size() == 1) return fail("--compare needs two or more sessions (--compare A --compare B)");
  if (!compared.isEmpty() && (parser.isSet(openOption) || parser.isSet(runOption)))
    return fail("--compare cannot be combined with --open or --run");

  fog::app::ScreenshotRequest screenshot{parser.value(screenshotOption), view, after, parser.isSet(afterOption),
                                        parser.isSet(openOption)};
  const bool run = parser.isSet(runOption) || fog::app::screenshotNeedsRun(screenshot);
  // --view response: Results on the frequency response once the result is
  // there (connected before the screenshot, which must see it).
  if (view == "response") {
    auto showResponse = [&window] {
      window.resultView()->leftTabs()->setCurrentWidget(window.resultView()->bodeView());
    };
    QObject::connect(&window, &fog::ui::MainWindow::sessionOpened, &window, showResponse);
    QObject::connect(&window, &fog::ui::MainWindow::runEnded, &window, showResponse);
  }
  if (!screenshot.path.isEmpty() && compared.isEmpty()) fog::app::armScreenshot(window, screenshot, run);

  window.setRemembering(true);

  window.showOnScreen();
  const std::map<QString, fog::ui::MainWindow::View> viewOf = {
      {"configure", fog::ui::MainWindow::kConfigure}, {"live", fog::ui::MainWindow::kLive},
      {"results", fog::ui::MainWindow::kResults},     {"response", fog::ui::MainWindow::kResults},
      {"sessions", fog::ui::MainWindow::kSessions},  {"units", fog::ui::MainWindow::kUnits},
      {"diagnosis", fog::ui::MainWindow::kDiagnosis}, {"noise", fog::ui::MainWindow::kNoise}};
  const auto asked = viewOf.find(view);
  if (asked != viewOf.end()) {
    window.showView(asked->second);
    // Opening a session shows Results when it arrives; the view asked for
    // wins (a diagnosis or noise of the session is one click away there).
    if (parser.isSet(openOption) && asked->second != fog::ui::MainWindow::kResults) {
      auto target = asked->second;
      auto once = std::make_shared<QMetaObject::Connection>();
      *once = QObject::connect(&window, &fog::ui::MainWindow::sessionOpened, &window, [&window, target, once](bool opened) {
        QObject::disconnect(*once);
        if (opened) window.showView(target);
      });
    }
  }
  if (!compared.isEmpty()) {
    const QString path = screenshot.path;
    QTimer::singleShot(0, &window, [&window, compared, path, view] {
      QWidget* compareWindow = window.compareSessions(compared);
      auto* compareView = compareWindow->findChild<fog::ui::CompareView*>();
      if (view == "response" && compareView)
        QObject::connect(compareView, &fog::ui::CompareView::loaded, compareWindow, [compareView] {
          if (auto* tabs = compareView->findChild<QTabWidget*>("compareTabs")) tabs->setCurrentWidget(compareView->bodeView());
        });
      if (!path.isEmpty()) fog::app::armCompareScreenshot(compareWindow, path);
    });
  } else if (parser.isSet(openOption)) {
    const QString path = parser.value(openOption);
    QTimer::singleShot(0, &window, [&window, path] { window.openSession(path); });
  } else if (run) {
    QTimer::singleShot(0, &window, &fog::ui::MainWindow::startRun);
  }
  return QApplication::exec();
}

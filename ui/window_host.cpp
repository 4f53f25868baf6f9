#include "ui/window_host.h"

#include <QApplication>
#include <QTimer>

#include "ui/language/language.h"
#include "ui/main_window.h"
#include "ui/configure_view.h"
#include "ui/plan_editor.h"

namespace fog::ui {

WindowHost::WindowHost(QApplication& app) : app_(app) { adopt(new MainWindow()); }

WindowHost::~WindowHost() { delete window_.data(); }

void WindowHost::adopt(MainWindow* window) {
  window_ = window;
  connect(window, &MainWindow::languageChosen, this, [this](const QString& language) {
    // Queued: the old window is deleted outside its own menu's signal.
    QTimer::singleShot(0, this, [this, language] { changeLanguage(language); });
  });
}

void WindowHost::changeLanguage(const QString& language) {
  MainWindow* old = window_;
  if (!old) return;
  const QByteArray geometry = old->saveGeometry();
  const bool visible = old->isVisible();
  const MainWindow::View view = old->currentView();
  const QString session = old->shownSessionPath();
  // What the window holds now, also what the command line gave and the
  // settings do not remember: the plan, the session folder, the bench
  // constants, the simulator's pace and seed.
  const TestPlan plan = old->planEditor()->plan();
  const QString folder = old->sessionFolder();
  const BenchConstants bench = old->benchConstants();
  const double pace = old->configureView()->pace();
  const int seed = old->configureView()->seed();
  delete old;
  const QString installed = installTranslations(app_, language);
  auto* window = new MainWindow();
  adopt(window);
  window->restoreGeometry(geometry);
  window->setRemembering(false);
  window->planEditor()->setPlan(plan);
  window->setSessionFolder(folder);
  window->setBenchConstants(bench);
  window->configureView()->setPace(pace);
  window->configureView()->setSeed(seed);
  window->setRemembering(true);
  window->showView(view);
  if (visible) window->show();
  if (!session.isEmpty()) window->openSession(session);
  emit windowReplaced(window, installed);
}

}  // namespace fog::ui

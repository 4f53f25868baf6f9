#pragma once
// Owns the bench's main window and makes it again when the operator picks
// another language (Settings → Language): every text of the window is built
// in the new language, with no restart. The new window gets the old one's
// plan, session folder, bench constants, pace and seed (also one-off choices
// of the command line), view, size and place; the session it showed is opened
// again; the rest (operator, IMU, source) comes back from the settings. A language is not
// changed during a run or a diagnosis: the window says so and keeps its own.
//
//   WindowHost host(app);
//   host.window()->show();

#include <QObject>
#include <QPointer>

class QApplication;

namespace fog::ui {

class MainWindow;

class WindowHost : public QObject {
  Q_OBJECT
 public:
  explicit WindowHost(QApplication& app);
  ~WindowHost() override;

  MainWindow* window() const { return window_; }

 signals:
  // The window was made again in `language` ("en", "zh_CN"); the old one is gone.
  void windowReplaced(fog::ui::MainWindow* window, const QString& language);

 private:
  void adopt(MainWindow* window);
  void changeLanguage(const QString& language);

  QApplication& app_;
  QPointer<MainWindow> window_;
};

}  // namespace fog::ui

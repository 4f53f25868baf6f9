#pragma once
// Owns the bench's main window and makes it again when the operator picks
// another language (Settings → Language): every text of the window is built
// in the new language, with no restart. What the window remembers (plan,
// pace, operator, IMU, session folder, size and place) comes back from the
// settings, and the session it showed is opened again. A language is not
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

#pragma once
// The GUI's --screenshot: an image of one view at the moment that view shows
// what it is for, then quit. Used for the docs' screenshots and by CI; an
// operator never needs it.
//
//   configure            at once
//   live                 afterS seconds into the run (default 3)
//   results, sessions    when the run (or --open) ended
//   units                when the catalog of the session folder was read,
//                        its first lot and the unit with the most
//                        results chosen
//   noise                when the noise analysis of that result ended
//   diagnosis            when its diagnosis ended, or afterS seconds into it
//                        when afterS was given (its progress)
//   --compare            the Compare window, once all its sessions arrived
//
// The program exits 1 when the run gave no result, the analysis failed or
// the image could not be written, 0 otherwise.

#include <QString>

namespace fog::ui {
class MainWindow;
}
class QWidget;

namespace fog::app {

struct ScreenshotRequest {
  QString path;               // the image to write (its suffix names the format)
  QString view;               // one of the above, or empty: the view shown
  double afterS = 3.0;
  bool afterGiven = false;    // --screenshot-after was given
  bool opensSession = false;  // --open: the view shows that session, not a run
};

// Whether the view needs a run to show anything (no session opened).
bool screenshotNeedsRun(const ScreenshotRequest& request);

// Arranges for the image to be taken and the program to quit; call before
// the window is shown and the run or the opening starts.
void armScreenshot(fog::ui::MainWindow& window, const ScreenshotRequest& request, bool run);

// The image of a Compare window (MainWindow::compareSessions) once its
// sessions arrived, then quit.
void armCompareScreenshot(QWidget* compareWindow, const QString& path);

}  // namespace fog::app

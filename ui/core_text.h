#pragma once
// The one translation layer for what the core says. The core speaks English:
// its messages are also what the command line prints and what session files
// keep, so they are never translated where they are made. The GUI shows them
// through coreText(), which knows the core's message templates ("closes %1 %
// of the held-out gap", "test point %1: %2", ...), the variable parts written
// %1, %2, ...:
//
//   label->setText(coreText(diagnosis.verdictReason));
//
//  - A message (each line of a multi-line text, each part of a "; "-joined
//    list) that matches a template is replaced by the template's translation
//    in the current language (QCoreApplication::translate, context
//    "core_text"), its variable parts put back, themselves translated when
//    they match a template (a channel's or an effect's name, a nested
//    reason). Runs of spaces in a template match any run of white space.
//  - What matches no template, or a template without a translation (the
//    English GUI), is shown as the core wrote it.
//  - ASCII units become the symbols the GUI uses elsewhere ("deg/s" -> "°/s",
//    displayUnits()).
// The templates live in core_text.cpp, marked for lupdate; the translation
// test requires each to be translated, and tests/ui/core_text_test.cpp runs
// the core's messages of every kind through this layer in Chinese and finds
// no English left.

#include <QString>
#include <string>

namespace fog::ui {

QString coreText(const QString& english);
QString coreText(const std::string& english);
QString coreText(const char* english);  // UTF-8

// The core's units speak ASCII ("50 deg", "deg/s^2", "deg/sqrt(h)"); the GUI
// shows the symbols it uses everywhere else ("50°", "°/s²", "°/√h").
QString displayUnits(const QString& text);

}  // namespace fog::ui

#pragma once
// The GUI's language: English (the source strings) or Simplified Chinese,
// chosen from the system locale unless the operator picked one in the menu
// (remembered in QSettings, "ui/language"). Numbers and units in the GUI are
// formatted for the chosen locale (QLocale::setDefault); files the bench
// writes (CSV, JSON, sessions) never depend on it.

#include <QString>
#include <QStringList>

class QCoreApplication;

namespace fog::ui {

// "system", "en" or "zh_CN".
QString languageSetting();
void setLanguageSetting(const QString& language);
// The language codes the GUI ships, and their names in their own language.
QStringList availableLanguages();
QString languageName(const QString& code);

// A number as the GUI shows it: in the default locale (decimal point and
// digit grouping of the chosen language).
QString localNumber(double value, char format = 'f', int precision = 4);

// Installs the translators for `language` ("system" resolves through the
// system locale), replacing those of an earlier call, and sets the default
// locale. Returns the language code in effect ("en" when nothing matched).
QString installTranslations(QCoreApplication& app, const QString& language);

}  // namespace fog::ui

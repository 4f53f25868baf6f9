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

// Qt's own widgets format some things with the system locale, not the
// default one (the file dialog's "Date Modified" column): before the
// application object exists, LC_TIME is set to the chosen language's
// (zh_CN.UTF-8 or en_US.UTF-8) when the system's is another; "system"
// leaves it. The C library's LC_TIME follows; the bench writes its own
// dates with numeric formats only (ISO 8601), so no file depends on it.
// Reads the remembered choice when `language` is empty (the organisation
// and application names must be set).
void setSystemTimeLocaleFor(QString language);

// Installs the translators for `language` ("system" resolves through the
// system locale), replacing those of an earlier call, and sets the default
// locale. Returns the language code in effect ("en" when nothing matched).
QString installTranslations(QCoreApplication& app, const QString& language);

}  // namespace fog::ui

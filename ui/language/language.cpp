#include "ui/language/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

// The .qm files are compiled into fog_ui, a static library: referencing the
// resource's initialiser keeps it in the program.
static void initTranslationResources() { Q_INIT_RESOURCE(translations); }

namespace fog::ui {

QString languageSetting() { return QSettings().value("ui/language", "system").toString(); }

void setLanguageSetting(const QString& language) { QSettings().setValue("ui/language", language); }

QStringList availableLanguages() { return {"en", "zh_CN"}; }

QString languageName(const QString& code) {
  if (code == "zh_CN") return QStringLiteral("简体中文");
  if (code == "en") return QStringLiteral("English");
  return code;
}

QString localNumber(double value, char format, int precision) { return QLocale().toString(value, format, precision); }

void setSystemTimeLocaleFor(QString language) {
  if (language.isEmpty()) language = languageSetting();
  if (language != "zh_CN" && language != "en") return;
  // From the environment as the system locale reads it (asking QLocale
  // here would fix the system locale before LC_TIME is set).
  QString system;
  for (const char* name : {"LC_ALL", "LC_TIME", "LANG"})
    if (system = qEnvironmentVariable(name); !system.isEmpty()) break;
  if (language == "zh_CN" && !system.startsWith("zh")) qputenv("LC_TIME", "zh_CN.UTF-8");
  if (language == "en" && system.startsWith("zh")) qputenv("LC_TIME", "en_US.UTF-8");
}

// Words of Qt's file dialog that Debian's Qt 6 translations lack (6.4 moved
// them to this context): ours carries them.
struct QtWord {
  const char* source;
  const char* comment;
};
[[maybe_unused]] const QtWord kQtWordsOurTranslationCarries[] = {
    QT_TRANSLATE_NOOP3("QAbstractFileIconProvider", "Folder", "All other platforms"),
    QT_TRANSLATE_NOOP3("QAbstractFileIconProvider", "Drive", ""),
};

QString installTranslations(QCoreApplication& app, const QString& language) {
  QString code = language;
  if (code.isEmpty() || code == "system") code = QLocale::system().name().startsWith("zh") ? "zh_CN" : "en";
  if (!availableLanguages().contains(code)) code = "en";
  // Measurements read better without digit grouping (10000.0837 ms, not
  // 10,000.0837): the locale decides the decimal sign, not groups.
  QLocale locale(code == "en" ? QString("en_US") : code);
  locale.setNumberOptions(QLocale::OmitGroupSeparator);
  QLocale::setDefault(locale);
  // The translators of an earlier choice go: the language can change while
  // the program runs (WindowHost makes the window again).
  static QPointer<QTranslator> installedOurs, installedQt;
  for (QPointer<QTranslator>* t : {&installedOurs, &installedQt})
    if (*t) {
      QCoreApplication::removeTranslator(*t);
      delete t->data();
    }
  if (code == "en") return code;
  initTranslationResources();
  // Ours, compiled into the program; Qt's own (standard dialogs) where the
  // system has them.
  auto* ours = new QTranslator(&app);
  if (!ours->load(":/translations/fogbench_" + code + ".qm")) {
    delete ours;
    QLocale::setDefault(QLocale(QStringLiteral("en_US")));
    return "en";
  }
  QCoreApplication::installTranslator(ours);
  installedOurs = ours;
  auto* qt = new QTranslator(&app);
  installedQt = qt;
#if QT_VERSION >= QT_VERSION_CHECK(6, 0, 0)
  const QString qtDir = QLibraryInfo::path(QLibraryInfo::TranslationsPath);
#else
  const QString qtDir = QLibraryInfo::location(QLibraryInfo::TranslationsPath);
#endif
  if (qt->load("qtbase_" + code, qtDir)) QCoreApplication::installTranslator(qt);
  return code;
}

}  // namespace fog::ui

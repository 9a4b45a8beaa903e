#include "i18n/translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace microsim::i18n {

QStringList availableLanguages() {
  return {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("es")};
}

QString chooseLanguage(const QString& setting, const QLocale& system) {
  const QStringList shipped = availableLanguages();
  if (shipped.contains(setting)) return setting;
  QString systemLanguage = QLocale::languageToCode(system.language());
  if (shipped.contains(systemLanguage)) return systemLanguage;
  return QStringLiteral("en");
}

QString languageFromSettings() {
  return chooseLanguage(QSettings().value(languageSettingKey()).toString());
}

QLocale localeFor(const QString& language, const QLocale& system) {
  if (QLocale::languageToCode(system.language()) == language) return system;
  return QLocale(language);
}

bool installTranslations(QCoreApplication& app, const QString& language) {
  QLocale::setDefault(localeFor(language));
  if (language == QLatin1String("en")) return true;

  // the translators live as long as the application, which owns them
  auto* qt = new QTranslator(&app);
  if (qt->load(QStringLiteral("qtbase_") + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
    QCoreApplication::installTranslator(qt);
  auto* ours = new QTranslator(&app);
  if (!ours->load(QStringLiteral(":/i18n/microsim_") + language)) return false;
  QCoreApplication::installTranslator(ours);
  return true;
}

}  // namespace microsim::i18n

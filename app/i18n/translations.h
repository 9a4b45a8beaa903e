#pragma once
// Loads the interface language: Qt's own catalogue first (standard dialogs, buttons),
// then microsim's, both for the language chosen in the settings or else the system's.

#include <QLocale>
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace microsim::i18n {

/// The QSettings key that holds the chosen language (empty: the system's).
inline QString languageSettingKey() { return QStringLiteral("ui/language"); }

/// The language to use now: the setting, else the system's, else English.
QString languageFromSettings();

/// Languages the interface ships in, as BCP-47 codes ("en" needs no catalogue).
QStringList availableLanguages();

/// The language to use: the setting if it names a shipped one, else the system's if
/// shipped, else English.
QString chooseLanguage(const QString& setting, const QLocale& system = QLocale::system());

/// Installs the translators for `language` on the application; returns false when
/// microsim's catalogue for it could not be loaded (the interface stays in English).
bool installTranslations(QCoreApplication& app, const QString& language);

}  // namespace microsim::i18n

#pragma once
// Loads the interface language: Qt's own catalogue first (standard dialogs, buttons),
// then microsim's, both for the language chosen in the settings or else the system's, and
// makes that language's locale the default, so numbers and dates are written as the words
// around them are ("26,9 s" in German even on an English system).

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

/// The locale for `language`: the system's own when it speaks that language (its region's
/// conventions kept: de_CH writes "1’234.5"), else the language's main one.
QLocale localeFor(const QString& language, const QLocale& system = QLocale::system());

/// Makes localeFor(language) the default locale and installs the translators for `language` on the application; returns false when
/// microsim's catalogue for it could not be loaded (the interface stays in English).
bool installTranslations(QCoreApplication& app, const QString& language);

}  // namespace microsim::i18n

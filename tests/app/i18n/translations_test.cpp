#include "i18n/translations.h"

#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QTranslator>

#include <gtest/gtest.h>

namespace microsim::i18n {
namespace {

TEST(Translations, ChoosesTheSettingThenTheSystemThenEnglish) {
  EXPECT_EQ(chooseLanguage(QStringLiteral("de"), QLocale(QLocale::Spanish)).toStdString(), "de");
  EXPECT_EQ(chooseLanguage(QString(), QLocale(QLocale::Spanish)).toStdString(), "es");
  EXPECT_EQ(chooseLanguage(QStringLiteral("xx"), QLocale(QLocale::Japanese)).toStdString(), "en");
}

TEST(Translations, NumbersFollowTheInterfaceLanguageAndKeepTheSystemsRegion) {
  // German on an English system writes German numbers
  const QLocale german = localeFor(QStringLiteral("de"), QLocale(QLocale::English, QLocale::UnitedStates));
  EXPECT_EQ(german.language(), QLocale::German);
  EXPECT_EQ(german.toString(26.9, 'f', 1).toStdString(), "26,9");
  EXPECT_EQ(localeFor(QStringLiteral("es"), QLocale(QLocale::German)).toString(0.3, 'f', 1).toStdString(), "0,3");
  EXPECT_EQ(localeFor(QStringLiteral("en"), QLocale(QLocale::German)).toString(26.9, 'f', 1).toStdString(), "26.9");
  // the system's own region when it speaks the language
  const QLocale swiss(QLocale::German, QLocale::Switzerland);
  EXPECT_EQ(localeFor(QStringLiteral("de"), swiss), swiss);
  EXPECT_EQ(localeFor(QStringLiteral("de"), swiss).toString(1234.5, 'f', 1), swiss.toString(1234.5, 'f', 1));
}

TEST(Translations, ShippedCataloguesLoadFromResources) {
  for (const QString& language : availableLanguages()) {
    if (language == QLatin1String("en")) continue;
    QTranslator translator;
    EXPECT_TRUE(translator.load(QStringLiteral(":/i18n/microsim_") + language)) << language.toStdString();
    EXPECT_FALSE(translator.isEmpty()) << language.toStdString();
  }
}

TEST(Translations, GermanCatalogueTranslatesTheWindowTitle) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/microsim_de")));
  const QString german = translator.translate("microsim::gui::MainWindow", "&File");
  EXPECT_EQ(german.toStdString(), "&Datei");
}

}  // namespace
}  // namespace microsim::i18n

namespace microsim::i18n {
namespace {

// Re-extracts every tr() string of app/ into copies of the shipped catalogues (as the
// update_translations target does) and lists the entries that are not finished.
QStringList unfinishedEntries(const QString& language) {
  QTemporaryDir dir;
  const QString shipped = QStringLiteral(MICROSIM_SOURCE_DIR "/translations/microsim_%1.ts").arg(language);
  const QString copy = dir.filePath(QStringLiteral("catalogue.ts"));
  if (!QFile::copy(shipped, copy)) return {QStringLiteral("cannot copy ") + shipped};

  QProcess lupdate;
  lupdate.start(QStringLiteral(MICROSIM_LUPDATE_PATH),
                {QStringLiteral("-locations"), QStringLiteral("none"), QStringLiteral("-no-obsolete"),
                 QStringLiteral(MICROSIM_SOURCE_DIR "/app"), QStringLiteral("-ts"), copy});
  if (!lupdate.waitForFinished(120000) || lupdate.exitCode() != 0)
    return {QStringLiteral("lupdate failed: ") + QString::fromUtf8(lupdate.readAllStandardError())};

  QFile file(copy);
  if (!file.open(QIODevice::ReadOnly)) return {QStringLiteral("cannot read ") + copy};
  QStringList problems;
  QXmlStreamReader xml(&file);
  QString context;
  QString source;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == QLatin1String("name")) context = xml.readElementText();
    else if (xml.name() == QLatin1String("source")) source = xml.readElementText();
    else if (xml.name() == QLatin1String("translation")) {
      const QString type = xml.attributes().value(QLatin1String("type")).toString();
      // a plural's forms are child elements: read them as its text (the default reader stops
      // at the first, with an error, and the entries after it went unchecked)
      const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
      if (!type.isEmpty() || text.isEmpty()) problems << QStringLiteral("[%1] %2 (%3)").arg(context, source, type);
    }
  }
  if (xml.hasError()) problems << QStringLiteral("unreadable catalogue: ") + xml.errorString();
  return problems;
}

TEST(Translations, EveryStringIsTranslatedInGerman) {
  const QStringList problems = unfinishedEntries(QStringLiteral("de"));
  EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
}

TEST(Translations, EveryStringIsTranslatedInSpanish) {
  const QStringList problems = unfinishedEntries(QStringLiteral("es"));
  EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
}

}  // namespace
}  // namespace microsim::i18n

#include "i18n/translations.h"

#include <QCoreApplication>
#include <QTranslator>

#include <gtest/gtest.h>

namespace microsim::i18n {
namespace {

TEST(Translations, ChoosesTheSettingThenTheSystemThenEnglish) {
  EXPECT_EQ(chooseLanguage(QStringLiteral("de"), QLocale(QLocale::Spanish)).toStdString(), "de");
  EXPECT_EQ(chooseLanguage(QString(), QLocale(QLocale::Spanish)).toStdString(), "es");
  EXPECT_EQ(chooseLanguage(QStringLiteral("xx"), QLocale(QLocale::Japanese)).toStdString(), "en");
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

// Issue 20: every screen the screenshot tool captures, at 1280×800, in English, German and
// Spanish, shows each label, button, title, header and table cell whole — none wider than its
// widget, none drawn over another (tests/app/gui/label_fit.h says how each is measured).
#include "gui/screenshots.h"
#include "i18n/translations.h"

#include "app/gui/core_profile.h"
#include "app/gui/label_fit.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTranslator>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

// the interface in `language` while it lives, as the app's start-up installs it: Qt's and
// our catalogues and the language's number format; English and the previous locale after
class ScopedInterfaceLanguage {
 public:
  explicit ScopedInterfaceLanguage(const QString& language) {
    QLocale::setDefault(i18n::localeFor(language));
    if (language == QLatin1String("en")) return;
    if (qt_.load(QStringLiteral("qtbase_") + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
      QCoreApplication::installTranslator(&qt_);
    loaded_ = ours_.load(QStringLiteral(":/i18n/microsim_") + language);
    if (loaded_) QCoreApplication::installTranslator(&ours_);
  }
  ~ScopedInterfaceLanguage() {
    QCoreApplication::removeTranslator(&ours_);
    QCoreApplication::removeTranslator(&qt_);
    QLocale::setDefault(previousLocale_);
  }
  ScopedInterfaceLanguage(const ScopedInterfaceLanguage&) = delete;
  ScopedInterfaceLanguage& operator=(const ScopedInterfaceLanguage&) = delete;

  /// False when the language's catalogue is missing (English needs none).
  bool loaded(const QString& language) const { return loaded_ || language == QLatin1String("en"); }

 private:
  QLocale previousLocale_;
  QTranslator qt_;
  QTranslator ours_;
  bool loaded_ = false;
};

// every fit problem of every captured screen in `language`, each line prefixed by the screen;
// `written` gets the names of the files the tool wrote, `inspected` those of the screens seen
QStringList labelProblemsOfEveryScreen(const QString& language, QStringList& written, QStringList& inspected) {
  QSettings().clear();
  requestCoreProfile();
  ScopedInterfaceLanguage interface(language);
  EXPECT_TRUE(interface.loaded(language)) << language.toStdString();
  QStringList problems;
  const ScreenInspector inspect = [&](const QString& file, QWidget& screen) {
    inspected << file;
    for (const QString& p : testing::labelFitProblems(screen)) problems << file + QStringLiteral(": ") + p;
  };
  QTemporaryDir dir;
  QString error;
  const QStringList files = writeScreenshots(dir.path(), &error, 1280, 800, inspect);
  EXPECT_FALSE(files.isEmpty()) << error.toStdString();
  for (const QString& f : files) written << QFileInfo(f).fileName();
  return problems;
}

void expectEveryLabelFits(const QString& language) {
  QStringList written;
  QStringList inspected;
  const QStringList problems = labelProblemsOfEveryScreen(language, written, inspected);
  // every screen the tool captures was checked: the lessons, an attempt, its results, the
  // settings and the review's three screens at least
  EXPECT_EQ(inspected, written);
  EXPECT_GE(written.size(), 8);
  EXPECT_TRUE(written.contains(QStringLiteral("results.png")));
  EXPECT_TRUE(written.contains(QStringLiteral("review-attempt.png")));
  EXPECT_TRUE(written.contains(QStringLiteral("review-end-product.png")));
  EXPECT_TRUE(problems.isEmpty()) << language.toStdString() << ":\n" << problems.join(QLatin1Char('\n')).toStdString();
}

TEST(ScreenshotLabels, EveryLabelFitsInEnglish) { expectEveryLabelFits(QStringLiteral("en")); }
TEST(ScreenshotLabels, EveryLabelFitsInGerman) { expectEveryLabelFits(QStringLiteral("de")); }
TEST(ScreenshotLabels, EveryLabelFitsInSpanish) { expectEveryLabelFits(QStringLiteral("es")); }

// the checker itself: it must see a cut label and an overlap, or the tests above prove nothing
TEST(ScreenshotLabels, TheCheckFindsACutLabelAndAnOverlap) {
  QWidget screen;
  screen.resize(300, 100);
  auto* cut = new QLabel(QStringLiteral("A label far too long for forty pixels"), &screen);
  cut->setGeometry(0, 0, 40, 20);
  auto* whole = new QLabel(QStringLiteral("Fits"), &screen);
  whole->setGeometry(0, 50, 100, 30);
  auto* over = new QPushButton(QStringLiteral("OK"), &screen);
  over->setGeometry(60, 45, 120, 40);
  screen.show();
  QCoreApplication::processEvents();
  const QStringList problems = testing::labelFitProblems(screen);
  const QString all = problems.join(QLatin1Char('\n'));
  EXPECT_TRUE(all.contains(QStringLiteral("far too long"))) << all.toStdString();
  EXPECT_TRUE(all.contains(QStringLiteral("overlaps"))) << all.toStdString();

  over->move(180, 50);
  cut->resize(cut->sizeHint());
  EXPECT_TRUE(testing::labelFitProblems(screen).isEmpty()) << testing::labelFitProblems(screen).join(QLatin1Char('\n')).toStdString();
}

}  // namespace
}  // namespace microsim::gui

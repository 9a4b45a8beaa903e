#include "gui/main_window.h"
#include "gui/app_settings.h"
#include "gui/viewport.h"
#include "gui/pages/attempt_page.h"
#include "gui/pages/sign_in_page.h"

#include <QImage>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

#include <set>

namespace microsim::gui {
namespace {


struct OpenWindow {
  QTemporaryDir dir;
  assessment::HistoryDatabase history;
  std::unique_ptr<MainWindow> window;

  OpenWindow() {
    requestCoreProfile();
    const QString path = dir.filePath(QStringLiteral("history.sqlite"));
    const assessment::DatabaseStatus status = history.open(path);
    window = std::make_unique<MainWindow>(&history, status, path);
    window->resize(800, 600);
  }
};

TEST(MainWindow, ViewportDrawsAShadedObject) {
  OpenWindow w;
  QSignalSpy frames(w.window->viewport(), &Viewport::frameDrawn);
  w.window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(w.window.get()));
  // the viewport lives on the attempt page: start lesson 1 as a guest
  ASSERT_TRUE(w.window->startLesson(0, assessment::AttemptMode::Learn));
  ASSERT_EQ(w.window->currentPage(), w.window->attemptPage());
  ASSERT_TRUE(frames.count() > 0 || frames.wait(10000));
  EXPECT_TRUE(w.window->viewport()->lastError().isEmpty()) << w.window->viewport()->lastError().toStdString();

  const QImage image = w.window->viewport()->grabFramebuffer();
  ASSERT_FALSE(image.isNull());
  // a shaded object gives many distinct colours; a blank or flat-filled frame gives one or two
  std::set<QRgb> colours;
  int reddish = 0;
  for (int y = 0; y < image.height(); y += 3) {
    for (int x = 0; x < image.width(); x += 3) {
      const QRgb c = image.pixel(x, y);
      colours.insert(c);
      if (qRed(c) > qGreen(c) + 40 && qRed(c) > 80) ++reddish;
    }
  }
  EXPECT_GT(colours.size(), 50u);
  EXPECT_GT(reddish, 500) << "the vessel should cover a visible part of the view";
}

TEST(MainWindow, HasMenusAndReportsTheDatabase) {
  OpenWindow w;
  QStringList titles;
  for (QAction* a : w.window->menuBar()->actions()) titles << a->text();
  EXPECT_TRUE(titles.contains(QStringLiteral("&File")));
  EXPECT_TRUE(titles.contains(QStringLiteral("&Help")));
  EXPECT_TRUE(w.window->databaseMessage().contains(QStringLiteral("schema"))) << w.window->databaseMessage().toStdString();
  EXPECT_EQ(w.window->currentPage(), w.window->signInPage());
  EXPECT_EQ(w.window->lessons().size(), 6u);
}

TEST(MainWindow, QuitActionClosesTheWindow) {
  OpenWindow w;
  w.window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(w.window.get()));
  QAction* quit = w.window->findChild<QAction*>(QStringLiteral("quitAction"));
  ASSERT_NE(quit, nullptr);
  quit->trigger();
  EXPECT_FALSE(w.window->isVisible());
}

// View → Depth of field: off by default on this software renderer, toggles the viewport's
// blur and is remembered for the next window
TEST(MainWindow, TheViewMenuTurnsDepthOfFieldOnAndRemembersIt) {
  QSettings().remove(settings::depthOfField());
  {
    OpenWindow w;
    auto* focus = w.window->findChild<QAction*>(QStringLiteral("depthOfFieldAction"));
    ASSERT_NE(focus, nullptr);
    EXPECT_TRUE(focus->isCheckable());
    EXPECT_FALSE(focus->isChecked());
    EXPECT_FALSE(w.window->viewport()->depthOfField());
    focus->trigger();
    EXPECT_TRUE(w.window->viewport()->depthOfField());
  }
  OpenWindow again;
  EXPECT_TRUE(again.window->viewport()->depthOfField());
  EXPECT_TRUE(again.window->findChild<QAction*>(QStringLiteral("depthOfFieldAction"))->isChecked());
  QSettings().remove(settings::depthOfField());
}

TEST(MainWindow, DescribesAnUnusableDatabase) {
  assessment::DatabaseStatus status;
  status.error = assessment::DatabaseError::NotADatabase;
  const QString text = MainWindow::describe(status, QStringLiteral("/tmp/x.sqlite"));
  EXPECT_TRUE(text.contains(QStringLiteral("/tmp/x.sqlite")));
  EXPECT_TRUE(text.contains(QStringLiteral("untouched")));
}

}  // namespace
}  // namespace microsim::gui

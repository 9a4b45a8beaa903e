// The main window stays on its screen: a saved geometry larger than the screen is fitted to it
// when restored, and no page (the review's charts once did) grows the window past it.
#include "gui/app_settings.h"
#include "gui/main_window.h"
#include "gui/review/review_page.h"
#include "gui/review/trainee_history_view.h"
#include "gui/window_geometry.h"
#include "support/stored_attempts.h"

#include "microsim/assessment/storage/people_store.h"

#include <QGuiApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QScreen>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace microsim::gui {
namespace {

TEST(FitInside, ShrinksAndMovesOntoTheAvailableArea) {
  const QRect screen(0, 0, 1280, 800);
  // the case: 853×869 at the top left of an 800-line screen
  EXPECT_EQ(fitInside(QRect(0, 0, 853, 869), screen), QRect(0, 0, 853, 800));
  // fits already: unchanged
  EXPECT_EQ(fitInside(QRect(100, 50, 800, 600), screen), QRect(100, 50, 800, 600));
  // hanging off the bottom right: moved back in, size kept
  EXPECT_EQ(fitInside(QRect(900, 500, 800, 600), screen), QRect(480, 200, 800, 600));
  // larger and off the top left: shrunk to the area and placed at its corner
  EXPECT_EQ(fitInside(QRect(-50, -40, 2000, 1000), QRect(0, 30, 1280, 770)), QRect(0, 30, 1280, 770));
  // a second screen to the right, its own origin
  EXPECT_EQ(fitInside(QRect(1300, 0, 1000, 1200), QRect(1280, 0, 1920, 1050)), QRect(1300, 0, 1000, 1050));
}

TEST(FirstPlacement, MostOfTheScreenCentredWithinBounds) {
  // 85 % each way, centred
  EXPECT_EQ(firstPlacement(QRect(0, 0, 1280, 800), QSize(400, 300)), QRect(96, 60, 1088, 680));
  // a large screen: at most 1600 by 1000
  EXPECT_EQ(firstPlacement(QRect(0, 0, 3840, 2160), QSize(400, 300)), QRect(1120, 580, 1600, 1000));
  // a small one: at least the window's minimum, never past the area
  EXPECT_EQ(firstPlacement(QRect(0, 30, 800, 570), QSize(720, 560)), QRect(40, 35, 720, 560));
  EXPECT_EQ(firstPlacement(QRect(0, 0, 640, 480), QSize(720, 560)), QRect(0, 0, 640, 480));
  // a second screen's area, its own origin
  EXPECT_EQ(firstPlacement(QRect(1280, 0, 1920, 1080), QSize(400, 300)).center(), QRect(1280, 0, 1920, 1080).center());
}

struct WindowHistory {
  QTemporaryDir dir;
  QString path;
  assessment::HistoryDatabase history;

  WindowHistory() {
    QSettings().clear();
    requestCoreProfile();
    path = dir.filePath(QStringLiteral("history.sqlite"));
    history.setPasswordIterations(1000);
    EXPECT_TRUE(history.open(path).ok());
  }
  ~WindowHistory() { QSettings().remove(settings::windowGeometry()); }
  WindowHistory(const WindowHistory&) = delete;
  WindowHistory& operator=(const WindowHistory&) = delete;
};

TEST(WindowGeometry, ASavedGeometryLargerThanTheScreenIsFittedToIt) {
  WindowHistory h;
  QScreen* screen = QGuiApplication::primaryScreen();
  ASSERT_NE(screen, nullptr);
  const QRect available = screen->availableGeometry();

  // what a window taller and wider than this screen saved (a larger monitor, the review
  // page of old)
  {
    QWidget large;
    large.setGeometry(available.x() + 20, available.y() + 10, available.width() + 300, available.height() + 200);
    QSettings().setValue(settings::windowGeometry(), large.saveGeometry());
  }
  MainWindow window(&h.history, {}, h.path);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  EXPECT_TRUE(available.contains(window.frameGeometry()))
      << window.frameGeometry().width() << "x" << window.frameGeometry().height() << " on " << available.width() << "x"
      << available.height();
  // the sign-in buttons at the bottom of the page are on the screen
  auto* signIn = window.findChild<QPushButton*>(QStringLiteral("signInButton"));
  ASSERT_NE(signIn, nullptr);
  EXPECT_TRUE(available.contains(QRect(signIn->mapToGlobal(QPoint(0, 0)), signIn->size())));
}

// The first start: nothing saved, the window opens on most of the screen, and the sign-in
// page fits it with no scroll bar (it opened at 466 by 348 behind two).
TEST(WindowGeometry, WithNothingSavedTheWindowOpensOnMostOfTheScreen) {
  WindowHistory h;
  QScreen* screen = QGuiApplication::primaryScreen();
  ASSERT_NE(screen, nullptr);
  const QRect available = screen->availableGeometry();
  MainWindow window(&h.history, {}, h.path);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  EXPECT_TRUE(available.contains(window.frameGeometry()));
  EXPECT_GE(window.width(), 0.8 * std::min(available.width(), 1600));
  EXPECT_GE(window.height(), 0.8 * std::min(available.height(), 1000));
  for (const QScrollBar* bar : window.findChildren<QScrollBar*>())
    EXPECT_FALSE(bar->isVisible()) << "a scroll bar on the first page";
  auto* signIn = window.findChild<QPushButton*>(QStringLiteral("signInButton"));
  ASSERT_NE(signIn, nullptr);
  EXPECT_TRUE(signIn->isVisible());
}

TEST(WindowGeometry, TheReviewPageDoesNotGrowTheWindow) {
  WindowHistory h;
  ASSERT_TRUE(assessment::PeopleStore(h.history).addInstructor(QStringLiteral("Dr Grey"), QStringLiteral("correct horse")));
  const qint64 ana = assessment::PeopleStore(h.history).addTrainee(QStringLiteral("Ana")).value_or(0);
  ASSERT_NE(ana, 0);
  // finished attempts with metrics: the history tab then shows the score and key-metric charts
  const QString lesson = QStringLiteral("02_needle_entry");
  const assessment::Rubric rubric = testing::shippedLessonRubric(lesson);
  for (double angle : {30.0, 10.0})
    testing::storeFinishedAttempt(h.history, ana, lesson, assessment::AttemptMode::Test,
                                  testing::scoreOnRubric(rubric, {{"entry_angle", angle}}));
  MainWindow window(&h.history, {}, h.path);
  // a window that fits a 1280×800 screen with its panels and title bar
  const QSize small(1000, 640);
  window.resize(small);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  window.findChild<QLineEdit*>(QStringLiteral("instructorName"))->setText(QStringLiteral("Dr Grey"));
  window.findChild<QLineEdit*>(QStringLiteral("instructorPassword"))->setText(QStringLiteral("correct horse"));
  window.findChild<QPushButton*>(QStringLiteral("instructorSignInButton"))->click();
  ASSERT_NE(window.reviewPage(), nullptr);
  ASSERT_EQ(window.currentPage(), window.reviewPage());
  window.reviewPage()->showTrainee(ana, lesson);  // the charts' tab
  ASSERT_FALSE(window.reviewPage()->historyView()->metricCharts().isEmpty());
  QCoreApplication::processEvents();
  EXPECT_LE(window.minimumSizeHint().height(), small.height());
  EXPECT_LE(window.minimumSizeHint().width(), small.width());
  EXPECT_EQ(window.size(), small);
}

}  // namespace
}  // namespace microsim::gui

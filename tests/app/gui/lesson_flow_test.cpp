// The lesson flow as a trainee goes through it, with real widgets and QTest input: create a
// trainee, open lesson 2 in Test mode, feed the shipped stitch in, reach the results.
#include "gui/main_window.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/results_page.h"
#include "gui/pages/sign_in_page.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"
#include "support/golden_stitch.h"

#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/sim/scene/recording.h"

#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace microsim::gui {
namespace {

const QString kSource = QStringLiteral(MICROSIM_SOURCE_DIR);


struct App {
  QTemporaryDir dir;
  QString path;
  assessment::HistoryDatabase history;
  std::unique_ptr<MainWindow> window;

  App() {
    QSettings().clear();  // the test suite's own settings: every tunable at its default
    requestCoreProfile();
    path = dir.filePath(QStringLiteral("history.sqlite"));
    const assessment::DatabaseStatus status = history.open(path);
    EXPECT_TRUE(status.ok()) << status.driverMessage.toStdString();
    window = std::make_unique<MainWindow>(&history, status, path);
    window->resize(1024, 700);
    window->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  }

  template <typename T>
  T* child(const char* name) const {
    T* w = window->findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(w, nullptr) << name;
    return w;
  }

  // types a new trainee's name and clicks Create
  void createTrainee(const QString& name) {
    auto* field = child<QLineEdit>("newTraineeName");
    QTest::mouseClick(field, Qt::LeftButton);
    QTest::keyClicks(field, name);
    QTest::mouseClick(child<QPushButton>("createTraineeButton"), Qt::LeftButton);
  }

  // clicks lesson `row` in the list, then the button
  void openLesson(int row, const char* button) {
    auto* table = child<QTableWidget>("lessonTable");
    const QRect cell = table->visualItemRect(table->item(row, 0));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    QTest::mouseClick(child<QPushButton>(button), Qt::LeftButton);
  }

  // the attempts of the history's one trainee, oldest first
  QList<assessment::AttemptSummary> traineesAttempts() {
    const QList<assessment::Trainee> people = assessment::PeopleStore(history).trainees();
    EXPECT_EQ(people.size(), 1);
    if (people.isEmpty()) return {};
    return assessment::AttemptStore(history).list({people[0].id, assessment::Role::Trainee});
  }

  // a new trainee opens lesson `row` with `button` and practises live for a few steps; the
  // attempt page, once the history has begun the attempt
  AttemptPage* practiseLive(const QString& trainee, int row, const char* button) {
    createTrainee(trainee);
    openLesson(row, button);
    AttemptPage* attempt = window->attemptPage();
    EXPECT_TRUE(attempt->isActive());
    const auto running = [attempt] { return attempt->attemptId() != 0 && attempt->runner()->steps() > 5; };
    EXPECT_TRUE(QTest::qWaitFor(running, 20000));
    return attempt;
  }
};

int reddishPixels(const QImage& image) {
  int reddish = 0;
  for (int y = 0; y < image.height(); y += 3)
    for (int x = 0; x < image.width(); x += 3) {
      const QRgb c = image.pixel(x, y);
      if (qRed(c) > qGreen(c) + 40 && qRed(c) > 80) ++reddish;
    }
  return reddish;
}

TEST(LessonFlow, TestModeReplayOfTheStitchScoresAsTheCliDoes) {
  App app;
  app.createTrainee(QStringLiteral("Ada Trainee"));
  ASSERT_EQ(app.window->currentPage(), app.window->lessonListPage());
  ASSERT_GE(app.window->lessons().size(), 2u);
  QTRY_VERIFY_WITH_TIMEOUT(app.window->lessonListPage()->statusesLoaded(), 20000);
  EXPECT_EQ(app.window->lessonListPage()->status(1), LessonStatus::NotStarted);

  app.openLesson(1, "testButton");
  ASSERT_EQ(app.window->currentPage(), app.window->attemptPage());
  AttemptPage* attempt = app.window->attemptPage();
  ASSERT_TRUE(attempt->isActive());
  // begun in the history on the attempt's own thread
  QTRY_VERIFY_WITH_TIMEOUT(attempt->attemptId() != 0, 20000);

  // the viewport shows the vessel
  Viewport* viewport = app.window->viewport();
  QSignalSpy frames(viewport, &Viewport::frameDrawn);
  ASSERT_TRUE(frames.count() > 0 || frames.wait(20000));
  EXPECT_TRUE(viewport->lastError().isEmpty()) << viewport->lastError().toStdString();
  EXPECT_GT(reddishPixels(viewport->grabFramebuffer()), 300);

  // the shipped stitch, fed in through the runner
  sim::Recording stitch;
  ASSERT_TRUE(sim::readRecording((kSource + QStringLiteral("/resources/recordings/stitch.msrec")).toStdString(), stitch).ok());
  QSignalSpy finished(attempt, &AttemptPage::finished);
  attempt->replay(stitch.frames);
  ASSERT_TRUE(finished.wait(180000));
  EXPECT_EQ(attempt->stepsDone(), 2) << "both targets of lesson 2 were pierced";
  ASSERT_EQ(app.window->currentPage(), app.window->resultsPage());
  const AttemptResult& result = app.window->resultsPage()->result();
  ASSERT_TRUE(result.scored) << (result.problem ? AttemptPage::describe(*result.problem).toStdString() : "");
  EXPECT_TRUE(result.stored) << (result.problem ? AttemptPage::describe(*result.problem).toStdString() : "");
  EXPECT_EQ(result.pierces.size(), 4u);

  // the score microsim-cli gives the same recording on the same rubric: both are held to the
  // pinned value (tests/app/cli/score_command_test.cpp for the CLI). Pinned rather than run
  // here so this suite forks no process: it also runs under ThreadSanitizer, whose fork
  // handling aborts in QProcess's clone.
  EXPECT_NEAR(result.score.score, testing::kGoldenStitchScoreNeedleEntry, 1e-9);

  // stored as a finished Test attempt with that score
  const QList<assessment::AttemptSummary> mine = app.traineesAttempts();
  ASSERT_EQ(mine.size(), 1);
  EXPECT_EQ(mine[0].status, assessment::AttemptStatus::Finished);
  EXPECT_EQ(mine[0].mode, assessment::AttemptMode::Test);
  EXPECT_EQ(mine[0].lesson, QStringLiteral("02_needle_entry"));
  ASSERT_TRUE(mine[0].score.has_value());
  EXPECT_DOUBLE_EQ(*mine[0].score, result.score.score);

  // back to the list: the lesson is no longer "not started"
  QTest::mouseClick(app.child<QPushButton>("backButton"), Qt::LeftButton);
  ASSERT_EQ(app.window->currentPage(), app.window->lessonListPage());
  QTRY_VERIFY_WITH_TIMEOUT(app.window->lessonListPage()->statusesLoaded(), 20000);
  EXPECT_NE(app.window->lessonListPage()->status(1), LessonStatus::NotStarted);
}

// Lesson 1 by keyboard: the right forceps moved 1 mm towards the viewer, away from the vessel,
// and its jaws closed (Space): they close on nothing, and the page says so.
TEST(LessonFlow, JawsClosedOnNothingAreReportedOnThePage) {
  App app;
  app.createTrainee(QStringLiteral("Cy Trainee"));
  app.openLesson(0, "learnButton");
  AttemptPage* attempt = app.window->attemptPage();
  ASSERT_TRUE(attempt->isActive());
  QTRY_VERIFY_WITH_TIMEOUT(attempt->runner()->steps() > 5, 20000);
  Viewport* viewport = app.window->viewport();
  viewport->setFocus();
  for (int k = 0; k < 20; ++k) QTest::keyClick(viewport, Qt::Key_E);
  QTest::keyPress(viewport, Qt::Key_Space);
  auto* status = app.child<QLabel>("attemptStatus");
  const QString expected = AttemptPage::tr("The right forceps closed on nothing: nothing lay between its jaws.");
  QTRY_COMPARE_WITH_TIMEOUT(status->text(), expected, 20000);
  QTest::keyRelease(viewport, Qt::Key_Space);
  const std::vector<sim::SceneEvent> events = attempt->runner()->events();
  EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const sim::SceneEvent& e) {
    return e.kind == sim::SceneEventKind::GraspEmpty && e.hand == static_cast<int>(sim::Hand::Right);
  }));
}

TEST(LessonFlow, ClosingMidAttemptLeavesItUnfinished) {
  App app;
  AttemptPage* attempt = app.practiseLive(QStringLiteral("Bo Trainee"), 2, "learnButton");
  const qint64 id = attempt->attemptId();
  ASSERT_NE(id, 0);

  app.window->close();
  EXPECT_FALSE(attempt->isActive());
  EXPECT_FALSE(attempt->runner()->isRunning());

  const QList<assessment::Trainee> people = assessment::PeopleStore(app.history).trainees();
  ASSERT_EQ(people.size(), 1);
  const QList<assessment::AttemptSummary> attempts = assessment::AttemptStore(app.history).list({people[0].id, assessment::Role::Trainee});
  ASSERT_EQ(attempts.size(), 1);
  EXPECT_EQ(attempts[0].id, id);
  EXPECT_NE(attempts[0].status, assessment::AttemptStatus::Finished);
  EXPECT_FALSE(attempts[0].score.has_value());

  // the database is still consistent and usable: a new session can start another attempt
  app.window.reset();
  assessment::HistoryDatabase again;
  ASSERT_TRUE(again.open(app.path).ok());
  const QList<assessment::AttemptSummary> reopened = assessment::AttemptStore(again).list({people[0].id, assessment::Role::Trainee});
  ASSERT_EQ(reopened.size(), 1);
  EXPECT_EQ(reopened[0].status, assessment::AttemptStatus::Interrupted) << "a closed window is not an abandonment";
}

// clicks the page's Abandon button and answers its confirmation with `answer`
void abandonAnswering(AttemptPage* page, QMessageBox::StandardButton answer) {
  bool answered = false;
  QTimer::singleShot(0, page, [page, answer, &answered] {
    auto* box = page->findChild<QMessageBox*>(QStringLiteral("abandonConfirmation"));
    ASSERT_NE(box, nullptr);
    ASSERT_TRUE(box->isVisible());
    answered = true;
    box->button(answer)->click();
  });
  QTest::mouseClick(page->findChild<QPushButton*>(QStringLiteral("abandonButton")), Qt::LeftButton);
  EXPECT_TRUE(answered) << "the abandon button asked nothing";
}

TEST(LessonFlow, AbandonAsksFirstAndIsStoredAsAbandoned) {
  App app;
  AttemptPage* attempt = app.practiseLive(QStringLiteral("Cy Trainee"), 2, "testButton");
  const qint64 id = attempt->attemptId();
  ASSERT_NE(id, 0);

  // "keep practising": nothing changes
  abandonAnswering(attempt, QMessageBox::No);
  EXPECT_TRUE(attempt->isActive());
  EXPECT_TRUE(attempt->runner()->isRunning());
  EXPECT_EQ(app.window->currentPage(), app.window->attemptPage());

  // confirmed: stored as abandoned, back on the lesson list
  QSignalSpy abandoned(attempt, &AttemptPage::abandoned);
  abandonAnswering(attempt, QMessageBox::Yes);
  ASSERT_TRUE(abandoned.count() > 0 || abandoned.wait(20000));
  EXPECT_FALSE(attempt->isActive());
  EXPECT_FALSE(attempt->runner()->isRunning());
  EXPECT_EQ(app.window->currentPage(), app.window->lessonListPage());
  const QList<assessment::AttemptSummary> attempts = app.traineesAttempts();
  ASSERT_EQ(attempts.size(), 1);
  EXPECT_EQ(attempts[0].id, id);
  EXPECT_EQ(attempts[0].status, assessment::AttemptStatus::Abandoned);
  EXPECT_FALSE(attempts[0].score.has_value());
  // the lesson counts as practised, not passed
  QTRY_VERIFY_WITH_TIMEOUT(app.window->lessonListPage()->statusesLoaded(), 20000);
  EXPECT_EQ(app.window->lessonListPage()->status(2), LessonStatus::Practised);
}

}  // namespace
}  // namespace microsim::gui

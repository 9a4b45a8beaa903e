// "My progress" as a trainee opens it: signed in through the sign-in page of the main
// window, on a real temporary SQLite history holding two of their finished attempts, one of
// them with an instructor's note. The history is read off the GUI thread.
#include "gui/main_window.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/my_progress_page.h"
#include "gui/review/attempt_detail_view.h"
#include "gui/review/review_charts.h"
#include "gui/review/trainee_history_view.h"
#include "support/history_threads.h"
#include "support/stored_attempts.h"

#include "microsim/assessment/storage/annotation_store.h"
#include "microsim/assessment/storage/people_store.h"

#include <QComboBox>
#include <QLineSeries>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

using assessment::AttemptMode;
using assessment::Role;

const QString kProgressLesson = QStringLiteral("02_needle_entry");
const QString kProgressNote = QStringLiteral("Enter at 90°: you came in flat on the second bite.");

class MyProgress : public ::testing::Test {
 protected:
  void SetUp() override {
    QSettings().clear();
    requestCoreProfile();
    ASSERT_TRUE(dir_.isValid());
    const QString path = dir_.filePath(QStringLiteral("history.sqlite"));
    history_.setPasswordIterations(1000);
    const assessment::DatabaseStatus status = history_.open(path);
    ASSERT_TRUE(status.ok());
    assessment::PeopleStore people(history_);
    const qint64 instructor = people.addInstructor(QStringLiteral("Dr Grey"), QStringLiteral("correct horse")).value_or(0);
    ana_ = people.addTrainee(QStringLiteral("Ana")).value_or(0);
    const qint64 ben = people.addTrainee(QStringLiteral("Ben")).value_or(0);
    ASSERT_TRUE(instructor && ana_ && ben);

    // Ana: an oblique first attempt (feedback on the entry angle), the instructor's note on
    // it, then a clean one; Ben's attempt and note must not show
    const assessment::Rubric rubric = testing::shippedLessonRubric(kProgressLesson);
    first_ = testing::storeFinishedAttempt(history_, ana_, kProgressLesson, AttemptMode::Test,
                                           testing::scoreOnRubric(rubric, {{"entry_angle", 65.0}}));
    second_ = testing::storeFinishedAttempt(history_, ana_, kProgressLesson, AttemptMode::Test, testing::scoreOnRubric(rubric));
    const qint64 bens = testing::storeFinishedAttempt(history_, ben, kProgressLesson, AttemptMode::Test, testing::scoreOnRubric(rubric));
    assessment::AnnotationStore notes(history_);
    ASSERT_TRUE(notes.add({instructor, Role::Instructor}, first_, kProgressNote));
    ASSERT_TRUE(notes.add({instructor, Role::Instructor}, bens, QStringLiteral("Ben's note")));

    window_ = std::make_unique<MainWindow>(&history_, status, path);
    window_->resize(1200, 760);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }

  template <typename T>
  T* child(const char* name) const {
    T* w = window_->findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(w, nullptr) << name;
    return w;
  }

  // Ana signs in from the list, selects the lesson and opens My progress; the page once its
  // history has arrived
  MyProgressPage* openProgress() {
    auto* list = child<QListWidget>("traineeList");
    const QList<QListWidgetItem*> items = list->findItems(QStringLiteral("Ana"), Qt::MatchExactly);
    EXPECT_EQ(items.size(), 1);
    if (items.isEmpty()) return nullptr;
    list->setCurrentItem(items[0]);
    QTest::mouseClick(child<QPushButton>("signInButton"), Qt::LeftButton);
    EXPECT_EQ(window_->currentPage(), window_->lessonListPage());
    int row = -1;
    for (std::size_t i = 0; i < window_->lessons().size(); ++i)
      if (window_->lessons()[i].id == kProgressLesson) row = int(i);
    window_->lessonListPage()->selectRow(row);

    MyProgressPage* page = window_->progressPage();
    QSignalSpy loaded(page, &MyProgressPage::loaded);
    QTest::mouseClick(child<QPushButton>("myProgressButton"), Qt::LeftButton);
    EXPECT_EQ(window_->currentPage(), page);
    EXPECT_TRUE(loaded.count() > 0 || loaded.wait(10000));
    return page;
  }

  QTemporaryDir dir_;
  assessment::HistoryDatabase history_;
  std::unique_ptr<MainWindow> window_;
  qint64 ana_ = 0;
  qint64 first_ = 0;
  qint64 second_ = 0;
};

TEST_F(MyProgress, TraineeSeesTheirAttemptsFeedbackAndTheInstructorsNote) {
  MyProgressPage* page = openProgress();
  ASSERT_NE(page, nullptr);
  EXPECT_EQ(page->lessonId(), kProgressLesson);

  // the score over their two attempts, none of Ben's
  QLineSeries* scores = ReviewCharts::scoreSeries(page->historyView()->scoreChart());
  ASSERT_NE(scores, nullptr);
  const QList<assessment::AttemptSummary> stored = assessment::AttemptStore(history_).list({ana_, Role::Trainee});
  ASSERT_EQ(stored.size(), 2);
  ASSERT_EQ(scores->count(), 2);
  EXPECT_DOUBLE_EQ(scores->at(0).y(), *stored[0].score);
  EXPECT_DOUBLE_EQ(scores->at(1).y(), *stored[1].score);
  EXPECT_LT(scores->at(0).y(), scores->at(1).y());
  QTableWidget* table = page->historyView()->attemptsTable();
  ASSERT_EQ(table->rowCount(), 2);
  EXPECT_TRUE(page->message().contains(QStringLiteral("note"))) << page->message().toStdString();

  // the newest attempt is shown at once; it has no note
  AttemptDetailView* detail = page->detailView();
  EXPECT_EQ(detail->attemptId(), second_);
  EXPECT_EQ(detail->annotationsList()->count(), 0);

  // the older attempt (last row: newest first) opens with its feedback and the note, read-only
  table->setCurrentCell(1, 0);
  QTest::keyClick(table, Qt::Key_Return);
  ASSERT_EQ(detail->attemptId(), first_);
  EXPECT_EQ(page->tabs()->currentWidget(), detail);
  ASSERT_EQ(detail->annotationsList()->count(), 1);
  EXPECT_TRUE(detail->annotationsList()->item(0)->text().contains(kProgressNote));
  EXPECT_TRUE(detail->annotationsList()->item(0)->text().contains(QStringLiteral("Dr Grey")));
  EXPECT_FALSE(detail->addNoteButton()->isVisible());
  EXPECT_FALSE(detail->noteEditor()->isEnabled());
  bool angleFeedback = false;
  for (int r = 0; r < detail->metricsTable()->rowCount(); ++r) {
    const QTableWidgetItem* feedback = detail->metricsTable()->item(r, 6);
    angleFeedback = angleFeedback || (feedback && !feedback->text().isEmpty());
  }
  EXPECT_TRUE(angleFeedback) << "the oblique entry's feedback is shown";

  // back to the lessons
  QTest::mouseClick(child<QPushButton>("progressBackButton"), Qt::LeftButton);
  EXPECT_EQ(window_->currentPage(), window_->lessonListPage());
}

TEST_F(MyProgress, ReadsTheHistoryOffTheGuiThread) {
  auto* list = child<QListWidget>("traineeList");
  list->setCurrentItem(list->findItems(QStringLiteral("Ana"), Qt::MatchExactly).value(0));
  QTest::mouseClick(child<QPushButton>("signInButton"), Qt::LeftButton);
  ASSERT_EQ(window_->currentPage(), window_->lessonListPage());

  const testing::HistoryThreads threads;
  MyProgressPage* page = window_->progressPage();
  QSignalSpy loaded(page, &MyProgressPage::loaded);
  QTest::mouseClick(child<QPushButton>("myProgressButton"), Qt::LeftButton);
  ASSERT_TRUE(loaded.count() > 0 || loaded.wait(10000));
  // another lesson: another load, also off the GUI thread
  page->lessonChooser()->setCurrentIndex(page->lessonChooser()->findData(kProgressLesson));
  ASSERT_TRUE(loaded.count() > 1 || loaded.wait(10000));
  EXPECT_EQ(page->historyView()->attemptsTable()->rowCount(), 2);
  EXPECT_GT(threads.accesses(), 0);
  EXPECT_EQ(threads.onGuiThread(), 0);
}

// without a history nothing is stored, so there is no progress to open
TEST(MyProgressGuest, AGuestHasNoProgressToShow) {
  requestCoreProfile();
  assessment::HistoryDatabase closed;
  assessment::DatabaseStatus status;
  status.error = assessment::DatabaseError::CannotOpen;
  MainWindow window(&closed, status, QStringLiteral("/nonexistent/history.sqlite"));
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  QTest::mouseClick(window.findChild<QPushButton*>(QStringLiteral("signInButton")), Qt::LeftButton);
  ASSERT_EQ(window.currentPage(), window.lessonListPage());
  auto* progress = window.findChild<QPushButton*>(QStringLiteral("myProgressButton"));
  ASSERT_NE(progress, nullptr);
  EXPECT_FALSE(progress->isEnabled());
}

}  // namespace
}  // namespace microsim::gui

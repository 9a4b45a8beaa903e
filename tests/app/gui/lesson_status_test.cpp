// The trainee's lesson list and the instructor's grid name a lesson's status with the same
// word, from attempts stored in a real temporary SQLite history.
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/lesson_status.h"
#include "gui/review/review_page.h"
#include "lesson/lesson.h"
#include "support/history_threads.h"
#include "support/instructor_history.h"
#include "support/stored_attempts.h"

#include "microsim/assessment/storage/people_store.h"

#include <QComboBox>
#include <QSignalSpy>
#include <QTableWidget>

#include <gtest/gtest.h>

#include <vector>

namespace microsim::gui {
namespace {

using assessment::AttemptMode;
using assessment::Role;
using assessment::Viewer;

class StatusWords : public testing::InstructorHistoryTest {
 protected:
  void SetUp() override {
    InstructorHistoryTest::SetUp();
    ana_ = assessment::PeopleStore(history_).addTrainee(QStringLiteral("Ana")).value_or(0);
    ASSERT_NE(ana_, 0);
    lessons_ = lesson::loadLessons(lesson::lessonsDirectory());
    ASSERT_EQ(lessons_.size(), 6u);
  }

  void store(const QString& lesson, AttemptMode mode, bool pass) {
    const assessment::Rubric rubric = testing::shippedLessonRubric(lesson);
    const assessment::AttemptScore score = pass ? testing::scoreOnRubric(rubric) : testing::failingScoreOnRubric(rubric);
    ASSERT_EQ(score.passed, pass) << score.score;
    ASSERT_NE(testing::storeFinishedAttempt(history_, ana_, lesson, mode, score), 0);
  }

  // the word on the last line of Ana's cell in `lesson`'s column of the instructor's grid
  static QString gridWord(const ReviewPage& page, const QString& lesson) {
    for (int c = 2; c < page.grid()->columnCount(); ++c) {
      if (page.lessonChooser()->itemData(c - 2).toString() != lesson) continue;
      const QTableWidgetItem* cell = page.grid()->item(0, c);
      return cell ? cell->text().section(QLatin1Char('\n'), -1) : QString();
    }
    ADD_FAILURE() << "no grid column for " << lesson.toStdString();
    return {};
  }

  int row(const QString& lesson) const {
    for (std::size_t i = 0; i < lessons_.size(); ++i)
      if (lessons_[i].id == lesson) return int(i);
    return -1;
  }

  std::vector<lesson::Lesson> lessons_;
  qint64 ana_ = 0;
};

TEST_F(StatusWords, TheTraineesListAndTheInstructorsGridAgree) {
  const QString notStarted = QStringLiteral("01_orientation");
  const QString practised = QStringLiteral("02_needle_entry");
  const QString passed = QStringLiteral("03_single_stitch");
  const QString proficient = QStringLiteral("04_triangulation");
  // a pass in Learn mode (guided) is practice, and so is a failed Test; the grid once called
  // this lesson passed while the trainee's list said practised
  store(practised, AttemptMode::Learn, true);
  store(practised, AttemptMode::Test, false);
  store(passed, AttemptMode::Test, false);
  store(passed, AttemptMode::Test, true);
  store(proficient, AttemptMode::Test, true);
  store(proficient, AttemptMode::Test, true);
  // an abandoned attempt is practice too, and does not break the two consecutive passes
  const qint64 gaveUp = assessment::AttemptStore(history_).begin(ana_, proficient, AttemptMode::Test).value_or(0);
  ASSERT_TRUE(assessment::AttemptStore(history_).abandon(gaveUp));

  // the list reads the history on a thread of its own, never on the GUI thread: the
  // statuses follow the lessons
  LessonListPage list(historyPath());
  QSignalSpy shown(&list, &LessonListPage::statusesShown);
  {
    const testing::HistoryThreads threads;
    list.show(lessons_, Viewer{ana_, Role::Trainee}, QStringLiteral("Ana"), QStringLiteral("en"));
    EXPECT_FALSE(list.statusesLoaded());
    EXPECT_EQ(list.statusText(0), QStringLiteral("…"));
    ASSERT_TRUE(shown.count() > 0 || shown.wait(20000));
    EXPECT_TRUE(list.statusesLoaded());
    EXPECT_GT(threads.accesses(), 0);
    EXPECT_EQ(threads.onGuiThread(), 0);
  }
  ReviewPage grid(history_, Viewer{instructor_, Role::Instructor});
  ASSERT_EQ(grid.shownTrainees().size(), 1);

  const std::vector<std::pair<QString, LessonStatus>> expected{{notStarted, LessonStatus::NotStarted},
                                                               {practised, LessonStatus::Practised},
                                                               {passed, LessonStatus::Passed},
                                                               {proficient, LessonStatus::Proficient}};
  for (const auto& [lesson, status] : expected) {
    const int r = row(lesson);
    ASSERT_GE(r, 0) << lesson.toStdString();
    EXPECT_EQ(list.status(r), status) << lesson.toStdString();
    EXPECT_EQ(list.statusText(r), LessonStatusText::word(status)) << lesson.toStdString();
    EXPECT_EQ(gridWord(grid, lesson), list.statusText(r)) << lesson.toStdString();
  }
  // the four words are four different words
  EXPECT_EQ(QStringList({LessonStatusText::word(LessonStatus::NotStarted), LessonStatusText::word(LessonStatus::Practised),
                         LessonStatusText::word(LessonStatus::Passed), LessonStatusText::word(LessonStatus::Proficient)})
                .removeDuplicates(),
            0);
}

// the rule itself, on rows without a database: other trainees' and lessons' attempts are not
// counted, and a lesson no longer shipped (no rubric) is never proficient
TEST(LessonStatusRule, CountsOnlyThisTraineesAttemptsInThisLesson) {
  using assessment::AttemptStatus;
  const auto attempt = [](qint64 trainee, const char* lesson, AttemptMode mode, double score, bool passed) {
    assessment::AttemptSummary a;
    a.traineeId = trainee;
    a.lesson = QString::fromLatin1(lesson);
    a.mode = mode;
    a.status = AttemptStatus::Finished;
    a.score = score;
    a.passed = passed;
    return a;
  };
  assessment::Rubric rubric;
  rubric.passMark = 70;
  const QList<assessment::AttemptSummary> rows{attempt(2, "a", AttemptMode::Test, 90, true),
                                               attempt(2, "a", AttemptMode::Test, 95, true),
                                               attempt(1, "b", AttemptMode::Test, 80, true),
                                               attempt(1, "a", AttemptMode::Learn, 99, true)};
  EXPECT_EQ(lessonStatus(rows, 1, QStringLiteral("a"), &rubric), LessonStatus::Practised);
  EXPECT_EQ(lessonStatus(rows, 1, QStringLiteral("b"), &rubric), LessonStatus::Passed);
  EXPECT_EQ(lessonStatus(rows, 1, QStringLiteral("c"), &rubric), LessonStatus::NotStarted);
  EXPECT_EQ(lessonStatus(rows, 2, QStringLiteral("a"), &rubric), LessonStatus::Proficient);
  EXPECT_EQ(lessonStatus(rows, 2, QStringLiteral("a"), nullptr), LessonStatus::Passed);
}

}  // namespace
}  // namespace microsim::gui

// An AttemptSession without any widget, on a real temporary SQLite history: the shipped
// stitch replayed into lesson 2 stores exactly one scored attempt; an abandoned attempt is
// stored as abandoned; a session destroyed mid-attempt leaves it interrupted at the next
// start; and every history call of a session happens off the GUI thread (each access is
// recorded with its thread through HistoryDatabase::setAccessObserver).
#include "gui/session/attempt_session.h"
#include "gui/simulation_runner.h"
#include "lesson/lesson.h"
#include "support/golden_stitch.h"
#include "support/history_threads.h"
#include "support/shipped_files.h"

#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/sim/scene/recording.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <vector>

namespace microsim::gui {
namespace {

using assessment::AttemptStatus;
using assessment::AttemptSummary;
using assessment::HistoryDatabase;
using assessment::Role;
using testing::HistoryThreads;

class AttemptSessionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = dir_.filePath(QStringLiteral("history.sqlite"));
    HistoryDatabase db;
    ASSERT_TRUE(db.open(path_).ok());
    trainee_ = assessment::PeopleStore(db).addTrainee(QStringLiteral("Sam")).value_or(0);
    ASSERT_NE(trainee_, 0);
    std::vector<lesson::LessonError> errors;
    const std::vector<lesson::Lesson> lessons = lesson::loadLessons(lesson::lessonsDirectory(), &errors);
    ASSERT_GE(lessons.size(), 2u);
    needleEntry_ = lessons[1];
    ASSERT_EQ(needleEntry_.id, QStringLiteral("02_needle_entry"));
    ASSERT_TRUE(sim::readRecording(testing::kShippedStitch.toStdString(), stitch_).ok());
  }

  AttemptSetup setup(assessment::AttemptMode mode = assessment::AttemptMode::Test) const {
    AttemptSetup s;
    s.lesson = needleEntry_;
    s.lessonIndex = 1;
    s.mode = mode;
    s.viewer = {trainee_, Role::Trainee};
    s.historyLocation = path_;
    s.solver = {QStringLiteral("scene"), 0};
    s.recordingFolder = dir_.filePath(QStringLiteral("recordings"));
    return s;
  }

  // prepares `session` and waits until the history has begun its attempt
  qint64 prepareAndBegin(AttemptSession& session, const AttemptSetup& s) {
    QSignalSpy begun(&session, &AttemptSession::begun);
    AttemptProblem problem;
    EXPECT_TRUE(session.prepare(s, &problem)) << static_cast<int>(problem.failure);
    EXPECT_TRUE(begun.wait(20000));
    return session.attemptId();
  }

  QList<AttemptSummary> storedAttempts() const {
    HistoryDatabase db;
    EXPECT_TRUE(db.open(path_).ok());
    return assessment::AttemptStore(db).list({trainee_, Role::Trainee});
  }

  QTemporaryDir dir_;
  QString path_;
  qint64 trainee_ = 0;
  lesson::Lesson needleEntry_;
  sim::Recording stitch_;
};

TEST_F(AttemptSessionTest, FramesThenFinishStoreExactlyOneScoredAttemptOffTheGuiThread) {
  AttemptResult result;
  QByteArray recordingBytes;
  {
    const HistoryThreads threads;
    AttemptSession session;
    const qint64 id = prepareAndBegin(session, setup());
    ASSERT_NE(id, 0);
    EXPECT_EQ(session.state(), AttemptSession::State::Active);

    QSignalSpy finished(&session, &AttemptSession::finished);
    session.replay(stitch_.frames);
    ASSERT_TRUE(finished.wait(180000));
    ASSERT_EQ(finished.count(), 1);
    result = finished.first().first().value<AttemptResult>();
    EXPECT_EQ(session.state(), AttemptSession::State::Finished);
    EXPECT_EQ(session.progress().stepsDone, 2) << "both targets of lesson 2 were pierced";
    EXPECT_EQ(session.runner()->steps(), static_cast<int>(stitch_.frames.size()));
    QFile file(session.recordingPath());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    recordingBytes = file.readAll();

    EXPECT_GT(threads.accesses(), 0) << "the session did reach the history";
    EXPECT_EQ(threads.onGuiThread(), 0) << "a history call on the GUI thread";
  }

  ASSERT_TRUE(result.scored);
  EXPECT_TRUE(result.stored);
  EXPECT_FALSE(result.problem.has_value());
  EXPECT_EQ(result.lessonIndex, 1);
  EXPECT_EQ(result.pierces.size(), 4u);
  EXPECT_FALSE(result.vessels.empty());
  EXPECT_NEAR(result.score.score, testing::kGoldenStitchScoreNeedleEntry, 1e-9);

  const QList<AttemptSummary> stored = storedAttempts();
  ASSERT_EQ(stored.size(), 1);
  EXPECT_EQ(stored[0].id, result.attemptId);
  EXPECT_EQ(stored[0].status, AttemptStatus::Finished);
  EXPECT_EQ(stored[0].mode, assessment::AttemptMode::Test);
  EXPECT_EQ(stored[0].lesson, QStringLiteral("02_needle_entry"));
  EXPECT_DOUBLE_EQ(stored[0].score.value_or(-1), result.score.score);
  HistoryDatabase db;
  ASSERT_TRUE(db.open(path_).ok());
  const auto detail = assessment::readAttemptDetail(db, {trainee_, Role::Trainee}, result.attemptId);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->recording, recordingBytes);
  EXPECT_EQ(detail->metrics.size(), static_cast<qsizetype>(result.score.metrics.size()));
}

TEST_F(AttemptSessionTest, AbandonIsStoredAsAbandonedWithoutAScore) {
  qint64 id = 0;
  {
    const HistoryThreads threads;
    AttemptSession session;
    id = prepareAndBegin(session, setup());
    ASSERT_NE(id, 0);
    session.startLive();
    QTRY_VERIFY_WITH_TIMEOUT(session.runner()->steps() > 3, 20000);
    QSignalSpy abandoned(&session, &AttemptSession::abandoned);
    session.abandon();
    EXPECT_FALSE(session.runner()->isRunning());
    EXPECT_EQ(session.state(), AttemptSession::State::Abandoned);
    ASSERT_TRUE(abandoned.wait(20000));
    EXPECT_TRUE(abandoned.first().first().toBool());
    // no finish after an abandon
    session.finish();
    EXPECT_EQ(session.state(), AttemptSession::State::Abandoned);
    EXPECT_EQ(threads.onGuiThread(), 0) << "a history call on the GUI thread";
  }
  const QList<AttemptSummary> stored = storedAttempts();
  ASSERT_EQ(stored.size(), 1);
  EXPECT_EQ(stored[0].id, id);
  EXPECT_EQ(stored[0].status, AttemptStatus::Abandoned);
  EXPECT_FALSE(stored[0].score.has_value());
}

TEST_F(AttemptSessionTest, ASessionDestroyedMidAttemptLeavesItInterruptedAtTheNextStart) {
  const HistoryThreads threads;
  qint64 left = 0;
  {
    AttemptSession session;
    left = prepareAndBegin(session, setup(assessment::AttemptMode::Learn));
    ASSERT_NE(left, 0);
    session.startLive();
    QTRY_VERIFY_WITH_TIMEOUT(session.runner()->steps() > 3, 20000);
  }  // neither finished nor abandoned: as when the window closes
  AttemptSession next;
  const qint64 second = prepareAndBegin(next, setup());
  ASSERT_NE(second, 0);
  EXPECT_NE(second, left);
  EXPECT_EQ(threads.onGuiThread(), 0) << "a history call on the GUI thread";

  const QList<AttemptSummary> stored = storedAttempts();
  ASSERT_EQ(stored.size(), 2);
  EXPECT_EQ(stored[0].id, left);
  EXPECT_EQ(stored[0].status, AttemptStatus::Interrupted);
  EXPECT_EQ(stored[1].id, second);
  EXPECT_EQ(stored[1].status, AttemptStatus::InProgress) << "the live session's attempt is left alone";
}

TEST_F(AttemptSessionTest, TheThreadLogSeesACallOnTheGuiThread) {
  // the assertion above can fail: a history opened here is seen on the GUI thread
  const HistoryThreads threads;
  HistoryDatabase db;
  ASSERT_TRUE(db.open(path_).ok());
  EXPECT_GT(threads.onGuiThread(), 0);
}

TEST_F(AttemptSessionTest, SolverSettingsApplyInMemoryAndTheRecordingNamesThem) {
  AttemptSetup s = setup(assessment::AttemptMode::Learn);
  s.solver = {QStringLiteral("newton"), 7};
  AttemptSession session;
  ASSERT_NE(prepareAndBegin(session, s), 0);
  EXPECT_EQ(session.sceneDef().solver.iterations, 7);
  ASSERT_NE(session.runner()->sceneDef(), nullptr);
  EXPECT_EQ(session.runner()->sceneDef()->solver.iterations, 7);

  QSignalSpy ended(&session, &AttemptSession::replayEnded);
  session.replay({stitch_.frames.begin(), stitch_.frames.begin() + 20}, false);
  ASSERT_TRUE(ended.wait(60000));
  EXPECT_TRUE(session.isActive());
  session.stop();
  EXPECT_EQ(session.state(), AttemptSession::State::Stopped);

  // no patched copy of the scene anywhere: the recording folder holds the recording only
  EXPECT_EQ(QDir(s.recordingFolder).entryList(QDir::Files), QStringList{QFileInfo(session.recordingPath()).fileName()});
  sim::Recording recording;
  ASSERT_TRUE(sim::readRecording(session.recordingPath().toStdString(), recording).ok());
  EXPECT_EQ(recording.frames.size(), 20u);
  const QJsonObject meta = QJsonDocument::fromJson(QByteArray::fromStdString(recording.metadata)).object();
  EXPECT_EQ(QString::fromStdString(recording.scene.path), QFileInfo(needleEntry_.scenePath).absoluteFilePath())
      << "the header names the lesson's own scene file, not a patched copy";
  EXPECT_EQ(meta.value(QStringLiteral("lesson")).toString(), QStringLiteral("02_needle_entry"));
  EXPECT_EQ(meta.value(QStringLiteral("solver")).toObject(),
            (QJsonObject{{QStringLiteral("name"), QStringLiteral("newton")}, {QStringLiteral("iterations"), 7}}));
}

TEST_F(AttemptSessionTest, FilesThatDoNotLoadAreReportedByReason) {
  AttemptSetup s = setup();
  s.solver = {QStringLiteral("simplex"), 0};
  AttemptSession unknownSolver;
  AttemptProblem problem;
  EXPECT_FALSE(unknownSolver.prepare(s, &problem));
  EXPECT_EQ(problem.failure, AttemptFailure::UnknownSolver);
  EXPECT_EQ(problem.field, QStringLiteral("simplex"));
  EXPECT_EQ(unknownSolver.state(), AttemptSession::State::Idle);

  s = setup();
  s.lesson.rubricPath = dir_.filePath(QStringLiteral("missing-rubric.json"));
  AttemptSession noRubric;
  EXPECT_FALSE(noRubric.prepare(s, &problem));
  EXPECT_EQ(problem.failure, AttemptFailure::RubricUnreadable);

  s = setup();
  s.lesson.scenePath = dir_.filePath(QStringLiteral("missing-scene.json"));
  AttemptSession noScene;
  EXPECT_FALSE(noScene.prepare(s, &problem));
  EXPECT_EQ(problem.failure, AttemptFailure::SceneUnreadable);
  EXPECT_EQ(problem.file, s.lesson.scenePath);
  EXPECT_EQ(storedAttempts().size(), 0) << "nothing was begun";
}

TEST_F(AttemptSessionTest, WithoutAHistoryTheAttemptIsScoredButNotStored) {
  AttemptSetup s = setup();
  s.historyLocation = dir_.filePath(QStringLiteral("not-a-folder/history.sqlite"));
  QFile blocker(dir_.filePath(QStringLiteral("not-a-folder")));
  ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));  // a file where the folder should be
  blocker.close();

  AttemptSession session;
  QSignalSpy failed(&session, &AttemptSession::failed);
  EXPECT_EQ(prepareAndBegin(session, s), 0);
  ASSERT_GE(failed.count(), 1);
  EXPECT_EQ(failed.first().first().value<AttemptProblem>().failure, AttemptFailure::HistoryUnavailable);

  QSignalSpy finished(&session, &AttemptSession::finished);
  session.replay({stitch_.frames.begin(), stitch_.frames.begin() + 50});
  ASSERT_TRUE(finished.wait(60000));
  const AttemptResult result = finished.first().first().value<AttemptResult>();
  EXPECT_TRUE(result.scored);
  EXPECT_FALSE(result.stored);
  EXPECT_EQ(result.attemptId, 0);
}

}  // namespace
}  // namespace microsim::gui

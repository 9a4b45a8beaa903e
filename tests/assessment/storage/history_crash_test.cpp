// SIGKILL in the middle of an attempt: a child process (this test binary, running the
// disabled case below) begins an attempt, says so on stdout and waits; the test kills it
// and reopens the history. Finished attempts are intact; the child's is Interrupted.
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include "assessment/storage/history_backend.h"
#include "support/ready_child.h"

#include <QDeadlineTimer>
#include <QProcess>

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace microsim::assessment {
namespace {

using testing::HistoryBackend;

// the child: run only when the parent starts it with MICROSIM_CHILD_DB set
TEST(HistoryCrashChild, DISABLED_BeginAttemptAndWait) {
  const QString location = qEnvironmentVariable("MICROSIM_CHILD_DB");
  if (location.isEmpty()) GTEST_SKIP() << "started by HistoryCrash only";
  HistoryDatabase db;
  ASSERT_TRUE(db.open(location).ok());
  const auto id = AttemptStore(db).begin(qEnvironmentVariable("MICROSIM_CHILD_TRAINEE").toLongLong(),
                                  QStringLiteral("03_crash"), AttemptMode::Test);
  ASSERT_TRUE(id.has_value());
  std::printf("ready %lld\n", static_cast<long long>(*id));
  std::fflush(stdout);
  std::string line;
  std::getline(std::cin, line);  // blocks until the parent kills us
}

class HistoryCrash : public HistoryBackend {
 protected:
  // On PostgreSQL the server ends a killed or closed client's backend when it sees the socket
  // close, a moment later; reopens `db` until the viewer's attempt `index` is no longer in
  // progress or 20 s have passed (the session test is the backend's absence). SQLite knows
  // at once.
  void reopenUntilNotInProgress(HistoryDatabase& db, const Viewer& viewer, qsizetype index) {
    if (GetParam() != Driver::PostgreSQL) return;
    QDeadlineTimer deadline(20000);
    while (AttemptStore(db).list(viewer).value(index).status == AttemptStatus::InProgress && !deadline.hasExpired()) {
      QSqlQuery wait(db.connection());
      wait.exec(QStringLiteral("SELECT pg_sleep(0.05)"));
      db.close();
      openInto(db);
    }
  }
};

TEST_P(HistoryCrash, KilledAttemptBecomesInterruptedAndFinishedOnesSurvive) {
  qint64 trainee = 0, done = 0;
  {
    HistoryDatabase db;
    openInto(db);
    trainee = PeopleStore(db).addTrainee(QStringLiteral("Carla")).value_or(0);
    done = AttemptStore(db).begin(trainee, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
    AttemptScore score;
    score.score = 77;
    score.rubricId = "r";
    score.rubricVersion = 1;
    score.metrics.push_back({"time", 61.0, "s", 60, 30, 1, 0.9, ""});
    ASSERT_TRUE(ScoreStore(db).finish(done, score, QByteArray("rec")));
  }

  QProcess child;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("MICROSIM_CHILD_DB"), location_);
  env.insert(QStringLiteral("MICROSIM_CHILD_TRAINEE"), QString::number(trainee));
  std::string output;
  const std::optional<qint64> ready = microsim::testing::startReadyChild(
      child, QStringLiteral("HistoryCrashChild.DISABLED_BeginAttemptAndWait"), env, 30000, &output);
  ASSERT_TRUE(ready.has_value()) << output;
  const qint64 begun = *ready;
  child.kill();  // SIGKILL: no destructor, no rollback, no close
  ASSERT_TRUE(child.waitForFinished());
  EXPECT_EQ(child.exitStatus(), QProcess::CrashExit);

  HistoryDatabase db;
  openInto(db);
  const Viewer carla{trainee, Role::Trainee};
  reopenUntilNotInProgress(db, carla, 1);
  const QList<AttemptSummary> all = AttemptStore(db).list(carla);
  ASSERT_EQ(all.size(), 2);
  EXPECT_EQ(all[0].id, done);
  EXPECT_EQ(all[0].status, AttemptStatus::Finished);
  ASSERT_TRUE(all[0].score.has_value());
  EXPECT_DOUBLE_EQ(*all[0].score, 77.0);
  EXPECT_EQ(all[1].id, begun);
  EXPECT_EQ(all[1].status, AttemptStatus::Interrupted);
  EXPECT_TRUE(all[1].finished.isValid());
  EXPECT_FALSE(all[1].score.has_value());
  const auto detail = readAttemptDetail(db, carla, done);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->recording, QByteArray("rec"));
  ASSERT_EQ(detail->metrics.size(), 1);
  // an interrupted attempt can no longer be finished
  ScoreStore scores(db);
  EXPECT_FALSE(scores.finish(begun, AttemptScore{}, {}));
  EXPECT_EQ(scores.lastError().error, HistoryError::NotInProgress);
}

TEST_P(HistoryCrash, LiveSessionsAttemptsAreLeftInProgress) {
  HistoryDatabase first;
  openInto(first);
  const qint64 trainee = PeopleStore(first).addTrainee(QStringLiteral("Dev")).value_or(0);
  const qint64 running = AttemptStore(first).begin(trainee, QStringLiteral("01_bite"), AttemptMode::Learn).value_or(0);
  ASSERT_TRUE(running);
  // a second program (here: connection) opening the same history must not end it
  HistoryDatabase second;
  openInto(second);
  const QList<AttemptSummary> seen = AttemptStore(second).list({trainee, Role::Trainee});
  ASSERT_EQ(seen.size(), 1);
  EXPECT_EQ(seen[0].status, AttemptStatus::InProgress);
  AttemptScore score;
  score.score = 50;
  EXPECT_TRUE(ScoreStore(first).finish(running, score, {}));
}

TEST_P(HistoryCrash, AClosedConnectionsAttemptIsInterruptedAtTheNextOpenInTheSameProcess) {
  qint64 trainee = 0, left = 0;
  {
    HistoryDatabase session;
    openInto(session);
    trainee = PeopleStore(session).addTrainee(QStringLiteral("Eli")).value_or(0);
    left = AttemptStore(session).begin(trainee, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
    ASSERT_TRUE(left);
  }  // closed without finishing or abandoning, as a destroyed attempt session leaves it
  HistoryDatabase next;
  openInto(next);
  const Viewer eli{trainee, Role::Trainee};
  reopenUntilNotInProgress(next, eli, 0);
  const QList<AttemptSummary> all = AttemptStore(next).list(eli);
  ASSERT_EQ(all.size(), 1);
  EXPECT_EQ(all[0].id, left);
  EXPECT_EQ(all[0].status, AttemptStatus::Interrupted);
}

INSTANTIATE_TEST_SUITE_P(Backends, HistoryCrash, ::testing::Values(Driver::SQLite, Driver::PostgreSQL),
                         testing::backendName);

}  // namespace
}  // namespace microsim::assessment

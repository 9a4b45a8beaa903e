// The database itself full (SQLITE_FULL, forced with PRAGMA max_page_count), and a power
// cut that leaves the write-ahead log cut short. Either way the finished attempts stay as
// they were and no attempt is left half-scored.
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <QFile>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::assessment {
namespace {

AttemptScore scoreOf(double value) {
  AttemptScore s;
  s.score = value;
  s.rubricId = "r";
  s.rubricVersion = 1;
  s.metrics.push_back({"time", 61.0, "s", 60, 30, 1, 0.9, ""});
  return s;
}

// no page beyond those the file has now
void capAtCurrentSize(HistoryDatabase& db) {
  QSqlQuery q(db.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA page_count")) && q.next());
  const qint64 pages = q.value(0).toLongLong();
  q.finish();
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA max_page_count = %1").arg(pages)));
}

void uncap(HistoryDatabase& db) {
  QSqlQuery q(db.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA max_page_count = 1073741823")));
}

class HistoryFull : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(db_.open(dir_.filePath(QStringLiteral("history.sqlite"))).ok());
    db_.setPasswordIterations(1000);
    trainee_ = PeopleStore(db_).addTrainee(QStringLiteral("Ada")).value_or(0);
    instructor_ = PeopleStore(db_).addInstructor(QStringLiteral("Ines"), QStringLiteral("s3cret-enough")).value_or(0);
    finished_ = AttemptStore(db_).begin(trainee_, QStringLiteral("01_orientation"), AttemptMode::Test).value_or(0);
    ASSERT_TRUE(ScoreStore(db_).finish(finished_, scoreOf(71), QByteArray("first recording")));
  }

  // the finished attempt with its score, metric and recording
  void expectFirstAttemptIntact() {
    const auto detail = readAttemptDetail(db_, {instructor_, Role::Instructor}, finished_);
    ASSERT_TRUE(detail.has_value());
    EXPECT_EQ(detail->summary.status, AttemptStatus::Finished);
    EXPECT_EQ(detail->summary.score.value_or(-1), 71.0);
    EXPECT_EQ(detail->metrics.size(), 1);
    EXPECT_EQ(detail->recording, QByteArray("first recording"));
  }

  QTemporaryDir dir_;
  HistoryDatabase db_;
  qint64 trainee_ = 0, instructor_ = 0, finished_ = 0;
};

TEST_F(HistoryFull, FinishOnAFullDatabaseFailsWholeAndSucceedsOnceThereIsRoom) {
  const qint64 open = AttemptStore(db_).begin(trainee_, QStringLiteral("03_single_stitch"), AttemptMode::Test).value_or(0);
  ASSERT_GT(open, 0);
  capAtCurrentSize(db_);
  const QByteArray recording(256 * 1024, 'r');
  ScoreStore scores(db_);
  EXPECT_FALSE(scores.finish(open, scoreOf(88), recording));
  EXPECT_EQ(scores.lastError().error, HistoryError::QueryFailed);
  EXPECT_TRUE(scores.lastError().driverMessage.contains(QStringLiteral("full"))) << scores.lastError().driverMessage.toStdString();

  // nothing of the failed finish was kept; the attempt may be finished later
  expectFirstAttemptIntact();
  auto detail = readAttemptDetail(db_, {instructor_, Role::Instructor}, open);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->summary.status, AttemptStatus::InProgress);
  EXPECT_FALSE(detail->summary.score.has_value());
  EXPECT_TRUE(detail->metrics.isEmpty());
  uncap(db_);
  ASSERT_TRUE(scores.finish(open, scoreOf(88), recording)) << scores.lastError().driverMessage.toStdString();
  detail = readAttemptDetail(db_, {instructor_, Role::Instructor}, open);
  EXPECT_EQ(detail->summary.score.value_or(-1), 88.0);
  EXPECT_EQ(detail->recording, recording);
}

TEST_F(HistoryFull, BeginOnAFullDatabaseFailsAndKeepsTheEarlierAttempts) {
  capAtCurrentSize(db_);
  // begin until the last page is full
  int begun = 0;
  std::optional<qint64> id;
  AttemptStore attempts(db_);
  while ((id = attempts.begin(trainee_, QStringLiteral("02_needle_entry"), AttemptMode::Learn)) && begun < 100000) ++begun;
  ASSERT_FALSE(id.has_value());
  EXPECT_EQ(attempts.lastError().error, HistoryError::QueryFailed);
  EXPECT_TRUE(attempts.lastError().driverMessage.contains(QStringLiteral("full"))) << attempts.lastError().driverMessage.toStdString();

  expectFirstAttemptIntact();
  EXPECT_EQ(AttemptStore(db_).list({instructor_, Role::Instructor}).size(), 1 + begun);
  // the file is sound
  QSqlQuery q(db_.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA integrity_check")) && q.next());
  EXPECT_EQ(q.value(0).toString(), QStringLiteral("ok"));
}

TEST_F(HistoryFull, PowerCutInTheLogKeepsEveryWholeTransaction) {
  const QString path = db_.path();
  const auto fileSize = [](const QString& p) { return QFile(p).size(); };
  const qint64 before = fileSize(path + QStringLiteral("-wal"));
  ASSERT_GT(before, 0) << "the history is expected in WAL mode";
  const qint64 second = AttemptStore(db_).begin(trainee_, QStringLiteral("03_single_stitch"), AttemptMode::Test).value_or(0);
  const qint64 begun = fileSize(path + QStringLiteral("-wal"));
  ASSERT_TRUE(ScoreStore(db_).finish(second, scoreOf(90), QByteArray(64 * 1024, 's')));
  const qint64 after = fileSize(path + QStringLiteral("-wal"));
  ASSERT_GT(after, begun);

  // what the disk would hold if power failed half-way through writing the finish
  QTemporaryDir cut;
  const QString copy = cut.filePath(QStringLiteral("history.sqlite"));
  ASSERT_TRUE(QFile::copy(path, copy));
  QFile wal(path + QStringLiteral("-wal"));
  ASSERT_TRUE(wal.open(QIODevice::ReadOnly));
  QFile walCopy(copy + QStringLiteral("-wal"));
  ASSERT_TRUE(walCopy.open(QIODevice::WriteOnly));
  walCopy.write(wal.read(begun + (after - begun) / 2));
  walCopy.close();

  HistoryDatabase reopened;
  ASSERT_TRUE(reopened.open(copy).ok());
  const auto first = readAttemptDetail(reopened, {instructor_, Role::Instructor}, finished_);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->summary.score.value_or(-1), 71.0);
  EXPECT_EQ(first->recording, QByteArray("first recording"));
  // the begin was whole, the finish was not: no score, no metrics, no recording
  const auto half = readAttemptDetail(reopened, {instructor_, Role::Instructor}, second);
  ASSERT_TRUE(half.has_value());
  EXPECT_NE(half->summary.status, AttemptStatus::Finished);
  EXPECT_FALSE(half->summary.score.has_value());
  EXPECT_TRUE(half->metrics.isEmpty());
  EXPECT_TRUE(half->recording.isEmpty());
}

}  // namespace
}  // namespace microsim::assessment

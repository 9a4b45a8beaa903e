// The SQLite file itself: read-only and corrupt files are refused and left byte-identical,
// a session-1 file is upgraded in place, backups are consistent and restores are checked.
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/migrations.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <QFile>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::assessment {
namespace {

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(bytes);
}

// a history with one trainee and one finished attempt; returns the file's path
QString makeHistory(const QTemporaryDir& dir, const QString& name, const QString& trainee) {
  QString path = dir.filePath(name);
  HistoryDatabase db;
  EXPECT_TRUE(db.open(path).ok());
  const qint64 id = PeopleStore(db).addTrainee(trainee).value_or(0);
  const qint64 attempt = AttemptStore(db).begin(id, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
  AttemptScore score;
  score.score = 64;
  score.rubricId = "r";
  score.rubricVersion = 2;
  ScoreStore scores(db);
  EXPECT_TRUE(scores.finish(attempt, score, QByteArray("recording"))) << scores.lastError().driverMessage.toStdString();
  return path;
}

TEST(HistoryFiles, ReadOnlyFileIsRefusedAndLeftByteIdentical) {
  QTemporaryDir dir;
  const QString path = makeHistory(dir, QStringLiteral("history.sqlite"), QStringLiteral("Eve"));
  const QByteArray before = readAll(path);
  ASSERT_TRUE(QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::ReadGroup));
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  EXPECT_EQ(status.error, DatabaseError::ReadOnly);
  EXPECT_FALSE(db.isOpen());
  EXPECT_EQ(readAll(path), before);
  EXPECT_FALSE(QFile::exists(path + QStringLiteral("-wal")));
}

TEST(HistoryFiles, CorruptPagesAreRefusedAndLeftByteIdentical) {
  QTemporaryDir dir;
  const QString path = makeHistory(dir, QStringLiteral("history.sqlite"), QStringLiteral("Fay"));
  QByteArray bytes = readAll(path);
  ASSERT_GT(bytes.size(), 4096);
  // keep the 100-byte header, trash the rest of the schema page
  for (qsizetype i = 100; i < 4096; ++i) bytes[i] = char(0xA5);
  write(path, bytes);
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  EXPECT_EQ(status.error, DatabaseError::NotADatabase) << status.driverMessage.toStdString();
  EXPECT_FALSE(db.isOpen());
  EXPECT_EQ(readAll(path), bytes);
}

// an SQLite history at file `path` as an older microsim left it: the first `version`
// migrations, then `rows` (SQL statements; each must succeed)
void writeOldHistory(const QString& path, int version, const std::vector<const char*>& rows) {
  {
    QSqlDatabase old = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("old"));
    old.setDatabaseName(path);
    ASSERT_TRUE(old.open());
    QSqlQuery q(old);
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA foreign_keys = ON")));
    const std::vector<Migration> all = bundledMigrations();
    ASSERT_EQ(migrate(old, {all.begin(), all.begin() + version}).version, version);
    for (const char* sql : rows)
      EXPECT_TRUE(q.exec(QString::fromLatin1(sql))) << sql << ": " << q.lastError().text().toStdString();
    q.finish();
    old.close();
  }
  QSqlDatabase::removeDatabase(QStringLiteral("old"));
}

TEST(HistoryFiles, SessionOneFileIsUpgradedInPlace) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("old.sqlite"));
  // exactly what session 1 created: migration 1 only
  writeOldHistory(path, 1, {"INSERT INTO trainees (name, created_at) VALUES ('Gus', '2026-11-01T09:00:00Z')"});
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  ASSERT_TRUE(status.ok()) << status.driverMessage.toStdString();
  EXPECT_EQ(status.schemaVersion, bundledMigrations().back().version);
  const QList<Trainee> people = PeopleStore(db).trainees();
  ASSERT_EQ(people.size(), 1);
  EXPECT_EQ(people[0].name.toStdString(), "Gus");
  EXPECT_TRUE(AttemptStore(db).begin(people[0].id, QStringLiteral("01_bite"), AttemptMode::Learn).has_value());
}

TEST(HistoryFiles, SchemaThreeFileKeepsEveryRowAndItsGuardsWhenAbandonedArrives) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("v3.sqlite"));
  // a history as schema 3 left it: a finished attempt with its score rows, recording and a
  // note, an interrupted one and one in progress
  writeOldHistory(
      path, 3,
      {"INSERT INTO trainees (id, name, role, created_at) VALUES (7, 'Lena', 'trainee', 't')",
       "INSERT INTO trainees (id, name, role, created_at) VALUES (8, 'Ines', 'instructor', 't')",
       "INSERT INTO attempts (id, trainee_id, lesson, mode, status, started_at, finished_at, session) "
       "VALUES (40, 7, '01_bite', 'test', 'in_progress', 't1', NULL, '')",
       "INSERT INTO scores (attempt_id, score, passed, rubric_id, rubric_version) VALUES (40, 81, 1, 'r', 2)",
       "INSERT INTO score_metrics (attempt_id, position, metric, value, unit, target, tolerance, weight, "
       "points, feedback) VALUES (40, 0, 'time', 61, 's', 60, 30, 1, 0.9, '')",
       "INSERT INTO recordings (attempt_id, data) VALUES (40, X'4D5352')",
       "UPDATE attempts SET status = 'finished', finished_at = 't2' WHERE id = 40",
       "INSERT INTO annotations (attempt_id, author_id, note, created_at) VALUES (40, 8, 'steady', 't3')",
       "INSERT INTO attempts (id, trainee_id, lesson, mode, status, started_at, finished_at, session) "
       "VALUES (41, 7, '01_bite', 'learn', 'interrupted', 't4', 't5', 'x')",
       "INSERT INTO attempts (id, trainee_id, lesson, mode, status, started_at, finished_at, session) "
       "VALUES (42, 7, '02_needle_entry', 'test', 'in_progress', 't6', NULL, '1@another-host')"});

  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  ASSERT_TRUE(status.ok()) << status.driverMessage.toStdString();
  EXPECT_EQ(status.schemaVersion, bundledMigrations().back().version);

  // every row and id is there; the attempt of another machine's session is left in progress
  AttemptStore attempts(db);
  const QList<AttemptSummary> lena = attempts.list({7, Role::Trainee});
  ASSERT_EQ(lena.size(), 3);
  EXPECT_EQ(lena[0].id, 40);
  EXPECT_EQ(lena[0].status, AttemptStatus::Finished);
  EXPECT_DOUBLE_EQ(lena[0].score.value_or(-1), 81.0);
  EXPECT_EQ(lena[1].status, AttemptStatus::Interrupted);
  EXPECT_EQ(lena[2].status, AttemptStatus::InProgress);
  const auto detail = readAttemptDetail(db, {8, Role::Instructor}, 40);
  ASSERT_TRUE(detail.has_value());
  ASSERT_EQ(detail->metrics.size(), 1);
  EXPECT_EQ(detail->recording, QByteArray("MSR"));
  ASSERT_EQ(detail->annotations.size(), 1);
  EXPECT_EQ(detail->annotations[0].note.toStdString(), "steady");

  // the new status is accepted, the guards of stored scores are back, foreign keys are on
  ASSERT_TRUE(attempts.abandon(42)) << attempts.lastError().driverMessage.toStdString();
  EXPECT_EQ(attempts.summary({7, Role::Trainee}, 42)->status, AttemptStatus::Abandoned);
  QSqlDatabase c = db.connection();
  QSqlQuery q(c);
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE attempts SET status = 'in_progress' WHERE id = 40")));
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE scores SET score = 100")));
  // a score from before the end product was stored is not judged, rather than judged clean
  EXPECT_FALSE(detail->endProduct.judged);
  EXPECT_TRUE(detail->endProduct.errors.isEmpty());
  EXPECT_FALSE(q.exec(QStringLiteral("INSERT INTO recordings (attempt_id, data) VALUES (42, X'00')")));
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE attempts SET status = 'lost' WHERE id = 41")));
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA foreign_keys")) && q.next());
  EXPECT_EQ(q.value(0).toInt(), 1);
  EXPECT_FALSE(q.exec(QStringLiteral("INSERT INTO annotations (attempt_id, author_id, note, created_at) "
                                     "VALUES (999, 8, 'orphan', 't')")));
  ASSERT_TRUE(q.exec(QStringLiteral("DELETE FROM trainees WHERE id = 7")));
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT (SELECT count(*) FROM attempts) + (SELECT count(*) FROM scores)")) &&
              q.next());
  EXPECT_EQ(q.value(0).toInt(), 0) << "deleting the trainee cascades through the rebuilt table";
}

TEST(HistoryFiles, BackupWhileOpenAndRestoreBringBackTheRows) {
  QTemporaryDir dir;
  const QString path = makeHistory(dir, QStringLiteral("history.sqlite"), QStringLiteral("Hal"));
  HistoryDatabase db;
  ASSERT_TRUE(db.open(path).ok());
  const QString copy = dir.filePath(QStringLiteral("backup.sqlite"));
  ASSERT_TRUE(db.backup(copy)) << db.lastError().driverMessage.toStdString();
  EXPECT_FALSE(db.backup(copy));  // never overwrites
  EXPECT_EQ(db.lastError().error, HistoryError::FileError);

  ASSERT_TRUE(PeopleStore(db).addTrainee(QStringLiteral("After")).has_value());
  ASSERT_EQ(PeopleStore(db).trainees().size(), 2);
  ASSERT_TRUE(db.restore(copy)) << db.lastError().driverMessage.toStdString();
  ASSERT_TRUE(db.isOpen());
  const QList<Trainee> people = PeopleStore(db).trainees();
  ASSERT_EQ(people.size(), 1);
  EXPECT_EQ(people[0].name.toStdString(), "Hal");
  const QList<AttemptSummary> attempts = AttemptStore(db).list({people[0].id, Role::Trainee});
  ASSERT_EQ(attempts.size(), 1);
  EXPECT_DOUBLE_EQ(attempts[0].score.value_or(-1), 64.0);
}

TEST(HistoryFiles, RestoreRefusesForeignAndNewerFilesAndKeepsTheHistory) {
  QTemporaryDir dir;
  const QString path = makeHistory(dir, QStringLiteral("history.sqlite"), QStringLiteral("Ivy"));
  HistoryDatabase db;
  ASSERT_TRUE(db.open(path).ok());

  const QString notes = dir.filePath(QStringLiteral("notes.txt"));
  write(notes, "not a database\n");
  EXPECT_FALSE(db.restore(notes));
  EXPECT_EQ(db.lastError().error, HistoryError::NotABackup);

  // an SQLite file that is not a microsim history
  const QString other = dir.filePath(QStringLiteral("other.sqlite"));
  {
    QSqlDatabase o = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("other"));
    o.setDatabaseName(other);
    ASSERT_TRUE(o.open());
    QSqlQuery(o).exec(QStringLiteral("CREATE TABLE photos (id INTEGER)"));
    o.close();
  }
  QSqlDatabase::removeDatabase(QStringLiteral("other"));
  EXPECT_FALSE(db.restore(other));
  EXPECT_EQ(db.lastError().error, HistoryError::NotABackup);

  // a history from a newer microsim
  const QString newer = makeHistory(dir, QStringLiteral("newer.sqlite"), QStringLiteral("Future"));
  {
    HistoryDatabase n;
    ASSERT_TRUE(n.open(newer).ok());
    QSqlQuery(n.connection()).exec(QStringLiteral(
        "INSERT INTO schema_migrations (version, name, applied_at) VALUES (9999, 'future.sql', 'x')"));
  }
  EXPECT_FALSE(db.restore(newer));
  EXPECT_EQ(db.lastError().error, HistoryError::BackupTooNew);

  ASSERT_TRUE(db.isOpen());
  ASSERT_EQ(PeopleStore(db).trainees().size(), 1);
  EXPECT_EQ(PeopleStore(db).trainees()[0].name.toStdString(), "Ivy");
}

TEST(HistoryFiles, UnreachableServerOrBadUrlIsCannotOpen) {
  HistoryDatabase db;
  // port 1 on loopback: refused at once
  EXPECT_EQ(db.open(QStringLiteral("postgresql://nobody@127.0.0.1:1/none")).error, DatabaseError::CannotOpen);
  EXPECT_FALSE(db.isOpen());
  EXPECT_EQ(db.open(QStringLiteral("postgresql://127.0.0.1:5432/")).error, DatabaseError::CannotOpen);
  EXPECT_TRUE(HistoryDatabase::isUrl(QStringLiteral("postgres://a@b/c")));
  EXPECT_FALSE(HistoryDatabase::isUrl(QStringLiteral("/home/a/postgresql.sqlite")));
}

}  // namespace
}  // namespace microsim::assessment

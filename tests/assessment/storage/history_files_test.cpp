// The SQLite file itself: read-only and corrupt files are refused and left byte-identical,
// a session-1 file is upgraded in place, backups are consistent and restores are checked.
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/migrations.h"

#include <QFile>
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
  const qint64 id = db.addTrainee(trainee).value_or(0);
  const qint64 attempt = db.beginAttempt(id, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
  AttemptScore score;
  score.score = 64;
  score.rubricId = "r";
  score.rubricVersion = 2;
  EXPECT_TRUE(db.finishAttempt(attempt, score, QByteArray("recording"))) << db.lastError().driverMessage.toStdString();
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

TEST(HistoryFiles, SessionOneFileIsUpgradedInPlace) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("old.sqlite"));
  {
    // exactly what session 1 created: migration 1 only
    QSqlDatabase old = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("old"));
    old.setDatabaseName(path);
    ASSERT_TRUE(old.open());
    ASSERT_EQ(migrate(old, {bundledMigrations().front()}).version, 1);
    QSqlQuery q(old);
    ASSERT_TRUE(q.exec(QStringLiteral("INSERT INTO trainees (name, created_at) VALUES ('Gus', '2026-11-01T09:00:00Z')")));
    old.close();
  }
  QSqlDatabase::removeDatabase(QStringLiteral("old"));
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  ASSERT_TRUE(status.ok()) << status.driverMessage.toStdString();
  EXPECT_EQ(status.schemaVersion, bundledMigrations().back().version);
  const QList<Trainee> people = db.trainees();
  ASSERT_EQ(people.size(), 1);
  EXPECT_EQ(people[0].name.toStdString(), "Gus");
  EXPECT_TRUE(db.beginAttempt(people[0].id, QStringLiteral("01_bite"), AttemptMode::Learn).has_value());
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

  ASSERT_TRUE(db.addTrainee(QStringLiteral("After")).has_value());
  ASSERT_EQ(db.trainees().size(), 2);
  ASSERT_TRUE(db.restore(copy)) << db.lastError().driverMessage.toStdString();
  ASSERT_TRUE(db.isOpen());
  const QList<Trainee> people = db.trainees();
  ASSERT_EQ(people.size(), 1);
  EXPECT_EQ(people[0].name.toStdString(), "Hal");
  const QList<AttemptSummary> attempts = db.attempts({people[0].id, Role::Trainee});
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
  ASSERT_EQ(db.trainees().size(), 1);
  EXPECT_EQ(db.trainees()[0].name.toStdString(), "Ivy");
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

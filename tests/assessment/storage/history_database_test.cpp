#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/migrations.h"

#include <QFile>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::assessment {
namespace {

QString tablesOf(const QSqlDatabase& db) {
  QSqlQuery q(db);
  q.exec(QStringLiteral("SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name"));
  QStringList names;
  while (q.next()) names << q.value(0).toString();
  return names.join(QLatin1Char(','));
}

TEST(HistoryDatabase, NewFileGetsEveryMigrationInWalMode) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("nested/folder/history.sqlite"));
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  ASSERT_TRUE(status.ok()) << status.driverMessage.toStdString();
  EXPECT_EQ(status.schemaVersion, bundledMigrations().back().version);
  EXPECT_GE(status.schemaVersion, 1);
  EXPECT_TRUE(QFile::exists(path));
  EXPECT_EQ(tablesOf(db.connection()).toStdString(),
            "annotations,attempts,instructor_passwords,recordings,schema_migrations,score_end_"
            "product,score_metrics,"
            "score_pierces,scores,setup_profiles,trainee_groups,trainees");

  QSqlQuery q(db.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA journal_mode")) && q.next());
  EXPECT_EQ(q.value(0).toString().toStdString(), "wal");
  ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA foreign_keys")) && q.next());
  EXPECT_EQ(q.value(0).toInt(), 1);
}

TEST(HistoryDatabase, ReopeningAppliesNothingTwiceAndKeepsRows) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  {
    HistoryDatabase db;
    ASSERT_TRUE(db.open(path).ok());
    QSqlQuery q(db.connection());
    ASSERT_TRUE(q.exec(QStringLiteral(
        "INSERT INTO trainees (name, created_at) VALUES ('Ana', '2026-11-22T10:00:00Z')")));
  }
  HistoryDatabase again;
  const DatabaseStatus status = again.open(path);
  ASSERT_TRUE(status.ok());
  QSqlQuery q(again.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT count(*) FROM schema_migrations")) && q.next());
  EXPECT_EQ(q.value(0).toInt(), static_cast<int>(bundledMigrations().size()));
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT name FROM trainees")) && q.next());
  EXPECT_EQ(q.value(0).toString().toStdString(), "Ana");
}

TEST(HistoryDatabase, ForeignFileIsReportedAndLeftUntouched) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  const QByteArray garbage = QByteArray("this is not an SQLite database, but a trainee's notes\n").repeated(200);
  {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(garbage);
  }
  HistoryDatabase db;
  const DatabaseStatus status = db.open(path);
  EXPECT_EQ(status.error, DatabaseError::NotADatabase);
  EXPECT_FALSE(db.isOpen());
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  EXPECT_EQ(f.readAll(), garbage);
}

TEST(HistoryDatabase, LockedFileIsReportedAndKeepsItsRows) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  {
    HistoryDatabase db;
    ASSERT_TRUE(db.open(path).ok());
    QSqlQuery q(db.connection());
    ASSERT_TRUE(q.exec(QStringLiteral(
        "INSERT INTO trainees (name, created_at) VALUES ('Ben', '2026-11-22T10:00:00Z')")));
  }
  // another program holds an exclusive lock on the file
  QSqlDatabase holder = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("holder"));
  {
    holder.setDatabaseName(path);
    ASSERT_TRUE(holder.open());
    QSqlQuery q(holder);
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA locking_mode = EXCLUSIVE")));
    ASSERT_TRUE(q.exec(QStringLiteral("BEGIN EXCLUSIVE")));
    HistoryDatabase blocked;
    EXPECT_EQ(blocked.open(path).error, DatabaseError::Locked);
    EXPECT_FALSE(blocked.isOpen());
    ASSERT_TRUE(q.exec(QStringLiteral("COMMIT")));
    holder.close();
  }
  holder = QSqlDatabase();
  QSqlDatabase::removeDatabase(QStringLiteral("holder"));

  HistoryDatabase after;
  ASSERT_TRUE(after.open(path).ok());
  QSqlQuery q(after.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT name FROM trainees")) && q.next());
  EXPECT_EQ(q.value(0).toString().toStdString(), "Ben");
}

TEST(HistoryDatabase, NewerSchemaIsRefused) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  {
    HistoryDatabase db;
    ASSERT_TRUE(db.open(path).ok());
    QSqlQuery q(db.connection());
    ASSERT_TRUE(q.exec(QStringLiteral(
        "INSERT INTO schema_migrations (version, name, applied_at) VALUES (9999, 'future.sql', 'x')")));
  }
  HistoryDatabase db;
  EXPECT_EQ(db.open(path).error, DatabaseError::NewerSchema);
}

TEST(Migrations, AFailingMigrationRollsBackWhole) {
  QTemporaryDir dir;
  HistoryDatabase db;
  ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("h.sqlite"))).ok());
  QSqlDatabase c = db.connection();
  const int before = schemaVersion(c);
  std::vector<Migration> migrations = bundledMigrations();
  migrations.push_back({before + 1, QStringLiteral("broken.sql"),
                        QStringLiteral("CREATE TABLE half_done (x INTEGER);\nTHIS IS NOT SQL;\n")});
  const MigrationOutcome outcome = migrate(c, migrations);
  EXPECT_EQ(outcome.result, MigrationResult::Failed);
  EXPECT_EQ(outcome.failedVersion, before + 1);
  EXPECT_EQ(schemaVersion(c), before);
  EXPECT_FALSE(tablesOf(c).contains(QStringLiteral("half_done")));
}

TEST(Migrations, PlaceholdersAndDriverOnlyStatementsFollowTheDriver) {
  const QString sql = QStringLiteral(
      "CREATE TABLE t (id @ID@, v @REAL@, b @BLOB@);\n"
      "@SQLITE@ CREATE TRIGGER x BEFORE UPDATE ON t BEGIN SELECT RAISE(ABORT, 'no'); END;\n"
      "@POSTGRESQL@ CREATE FUNCTION f() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN RETURN NEW; END $$;\n");
  const QStringList lite = statementsFor(sql, Driver::SQLite);
  ASSERT_EQ(lite.size(), 2);
  EXPECT_EQ(lite[0].toStdString(), "CREATE TABLE t (id INTEGER PRIMARY KEY, v REAL, b BLOB)");
  EXPECT_EQ(lite[1].toStdString(), "CREATE TRIGGER x BEFORE UPDATE ON t BEGIN SELECT RAISE(ABORT, 'no'); END");
  const QStringList pg = statementsFor(sql, Driver::PostgreSQL);
  ASSERT_EQ(pg.size(), 2);
  EXPECT_EQ(pg[0].toStdString(), "CREATE TABLE t (id BIGSERIAL PRIMARY KEY, v DOUBLE PRECISION, b BYTEA)");
  EXPECT_EQ(pg[1].toStdString(),
            "CREATE FUNCTION f() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN RETURN NEW; END $$");
}

TEST(Migrations, FirstMigrationOnSqliteIsTheSessionOneSchema) {
  // the text session-1 databases were created from, before placeholders
  const QString before = QStringLiteral(
      "CREATE TABLE trainees (\nid          INTEGER PRIMARY KEY,\nname        TEXT NOT NULL UNIQUE,\n"
      "role        TEXT NOT NULL DEFAULT 'trainee' CHECK (role IN ('trainee', 'instructor')),\n"
      "created_at  TEXT NOT NULL\n)");
  const QStringList now = statementsFor(bundledMigrations().front().sql, Driver::SQLite);
  ASSERT_EQ(now.size(), 4);
  EXPECT_EQ(now[0].toStdString(), before.toStdString());
  EXPECT_TRUE(now[1].contains(QStringLiteral("id              INTEGER PRIMARY KEY,")));
  EXPECT_TRUE(now[1].contains(QStringLiteral("score           REAL,")));
  EXPECT_TRUE(now[1].contains(QStringLiteral("recording       BLOB")));
  EXPECT_TRUE(now[3].contains(QStringLiteral("value       REAL NOT NULL,")));
}

TEST(Migrations, SplitStatementsDropsCommentsAndKeepsMultilineStatements) {
  const QStringList s = splitStatements(QStringLiteral(
      "-- comment\nCREATE TABLE a (\n  x INTEGER\n);\n\nCREATE INDEX i ON a(x);\n"));
  ASSERT_EQ(s.size(), 2);
  EXPECT_EQ(s[0].toStdString(), "CREATE TABLE a (\nx INTEGER\n)");
  EXPECT_EQ(s[1].toStdString(), "CREATE INDEX i ON a(x)");
}

}  // namespace
}  // namespace microsim::assessment

// `microsim-cli db` as a user runs it, on a real temporary SQLite file (and on the
// PostgreSQL server of scripts/postgres-for-tests.sh when MICROSIM_TEST_PG_URL is set).
#include "support/cli_runner.h"

#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::assessment::AttemptStore;
using microsim::assessment::HistoryDatabase;
using microsim::testing::CliRun;
using microsim::testing::runCli;

// runCli with `input` written to the program's stdin
CliRun runCliWithInput(const QStringList& args, const QByteArray& input) {
  return runCli(args, 120000, input);
}

QByteArray readDbFile(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

TEST(DbCommand, AddListBackupRestoreAndExport) {
  QTemporaryDir dir;
  const QString db = dir.filePath(QStringLiteral("history.sqlite"));
  const QStringList on = {QStringLiteral("--db"), db};

  CliRun r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("migrate")} + on);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(QStringLiteral("schema version"))) << r.out.toStdString();

  const QString evil = QStringLiteral("x'); DROP TABLE attempts;--");
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("add-trainee"), evil, QStringLiteral("--group"),
                         QStringLiteral("PGY-1")} + on);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("add-trainee"), evil} + on);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("taken"))) << r.err.toStdString();

  // the password comes on stdin only
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("add-instructor"), QStringLiteral("Ines")} + on);
  EXPECT_EQ(r.exitCode, 2);
  r = runCliWithInput(QStringList{QStringLiteral("db"), QStringLiteral("add-instructor"), QStringLiteral("Ines"),
                                  QStringLiteral("--password-stdin")} + on,
                      "s3cret-enough\n");
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  const QString json = dir.filePath(QStringLiteral("people.json"));
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("list-trainees"), QStringLiteral("--json"), json} + on);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(evil));
  const QJsonArray people = QJsonDocument::fromJson(readDbFile(json)).array();
  ASSERT_EQ(people.size(), 2);
  EXPECT_EQ(people[0].toObject()[QStringLiteral("name")].toString().toStdString(), "Ines");
  EXPECT_EQ(people[0].toObject()[QStringLiteral("role")].toString().toStdString(), "instructor");
  EXPECT_EQ(people[1].toObject()[QStringLiteral("name")].toString(), evil);
  EXPECT_EQ(people[1].toObject()[QStringLiteral("group")].toString().toStdString(), "PGY-1");

  // one attempt, abandoned, so the export has a row with that status
  {
    HistoryDatabase h;
    ASSERT_TRUE(h.open(db).ok());
    AttemptStore attempts(h);
    const auto id = attempts.begin(people[1].toObject()[QStringLiteral("id")].toInteger(), QStringLiteral("01_bite"),
                                   microsim::assessment::AttemptMode::Learn);
    ASSERT_TRUE(id);
    ASSERT_TRUE(attempts.abandon(*id));
  }
  const QString csv = dir.filePath(QStringLiteral("attempts.csv"));
  r = runCliWithInput(QStringList{QStringLiteral("db"), QStringLiteral("export-csv"), csv, QStringLiteral("--instructor"),
                                  QStringLiteral("Ines")} + on,
                      "wrong password\n");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(QFile::exists(csv));
  r = runCliWithInput(QStringList{QStringLiteral("db"), QStringLiteral("export-csv"), csv, QStringLiteral("--instructor"),
                                  QStringLiteral("Ines")} + on,
                      "s3cret-enough\n");
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const QList<QByteArray> lines = readDbFile(csv).split('\n');
  ASSERT_EQ(lines.size(), 3);
  EXPECT_TRUE(lines[1].contains("x'); DROP TABLE attempts;--,PGY-1,01_bite,learn,abandoned,")) << lines[1].toStdString();

  const QString copy = dir.filePath(QStringLiteral("backup.sqlite"));
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("backup"), copy} + on);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("add-trainee"), QStringLiteral("Later")} + on);
  ASSERT_EQ(r.exitCode, 0);
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("restore"), copy} + on);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("list-trainees")} + on);
  EXPECT_FALSE(r.out.contains(QStringLiteral("Later")));
  EXPECT_TRUE(r.out.contains(evil));
}

TEST(DbCommand, DamagedFileGivesAClearMessageAndStaysAsItWas) {
  QTemporaryDir dir;
  const QString db = dir.filePath(QStringLiteral("notes.sqlite"));
  const QByteArray garbage = QByteArray("my notes, not a database\n").repeated(100);
  {
    QFile f(db);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(garbage);
  }
  const CliRun r = runCli({QStringLiteral("db"), QStringLiteral("list-trainees"), QStringLiteral("--db"), db});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("not a microsim database or is damaged"))) << r.err.toStdString();
  EXPECT_EQ(readDbFile(db), garbage);
}

TEST(DbCommand, BackupOntoAnExistingFileSaysSoAndLeavesItUntouched) {
  QTemporaryDir dir;
  const QString db = dir.filePath(QStringLiteral("history.sqlite"));
  const QStringList on = {QStringLiteral("--db"), db};
  ASSERT_EQ(runCli(QStringList{QStringLiteral("db"), QStringLiteral("add-trainee"), QStringLiteral("Ada")} + on).exitCode, 0);
  const QString target = dir.filePath(QStringLiteral("monday.sqlite"));
  const QByteArray before = QByteArray("last week's backup, or something else entirely\n").repeated(50);
  {
    QFile f(target);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(before);
  }
  const CliRun r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("backup"), target} + on);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("%1 exists already; it was left untouched").arg(target))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("Choose another name"))) << r.err.toStdString();
  EXPECT_FALSE(r.err.contains(QStringLiteral("could not be"))) << r.err.toStdString();
  EXPECT_EQ(readDbFile(target), before);
  EXPECT_FALSE(QFile::exists(target + QStringLiteral(".part")));

  // another name works
  const CliRun again = runCli(QStringList{QStringLiteral("db"), QStringLiteral("backup"),
                                          dir.filePath(QStringLiteral("tuesday.sqlite"))} + on);
  EXPECT_EQ(again.exitCode, 0) << again.err.toStdString();
}

TEST(DbCommand, UsageErrors) {
  EXPECT_EQ(runCli({QStringLiteral("db")}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("db"), QStringLiteral("frobnicate")}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("db"), QStringLiteral("backup")}).exitCode, 2);
  const CliRun help = runCli({QStringLiteral("db"), QStringLiteral("--help")});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_TRUE(help.out.contains(QStringLiteral("--password-stdin")));
}

TEST(DbCommand, PostgresServerByUrl) {
  const QString url = qEnvironmentVariable("MICROSIM_TEST_PG_URL");
  if (url.isEmpty())
    GTEST_SKIP() << "MICROSIM_TEST_PG_URL is not set: run under scripts/postgres-for-tests.sh";
  const CliRun migrate = runCli({QStringLiteral("db"), QStringLiteral("migrate"), QStringLiteral("--db"), url});
  ASSERT_EQ(migrate.exitCode, 0) << migrate.err.toStdString();
  const QString name = QStringLiteral("cli-pg-%1").arg(QCoreApplication::applicationPid());
  const CliRun add = runCli({QStringLiteral("db"), QStringLiteral("add-trainee"), name, QStringLiteral("--db"), url});
  ASSERT_EQ(add.exitCode, 0) << add.err.toStdString();
  const CliRun list = runCli({QStringLiteral("db"), QStringLiteral("list-trainees"), QStringLiteral("--db"), url});
  EXPECT_TRUE(list.out.contains(name));
  const CliRun backup = runCli({QStringLiteral("db"), QStringLiteral("backup"), QStringLiteral("/tmp/x.sqlite"),
                                QStringLiteral("--db"), url});
  EXPECT_EQ(backup.exitCode, 1);
  EXPECT_TRUE(backup.err.contains(QStringLiteral("pg_dump"))) << backup.err.toStdString();
}

}  // namespace

#pragma once
// The storage tests run every case on SQLite (a temporary file) and, when
// MICROSIM_TEST_PG_URL names a server (scripts/postgres-for-tests.sh), on PostgreSQL in
// a database made for the test and dropped after it.
#include "microsim/assessment/storage/history_database.h"

#include <QRandomGenerator>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QUrl>

#include <gtest/gtest.h>

namespace microsim::assessment::testing {

inline QString postgresUrl() { return qEnvironmentVariable("MICROSIM_TEST_PG_URL"); }

/// Runs `sql` on the server's own database (outside any test database).
inline bool onServer(const QString& sql, QString* error = nullptr) {
  const QUrl url(postgresUrl());
  const QString name = QStringLiteral("microsim-test-admin");
  bool ok = false;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), name);
    db.setHostName(url.host());
    db.setPort(url.port(5432));
    db.setDatabaseName(url.path().mid(1));
    db.setUserName(url.userName());
    db.setPassword(url.password());
    if (db.open()) {
      QSqlQuery q(db);
      ok = q.exec(sql);
      if (!ok && error) *error = q.lastError().text();
    } else if (error) {
      *error = db.lastError().text();
    }
    db.close();
  }
  QSqlDatabase::removeDatabase(name);
  return ok;
}

class HistoryBackend : public ::testing::TestWithParam<Driver> {
 protected:
  void SetUp() override {
    if (GetParam() == Driver::SQLite) {
      location_ = dir_.filePath(QStringLiteral("history.sqlite"));
      return;
    }
    if (postgresUrl().isEmpty())
      GTEST_SKIP() << "MICROSIM_TEST_PG_URL is not set: run under scripts/postgres-for-tests.sh "
                      "(scripts/test.sh does) to test on PostgreSQL";
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QPSQL")))
      GTEST_SKIP() << "the Qt PostgreSQL driver (libqt6sql6-psql) is not installed";
    pgName_ = QStringLiteral("microsim_test_%1").arg(QRandomGenerator::global()->generate64(), 0, 16);
    QString error;
    ASSERT_TRUE(onServer(QStringLiteral("CREATE DATABASE %1").arg(pgName_), &error)) << error.toStdString();
    QUrl url(postgresUrl());
    url.setPath(QLatin1Char('/') + pgName_);
    location_ = url.toString();
  }

  void TearDown() override {
    if (!pgName_.isEmpty()) onServer(QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(pgName_));
  }

  /// Opens a HistoryDatabase on this test's database, with cheap password hashing.
  void openInto(HistoryDatabase& db) {
    const DatabaseStatus status = db.open(location_);
    ASSERT_TRUE(status.ok()) << status.driverMessage.toStdString();
    db.setPasswordIterations(1000);
  }

  QString location_;
  QTemporaryDir dir_;
  QString pgName_;
};

inline std::string backendName(const ::testing::TestParamInfo<Driver>& info) {
  return info.param == Driver::SQLite ? "SQLite" : "PostgreSQL";
}

}  // namespace microsim::assessment::testing

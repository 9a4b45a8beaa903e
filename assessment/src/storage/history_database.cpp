#include "microsim/assessment/storage/history_database.h"

#include "microsim/assessment/storage/migrations.h"

#include <QAtomicInt>
#include <QDir>
#include <QFileInfo>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>

namespace microsim::assessment {

namespace {

// SQLite's primary result codes, as QSqlError::nativeErrorCode() reports them.
constexpr int kSqliteBusy = 5;
constexpr int kSqliteLocked = 6;
constexpr int kSqliteCorrupt = 11;
constexpr int kSqliteNotADb = 26;

QString nextConnectionName() {
  static QAtomicInt counter;
  return QStringLiteral("microsim-history-%1").arg(counter.fetchAndAddRelaxed(1));
}

DatabaseError classify(const QSqlError& error) {
  const int code = error.nativeErrorCode().toInt() & 0xff;  // extended codes keep the primary in the low byte
  switch (code) {
    case kSqliteBusy:
    case kSqliteLocked:
      return DatabaseError::Locked;
    case kSqliteCorrupt:
    case kSqliteNotADb:
      return DatabaseError::NotADatabase;
    default:
      return DatabaseError::CannotOpen;
  }
}

}  // namespace

HistoryDatabase::HistoryDatabase() : connectionName_(nextConnectionName()) {}

HistoryDatabase::~HistoryDatabase() { close(); }

QString HistoryDatabase::defaultPath() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/history.sqlite");
}

DatabaseStatus HistoryDatabase::open(const QString& path) {
  close();
  DatabaseStatus status;
  const QFileInfo info(path);
  if (!QDir().mkpath(info.absolutePath())) {
    status.error = DatabaseError::CannotCreateFolder;
    status.driverMessage = info.absolutePath();
    return status;
  }

  QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connectionName_);
  db.setDatabaseName(info.absoluteFilePath());
  db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=2000"));
  if (!db.open()) {
    status.error = classify(db.lastError());
    status.driverMessage = db.lastError().text();
    close();
    return status;
  }

  // the first statements touch the file: a corrupt or foreign file fails here
  QSqlQuery q(db);
  for (const char* pragma : {"PRAGMA foreign_keys = ON", "PRAGMA journal_mode = WAL",
                             "PRAGMA synchronous = NORMAL"}) {
    if (!q.exec(QString::fromLatin1(pragma))) {
      status.error = classify(q.lastError());
      status.driverMessage = q.lastError().text();
      close();
      return status;
    }
  }
  if (!q.exec(QStringLiteral("SELECT count(*) FROM sqlite_master"))) {
    status.error = classify(q.lastError());
    status.driverMessage = q.lastError().text();
    close();
    return status;
  }

  const MigrationOutcome outcome = migrate(db, bundledMigrations());
  status.schemaVersion = outcome.version;
  switch (outcome.result) {
    case MigrationResult::Ok:
      break;
    case MigrationResult::NewerSchema:
      status.error = DatabaseError::NewerSchema;
      close();
      return status;
    case MigrationResult::Failed:
      status.error = DatabaseError::MigrationFailed;
      status.driverMessage = outcome.driverMessage;
      close();
      return status;
  }
  path_ = info.absoluteFilePath();
  return status;
}

void HistoryDatabase::close() {
  if (QSqlDatabase::contains(connectionName_)) {
    {
      QSqlDatabase db = QSqlDatabase::database(connectionName_, false);
      db.close();
    }
    QSqlDatabase::removeDatabase(connectionName_);
  }
  path_.clear();
}

bool HistoryDatabase::isOpen() const {
  return QSqlDatabase::contains(connectionName_) &&
         QSqlDatabase::database(connectionName_, false).isOpen();
}

int HistoryDatabase::schemaVersion() {
  if (!isOpen()) return 0;
  QSqlDatabase db = connection();
  return microsim::assessment::schemaVersion(db);
}

QSqlDatabase HistoryDatabase::connection() const {
  return QSqlDatabase::database(connectionName_, false);
}

}  // namespace microsim::assessment

#include "microsim/assessment/storage/history_database.h"

#include "storage/sql_util.h"

#include <QAtomicInt>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSet>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QSysInfo>
#include <QUrl>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <csignal>
#endif

namespace microsim::assessment {

namespace {

// SQLite's primary result codes, as QSqlError::nativeErrorCode() reports them.
constexpr int kSqliteBusy = 5;
constexpr int kSqliteLocked = 6;
constexpr int kSqliteReadOnly = 8;
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
    case kSqliteReadOnly:
      return DatabaseError::ReadOnly;
    case kSqliteCorrupt:
    case kSqliteNotADb:
      return DatabaseError::NotADatabase;
    default:
      return DatabaseError::CannotOpen;
  }
}

DatabaseStatus failure(DatabaseError error, const QString& message) {
  DatabaseStatus status;
  status.error = error;
  status.driverMessage = message;
  return status;
}

// the owner's write bit and ours: root may write anything, but a file whose owner made it
// read-only is meant to stay as it is
bool writable(const QString& path) {
  const QFileDevice::Permissions p = QFile::permissions(path);
  return (p & QFileDevice::WriteOwner) && (p & QFileDevice::WriteUser);
}

// true unless `pid` is certainly gone (no such process on this machine)
bool processMayBeAlive(qint64 pid) {
#ifdef Q_OS_UNIX
  if (pid <= 0) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
#else
  Q_UNUSED(pid);
  return true;
#endif
}

}  // namespace

HistoryDatabase::HistoryDatabase() : connectionName_(nextConnectionName()) {}

HistoryDatabase::~HistoryDatabase() { close(); }

QString HistoryDatabase::defaultPath() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
         QStringLiteral("/history.sqlite");
}

bool HistoryDatabase::isUrl(const QString& location) {
  return location.startsWith(QLatin1String("postgresql://")) ||
         location.startsWith(QLatin1String("postgres://"));
}

DatabaseStatus HistoryDatabase::open(const QString& location) {
  close();
  // the connection is removed only once the opening functions' handles to it are gone
  DatabaseStatus status = isUrl(location) ? openPostgres(location) : openSqlite(location);
  if (!status.ok()) close();
  return status;
}

DatabaseStatus HistoryDatabase::openSqlite(const QString& path) {
  driver_ = Driver::SQLite;
  const QFileInfo info(path);
  if (!QDir().mkpath(info.absolutePath()))
    return failure(DatabaseError::CannotCreateFolder, info.absolutePath());
  // permissions are checked by hand: as root SQLite would write a file marked read-only
  if ((info.exists() && !writable(info.absoluteFilePath())) || !writable(info.absolutePath()))
    return failure(DatabaseError::ReadOnly, info.absoluteFilePath());

  QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connectionName_);
  db.setDatabaseName(info.absoluteFilePath());
  db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=2000"));
  if (!db.open())
    return failure(classify(db.lastError()), db.lastError().text());

  // the first statements touch the file: a corrupt or foreign file fails here
  QSqlQuery q(db);
  for (const char* statement : {"PRAGMA foreign_keys = ON", "PRAGMA journal_mode = WAL",
                                "PRAGMA synchronous = NORMAL", "SELECT count(*) FROM sqlite_master"}) {
    if (!q.exec(QString::fromLatin1(statement)))
      return failure(classify(q.lastError()), q.lastError().text());
  }
  q.finish();  // an open read would lock the tables a migration drops
  session_ = QStringLiteral("%1@%2").arg(QCoreApplication::applicationPid()).arg(QSysInfo::machineHostName());
  path_ = info.absoluteFilePath();
  return finishOpen(db);
}

DatabaseStatus HistoryDatabase::openPostgres(const QString& location) {
  driver_ = Driver::PostgreSQL;
  const QUrl url(location, QUrl::StrictMode);
  const QString name = url.path(QUrl::FullyDecoded).mid(1);
  if (!url.isValid() || url.host().isEmpty() || name.isEmpty())
    return failure(DatabaseError::CannotOpen, url.toString(QUrl::RemovePassword));
  if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QPSQL")))
    return failure(DatabaseError::CannotOpen, QStringLiteral("QPSQL driver not available"));

  QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), connectionName_);
  db.setHostName(url.host());
  db.setPort(url.port(5432));
  db.setDatabaseName(name);
  db.setUserName(url.userName(QUrl::FullyDecoded));
  db.setPassword(url.password(QUrl::FullyDecoded));
  db.setConnectOptions(QStringLiteral("connect_timeout=10"));
  if (!db.open())
    return failure(DatabaseError::CannotOpen, db.lastError().text());
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("SELECT pg_backend_pid()")) || !q.next())
    return failure(DatabaseError::CannotOpen, q.lastError().text());
  session_ = QStringLiteral("pg:%1").arg(q.value(0).toLongLong());
  q.finish();
  path_ = url.toString(QUrl::RemovePassword);
  return finishOpen(db);
}

DatabaseStatus HistoryDatabase::finishOpen(QSqlDatabase& db) {
  DatabaseStatus status;
  const MigrationOutcome outcome = migrate(db, bundledMigrations());
  status.schemaVersion = outcome.version;
  if (outcome.result != MigrationResult::Ok) {
    status.error = outcome.result == MigrationResult::NewerSchema ? DatabaseError::NewerSchema
                                                                  : DatabaseError::MigrationFailed;
    status.driverMessage = outcome.driverMessage;
    return status;
  }
  interruptOrphanedAttempts();
  last_ = {};
  return status;
}

void HistoryDatabase::interruptOrphanedAttempts() {
  QSqlDatabase db = connection();
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("SELECT id, session FROM attempts WHERE status = 'in_progress'"))) return;
  QList<qint64> orphans;
  QSet<QString> liveBackends;
  if (driver_ == Driver::PostgreSQL) {
    QSqlQuery live(db);
    if (live.exec(QStringLiteral("SELECT pid FROM pg_stat_activity")))
      while (live.next()) liveBackends.insert(QStringLiteral("pg:%1").arg(live.value(0).toLongLong()));
  }
  const QString host = QSysInfo::machineHostName();
  while (q.next()) {
    const QString session = q.value(1).toString();
    bool gone = session.isEmpty();
    if (!gone && driver_ == Driver::PostgreSQL) {
      gone = !liveBackends.contains(session);
    } else if (!gone) {
      // pid@host: only this machine's processes can be checked; our own pid may be another
      // connection of this process
      const qsizetype at = session.indexOf(QLatin1Char('@'));
      const qint64 pid = session.left(at).toLongLong();
      gone = session.mid(at + 1) == host && pid != QCoreApplication::applicationPid() &&
             !processMayBeAlive(pid);
    }
    if (gone) orphans << q.value(0).toLongLong();
  }
  q.finish();
  for (qint64 id : orphans) {
    QSqlQuery u(db);
    u.prepare(QStringLiteral(
        "UPDATE attempts SET status = 'interrupted', finished_at = ? WHERE id = ? AND status = 'in_progress'"));
    u.addBindValue(sql::now());
    u.addBindValue(id);
    u.exec();
  }
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
  session_.clear();
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

bool HistoryDatabase::fail(HistoryError error, const QString& driverMessage) {
  last_ = {error, driverMessage};
  return false;
}

bool HistoryDatabase::succeed() {
  last_ = {};
  return true;
}

std::optional<Role> HistoryDatabase::storedRole(qint64 personId) {
  QSqlQuery q(connection());
  q.prepare(QStringLiteral("SELECT role FROM trainees WHERE id = ?"));
  q.addBindValue(personId);
  if (!q.exec() || !q.next()) return std::nullopt;
  return sql::roleFromText(q.value(0).toString());
}

bool HistoryDatabase::mayView(const Viewer& viewer, std::optional<qint64> traineeId) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  const std::optional<Role> role = storedRole(viewer.userId);
  if (!role || *role != viewer.role) return fail(HistoryError::Forbidden);
  if (viewer.role == Role::Trainee && traineeId && *traineeId != viewer.userId)
    return fail(HistoryError::Forbidden);
  return succeed();
}

}  // namespace microsim::assessment

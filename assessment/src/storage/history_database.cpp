#include "microsim/assessment/storage/history_database.h"

#include "microsim/assessment/storage/attempt_store.h"

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

#include <mutex>
#include <utility>

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

QAtomicInt connectionCounter;

// the SQLite session tags of this process's open connections: an attempt tagged with one
// of our pid's tags that is not here was begun by a connection closed since. Connections
// open and close on several threads; a std::mutex, which ThreadSanitizer follows.
struct OpenSessions {
  std::mutex mutex;
  QSet<QString> tags;
};
OpenSessions& openSessions() {
  static OpenSessions sessions;
  return sessions;
}

struct AccessObserverSlot {
  std::mutex mutex;
  HistoryDatabase::AccessObserver observer;
};
AccessObserverSlot& accessObserverSlot() {
  static AccessObserverSlot slot;
  return slot;
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

HistoryDatabase::HistoryDatabase()
    : connectionName_(QStringLiteral("microsim-history-%1").arg(connectionCounter.fetchAndAddRelaxed(1))) {}

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
  notifyAccess();
  close();
  location_ = location;
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
  // pid@host#n: the process and, within it, this connection
  session_ = QStringLiteral("%1@%2#%3")
                 .arg(QCoreApplication::applicationPid())
                 .arg(QSysInfo::machineHostName(), connectionName_.section(QLatin1Char('-'), -1));
  {
    OpenSessions& open = openSessions();
    const std::lock_guard lock(open.mutex);
    open.tags.insert(session_);
  }
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
  AttemptStore(*this).interruptEndedSessions();
  last_ = {};
  return status;
}

bool HistoryDatabase::sessionEnded(const QString& session) {
  if (session.isEmpty()) return true;
  if (driver_ == Driver::PostgreSQL) {
    // pg:<backend pid>, ended when the server no longer runs that backend
    QSqlQuery q(connection());
    q.prepare(QStringLiteral("SELECT count(*) FROM pg_stat_activity WHERE pid = ?"));
    q.addBindValue(session.mid(3).toLongLong());
    return q.exec() && q.next() && q.value(0).toInt() == 0;
  }
  // pid@host#n (pid@host before schema 4): only this machine's processes can be checked
  const qsizetype at = session.indexOf(QLatin1Char('@'));
  const qsizetype hash = session.indexOf(QLatin1Char('#'), at);
  const qint64 pid = session.left(at).toLongLong();
  const QString host = session.mid(at + 1, hash < 0 ? -1 : hash - at - 1);
  if (at < 0 || host != QSysInfo::machineHostName()) return false;
  if (pid != QCoreApplication::applicationPid()) return !processMayBeAlive(pid);
  // ours: ended when its connection is closed; an untagged one may be any of ours
  if (hash < 0) return false;
  OpenSessions& open = openSessions();
  const std::lock_guard lock(open.mutex);
  return !open.tags.contains(session);
}

void HistoryDatabase::close() {
  if (QSqlDatabase::contains(connectionName_)) {
    notifyAccess();
    {
      QSqlDatabase db = QSqlDatabase::database(connectionName_, false);
      db.close();
    }
    QSqlDatabase::removeDatabase(connectionName_);
  }
  if (!session_.isEmpty()) {
    OpenSessions& open = openSessions();
    const std::lock_guard lock(open.mutex);
    open.tags.remove(session_);
  }
  path_.clear();
  location_.clear();
  session_.clear();
}

bool HistoryDatabase::isOpen() const {
  notifyAccess();
  return QSqlDatabase::contains(connectionName_) &&
         QSqlDatabase::database(connectionName_, false).isOpen();
}

int HistoryDatabase::schemaVersion() {
  if (!isOpen()) return 0;
  QSqlDatabase db = connection();
  return microsim::assessment::schemaVersion(db);
}

QSqlDatabase HistoryDatabase::connection() const {
  notifyAccess();
  return QSqlDatabase::database(connectionName_, false);
}

void HistoryDatabase::setAccessObserver(AccessObserver observer) {
  AccessObserverSlot& slot = accessObserverSlot();
  const std::lock_guard lock(slot.mutex);
  slot.observer = std::move(observer);
}

void HistoryDatabase::notifyAccess() const {
  AccessObserverSlot& slot = accessObserverSlot();
  const std::lock_guard lock(slot.mutex);
  if (slot.observer) slot.observer(*this);
}

bool HistoryDatabase::fail(HistoryError error, const QString& driverMessage) {
  last_ = {error, driverMessage};
  return false;
}

bool HistoryDatabase::succeed() {
  last_ = {};
  return true;
}

}  // namespace microsim::assessment

// HistoryDatabase: backup and restore of an SQLite history.
#include "microsim/assessment/storage/history_database.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QSqlError>
#include <QSqlQuery>

namespace microsim::assessment {

namespace {

enum class BackupCheck { Ok, NotABackup, TooNew };

// opens `file` read-only on its own connection: a microsim history whose schema this
// program knows, and whose pages are sound
BackupCheck checkBackup(const QString& file, QString* message) {
  if (!QFileInfo(file).isFile()) return BackupCheck::NotABackup;
  const QString name = QStringLiteral("microsim-restore-check");
  BackupCheck result = BackupCheck::NotABackup;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
    db.setDatabaseName(file);
    db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
    if (db.open()) {
      QSqlQuery q(db);
      const bool sound = q.exec(QStringLiteral("PRAGMA quick_check")) && q.next() &&
                         q.value(0).toString() == QLatin1String("ok");
      q.finish();
      const bool ours =
          sound && q.exec(QStringLiteral(
                       "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name IN "
                       "('schema_migrations', 'trainees', 'attempts')")) &&
          q.next() && q.value(0).toInt() == 3;
      q.finish();
      if (ours && q.exec(QStringLiteral("SELECT COALESCE(MAX(version), 0) FROM schema_migrations")) &&
          q.next()) {
        const std::vector<Migration> known = bundledMigrations();
        const int newest = known.empty() ? 0 : known.back().version;
        result = q.value(0).toInt() > newest ? BackupCheck::TooNew : BackupCheck::Ok;
      }
      if (result == BackupCheck::NotABackup) *message = q.lastError().text();
      q.finish();
    } else {
      *message = db.lastError().text();
    }
    db.close();
  }
  QSqlDatabase::removeDatabase(name);
  return result;
}

}  // namespace

bool HistoryDatabase::backup(const QString& toFile) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  if (driver_ != Driver::SQLite) return fail(HistoryError::Unsupported);
  const QFileInfo target(toFile);
  if (target.exists()) return fail(HistoryError::FileError, target.absoluteFilePath());
  // VACUUM INTO reads one snapshot: a consistent copy while others write. It goes to a
  // side file renamed when complete, so a full disk or a killed process never leaves a
  // half-written file under the backup's name.
  const QString partial = target.absoluteFilePath() + QStringLiteral(".part");
  QFile::remove(partial);
  QSqlQuery q(connection());
  q.prepare(QStringLiteral("VACUUM INTO ?"));
  q.addBindValue(partial);
  if (!q.exec()) {
    const QString why = q.lastError().text();
    QFile::remove(partial);
    return fail(HistoryError::FileError, why);
  }
  if (!QFile::rename(partial, target.absoluteFilePath())) {
    QFile::remove(partial);
    return fail(HistoryError::FileError, target.absoluteFilePath());
  }
  return succeed();
}

bool HistoryDatabase::restore(const QString& fromFile) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  if (driver_ != Driver::SQLite) return fail(HistoryError::Unsupported);
  QString message;
  switch (checkBackup(fromFile, &message)) {
    case BackupCheck::NotABackup:
      return fail(HistoryError::NotABackup, message);
    case BackupCheck::TooNew:
      return fail(HistoryError::BackupTooNew);
    case BackupCheck::Ok:
      break;
  }
  QFile source(fromFile);
  if (!source.open(QIODevice::ReadOnly)) return fail(HistoryError::FileError, source.errorString());

  // closing checkpoints and removes our WAL; a stale one must not be replayed onto the copy
  const QString path = path_;
  close();
  QFile::remove(path + QStringLiteral("-wal"));
  QFile::remove(path + QStringLiteral("-shm"));
  QSaveFile target(path);
  bool copied = target.open(QIODevice::WriteOnly);
  while (copied && !source.atEnd()) copied = target.write(source.read(1 << 20)) >= 0;
  copied = copied && target.commit();  // an atomic rename: the old file stays until here
  const QString copyError = target.errorString();

  const DatabaseStatus reopened = open(path);
  if (!copied) return fail(HistoryError::FileError, copyError);
  if (!reopened.ok()) return fail(HistoryError::QueryFailed, reopened.driverMessage);
  return succeed();
}

}  // namespace microsim::assessment

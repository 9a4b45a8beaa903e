#pragma once
// The trainees' history: one SQLite file (by default in the user's data folder) opened
// through QtSql, with WAL journaling and foreign keys on, and brought to the newest
// schema on open. Errors come back as an enum plus the driver's text as data; the app
// decides what to tell the user, and a database that cannot be opened is never changed.

#include <QSqlDatabase>
#include <QString>

namespace microsim::assessment {

enum class DatabaseError {
  None,
  CannotCreateFolder,  ///< the folder for the file could not be made
  CannotOpen,          ///< the driver refused the file (permissions, missing driver)
  NotADatabase,        ///< the file exists but is not SQLite, or is corrupt
  Locked,              ///< another process holds a lock longer than the busy timeout
  NewerSchema,         ///< written by a newer microsim; opened read-only would be unsafe
  MigrationFailed,     ///< a migration failed and was rolled back
};

struct DatabaseStatus {
  DatabaseError error = DatabaseError::None;
  int schemaVersion = 0;
  QString driverMessage;
  bool ok() const { return error == DatabaseError::None; }
};

class HistoryDatabase {
 public:
  HistoryDatabase();
  ~HistoryDatabase();
  HistoryDatabase(const HistoryDatabase&) = delete;
  HistoryDatabase& operator=(const HistoryDatabase&) = delete;

  /// <AppDataLocation>/history.sqlite
  static QString defaultPath();

  /// Opens (creating if needed) the SQLite file at `path` and applies pending migrations.
  DatabaseStatus open(const QString& path);
  void close();

  bool isOpen() const;
  QString path() const { return path_; }
  int schemaVersion();
  /// The connection, for repositories in this library.
  QSqlDatabase connection() const;

 private:
  QString connectionName_;
  QString path_;
};

}  // namespace microsim::assessment
